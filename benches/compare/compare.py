#!/usr/bin/env python3
"""Our exact query against FLINT and FCL, side by side in one run.

For every shipped straight-line pair scene (both motions `static` or a
degree-1 `translation`, at least one moving; in tests/scenes,
tests/stability and benches/scenes) plus the paper's Example 5.1, this
measures in one process:

* ours: the median wall-clock time of the library call `ccd_exact::run`,
  exact total (the whole certified timeline) and exact first contact, as
  printed by `examples/speed.rs` (Rust, no process start-up);
* FLINT: the median time of `fmpz_poly(sr0).complex_roots()` (python-flint)
  on the scene's λ-discriminant `sr0(u)` as printed by `examples/sr0.rs`
  (`sr11` when `sr0 ≡ 0`). That is certified isolation of every complex
  root of one polynomial (squarefree factorisation, then every root of
  each factor to 53 bits, python-flint's default precision): only a part
  of our query (no states, no timeline, no contact geometry), and a
  different part (every complex root, not only the real ones in the span).
  Also on every other rational pair scene, FLINT and ours only;
* FCL: the median time of `fcl.continuousCollide` (python-fcl) with the
  naive solver at 100 samples (`CCDC_NAIVE`, `num_max_iterations=100`,
  translation motion): a discrete ellipsoid-ellipsoid test (libccd GJK) at
  u = i/99, i = 0..99, stopping at the first colliding sample. Not
  certified. Also FCL at its default request on Example 5.1.

Ground truth for FCL's answers is our certified answer (`ccd-exact --json`:
`collision_free`, `first_contact`, `timeline`). Prints markdown tables on
stdout (ready for docs/table4.md); progress goes to stderr.

Usage (benches/compare/run.sh sets this up):

    compare.py --bin target/release/ccd-exact \
        --speed target/release/examples/speed \
        --sr0 target/release/examples/sr0 [--reps 31] [--passes 1]
"""

import argparse
import glob
import json
import os
import statistics
import subprocess
import sys
import time

import fcl
import flint
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from speed_runs import speed  # noqa: E402  (benches/speed_runs.py)
from straight_lines import (  # noqa: E402  (benches/straight_lines.py)
    EXAMPLE_5_1,
    SCENE_DIRS,
    read_scene,
    select_scenes,
    straight_line_motion,
    to_fraction,
)

sys.set_int_max_str_digits(0)  # sr0's coefficients reach 12,000 digits

FCL_SAMPLES = 100
# Our times are enclosures at most 1e-15 of the span wide (the CLI's
# default), so a length of the timeline below this is not resolved.
RESOLUTION = 1e-14


def log(msg):
    """Progress to stderr (stdout carries only the tables)."""
    print(msg, file=sys.stderr, flush=True)


def ground_truth(binary, root, path):
    """Our certified answer for one scene, from `ccd-exact --json`.

    Times are the exact midpoints of the certified enclosures `[lo, hi]`,
    mapped to u = (t - t0)/(t1 - t0). Returns a dict: `collides` (True,
    False, or None when undecided), `first` (the first contact in u, or
    None), `overlap` (the `overlap` segments as (start, end) pairs in u),
    `hit` (the measure in u of the non-separate part of the span).
    """
    out = subprocess.run([binary, "--json", path], cwd=root, capture_output=True, text=True)
    doc = json.loads(out.stdout)
    t0, t1 = (to_fraction(x) for x in doc["span"])

    def to_u(instant):
        mid = (to_fraction(instant["lo"]) + to_fraction(instant["hi"])) / 2
        return (mid - t0) / (t1 - t0)

    cf = doc["collision_free"]
    fc = doc.get("first_contact")
    segments = [(seg["state"], to_u(seg["start"]), to_u(seg["end"])) for seg in doc.get("timeline", [])]
    return {
        "collides": None if cf is None else not cf,
        "first": None if fc is None else float(to_u(fc)),
        "overlap": [(float(a), float(b)) for state, a, b in segments if state == "overlap"],
        "hit": float(sum(b - a for state, a, b in segments if state != "separate")),
    }


