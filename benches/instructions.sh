#!/usr/bin/env bash
# Instruction counts (callgrind: deterministic, unlike wall-clock time on a
# shared 2-core machine) of the library call `ccd_exact::run` and of the
# whole `ccd-exact` process, per scene and mode, for one or two binaries.
#
#   bash benches/instructions.sh [OLD_BINARY] > counts.tsv
#
# Columns: scene, mode, run (new), process (new) and, with OLD_BINARY, the
# same for it and the change of `run`. Needs valgrind.
set -euo pipefail
cd "$(dirname "$0")/.."
NEW=${BIN:-target/release/ccd-exact}
OLD=${1:-}
SCENES=${SCENES:-"benches/scenes/rigid-deg2.toml benches/scenes/affine-deg2.toml benches/scenes/affine-rational-deg2.toml tests/scenes/paper-example-5-1.toml tests/scenes/rigid-tumbling.toml tests/stability/throughout-far-apart.toml tests/stability/graze-turned-k001-miss.toml tests/stability/graze-spheres-k08-overlap.toml benches/scenes/lines/line04.toml benches/scenes/lines/line07.toml"}
tmp=$(mktemp -d)
count() { # binary scene mode... -> "run process"
  local bin=$1 scene=$2; shift 2
  valgrind --tool=callgrind --callgrind-out-file="$tmp/cg" "$bin" "$scene" --json "$@" >/dev/null 2>"$tmp/err" || true
  local total run
  total=$(callgrind_annotate "$tmp/cg" 2>/dev/null | awk '/PROGRAM TOTALS/ && !done {gsub(",", "", $1); print $1; done = 1}')
  run=$(callgrind_annotate --inclusive=yes "$tmp/cg" 2>/dev/null | awk '/src\/lib.rs:ccd_exact::run / && !done {gsub(",", "", $1); print $1; done = 1}')
  echo "${run:-0} ${total:-0}"
}
printf 'scene\tmode\trun\tprocess'
[ -n "$OLD" ] && printf '\trun_old\tprocess_old\trun_change'
printf '\n'
for s in $SCENES; do
  for mode in "" "--first-contact" "--arithmetic float"; do
    # shellcheck disable=SC2086
    read -r run total < <(count "$NEW" "$s" $mode)
    printf '%s\t%s\t%s\t%s' "$(basename "$s" .toml)" "${mode:-full}" "$run" "$total"
    if [ -n "$OLD" ]; then
      # shellcheck disable=SC2086
      read -r orun ototal < <(count "$OLD" "$s" $mode)
      printf '\t%s\t%s\t%s' "$orun" "$ototal" "$(python3 -c "print(f'{($run - $orun) / $orun * 100:+.1f} %' if $orun else 'n/a')")"
    fi
    printf '\n'
  done
done
rm -rf "$tmp"
