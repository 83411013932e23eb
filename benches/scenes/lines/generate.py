"""Writes the straight-line benchmark scenes (benches/scenes/lines/*.toml).

Two ellipsoids of random shape and orientation; A static or translating,
B on a straight line aimed at A's path with a random miss distance, so
that about two thirds collide. Short decimal numbers, as users write
them. Deterministic (seed 2026): `python3 generate.py` rewrites the files.
"""

import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))


def fmt(x):
    """A short decimal string, as a user writes it."""
    text = f"{x:.3f}".rstrip("0").rstrip(".")
    return '"' + (text if text not in ("", "-0") else "0") + '"'


def vec(v):
    return "[" + ", ".join(fmt(x) for x in v) + "]"


def main():
    rng = random.Random(2026)
    for i in range(16):
        radii = [[rng.uniform(0.3, 3.0) for _ in range(3)] for _ in range(2)]
        quats = [[rng.randint(-4, 4) for _ in range(4)] for _ in range(2)]
        for q in quats:
            if not any(q):
                q[0] = 1
        a0 = [rng.uniform(-2, 2) for _ in range(3)]
        a_moves = i % 3 == 0
        a1 = [x + rng.uniform(-2, 2) for x in a0] if a_moves else a0
        # B passes A's midpoint at a miss distance of 0 to 1.5 reach.
        mid = [(x + y) / 2 for x, y in zip(a0, a1)]
        reach = max(radii[0]) + max(radii[1])
        miss = [rng.uniform(-1, 1) * 1.5 * reach / 3**0.5 for _ in range(3)]
        d = [rng.uniform(-1, 1) for _ in range(3)]
        norm = sum(x * x for x in d) ** 0.5
        d = [x / norm * reach * rng.uniform(2.5, 4) for x in d]
        b0 = [m + o - x for m, o, x in zip(mid, miss, d)]
        b1 = [m + o + x for m, o, x in zip(mid, miss, d)]
        a_motion = (
            f'kind = "translation"\ncenter = [{vec(a0)}, {vec(a1)}]'
            if a_moves
            else f'kind = "static"\ncenter = {vec(a0)}'
        )
        text = f"""# Straight-line benchmark scene {i:02d} (benches/scenes/lines/generate.py, seed 2026)
format = 1
span = ["0", "1"]

[a]
radii = {vec(radii[0])}
[a.motion]
{a_motion}
orientation = {vec(quats[0])}

[b]
radii = {vec(radii[1])}
[b.motion]
kind = "translation"
center = [{vec(b0)}, {vec(b1)}]
orientation = {vec(quats[1])}
"""
        with open(os.path.join(HERE, f"line{i:02d}.toml"), "w") as out:
            out.write(text)


if __name__ == "__main__":
    main()