def samples_inside(intervals, n=FCL_SAMPLES):
    """How many of FCL's sample instants u = i/(n-1) lie strictly inside one
    of `intervals` (where the bodies' interiors overlap)."""
    return sum(1 for i in range(n) if any(a < i / (n - 1) < b for a, b in intervals))


def discriminants(binary, root, paths):
    """{scene file name: (quantity, [int coefficients])} from `examples/sr0.rs`,
    for the scenes whose polynomial (sr0, or sr11 when sr0 ≡ 0) has degree
    at least 1: not helical scenes (no sr0), nor constant or zero ones
    (nothing to isolate)."""
    out = subprocess.run([binary, *paths], cwd=root, capture_output=True, text=True, check=True)
    polys = {}
    for line in out.stdout.splitlines():
        doc = json.loads(line)
        if "error" not in doc and len(doc["coeffs"]) > 1:  # not helical; a root to find
            polys[doc["scene"]] = (doc["quantity"], [int(c) for c in doc["coeffs"]])
    return polys


def median_us(reps, setup, call, budget_s=2.0):
    """Median over `reps` repetitions of the wall-clock time (µs) of
    `call(setup())`, the set-up outside the timed region. A call slower
    than `budget_s / reps` gets fewer repetitions (at least 3), so that one
    median takes about `budget_s` at most."""
    times = []
    while len(times) < reps:
        arg = setup()
        start = time.perf_counter_ns()
        call(arg)
        times.append((time.perf_counter_ns() - start) / 1e3)
        if len(times) == 1:
            reps = max(3, min(reps, int(budget_s * 1e6 / max(times[0], 1.0))))
    return statistics.median(times)


def flint_roots(coeffs, reps):
    """(median µs, number of distinct complex roots) of FLINT's certified
    complex root isolation of the integer polynomial `coeffs` (constant
    first). A fresh fmpz_poly per repetition, so nothing is cached."""
    roots = flint.fmpz_poly(coeffs).complex_roots()
    t = median_us(reps, lambda: flint.fmpz_poly(coeffs), lambda p: p.complex_roots())
    return t, len(roots)


def unit_quaternion(q):
    """A scene quaternion [w, x, y, z] (not necessarily unit) as a unit
    numpy array in the same order, as FCL's Transform expects it."""
    v = np.array([float(to_fraction(x)) for x in q])
    return v / np.linalg.norm(v)


def fcl_setup(scene):
    """The two FCL collision objects at u = 0 and their transforms at u = 1."""
    objects, ends = [], []
    for key in ("a", "b"):
        body = scene[key]
        start, end, quat = straight_line_motion(body)
        radii = [float(to_fraction(r)) for r in body["radii"]]
        q = unit_quaternion(quat)
        vec = lambda p: np.array([float(to_fraction(x)) for x in p])
        objects.append(fcl.CollisionObject(fcl.Ellipsoid(*radii), fcl.Transform(q, vec(start))))
        ends.append(fcl.Transform(q, vec(end)))
    return objects, ends


def fcl_request(samples=None):
    """FCL's request: the naive (sampling) solver at `samples` samples under
    translation motion, or FCL's defaults when `samples` is None."""
    if samples is None:
        return fcl.ContinuousCollisionRequest()
    return fcl.ContinuousCollisionRequest(
        num_max_iterations=samples,
        ccd_motion_type=fcl.CCDMotionType.CCDM_TRANS,
        ccd_solver_type=fcl.CCDSolverType.CCDC_NAIVE,
    )


def fcl_query(scene, request):
    """One FCL continuous query: (return value, is_collide, time_of_contact)."""
    (o1, o2), (e1, e2) = fcl_setup(scene)
    result = fcl.ContinuousCollisionResult()
    ret = fcl.continuousCollide(o1, e1, o2, e2, request, result)
    return ret, result.is_collide, result.time_of_contact


