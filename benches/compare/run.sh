#!/usr/bin/env bash
# Our exact query against FLINT (certified roots of the λ-discriminant
# alone) and FCL (sampling CCD, 100 samples) on the straight-line scenes, in
# one run: prints the markdown of docs/table4.md's "Against FLINT and FCL".
#
#   bash benches/compare/run.sh [--reps N] [--passes N] > /tmp/compare.md
#
# Creates a venv under target/compare-venv (python-flint, python-fcl,
# numpy from PyPI) once, builds the release binary and the examples `speed`
# and `sr0`, and runs compare.py. A benchmark, not a test: not in .ci/run.
# CARGO_FLAGS (e.g. "-j1") is passed to cargo build.
set -euo pipefail
cd "$(dirname "$0")/../.."
VENV=target/compare-venv
if [ ! -x "$VENV/bin/python" ]; then
  python3 -m venv "$VENV"
  "$VENV/bin/pip" install -q python-flint python-fcl numpy >&2
fi
# shellcheck disable=SC2086
cargo build -q --release ${CARGO_FLAGS:-} --bin ccd-exact --example speed --example sr0 >&2
{ echo "== $(date -u '+%Y-%m-%d %H:%M UTC'), commit $(git rev-parse --short HEAD), uptime:$(uptime)"
  "$VENV/bin/pip" list 2>/dev/null | grep -iE '^(python-flint|python-fcl|numpy) '; } >&2
exec "$VENV/bin/python" benches/compare/compare.py \
  --bin target/release/ccd-exact \
  --speed target/release/examples/speed \
  --sr0 target/release/examples/sr0 "$@"
