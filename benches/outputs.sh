#!/usr/bin/env bash
# Prints the CLI's JSON for every shipped pair scene in the exact, exact
# first-contact and float modes, one block per run: the yardstick that a
# speed change leaves every answer byte-identical.
#
#   bash benches/outputs.sh > /tmp/before.txt   # on the old code
#   bash benches/outputs.sh > /tmp/after.txt    # on the new code
#   cmp /tmp/before.txt /tmp/after.txt
#
# BIN names the binary to run (default: target/release/ccd-exact, built here).
# ALL_MODES=1 adds `--raycast` and `--no-geometry` runs, the world scenes
# and the batch (comparing two builds of the same code: benches/pgo.sh in CI).
set -uo pipefail
cd "$(dirname "$0")/.."
BIN=${BIN:-target/release/ccd-exact}
[ -n "${BIN_BUILT:-}" ] || cargo build -q --release >&2
one() { # one SCENE MODE: a block of the output
  echo "== $1 $2"
  # shellcheck disable=SC2086
  "$BIN" "$1" --json $2 2>&1
  echo "exit $?"
}
modes=("" "--first-contact" "--arithmetic float")
[ -z "${ALL_MODES:-}" ] || modes+=("--raycast" "--no-geometry")
for s in tests/scenes/*.toml tests/stability/*.toml benches/scenes/*.toml benches/scenes/lines/*.toml; do
  case "$s" in *world*|*issue-18-*|*rigid-288*) continue ;; esac # worlds: tests/world.rs; the slow ones
  for mode in "${modes[@]}"; do one "$s" "$mode"; done
done
[ -n "${ALL_MODES:-}" ] || exit 0
for s in tests/scenes/world*.toml; do
  for mode in "" "--first-contact"; do one "$s" "$mode"; done
done
echo "== batch tests/scenes/pairs.jsonl"
"$BIN" batch < tests/scenes/pairs.jsonl 2>&1
echo "exit $?"