def fcl_time(scene, request, reps):
    """Median µs of `fcl.continuousCollide` alone (objects and a fresh
    result built outside the timed region)."""
    (o1, o2), (e1, e2) = fcl_setup(scene)
    return median_us(
        reps,
        fcl.ContinuousCollisionResult,
        lambda res: fcl.continuousCollide(o1, e1, o2, e2, request, res),
    )


def verdict(truth, fcl_collides):
    """'ok', 'missed' (we prove a collision, FCL says none), 'false hit'
    (we prove separation, FCL says collision) or 'undecided' (we do not)."""
    if truth["collides"] is None:
        return "undecided"
    if truth["collides"] == fcl_collides:
        return "ok"
    return "missed" if truth["collides"] else "false hit"


def fmt_us(x):
    """A time in µs for the tables."""
    return f"{x:.0f}" if x >= 100 else f"{x:.1f}"


def ours_and_flint(args, path, coeffs):
    """One pass over a scene for `fastest`: our medians (`speed`: exact
    total and first contact, `--raycast` total and first contact, and the
    path that answered `--raycast`) and FLINT's on `coeffs`, with its
    number of distinct roots."""
    ours = speed(args.speed, args.reps, [path], args.root)[os.path.basename(path)]
    flint_us, n_roots = flint_roots(coeffs, args.reps)
    return {
        "exact_us": ours["exact"],
        "first_us": ours["first"],
        "ray_us": ours["ray"],
        "ray_first_us": ours["ray_first"],
        "ray_path": ours["path"],
        "n_roots": n_roots,
        "flint_us": flint_us,
    }


def fastest(passes, paths, once):
    """`once(path)` (a dict of times and facts) for every path, `passes`
    times over the whole list (so that a slow spell of the machine falls on
    one pass, not on every pass of a few scenes), and per path the first
    pass's dict with each time key (`*_us`) the minimum over the passes."""
    runs = {path: [] for path in paths}
    for k in range(passes):
        if passes > 1:
            log(f"pass {k + 1} of {passes}")
        for path in paths:
            runs[path].append(once(path))
    best = {}
    for path, dicts in runs.items():
        row = dict(dicts[0])
        for key in row:
            if key.endswith("_us"):
                row[key] = min(d[key] for d in dicts)
        best[path] = row
    return best


def measure(args):
    """Run every measurement; one dict per scene. Each scene's three sides
    are measured one after the other (ours, FLINT, FCL), so that a change
    in the machine's load falls on all three alike; with `--passes`, each
    time is the minimum over the passes (`fastest`)."""
    root = args.root
    paths = select_scenes(root)
    log(f"{len(paths)} scenes")
    polys = discriminants(args.sr0, root, paths)
    request = fcl_request(FCL_SAMPLES)

    def once(path):
        name = os.path.basename(path)
        scene = read_scene(os.path.join(root, path))
        times = ours_and_flint(args, path, polys[name][1])
        times["fcl_us"] = fcl_time(scene, request, args.reps)
        log(
            f"  {name}: ours {times['exact_us']:.0f} µs, FLINT {times['flint_us']:.0f} µs, "
            f"FCL {times['fcl_us']:.0f} µs"
        )
        return times

    times = fastest(args.passes, paths, once)
    rows = []
    for path in paths:
        name = os.path.basename(path)
        scene = read_scene(os.path.join(root, path))
        truth = ground_truth(args.bin, root, path)
        quantity, coeffs = polys[name]
        _, hit, toc = fcl_query(scene, request)
        rows.append(
            {
                "scene": name,
                "example_5_1": path == EXAMPLE_5_1,
                "truth": truth,
                **times[path],
                "quantity": quantity,
                "degree": len(coeffs) - 1,
                "fcl_hit": hit,
                "fcl_toc": toc if hit else None,
                "verdict": verdict(truth, hit),
                "inside": samples_inside(truth["overlap"]),
            }
        )
        log(f"  {name}: {rows[-1]['verdict']}")
    scene51 = read_scene(os.path.join(root, EXAMPLE_5_1))
    default = fcl_query(scene51, fcl_request(None))
    return rows, default, flint_only(args, set(paths))


