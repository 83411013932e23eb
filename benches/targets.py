#!/usr/bin/env python3
"""Every target row of issue 17 ("Speed: certified answers at the cost of
floats"), measured in one run on this host, as the markdown table of
docs/table4.md: the number, the target, and whether it is met.

    python3 benches/targets.py --speed target/release/examples/speed \
        --bin target/release/ccd-exact [--class-passes 60] [--quick]

(benches/targets.sh builds both and runs this.) The rows are those of
docs/table4.md, issue 17, session 48; so is the method of the classes and
the stability set (session 48 timed the straight lines in
benches/compare's run, unpinned, beside FLINT and FCL):

* the five timing classes (benches/classes.sh), then the static pair
  (benches/scenes/static-apart.toml) in runs of its own: `--class-passes`
  runs of `examples/speed --reps 101`, the median of the per-pass
  medians, for the exact total, the exact first contact and the float
  mode; the exact / float ratio per class from those medians;
* the stability set (tests/stability, every scene): `--stability-passes`
  runs of `speed --reps 21`, per scene the minimum of the per-pass
  medians (this host has slow spells of seconds), then the median and the
  maximum over the scenes;
* the straight-line scenes (benches/straight_lines.py, the scenes of
  benches/compare): `--line-passes` runs of `speed --reps 101`, per scene
  the minimum over the passes, then medians over the scenes of the default
  path and of `--raycast`, total and first contact;
* the CLI's whole process (`ccd-exact` on Example 5.1 with `--json`,
  started `--spawns` times by `posix_spawn`, its output discarded) against
  the library call (Example 5.1's exact total above).

Everything runs pinned to one CPU (`--cpu`, by default the last one; the
children inherit the affinity), one measurement after the other: run it
on an otherwise idle machine. `--quick` (one pass, 3 repetitions, 20
spawns) checks the plumbing in a few seconds; its numbers mean nothing.
Progress goes to stderr, the table to stdout.
"""

import argparse
import datetime
import glob
import os
import platform
import statistics
import subprocess
import sys
import time

from speed_runs import COLUMNS, speed
from straight_lines import EXAMPLE_5_1, select_scenes

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
STATIC = "benches/scenes/static-apart.toml"
# The classes' names in the table, by scene file (benches/classes.sh).
CLASS_NAMES = {
    "rigid-deg2.toml": "degree-2 rigid",
    "affine-deg2.toml": "degree-2 affine",
    "affine-rational-deg2.toml": "degree-4 affine",
    "paper-example-5-1.toml": "Example 5.1",
    "rigid-tumbling.toml": "tumbling",
}
# Issue 17's targets (µs, or a ratio).
RIGID_TOTAL = 55.0
AFFINE2_TOTAL = 250.0
AFFINE4_TOTAL, AFFINE4_FIRST = 250.0, 180.0
RATIO = 1.3
STABILITY_MEDIAN, STABILITY_SPREAD = 120.0, 20.0
LINES_TOTAL, LINES_FIRST = 42.0, 10.0
STATIC_TOTAL = 5.0


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def classes():
    """The scene paths of benches/classes.sh's CLASSES array, as bash reads it."""
    script = 'source benches/classes.sh && printf "%s\\n" "${CLASSES[@]}"'
    out = subprocess.run(["bash", "-c", script], cwd=ROOT, capture_output=True, text=True, check=True)
    return out.stdout.split()


def passes(binary, reps, paths, count, label):
    """`count` runs of `speed` over `paths`: {scene: {column: [µs per pass]}}."""
    runs = {}
    for k in range(count):
        log(f"{label}: pass {k + 1} of {count}")
        for name, row in speed(binary, reps, paths, ROOT).items():
            cell = runs.setdefault(name, {"path": row["path"]})
            for key in COLUMNS:
                cell.setdefault(key, []).append(row[key])
    return runs


def spawn_ms(binary, args, count):
    """Median and minimum (ms) of `count` whole processes of `binary args`,
    each started by `posix_spawn` and waited for, stdout discarded (the
    first five, warming the page cache, not counted)."""
    devnull = os.open(os.devnull, os.O_WRONLY)
    argv = [binary, *args]
    times = []
    for i in range(count + 5):
        start = time.perf_counter()
        pid = os.posix_spawn(binary, argv, os.environ, file_actions=[(os.POSIX_SPAWN_DUP2, devnull, 1)])
        _, status = os.waitpid(pid, 0)
        if os.waitstatus_to_exitcode(status) != 0:
            sys.exit(f"{' '.join(argv)}: exit status {os.waitstatus_to_exitcode(status)}")
        if i >= 5:
            times.append((time.perf_counter() - start) * 1e3)
    os.close(devnull)
    return statistics.median(times), min(times)


