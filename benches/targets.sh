#!/usr/bin/env bash
# Every target row of issue 17 measured in one run on this host, printed as
# the markdown table of docs/table4.md (target, measured, met?): the five
# timing classes with their exact / float ratios, the stability set's
# median and maximum, the straight-line scenes (default path and
# `--raycast`), a static pair, and the CLI's whole process against the
# library call. So that the rows can be read on another host (the owner's
# question of which host the stability maximum is read on) with one
# command, the method of session 48 in the repository rather than in
# a session's notes.
#
#   bash benches/targets.sh [--class-passes 60] [--stability-passes 10] [--quick] > /tmp/targets.md
#
# About 2 minutes with the defaults, pinned to one CPU: run it
# on an otherwise idle machine. `--quick` checks the plumbing (CI does),
# its numbers mean nothing. Options: `python3 benches/targets.py --help`.
# CARGO_FLAGS (e.g. "-j1") is passed to cargo build.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck disable=SC2086
cargo build -q --release ${CARGO_FLAGS:-} --bin ccd-exact --example speed >&2
exec python3 benches/targets.py --speed target/release/examples/speed --bin target/release/ccd-exact "$@"