def other_rational_scenes(root, exclude):
    """Every shipped pair scene in SCENE_DIRS that is not in `exclude` (the
    straight-line set): rigid, affine, higher-degree translation, static."""
    paths = []
    for d in SCENE_DIRS:
        for path in sorted(glob.glob(os.path.join(root, d, "*.toml"))):
            rel = os.path.relpath(path, root)
            scene = read_scene(path)
            if "a" in scene and "b" in scene and rel not in exclude:
                paths.append(rel)
    return paths


def flint_only(args, exclude):
    """Ours against FLINT on every other rational pair scene (FCL's
    translation CCD does not apply to them; helical scenes, which have no
    sr0, and scenes whose sr0 or sr11 is constant are left out): one dict
    per scene with our two medians and FLINT's."""
    candidates = other_rational_scenes(args.root, exclude)
    polys = discriminants(args.sr0, args.root, candidates)
    paths = [p for p in candidates if os.path.basename(p) in polys]
    log(f"{len(paths)} other rational scenes (of {len(candidates)} other pair scenes), ours and FLINT ...")

    def once(path):
        name = os.path.basename(path)
        times = ours_and_flint(args, path, polys[name][1])
        log(f"  {name}: ours {times['exact_us']:.0f} µs, FLINT {times['flint_us']:.0f} µs")
        return times

    times = fastest(args.passes, paths, once)
    rows = []
    for path in paths:
        name = os.path.basename(path)
        quantity, coeffs = polys[name]
        rows.append(
            {
                "scene": name,
                **times[path],
                "quantity": quantity,
                "degree": len(coeffs) - 1,
                "bits": max(abs(c).bit_length() for c in coeffs),
            }
        )
    return rows