def verdict(ok):
    return "yes" if ok else "**no**"


def within(value, bound, digits=1):
    """`value ≤ bound` as printed (`digits` decimals): a row reads as met
    exactly when its printed number is within the target."""
    return round(value, digits) <= bound


def bold(text, ok):
    return text if ok else f"**{text}**"


def host():
    """One line naming the host: CPU model, CPUs, load."""
    model = platform.processor() or "?"
    try:
        with open("/proc/cpuinfo") as fh:
            model = next(line.split(":", 1)[1].strip() for line in fh if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    load = " / ".join(f"{x:.2f}" for x in os.getloadavg())
    return f"{model}, {os.cpu_count()} CPUs, load average {load} at the start"


def commit():
    """The commit measured; `-dirty` when the working tree has changes."""
    out = subprocess.run(["git", "describe", "--always", "--dirty"], cwd=ROOT, capture_output=True, text=True)
    return out.stdout.strip() or "?"


def measure(args):
    # The classes alone in their runs, with the command line sessions 35–48
    # timed them with (the static pair in runs of its own: with it in the
    # classes' runs, Example 5.1's float median read 22.3–22.4 µs in two
    # runs against 22.8–22.9 µs in three without it).
    runs = passes(args.speed, args.class_reps, classes(), args.class_passes, "classes")
    runs.update(passes(args.speed, args.class_reps, [STATIC], args.class_passes, "static pair"))
    stability_paths = sorted(glob.glob("tests/stability/*.toml", root_dir=ROOT))
    stability = passes(args.speed, args.stability_reps, stability_paths, args.stability_passes, "stability")
    line_paths = [p for p in select_scenes(ROOT) if p != EXAMPLE_5_1]
    lines = passes(args.speed, args.line_reps, line_paths, args.line_passes, "straight lines")
    log(f"the CLI's whole process: {args.spawns} spawns")
    cli = spawn_ms(args.bin, [EXAMPLE_5_1, "--json"], args.spawns)
    return runs, stability, lines, cli


def table(runs, stability, lines, cli):
    """The markdown rows: target, measured (a miss in bold), met. A row is
    judged on its printed numbers (`within`)."""
    med = lambda scene, key: statistics.median(runs[scene][key])
    us = lambda value, bound: bold(f"{value:.1f}", within(value, bound))
    rows = []

    def row(target, measured, ok, note=""):
        rows.append(f"| {target} | {measured} | {'stated' if ok is None else verdict(ok)}{note} |")

    rigid, aff2, aff4 = "rigid-deg2.toml", "affine-deg2.toml", "affine-rational-deg2.toml"
    for scene, name, bound in [(rigid, "degree-2 rigid", RIGID_TOTAL), (aff2, "degree-2 affine", AFFINE2_TOTAL)]:
        total = med(scene, "exact")
        row(f"{name}, exact total ≤ {bound:.0f} µs", f"{us(total, bound)} µs", within(total, bound))
    total, first = med(aff4, "exact"), med(aff4, "first")
    row(
        f"degree-4 affine, exact total / first contact ≤ {AFFINE4_TOTAL:.0f} / {AFFINE4_FIRST:.0f} µs",
        f"{us(total, AFFINE4_TOTAL)} / {us(first, AFFINE4_FIRST)} µs",
        within(total, AFFINE4_TOTAL) and within(first, AFFINE4_FIRST),
    )

    ratios = {scene: med(scene, "exact") / med(scene, "float") for scene in CLASS_NAMES}
    ok = {scene: within(r, RATIO, 2) for scene, r in ratios.items()}
    cells = ", ".join(
        bold(f"{name} {med(s, 'exact'):.1f} / {med(s, 'float'):.1f} = {ratios[s]:.2f}", ok[s])
        for s, name in CLASS_NAMES.items()
    )
    missed = [name for s, name in CLASS_NAMES.items() if not ok[s]]
    note = f" ({', '.join(missed)})" if missed else ""
    row(f"exact / own float ≤ {RATIO}× on every class", cells, not missed, note)

    stab = {name: min(cell["exact"]) for name, cell in stability.items()}
    median = statistics.median(stab.values())
    worst = max(stab, key=stab.get)
    spread = stab[worst] / median
    row(
        f"stability set ({len(stab)} scenes): median ≤ {STABILITY_MEDIAN:.0f} µs, "
        f"max ≤ {STABILITY_SPREAD:.0f}× median",
        f"median {us(median, STABILITY_MEDIAN)} µs; max `{worst.removesuffix('.toml')}` {stab[worst]:,.1f} µs = "
        + bold(f"{spread:.1f}×", within(spread, STABILITY_SPREAD)),
        within(median, STABILITY_MEDIAN) and within(spread, STABILITY_SPREAD),
    )

    line = {key: statistics.median(min(cell[key]) for cell in lines.values()) for key in COLUMNS}
    answered = sum(1 for cell in lines.values() if cell["path"] == "raycast")
    default_ok = within(line["exact"], LINES_TOTAL) and within(line["first"], LINES_FIRST)
    ray_ok = within(line["ray"], LINES_TOTAL) and within(line["ray_first"], LINES_FIRST)
    row(
        f"straight lines ({len(lines)} scenes, medians): total ≤ {LINES_TOTAL:.0f} µs, "
        f"first contact ≤ {LINES_FIRST:.0f} µs",
        bold(f"default {line['exact']:.1f} / {line['first']:.1f} µs", default_ok)
        + "; "
        + bold(f"`--raycast` {line['ray']:.1f} / {line['ray_first']:.1f} µs", ray_ok)
        + f" ({answered} answered by the ray cast, the rest by Algorithm 1)",
        default_ok,
        " (yes with `--raycast`)" if ray_ok and not default_ok else "",
    )

    static = med(os.path.basename(STATIC), "exact")
    row(f"a static pair's query ≤ {STATIC_TOTAL:.0f} µs (`static-apart`)", f"{us(static, STATIC_TOTAL)} µs",
        within(static, STATIC_TOTAL))
    row(
        "a query's library call vs the CLI's whole process (Example 5.1, `--json`)",
        f"{med(os.path.basename(EXAMPLE_5_1), 'exact'):.1f} µs against {cli[0]:.2f} ms (minimum {cli[1]:.2f} ms)",
        None,
    )
    return "\n".join(["| target | measured | met? |", "| --- | --- | --- |", *rows])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--speed", default="target/release/examples/speed", help="the `speed` example binary")
    parser.add_argument("--bin", default="target/release/ccd-exact", help="the CLI, for the whole-process row")
    parser.add_argument("--class-passes", type=int, default=60, help="passes over the classes (and the static pair)")
    parser.add_argument("--class-reps", type=int, default=101, help="repetitions per median")
    parser.add_argument("--stability-passes", type=int, default=10, help="passes over tests/stability")
    parser.add_argument("--stability-reps", type=int, default=21, help="repetitions per median")
    parser.add_argument("--line-passes", type=int, default=5, help="passes over the straight-line scenes")
    parser.add_argument("--line-reps", type=int, default=101, help="repetitions per median")
    parser.add_argument("--spawns", type=int, default=300, help="whole processes of the CLI timed")
    parser.add_argument("--cpu", default=None, help="the CPU to pin to (default: the last); `none`: no pinning")
    parser.add_argument("--quick", action="store_true", help="one pass, 3 repetitions, 20 spawns: the plumbing only")
    args = parser.parse_args()
    if args.quick:
        args.class_passes = args.stability_passes = args.line_passes = 1
        args.class_reps = args.stability_reps = args.line_reps = 3
        args.spawns = 20
    args.speed, args.bin = os.path.abspath(args.speed), os.path.abspath(args.bin)
    os.chdir(ROOT)  # the scene paths are the repository's
    pinned = "unpinned"
    if args.cpu != "none":
        cpu = max(os.sched_getaffinity(0)) if args.cpu is None else int(args.cpu)
        os.sched_setaffinity(0, {cpu})
        pinned = f"pinned to CPU {cpu}"
    started = time.time()
    n = lambda count: f"{count} pass{'' if count == 1 else 'es'}"
    header = (
        f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC, commit `{commit()}`, {host()}; {pinned}. "
        f"Classes and `static-apart`: {n(args.class_passes)} of `speed --reps {args.class_reps}`, medians of the "
        f"pass medians; stability: {n(args.stability_passes)} of `--reps {args.stability_reps}`, minima of the pass "
        f"medians; straight lines: {n(args.line_passes)} of `--reps {args.line_reps}`, minima; the CLI: "
        f"{args.spawns} spawns."
    )
    body = table(*measure(args))
    quick = "  QUICK RUN: not a measurement." if args.quick else ""
    print(header + f" ({time.time() - started:.0f} s in all)" + quick)
    print()
    print(body)


if __name__ == "__main__":
    main()
