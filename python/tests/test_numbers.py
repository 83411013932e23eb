"""Exact numbers in (int, Fraction, Decimal, str, float taken exactly,
numpy) and out (Fraction)."""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction

import pytest

import ccd_exact as ccd

np = pytest.importorskip("numpy")


def spheres(x0, r=Fraction(1, 3), **options):
    """Spheres of radius r; B from (x0, 0, 0) to the origin: they touch when
    the centres are 2r apart, at t* = 1 − 2r/x0 exactly."""
    a = ccd.Ellipsoid([r, r, r])
    b = ccd.Ellipsoid([r, r, r], ccd.Translation([[x0, 0, 0], [0, 0, 0]]))
    return ccd.collide(a, b, **options)


def test_every_spelling_of_one_number_is_one_scene():
    spellings = [Fraction(11, 10), Decimal("1.1"), "1.1", "11/10", "110e-2", np.array([Fraction(11, 10)])[0]]
    texts = {ccd.Scene(ccd.Ellipsoid([1, 1, 1]), ccd.Ellipsoid([x, 1, 1])).to_toml() for x in spellings}
    assert len(texts) <= 4  # the texts differ ("11/10", "1.1", "110e-2") …
    answers = {
        spheres(x, digits=30).to_json() for x in spellings
    }
    assert len(answers) == 1  # … the value does not


def test_a_float_is_its_exact_binary_value():
    x = 1.1  # 2476979795053773/2**51, not 11/10
    r = spheres(x, digits=30)
    exact = 1 - Fraction(2, 3) / Fraction(x)
    decimal = 1 - Fraction(2, 3) / Fraction(11, 10)
    c = r.contacts[0]
    assert exact in c
    assert decimal not in c  # 5e-17 away: outside a 1e-30 enclosure
    assert "2476979795053773/2251799813685248" in ccd.Scene(ccd.Ellipsoid([x, 1, 1]), ccd.Ellipsoid([1, 1, 1])).to_toml()


def test_tiny_and_huge_numbers_stay_exact():
    r = spheres("1e-20", r="1e-21", digits=30)
    assert (1 - Fraction(2, 10)) in r.contacts[0]
    big = 10**30 + 7  # beyond i64: written as a string, read exactly
    r = spheres(big, r=Fraction(big, 4), digits=30)
    assert Fraction(1, 2) in r.contacts[0]


def test_numpy_arrays_and_scalars():
    center = np.array([[11, 0, 0], [-1, 0, 0]])
    a = ccd.Ellipsoid(np.array([2.0, 1.0, 1.0]), ccd.Translation(center))
    b = ccd.Ellipsoid([np.int64(2), np.float32(1.0), 1], ccd.Translation(np.array([[3, -2, -4], [3, 2, 0]], dtype=float)))
    plain = ccd.collide(
        ccd.Ellipsoid([2, 1, 1], ccd.Translation([[11, 0, 0], [-1, 0, 0]])),
        ccd.Ellipsoid([2, 1, 1], ccd.Translation([[3, -2, -4], [3, 2, 0]])),
    )
    assert ccd.collide(a, b).to_json() == plain.to_json()
    # A float32 is taken exactly too: 0.1f is not 0.1.
    text = ccd.Scene(ccd.Ellipsoid([np.float32(0.1), 1, 1]), ccd.Ellipsoid([1, 1, 1])).to_toml()
    assert f'"{Fraction(float(np.float32(0.1)))}"' in text


def test_times_come_out_as_fractions():
    r = spheres(Fraction(4, 3), digits=20)
    c = r.contacts[0]
    assert Fraction(1, 2) in c
    assert all(isinstance(x, Fraction) for x in (c.lo, c.hi, *r.span))
    assert isinstance(c.approx, float) and abs(c.approx - 0.5) < 1e-15
    for s in r.timeline:
        assert isinstance(s.start.lo, Fraction) and s.start.lo <= s.start.hi


def test_the_float_mode_is_marked_not_certified():
    r = spheres(Fraction(4, 3), arithmetic="float")
    assert not r.certified and not r.contacts[0].certified
