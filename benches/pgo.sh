#!/usr/bin/env bash
# A profile-guided build (PGO) of the CLI and of `examples/speed`, trained
# on every shipped scene: for packagers who ship a binary (a distribution
# package, a container). Same code, same answers (CI compares the 638
# runs of `ALL_MODES=1 benches/outputs.sh` byte for byte: five modes,
# worlds, the batch); on the five timing classes the exact query ran
# 3–12 % faster, the float one 1–9 % (docs/table4.md, issue 17, session
# 42). A plain `cargo build --release` stays as it is.
#
#   bash benches/pgo.sh             # target/pgo/ccd-exact, target/pgo/speed
#   bash benches/pgo.sh --compare   # and the five classes, plain vs PGO
#
# Steps: an instrumented build (`-Cprofile-generate`), the training (the
# CLI over benches/outputs.sh's runs, then `speed`'s repeated queries, which
# weigh the hot paths), `llvm-profdata merge`, and the build that uses the
# profile (`-Cprofile-use`). The profile is made afresh each time: never
# stale. `--target` keeps the flags off build scripts and proc macros.
# Needs an `llvm-profdata` of the toolchain's LLVM version: rustup's
# `llvm-tools` (added here when missing), or the one `LLVM_PROFDATA` names
# (a toolchain without rustup).
set -euo pipefail
case "${1:-}" in
"" | --compare) ;;
*) echo "usage: bash benches/pgo.sh [--compare]" >&2; exit 2 ;;
esac
cd "$(dirname "$0")/.."
HOST=$(rustc -vV | sed -n 's/^host: //p')
PROFDATA=${LLVM_PROFDATA:-"$(rustc --print sysroot)/lib/rustlib/$HOST/bin/llvm-profdata"}
[ -x "$PROFDATA" ] || rustup component add llvm-tools >&2
OUT=$PWD/target/pgo
rm -rf "$OUT/data"
mkdir -p "$OUT/data"

build() { # build RUSTFLAGS DIR
  RUSTFLAGS="$1" CARGO_TARGET_DIR="$OUT/$2" \
    cargo build -q --release --target "$HOST" --bin ccd-exact --example speed
}

echo "== instrumented build" >&2
build "-Cprofile-generate=$OUT/data" gen
GEN=$OUT/gen/$HOST/release

echo "== training" >&2
# The CLI's own code (TOML, JSON, worlds, batch): every run of
# `ALL_MODES=1 benches/outputs.sh` (five modes; without the slow hostile
# scenes). Then the library's paths weighed by repetition in `speed`
# (every mode, with and without the contact geometry; it skips the world
# files), the long numbers included. Without them (issue 18's scenes,
# rigid-288) the long-number code is profiled cold, optimised for size,
# and degree-2 and degree-4 affine ran 19–29 % *slower* than the plain
# build, tumbling 11 %, the float mode too: a profile must cover the
# whole workload.
BIN=$GEN/ccd-exact BIN_BUILT=1 ALL_MODES=1 bash benches/outputs.sh > /dev/null
all=(tests/scenes/*.toml tests/stability/*.toml benches/scenes/*.toml benches/scenes/lines/*.toml)
"$GEN/examples/speed" --reps 3 "${all[@]}" > /dev/null
"$GEN/examples/speed" --reps 3 --no-geometry "${all[@]}" > /dev/null
"$PROFDATA" merge -o "$OUT/ccd.profdata" "$OUT/data"

echo "== optimised build" >&2
build "-Cprofile-use=$OUT/ccd.profdata" use
cp "$OUT/use/$HOST/release/ccd-exact" "$OUT/use/$HOST/release/examples/speed" "$OUT/"
echo "built $OUT/ccd-exact and $OUT/speed" >&2

[ "${1:-}" = "--compare" ] || exit 0

# The five classes of docs/table4.md, plain against PGO: alternated scene
# by scene, pinned to one core where `taskset` is, 60 passes of 21-query
# medians; the minimum over the passes (this host has slow spells lasting
# seconds, which short alternations ride out).
# The plain side built as the PGO one (same flags, same target).
build "" plain
PLAIN=$OUT/plain/$HOST/release/examples/speed
PIN=()
if command -v taskset > /dev/null; then PIN=(taskset -c "$(($(nproc) - 1))"); fi
source benches/classes.sh
for _ in $(seq 60); do
  for s in "${CLASSES[@]}"; do
    "${PIN[@]}" "$PLAIN" --reps 21 "$s" | tail -n +2 | sed 's/^/plain\t/'
    "${PIN[@]}" "$OUT/speed" --reps 21 "$s" | tail -n +2 | sed 's/^/pgo\t/'
  done
done > "$OUT/compare.tsv"
python3 benches/minima.py "$OUT/compare.tsv"
