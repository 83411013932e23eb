#!/usr/bin/env bash
# Wall clock of two revisions, each linked in several code layouts: whether
# a change is faster, not whether its binary drew a lucky layout.
#
#   bash benches/layouts.sh OLD NEW [SEEDS] [PASSES]
#
# OLD and NEW are git revisions (NEW may be `.`, the working tree). Each is
# built once (`examples/speed`, release profile) through a linker wrapper
# that keeps the objects, then relinked as built (seed 0) and with lld's
# `--shuffle-sections` under SEEDS further seeds (default 3). The binaries
# run alternated, pinned to one core, PASSES times (default 15) over the
# five class scenes; the table is the minimum of the per-pass medians.
#
# Why: on this project's short queries, a different function order moves
# the exact path's wall clock by 1–5 % with no code changed (rigid and
# Example 5.1 the most), the size of the gains measured since session 37.
# A change is kept when it is faster in the same layout, layout by layout
# (docs/table4.md, issue 17, session 40).
set -euo pipefail
cd "$(dirname "$0")/.."
OLD=${1:?usage: layouts.sh OLD NEW [SEEDS] [PASSES]}
NEW=${2:?usage: layouts.sh OLD NEW [SEEDS] [PASSES]}
SEEDS=${3:-3}
PASSES=${4:-15}
WORK=$(mktemp -d /tmp/layouts.XXXXXX)
ROOT=$PWD
# The worktrees and the build go with the script, however it ends.
cleanup() {
  for tree in "$WORK"/src-*; do
    if [ -d "$tree" ]; then git worktree remove --force "$tree"; fi
  done
  rm -rf "$WORK"
}
trap cleanup EXIT
source benches/classes.sh

# The wrapper links as `cc` does and, for the `speed` example, keeps its
# objects and the command line (output path as @OUT@) in $KEEP. Its name
# matters: rustc infers the linker's flavour from it. Named `cc`, `gcc` or
# `clang` it would lose rustc's `-fuse-ld=lld` (GNU ld has no
# `--shuffle-sections`); named `…ld` it would be handed `ld`'s arguments.
# (A response file `@…` holding the objects is not looked into: rustc
# writes one only for command lines too long for the system, and the
# `speed` example's is short.) Both revisions need rustc ≥ 1.90, whose
# default linker on x86_64 Linux is lld.
cat > "$WORK/save-objects.sh" <<'EOF'
#!/usr/bin/env bash
out=""; prev=""
for a in "$@"; do [ "$prev" = "-o" ] && out="$a"; prev="$a"; done
case "$(basename "$out")" in
speed-*)
  args=(); prev=""
  for a in "$@"; do
    if [ "$prev" = "-o" ]; then args+=("@OUT@")
    elif [[ "$a" == @* ]]; then cp "${a#@}" "$KEEP/response"; args+=("@$KEEP/response")
    elif [[ "$a" == *.o || "$a" == *.rlib || "$a" == *.a ]] && [ -f "$a" ]; then
      cp "$a" "$KEEP/"; args+=("$KEEP/$(basename "$a")")
    else args+=("$a"); fi
    prev="$a"
  done
  printf '%q ' cc "${args[@]}" > "$KEEP/link-command"
  ;;
esac
exec cc "$@"
EOF
chmod +x "$WORK/save-objects.sh"

build() { # build TAG REV
  local tag=$1 rev=$2 src
  if [ "$rev" = . ]; then src=$ROOT; else
    src=$WORK/src-$tag
    git worktree add -q --detach "$src" "$rev"
  fi
  mkdir -p "$WORK/keep-$tag"
  (cd "$src" && KEEP="$WORK/keep-$tag" \
    CARGO_TARGET_X86_64_UNKNOWN_LINUX_GNU_LINKER="$WORK/save-objects.sh" \
    CARGO_TARGET_DIR="$WORK/target" cargo build -q --release --example speed >&2)
  [ "$rev" = . ] || git worktree remove --force "$src"
  local cmd seed
  cmd=$(cat "$WORK/keep-$tag/link-command")
  for seed in $(seq 0 "$SEEDS"); do
    local extra=""
    [ "$seed" = 0 ] || extra="'-Wl,--shuffle-sections=.text*=$seed'"
    eval "${cmd//@OUT@/$WORK/$tag-$seed} $extra"
  done
}
build old "$OLD"
build new "$NEW"

for _ in $(seq "$PASSES"); do
  for seed in $(seq 0 "$SEEDS"); do
    for tag in old new; do
      taskset -c 1 "$WORK/$tag-$seed" --reps 101 "${CLASSES[@]}" | tail -n +2 |
        sed "s/^/$tag, seed $seed\t/" >> "$WORK/passes.tsv"
    done
  done
done

python3 - "$WORK/passes.tsv" "$SEEDS" <<'PY'
import collections, sys
sys.path.insert(0, "benches")
from minima import minima, print_table
table, seeds = minima(sys.argv[1]), int(sys.argv[2])
print_table(table, "layout")
faster = collections.Counter()
for seed in range(seeds + 1):
    old, new = table[f"old, seed {seed}"], table[f"new, seed {seed}"]
    for s in old:
        faster[s] += new[s][0] < old[s][0]
print("new exact faster than old in the same layout:")
for s, n in faster.items():
    print(f"  {s}: {n} of {seeds + 1} layouts")
PY
