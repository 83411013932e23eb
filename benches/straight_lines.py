"""The straight-line pair scenes of the repository, shared by the scripts
that time them: benches/compare/compare.py (ours against FLINT and FCL) and
benches/targets.py (issue 17's target rows).

A straight-line pair: both motions `static` or a degree-1 `translation`
(at most two control points, equal weights if any), at least one body
moving; from tests/scenes, tests/stability and benches/scenes, plus the
paper's Example 5.1 (docs/table4.md, "Against FLINT and FCL").
"""

import glob
import os
import tomllib
from fractions import Fraction

SCENE_DIRS = ("tests/scenes", "tests/stability", "benches/scenes")
EXAMPLE_5_1 = "tests/scenes/paper-example-5-1.toml"


def read_scene(path):
    """The TOML of a scene file, numbers as exact Fractions.

    Integers are left as int, TOML floats are read from their decimal text
    (as the engine reads them), and number strings ("1/3", "1e-20") are
    converted by `to_fraction` where used.
    """
    with open(path, "rb") as fh:
        return tomllib.load(fh, parse_float=Fraction)


def to_fraction(x):
    """A scene number (int, Fraction or number string) as a Fraction."""
    if isinstance(x, str):
        x = x.strip()
        if "/" in x:
            p, q = x.split("/")
            return Fraction(int(p), int(q))
        return Fraction(x)
    return Fraction(x)


def straight_line_motion(body):
    """(start, end, quaternion) of a body that moves on a straight line at
    constant speed (or stays put); None for any other motion.

    Accepted: `static` (or no motion), and `translation` whose centre curve
    has at most two control points and no weights (or equal weights), so
    that the centre is exactly linear in u = (t - t0)/(t1 - t0).
    """
    motion = body.get("motion", {"kind": "static"})
    kind = motion.get("kind")
    quat = motion.get("orientation", [1, 0, 0, 0])
    if kind == "static":
        centre = motion.get("center", [0, 0, 0])
        return centre, centre, quat
    if kind != "translation":
        return None
    points = motion["center"]
    weights = motion.get("weights")
    if len(points) > 2:
        return None
    if weights is not None and len({to_fraction(w) for w in weights}) > 1:
        return None
    return points[0], points[-1], quat


def is_moving(motion):
    """Whether a straight-line motion's start and end differ."""
    start, end, _ = motion
    return [to_fraction(x) for x in start] != [to_fraction(x) for x in end]


def select_scenes(root):
    """The straight-line pair scenes (sorted by path) and Example 5.1."""
    chosen = []
    for d in SCENE_DIRS:
        for path in sorted(glob.glob(os.path.join(root, d, "*.toml"))):
            scene = read_scene(path)
            if "a" not in scene or "b" not in scene:
                continue  # a world file
            ma, mb = straight_line_motion(scene["a"]), straight_line_motion(scene["b"])
            if ma is None or mb is None or not (is_moving(ma) or is_moving(mb)):
                continue
            chosen.append(os.path.relpath(path, root))
    if EXAMPLE_5_1 not in chosen:
        chosen.append(EXAMPLE_5_1)
    return chosen
