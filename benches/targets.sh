#!/usr/bin/env bash
# Every target row of issue 17 measured in one run on this host, printed as
# the markdown table of docs/table4.md (target, measured, met?): the five
# timing classes with their exact / float ratios, the stability set's
# median and maximum, the straight-line scenes (default path and
# `--raycast`), a static pair, and the CLI's whole process against the
# library call. So that the rows can be read on another host (the owner's
# question of which host the stability maximum is read on) with one
# command of the repository (docs/table4.md, issue 17, session 49).
#
#   bash benches/targets.sh [--class-passes 60] [--stability-passes 10] [--quick] > /tmp/targets.md
#
# About 50 s with the defaults (plus the build), pinned to one CPU; Linux
# (`sched_setaffinity`, `posix_spawn`). Run it on an otherwise idle
# machine. `--quick` checks the plumbing (CI does); its numbers mean
# nothing. Options: `python3 benches/targets.py --help`. CARGO_FLAGS (e.g.
# "-j1") is passed to cargo build.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck disable=SC2086
cargo build -q --release ${CARGO_FLAGS:-} --bin ccd-exact --example speed >&2
exec python3 benches/targets.py --speed target/release/examples/speed --bin target/release/ccd-exact "$@"
