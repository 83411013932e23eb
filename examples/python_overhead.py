"""Python's per-query overhead against the Rust call, on one scene.

    python examples/python_overhead.py [SCENE.toml] [--reps N]

Prints the median time of: ``ccd_exact::run`` inside Rust (the scene parsed
once), the native call on the TOML text (parse + run, no Python objects),
``collide_toml`` (plus reading the JSON into Python objects) and
``collide`` from Python objects (plus writing the scene's exact text). A
result's JSON is written, and its fields read into Python objects (exact
``Fraction``s), only when first asked for; both rows are shown. The
objects are Example 5.1's, whatever the scene.
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

import ccd_exact as ccd
from ccd_exact import _native

ROOT = Path(__file__).resolve().parents[1]


def median_seconds(f, reps: int) -> float:
    times = []
    for _ in range(reps):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("scene", nargs="?", default=str(ROOT / "tests/scenes/paper-example-5-1.toml"))
    p.add_argument("--reps", type=int, default=2000)
    args = p.parse_args()
    text = Path(args.scene).read_text()
    scene = ccd.Scene.from_toml(text)
    a = ccd.Ellipsoid([2, 1, 1], ccd.Translation([[11, 0, 0], [-1, 0, 0]]))
    b = ccd.Ellipsoid([2, 1, 1], ccd.Translation([[3, -2, -4], [3, 2, 0]]))
    rows = [
        ("Rust: ccd_exact::run (parsed once)", lambda: None, _native.median_run_seconds(text, args.reps)),
        ("native run_toml (parse + run)", lambda: _native.run_toml(text), None),
        ("collide_toml (result object, lazy)", lambda: ccd.collide_toml(text), None),
        ("collide_toml + to_json()", lambda: ccd.collide_toml(text).to_json(), None),
        ("collide_toml + every field read", lambda: ccd.collide_toml(text).contacts, None),
        ("collide(a, b) from Python objects", lambda: ccd.collide(a, b), None),
    ]
    base = rows[0][2]
    print(f"{args.scene}: medians of {args.reps} queries")
    for name, f, measured in rows:
        m = measured if measured is not None else median_seconds(f, args.reps)
        print(f"  {name:<40} {m * 1e6:9.1f} µs   overhead {(m - base) * 1e6:8.1f} µs")
    del scene


if __name__ == "__main__":
    main()
