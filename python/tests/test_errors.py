"""Bad input raises SceneError (a ValueError) naming the field; bad options
raise ValueError naming the option; nothing panics."""

from __future__ import annotations

import pytest

import ccd_exact as ccd

OK = ccd.Ellipsoid([1, 1, 1], ccd.Static(center=[5, 0, 0]))


@pytest.mark.parametrize(
    "a, field, words",
    [
        (ccd.Ellipsoid([0, 1, 1]), "a.radii[0]", "must be > 0"),
        (ccd.Ellipsoid([1, 1]), "a.radii", "expected 3"),
        (ccd.Ellipsoid([1, 1, float("nan")]), "a.radii[2]", "not a finite number"),
        (ccd.Ellipsoid([1, 1, float("inf")]), "a.radii[2]", "not a finite number"),
        (ccd.Ellipsoid([1, 1, "1/0"]), "a.radii[2]", "denominator"),
        (ccd.Ellipsoid([1, 1, "one"]), "a.radii[2]", ""),
        (ccd.Ellipsoid([1, 1, object()]), "a.radii[2]", "expected a number"),
        (ccd.Ellipsoid([1, 1, True]), "a.radii[2]", "boolean"),
        (ccd.Ellipsoid([1, 1, 1], ccd.Translation([])), "a.motion.center", ""),
        (ccd.Ellipsoid([1, 1, 1], ccd.Translation([[0, 0, 0], [1, 1]])), "a.motion.center[1]", "expected 3"),
        (ccd.Ellipsoid([1, 1, 1], ccd.Translation([[0, 0, 0], [1, 1, 1]], weights=[1, -1])), "a.motion.weights[1]", "must be > 0"),
        (ccd.Ellipsoid([1, 1, 1], ccd.Static(orientation=[0, 0, 0, 0])), "a.motion.orientation", ""),
        (ccd.Ellipsoid([1, 1, 1], ccd.Helical(axis=[0, 0, 0], rate=1)), "a.motion.axis", ""),
        (ccd.Ellipsoid([1, 1, 1], ccd.Rigid([[1, 0, 0, 0], [-1, 0, 0, 0]], [[0, 0, 0]])), "a.motion.orientation", "vanishes"),
        (ccd.Ellipsoid([1, 1, 1], "static"), "a.motion", "expected a table"),
        (ccd.Ellipsoid([1, 1, 1], {"kind": "wobble"}), "a.motion.kind", "wobble"),
        (ccd.Ellipsoid([1, 1, 1], {"kind": "static", "spin": 1}), "a.motion.spin", "unknown field"),
        ("a sphere", "a", "expected an Ellipsoid"),
    ],
)
def test_bad_bodies_name_the_field(a, field, words):
    with pytest.raises(ccd.SceneError) as e:
        ccd.collide(a, OK)
    assert isinstance(e.value, ValueError)
    assert e.value.field == field, str(e.value)
    assert f"`{field}`" in str(e.value) and words in str(e.value)


def test_the_second_body_and_the_span_are_named():
    with pytest.raises(ccd.SceneError) as e:
        ccd.collide(OK, ccd.Ellipsoid([1, -1, 1]))
    assert e.value.field == "b.radii[1]"
    with pytest.raises(ccd.SceneError) as e:
        ccd.collide(OK, OK, span=(1, 0))
    assert e.value.field == "span"


def test_bad_text():
    with pytest.raises(ccd.SceneError, match="not TOML") as e:
        ccd.collide_toml("[a\nradii = [1, 1, 1]")
    assert e.value.field is None
    with pytest.raises(ccd.SceneError, match="not JSON"):
        ccd.collide_json('{"a": ')
    with pytest.raises(ccd.SceneError) as e:
        ccd.collide_json('{"a": {"radii": [1, 1, 1]}, "b": {"radii": [1, 1, 1]}, "spin": 2}')
    assert e.value.field == "spin"
    with pytest.raises(ccd.SceneError) as e:
        ccd.collide_json('{"a": {"radii": [1, 1, NaN]}, "b": {"radii": [1, 1, 1]}}')
    assert e.value.field == "a.radii[2]"
    with pytest.raises(ccd.SceneError) as e:
        ccd.collide_json('{"a": {"radii": [1, 1, 1]}}')
    assert e.value.field == "b"


@pytest.mark.parametrize(
    "options, option",
    [
        ({"digits": -1}, "digits"),
        ({"digits": 1001}, "digits"),
        ({"digits": 2.5}, "digits"),
        ({"digits": True}, "digits"),
        ({"arithmetic": "fast"}, "arithmetic"),
        ({"first_contact": "yes"}, "first_contact"),
    ],
)
def test_bad_options_name_the_option(options, option):
    with pytest.raises(ValueError, match=f"option `{option}`"):
        ccd.collide(OK, ccd.Ellipsoid([1, 1, 1]), **options)
    with pytest.raises(TypeError):
        ccd.collide_toml("[a]\nradii = [1, 1, 1]\n[b]\nradii = [1, 1, 1]", colour="red")


def test_float_arithmetic_refuses_helical_motions():
    helical = ccd.Ellipsoid([1, 1, 1], ccd.Helical(axis=[0, 0, 1], rate=1))
    with pytest.raises(ValueError, match="arithmetic"):
        ccd.collide(helical, OK, arithmetic="float")


def test_collide_many_names_the_pair():
    pairs = [(OK, ccd.Ellipsoid([1, 1, 1])), (OK, ccd.Ellipsoid([1, 1, 0]))]
    with pytest.raises(ccd.SceneError, match=r"pairs\[1\]: field `b.radii\[2\]`") as e:
        ccd.collide_many(pairs)
    assert e.value.field == "b.radii[2]"
    with pytest.raises(ccd.SceneError, match=r"pairs\[0\]"):
        ccd.collide_many([42])
    with pytest.raises(ValueError, match="option `threads`"):
        ccd.collide_many(pairs, threads=0)
