"""Worlds of many bodies from Python: the CLI's --json, exact readings, a
world built in Python, errors naming the body, options, pickling."""

from __future__ import annotations

import json
import pickle
import subprocess
from decimal import Decimal
from fractions import Fraction

import pytest

import ccd_exact as ccd
from conftest import SCENES, WORLDS

CROSSING = WORLDS[0].parent / "world-crossing.toml"


def cli_json(cli, path, *args):
    done = subprocess.run([cli, str(path), "--json", *args], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return done.stdout


def crossing_in_python():
    """tests/scenes/world-crossing.toml, built from Ellipsoid objects (its
    numbers as Fractions, Decimals and strings: all exact)."""
    half = Fraction(1, 2)
    return {
        "left": ccd.Ellipsoid([2, 1, 1], ccd.Translation([[11, 0, 0], [-1, 0, 0]])),
        "right": ccd.Ellipsoid([2, 1, 1], ccd.Translation([[3, -2, -4], [3, 2, 0]])),
        "rod": ccd.Ellipsoid([3, half, "1/2"], ccd.Static([0, 30, 0])),
        "tumbler": ccd.Ellipsoid(
            [2, Decimal("1.5"), Fraction(1, 4)],
            ccd.Rigid([[1, 0, 0, 0], [1, 1, 0, 1]], [[-9, Fraction(312, 10), 0], [9, Decimal("30.9"), "0.1"]]),
        ),
        "coil": ccd.Ellipsoid(
            [1, 2, 1],
            ccd.Helical([1, 0, 0], -10, base=[0, -30, 0], cos=[1, 0, 0], sin=[0, 1, 0], velocity=[0, 0, 10], frequency=10),
        ),
        "post": ccd.Ellipsoid([1, 1, 3], ccd.Static([0, -30, 5])),
        "far": ccd.Ellipsoid([half] * 3, ccd.Translation([[40, 40, 40], [41, 40, 40], [41, 41, 40]], weights=[1, 2, 1])),
        "shadow": ccd.Ellipsoid([0.5, 0.5, 0.5], ccd.Static([Fraction(167, 4), Fraction(157, 4), 40])),
    }


@pytest.fixture(scope="module")
def crossing():
    return ccd.collide_world_toml(CROSSING.read_text())


@pytest.mark.parametrize("path", WORLDS, ids=[p.name for p in WORLDS])
def test_every_shipped_world_gives_the_clis_json(cli, path):
    w = ccd.collide_world_toml(path.read_text())
    want = cli_json(cli, path)
    assert w.to_json() + "\n" == want
    d = json.loads(want)
    assert w.bodies == d["bodies"]
    assert w.colliding == [tuple(p) for p in d["colliding"]]
    assert w.undecided == [tuple(p) for p in d["undecided"]]
    assert [(p.a, p.b) for p in w.pairs] == [(p["a"], p["b"]) for p in d["pairs"]]
    assert w.complete == d["complete"] and w.certified == d["certified"]
    # Each pair's result is the pair object of the world's JSON.
    for p, q in zip(w.pairs, d["pairs"]):
        assert p.error is None and "error" not in q
        assert json.loads(p.result.to_json()) == {k: v for k, v in q.items() if k not in ("a", "b")}


@pytest.mark.parametrize(
    "args, options",
    [
        (["--first-contact"], {"first_contact": True}),
        (["--digits", "30"], {"digits": 30}),
        (["--no-geometry"], {"geometry": False}),
        (["--threads", "1"], {"threads": 1}),
    ],
)
def test_options_are_the_clis(cli, args, options):
    w = ccd.collide_world_toml(CROSSING.read_text(), **options)
    assert w.to_json() + "\n" == cli_json(cli, CROSSING, *args)


def test_the_colliding_pairs_and_the_first_contact_read_exactly(crossing):
    w = crossing
    d = json.loads(w.to_json())
    assert w.bodies == ["left", "right", "rod", "tumbler", "coil", "post", "far", "shadow"]
    assert w.span == (Fraction(0), Fraction(1))
    assert set(w.colliding) == {("left", "right"), ("rod", "tumbler"), ("coil", "post")}
    assert w.undecided == [] and w.complete and w.certified
    # 28 pairs: 3 candidates, 25 proven separate by the broad phase.
    assert w.broad_phase == ccd.BroadPhase(candidates=3, pruned=25, box_overlaps=4, slices=32)
    assert w.broad_phase.candidates + w.broad_phase.pruned == 8 * 7 // 2
    fc = w.first_contact
    assert isinstance(fc, ccd.WorldContact) and isinstance(fc.lo, Fraction) and isinstance(fc.hi, Fraction)
    assert fc.pair == ("coil", "post") == tuple(d["first_contact"]["pair"])
    assert (fc.lo, fc.hi) == (Fraction(d["first_contact"]["lo"]), Fraction(d["first_contact"]["hi"]))
    assert fc.certified and fc.lo <= fc.hi and 0 < fc.width <= Fraction(1, 10**15)
    assert abs(fc.approx - 0.074983069235) < 1e-11
    # The world's first contact is the earliest of its pairs' first contacts.
    firsts = {p.names: p.result.first_contact for p in w.pairs if p.result.first_contact}
    assert min(firsts.items(), key=lambda kv: kv[1].lo)[0] == fc.pair
    assert (firsts[fc.pair].lo, firsts[fc.pair].hi) == (fc.lo, fc.hi)


def test_a_pair_of_the_world_is_its_pair_scene(crossing):
    # "left" and "right" are the paper's Example 5.1: the world's pair result
    # is the pair scene's, to the last character.
    p = crossing.pair("right", "left")
    assert p is not None and p.names == ("left", "right")
    pair = ccd.collide_toml((SCENES[0].parent / "paper-example-5-1.toml").read_text())
    assert p.result.to_json() == pair.to_json()
    assert p.result.contacts == pair.contacts
    assert [s.state for s in p.result.timeline] == ["separate", "touch", "overlap", "touch", "separate"]
    assert p.result.scene_toml() is None
    assert p.result.to_svg("5.1") == pair.to_svg("5.1")
    assert crossing.pair("left", "far") is None  # pruned: proven separate, never queried


def test_a_world_built_in_python_is_the_world_file(crossing):
    built = ccd.collide_world(crossing_in_python(), span=(0, 1))
    assert built.to_json() == crossing.to_json()
    # The same bodies as (name, Ellipsoid) pairs, and the World object.
    items = list(crossing_in_python().items())
    world = ccd.World(items)
    assert world == ccd.World(crossing_in_python(), span=(0, 1))
    assert ccd.collide_world_toml(world.to_toml()).to_json() == crossing.to_json()
    assert built.world_toml() == world.to_toml()


def test_the_written_world_file_is_the_clis(cli, tmp_path):
    path = tmp_path / "built.toml"
    path.write_text(ccd.World(crossing_in_python()).to_toml())
    assert ccd.collide_world(crossing_in_python()).to_json() + "\n" == cli_json(cli, path)


def test_a_world_in_first_contact_mode(crossing):
    w = ccd.collide_world_toml(CROSSING.read_text(), first_contact=True)
    assert not w.complete
    assert w.first_contact == crossing.first_contact
    assert {p.names for p in w.pairs} <= {p.names for p in crossing.pairs}


@pytest.mark.parametrize(
    "body, field",
    [
        ('motion = { kind = "translation", center = [[0, 0, 0], [1, 2]] }', 'body[1] "arm-2".motion.center[1]'),
        ('motion = { kind = "translation", center = [[0, 0, 0], [1, "x", 2]] }', 'body[1] "arm-2".motion.center[1][1]'),
        # Found exactly by the motion check (the quaternion curve passes through 0).
        ('motion = { kind = "rigid", orientation = [[1, 0, 0, 0], [-1, 0, 0, 0]], center = [[5, 0, 0]] }',
         'body[1] "arm-2".motion.orientation'),
    ],
)
def test_a_bad_body_names_the_body_and_the_field(body, field):
    text = f'[[body]]\nname = "ball"\nradii = [1, 1, 1]\n\n[[body]]\nname = "arm-2"\nradii = [1, 1, 1]\n{body}\n'
    with pytest.raises(ccd.SceneError) as e:
        ccd.collide_world_toml(text)
    assert e.value.field == field
    assert str(e.value).startswith(f"field `{field}`")


def test_a_bad_body_built_in_python_names_the_body():
    with pytest.raises(ccd.SceneError) as e:
        ccd.collide_world({"ball": ccd.Ellipsoid([1, 1, 1]), "arm-2": ccd.Ellipsoid([1, 0, 1])})
    assert e.value.field == 'body[1] "arm-2".radii[1]' and "must be > 0" in str(e.value)
    with pytest.raises(ccd.SceneError) as e:  # refused in Python, with the engine's path
        ccd.collide_world({"ball": ccd.Ellipsoid([1, 1, 1]), "arm-2": ccd.Ellipsoid([1, object(), 1])})
    assert e.value.field == 'body[1] "arm-2".radii[1]'
    with pytest.raises(ccd.SceneError) as e:
        ccd.collide_world([("ball", ccd.Ellipsoid([1, 1, 1])), ("ball", ccd.Ellipsoid([1, 1, 1]))])
    assert e.value.field == 'body[1] "ball".name' and "already" in str(e.value)
    with pytest.raises(ccd.SceneError) as e:
        ccd.collide_world({"ball": ccd.Ellipsoid([1, 1, 1]), "b": 5})
    assert e.value.field == 'body[1] "b"'


def test_pair_and_world_files_name_each_others_entry():
    with pytest.raises(ccd.SceneError, match="collide_world_toml") as e:
        ccd.collide_toml(CROSSING.read_text())
    assert e.value.field == "body"
    with pytest.raises(ccd.SceneError, match="pairs\\[1\\]: .*collide_world_toml"):
        ccd.collide_many([ccd.Scene.from_toml(SCENES[0].read_text()), ccd.Scene.from_toml(CROSSING.read_text())])
    with pytest.raises(ccd.SceneError, match="collide_toml") as e:
        ccd.collide_world_toml((SCENES[0].parent / "paper-example-5-1.toml").read_text())
    assert e.value.field == "body"


@pytest.mark.parametrize(
    "options, option",
    [({"threads": 0}, "threads"), ({"threads": True}, "threads"), ({"digits": -1}, "digits"),
     ({"arithmetic": "fast"}, "arithmetic"), ({"first_contact": 1}, "first_contact")],
)
def test_bad_options_name_the_option(options, option):
    with pytest.raises(ValueError, match=f"option `{option}`"):
        ccd.collide_world_toml(CROSSING.read_text(), **options)


def test_float_arithmetic_on_a_helical_world_is_refused():
    # The pair query's refusal is the caller's error, not one pair's.
    with pytest.raises(ValueError, match="float arithmetic needs rational motions"):
        ccd.collide_world_toml(CROSSING.read_text(), arithmetic="float")


def test_a_world_result_survives_pickling(crossing):
    back = pickle.loads(pickle.dumps(crossing))
    assert back.to_json() == crossing.to_json() and back.first_contact == crossing.first_contact
    p = pickle.loads(pickle.dumps(crossing.pairs[0].result))
    assert p.to_json() == crossing.pairs[0].result.to_json()
    assert p.to_svg() == crossing.pairs[0].result.to_svg()  # the world answered again, the same


def test_printing_a_world(crossing):
    text = str(crossing)
    assert "world of 8 bodies" in text and "25 proven separate" in text
    assert "colliding  left – right" in text and "first contact ≈ 0.07498306923" in text
    assert "coil, post" in repr(crossing)