def flint_table(rows, line_rows):
    """Ours against FLINT on the other rational scenes, and the medians of
    FLINT / ours over them, over the straight-line scenes and over all."""
    ratio = lambda rs: statistics.median(r["flint_us"] / r["exact_us"] for r in rs)
    both = rows + line_rows
    out = [
        f"FLINT / ours exact total, median of per-scene ratios: {ratio(rows):.1f}× on these "
        f"{len(rows)} scenes, {ratio(line_rows):.1f}× on the {len(line_rows)} straight-line scenes "
        f"(Example 5.1 among them), {ratio(both):.1f}× on all {len(both)} (every shipped rational "
        f"pair scene with a non-constant sr0 or sr11).",
        "",
        "| scene | poly | degree | largest coefficient (bits) | distinct complex roots | ours exact µs "
        "| ours first µs | FLINT µs | FLINT / exact |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for r in rows:
        out.append(
            f"| {r['scene']} | {r['quantity']} | {r['degree']} | {r['bits']} | {r['n_roots']} "
            f"| {fmt_us(r['exact_us'])} | {fmt_us(r['first_us'])} | {fmt_us(r['flint_us'])} "
            f"| {r['flint_us'] / r['exact_us']:.1f}× |"
        )
    return "\n".join(out)


def truth_word(truth):
    """Our answer in a word: overlap, touch (only), separate, undecided."""
    if truth["collides"] is None:
        return "undecided"
    if not truth["collides"]:
        return "separate"
    return "overlap" if truth["overlap"] else "touch only"


def summary_table(rows):
    """The summary: medians over the straight-line scenes and ratios."""
    line = [r for r in rows if not r["example_5_1"]]
    med = lambda key: statistics.median(r[key] for r in line)
    ratio = lambda num, den: statistics.median(r[num] / r[den] for r in line)
    wrong = [r for r in line if r["verdict"] in ("missed", "false hit")]
    rays = [r for r in line if r["ray_path"] == "raycast"] or line
    missed = [r for r in wrong if r["verdict"] == "missed"]
    out = [
        f"Straight-line scenes: {len(line)} (medians over the scenes of per-scene medians, "
        "or with several passes of their minima).",
        "",
        "| quantity | value |",
        "| --- | --- |",
        f"| ours, exact total (whole certified timeline) | {fmt_us(med('exact_us'))} µs |",
        f"| ours, exact first contact | {fmt_us(med('first_us'))} µs |",
        f"| FLINT `complex_roots` of sr0 alone (of sr11 on the "
        f"{sum(1 for r in line if r['quantity'] == 'sr11')} scenes where sr0 ≡ 0) | {fmt_us(med('flint_us'))} µs |",
        f"| ours, `--raycast` total (answered by the ray cast: "
        f"{sum(1 for r in line if r['ray_path'] == 'raycast')} of {len(line)}; the rest by the exact path) "
        f"| {fmt_us(med('ray_us'))} µs |",
        f"| ours, `--raycast` first contact | {fmt_us(med('ray_first_us'))} µs |",
        f"| FCL naive CCD, 100 samples | {fmt_us(med('fcl_us'))} µs |",
        f"| ours `--raycast` total / FCL | {ratio('ray_us', 'fcl_us'):.2f}× |",
        f"| ours `--raycast` first contact / FCL | {ratio('ray_first_us', 'fcl_us'):.2f}× |",
        f"| on the {len(rays)} scenes the ray cast answers: ours `--raycast` total / first contact / FCL "
        f"(medians of the times) | {fmt_us(statistics.median(r['ray_us'] for r in rays))} / "
        f"{fmt_us(statistics.median(r['ray_first_us'] for r in rays))} / "
        f"{fmt_us(statistics.median(r['fcl_us'] for r in rays))} µs |",
        f"| on those scenes: ours `--raycast` total / FCL, first contact / FCL (medians of per-scene ratios) "
        f"| {statistics.median(r['ray_us'] / r['fcl_us'] for r in rays):.2f}×, "
        f"{statistics.median(r['ray_first_us'] / r['fcl_us'] for r in rays):.2f}× |",
        f"| FLINT / ours exact total (median of per-scene ratios) | {ratio('flint_us', 'exact_us'):.1f}× |",
        f"| FLINT / ours exact first contact | {ratio('flint_us', 'first_us'):.1f}× |",
        f"| ours exact total / FCL | {ratio('exact_us', 'fcl_us'):.1f}× |",
        f"| ours exact first contact / FCL | {ratio('first_us', 'fcl_us'):.1f}× |",
        f"| FCL wrong (collision yes/no) | {len(wrong)} of {len(line)}: "
        f"{len(missed)} missed ({sum(1 for r in missed if not r['truth']['overlap'])} touch only, "
        f"{sum(1 for r in missed if r['truth']['overlap'])} with an overlap), "
        f"{len(wrong) - len(missed)} false hits |",
        f"| missed overlaps with a sample inside the overlap (GJK said no at an overlapping sample) "
        f"| {sum(1 for r in missed if r['inside'] > 0)} |",
        f"| missed overlaps shorter than FCL's sample spacing 1/{FCL_SAMPLES - 1} "
        f"| {sum(1 for r in missed if r['truth']['overlap'] and r['truth']['hit'] < 1 / (FCL_SAMPLES - 1))} |",
    ]
    both = [r for r in line if r["fcl_toc"] is not None and r["truth"]["first"] is not None]
    if both:
        errs = [r["fcl_toc"] - r["truth"]["first"] for r in both]
        out.append(
            f"| FCL time of contact − our first contact, where both see a collision ({len(both)} scenes) "
            f"| median {statistics.median(errs):.2e}, min {min(errs):.2e}, max {max(errs):.2e} (fractions of the span) |"
        )
    return "\n".join(out)


def scene_table(rows):
    """One row per scene."""
    out = [
        "| scene | ours | first contact (u) | non-separate length (u) | ours exact µs | ours first µs "
        "| `--raycast` µs (total / first) | FLINT µs (poly, deg, roots) | FLINT / exact | FCL µs | FCL says "
        "| FCL toc − first | samples in overlap |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for r in rows:
        t = r["truth"]
        first = "—" if t["first"] is None else f"{t['first']:.6f}"
        fcl_says = "collision" if r["fcl_hit"] else "none"
        if r["verdict"] != "ok":
            fcl_says = f"**{fcl_says} ({r['verdict']})**"
        hit = f"{t['hit']:.3g}"
        if t["overlap"] and t["hit"] < RESOLUTION:
            hit = f"< {RESOLUTION:.0e}"
        dt = "—"
        if r["fcl_toc"] is not None and t["first"] is not None:
            dt = f"{r['fcl_toc'] - t['first']:+.2e}"
        out.append(
            f"| {r['scene']} | {truth_word(t)} | {first} | {hit} | {fmt_us(r['exact_us'])} "
            f"| {fmt_us(r['first_us'])} "
            f"| {fmt_us(r['ray_us'])} / {fmt_us(r['ray_first_us'])}{'' if r['ray_path'] == 'raycast' else ' (exact)'} "
            f"| {fmt_us(r['flint_us'])} ({r['quantity']}, {r['degree']}, {r['n_roots']}) "
            f"| {r['flint_us'] / r['exact_us']:.1f}× | {fmt_us(r['fcl_us'])} | {fcl_says} | {dt} "
            f"| {r['inside']} |"
        )
    return "\n".join(out)


def uptime():
    """The output of `uptime` (the machine's load), stripped."""
    return subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", default=os.path.join(os.path.dirname(__file__), "..", ".."))
    parser.add_argument("--bin", required=True, help="the release ccd-exact binary")
    parser.add_argument("--speed", required=True, help="the release examples/speed binary")
    parser.add_argument("--sr0", required=True, help="the release examples/sr0 binary")
    parser.add_argument("--reps", type=int, default=31, help="repetitions per median")
    parser.add_argument(
        "--passes",
        type=int,
        default=1,
        help="passes over all scenes; each time is the minimum of its pass medians",
    )
    args = parser.parse_args()
    args.root = os.path.abspath(args.root)
    args.bin, args.speed, args.sr0 = (os.path.abspath(p) for p in (args.bin, args.speed, args.sr0))

    before = uptime()
    rows, default, other_rows = measure(args)
    print(
        f"Measured {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; python-flint "
        f"{flint.__version__}, python-fcl {fcl.__version__}; reps {args.reps}, "
        f"passes {args.passes} (each time the minimum of its pass medians). "
        f"Load before: {before}; after: {uptime()}."
    )
    print()
    print(summary_table(rows))
    print()
    ret, hit, toc = default
    r51 = next(r for r in rows if r["example_5_1"])
    print(
        f"Example 5.1 (first contact u = {r51['truth']['first']:.10f}): ours exact total "
        f"{fmt_us(r51['exact_us'])} µs, first contact {fmt_us(r51['first_us'])} µs; FLINT on "
        f"{r51['quantity']}{' (sr0 ≡ 0)' if r51['quantity'] == 'sr11' else ''} "
        f"{fmt_us(r51['flint_us'])} µs; FCL 100 samples "
        f"{'collision at u = %.6f' % r51['fcl_toc'] if r51['fcl_hit'] else 'no collision'} "
        f"({fmt_us(r51['fcl_us'])} µs); FCL default request (conservative advancement, "
        f"10 iterations): returned {ret}, is_collide = {hit}, time_of_contact = {toc}."
    )
    print()
    print(flint_table(other_rows, rows))
    print()
    print(scene_table(rows))


if __name__ == "__main__":
    main()
