"""The paper's examples from Python objects, and every shipped scene giving
the CLI's own JSON."""

from __future__ import annotations

import json
import math
import subprocess
from fractions import Fraction

import pytest

import ccd_exact as ccd
from conftest import SCENES


def example_5_1():
    a = ccd.Ellipsoid([2, 1, 1], ccd.Translation([[11, 0, 0], [-1, 0, 0]]))
    b = ccd.Ellipsoid([2, 1, 1], ccd.Translation([[3, -2, -4], [3, 2, 0]]))
    return a, b


def example_5_2():
    a = ccd.Ellipsoid(
        [1, 2, 1],
        ccd.Helical(axis=[1, 0, 0], rate=-10, cos=[1, 0, 0], sin=[0, 1, 0], velocity=[0, 0, 10], frequency=10),
    )
    b = ccd.Ellipsoid([1, 1, 3], ccd.Static(center=[0, 0, 5]))
    return a, b


@pytest.mark.parametrize(
    "example, paper",
    [(example_5_1, (0.5395042868, 0.8722604191)), (example_5_2, (0.0749830692, 0.8913371204))],
)
def test_the_papers_examples(example, paper):
    r = ccd.collide(*example())
    assert [s.state for s in r.timeline] == ["separate", "touch", "overlap", "touch", "separate"]
    assert r.collision_free is False and r.certified and r.complete
    assert len(r.contacts) == 2
    for c, t in zip(r.contacts, paper):
        assert isinstance(c.lo, Fraction) and isinstance(c.hi, Fraction)
        assert c.lo <= c.hi and c.hi - c.lo <= Fraction(1, 10**15)
        # The paper prints 10 decimals.
        assert c.lo - Fraction(1, 10**10) <= Fraction(str(t)) <= c.hi + Fraction(1, 10**10)
        assert abs(c.approx - t) < 1e-10 and c.certified
        assert c.point is not None and c.normal is not None and c.point.certified
        assert max(abs(x) for x in c.normal.approx) == 1.0
    assert r.first_contact == r.contacts[0]


def test_example_5_1_built_in_python_is_the_scene_file():
    text = (SCENES[0].parent / "paper-example-5-1.toml").read_text()
    assert ccd.collide(*example_5_1()).to_json() == ccd.collide_toml(text).to_json()


def test_print_shows_the_contacts():
    out = str(ccd.collide(*example_5_1()))
    assert "contact 1 ≈ 0.539504286" in out and "contact 2 ≈ 0.872260419" in out
    assert "lo = " in out and "hi = " in out


def cli_json(cli, path, *args):
    done = subprocess.run([cli, str(path), "--json", *args], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return done.stdout


@pytest.mark.parametrize("path", SCENES, ids=[p.name for p in SCENES])
def test_every_shipped_scene_gives_the_clis_json(cli, path):
    text = path.read_text()
    r = ccd.collide_toml(text)
    want = cli_json(cli, path)
    assert r.to_json() + "\n" == want
    # And every field of the Python result is the JSON's.
    d = json.loads(want)
    assert r.collision_free == d["collision_free"]
    assert [s.state for s in r.timeline] == [s["state"] for s in d["timeline"]]
    assert [(str(c.lo), str(c.hi)) for c in r.contacts] == [(c["lo"], c["hi"]) for c in d["contacts"]]
    assert r.complete == d["complete"] and r.certified == d["certified"]
    assert len(r.gaps) == len(d["gaps"])


@pytest.mark.parametrize(
    "args, options",
    [
        (["--digits", "30"], {"digits": 30}),
        (["--first-contact"], {"first_contact": True}),
        (["--no-geometry"], {"geometry": False}),
        (["--arithmetic", "float"], {"arithmetic": "float"}),
        (["--raycast"], {"raycast": True}),
    ],
)
def test_options_are_the_clis(cli, args, options):
    path = SCENES[0].parent / "rigid-tumbling.toml"
    r = ccd.collide_toml(path.read_text(), **options)
    assert r.to_json() + "\n" == cli_json(cli, path, *args)


def test_digits_narrow_the_enclosure():
    r = ccd.collide(*example_5_1(), digits=40)
    assert all(c.width <= Fraction(1, 10**40) for c in r.contacts)
    coarse = ccd.collide(*example_5_1(), digits=3)
    for fine, c in zip(r.contacts, coarse.contacts):
        assert c.lo <= fine.lo and fine.hi <= c.hi


def test_an_independent_closed_form():
    # Unit spheres, B from (4, 0, 0) to the origin along a straight line,
    # over the span [2, 6]: they touch when the centres are 2 apart, at
    # u = 1/2, i.e. t = 4, and overlap after.
    a = ccd.Ellipsoid([1, 1, 1])
    b = ccd.Ellipsoid([1, 1, 1], ccd.Translation([[4, 0, 0], [0, 0, 0]]))
    r = ccd.collide(a, b, span=(2, 6))
    assert r.span == (2, 6)
    assert [s.state for s in r.timeline] == ["separate", "touch", "overlap"]
    assert Fraction(4) in r.contacts[0]
    p = r.contacts[0].point  # the spheres touch at (1, 0, 0)
    assert all(p.lo[i] <= x <= p.hi[i] for i, x in enumerate((1, 0, 0)))
    assert math.isclose(r.contacts[0].approx, 4.0)


def test_raycast_answers_a_straight_line_pass():
    # Unit spheres, B from (-4, 1/2, 0) to (4, 1/2, 0): the ray cast answers
    # (stats branch "raycast"), the same states and contacts as the exact
    # path, each contact's enclosure meeting the exact one; the CLI's bytes.
    a = ccd.Ellipsoid([1, 1, 1])
    b = ccd.Ellipsoid([1, 1, 1], ccd.Translation([[-4, "1/2", 0], [4, "1/2", 0]]))
    ray = ccd.collide(a, b, raycast=True)
    exact = ccd.collide(a, b)
    assert json.loads(ray.to_json())["stats"]["branch"] == "raycast"
    assert json.loads(exact.to_json())["stats"]["branch"] != "raycast"
    assert [s.state for s in ray.timeline] == [s.state for s in exact.timeline]
    assert len(ray.contacts) == len(exact.contacts) == 2
    for r, e in zip(ray.contacts, exact.contacts):
        assert r.lo <= e.hi and e.lo <= r.hi
    with pytest.raises(ValueError, match="option `raycast`"):
        ccd.collide(a, b, raycast="yes")
