"""Writes pairs.jsonl: pair scenes for the Dask example and its test.

One JSON object per line with the structure of a scene file (numbers as
JSON integers, decimals read exactly, or "p/q" strings). Seeded, so the
file is reproducible: python make_pairs.py > pairs.jsonl
"""

import json
import random
from fractions import Fraction

rng = random.Random(16)


def q(lo, hi, den=8):
    """A random rational in [lo, hi] with denominator den, as JSON."""
    f = Fraction(rng.randint(lo * den, hi * den), den)
    return f.numerator if f.denominator == 1 else f"{f.numerator}/{f.denominator}"


def vec(lo=-6, hi=6):
    return [q(lo, hi) for _ in range(3)]


def radii():
    # JSON decimals (read exactly: 1.25 is 5/4) and fractions.
    return [rng.choice([1.25, 1.5, 2.75, 0.5]), q(1, 3, 4), q(1, 3, 4)]


def body(kind):
    if kind == "static":
        return {"radii": radii(), "motion": {"kind": "static", "center": vec(-2, 2)}}
    if kind == "translation":
        return {"radii": radii(), "motion": {"kind": "translation", "center": [vec(), vec()]}}
    if kind == "rigid":
        return {"radii": radii(), "motion": {
            "kind": "rigid", "orientation": [[1, 0, 0, 0], [1, q(-1, 1, 2), q(-1, 1, 2), q(-1, 1, 2)]],
            "center": [vec(), vec()]}}
    raise ValueError(kind)


kinds = [("translation", "translation"), ("translation", "static"), ("rigid", "static"), ("rigid", "translation")]
for i in range(1000):
    a, b = kinds[i % len(kinds)]
    print(json.dumps({"span": [0, 1], "a": body(a), "b": body(b)}))
