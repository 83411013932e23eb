"""The python-fcl-shaped entry: same calls as python-fcl, exact answers."""

from __future__ import annotations

import math
from fractions import Fraction

import pytest

import ccd_exact as ccd
from ccd_exact import fcl


def example_5_1(request=None):
    o1 = fcl.CollisionObject(fcl.Ellipsoid(2, 1, 1), fcl.Transform([11, 0, 0]))
    o2 = fcl.CollisionObject(fcl.Ellipsoid(2, 1, 1), fcl.Transform([3, -2, -4]))
    result = fcl.ContinuousCollisionResult()
    toc = fcl.continuousCollide(o1, fcl.Transform([-1, 0, 0]), o2, fcl.Transform([3, 2, 0]),
                                request or fcl.ContinuousCollisionRequest(), result)
    return toc, result


def test_example_5_1_with_python_fcls_defaults():
    toc, result = example_5_1()
    assert result.is_collide is True and toc == result.time_of_contact
    first = result.details.first_contact
    # Never late: the largest float not above the certified lower end.
    assert Fraction(toc) <= first.lo and first.lo - Fraction(toc) < Fraction(1, 10**15)
    assert abs(toc - 0.5395042868) < 1e-10
    direct = ccd.collide(
        ccd.Ellipsoid([2, 1, 1], ccd.Translation([[11, 0, 0], [-1, 0, 0]])),
        ccd.Ellipsoid([2, 1, 1], ccd.Translation([[3, -2, -4], [3, 2, 0]])),
        first_contact=True,
    )
    assert result.details.to_json() == direct.to_json()


def test_no_collision_is_time_one():
    o1 = fcl.CollisionObject(fcl.Sphere(1), fcl.Transform())
    o2 = fcl.CollisionObject(fcl.Sphere(1), fcl.Transform([5, 0, 0]))
    result = fcl.ContinuousCollisionResult()
    toc = fcl.continuousCollide(o1, fcl.Transform([1, 0, 0]), o2, fcl.Transform([5, 3, 0]),
                                fcl.ContinuousCollisionRequest(), result)
    assert toc == 1.0 and result.is_collide is False and result.details.collision_free is True


def test_linear_motion_is_the_linear_quaternion_curve():
    q1 = [1, 0, 0, 1]  # a quarter turn about z (not unit: that is allowed)
    o1 = fcl.CollisionObject(fcl.Ellipsoid(3, "1/2", "1/2"), fcl.Transform([1, 0, 0, 0], [0, 0, 0]))
    o2 = fcl.CollisionObject(fcl.Sphere("1/2"), fcl.Transform([0, 2, 0]))
    request = fcl.ContinuousCollisionRequest(ccd_motion_type=fcl.CCDMotionType.CCDM_LINEAR)
    result = fcl.ContinuousCollisionResult()
    fcl.continuousCollide(o1, fcl.Transform(q1, [0, 0, 0]), o2, fcl.Transform([0, 2, 0]), request, result)
    direct = ccd.collide(
        ccd.Ellipsoid([3, "1/2", "1/2"], ccd.Rigid([[1, 0, 0, 0], q1], [[0, 0, 0], [0, 0, 0]])),
        ccd.Ellipsoid(["1/2"] * 3, ccd.Static(center=[0, 2, 0])),
        first_contact=True,
    )
    assert result.details.to_json() == direct.to_json()
    assert result.is_collide  # the rod sweeps through the sphere
    # Under CCDM_TRANS (python-fcl's default) the rod keeps its start
    # orientation: it never reaches the sphere.
    trans = fcl.ContinuousCollisionResult()
    fcl.continuousCollide(o1, fcl.Transform(q1, [0, 0, 0]), o2, fcl.Transform([0, 2, 0]),
                          fcl.ContinuousCollisionRequest(), trans)
    assert trans.is_collide is False


def test_linear_takes_the_short_way():
    q0, q1 = (1, 0, 0, 0), (-1, 0, 0, -1)  # −q1 is the same rotation
    m = fcl._linear(q0, (0, 0, 0), q1, (0, 0, 0), turn=True)
    assert m.orientation == [[1, 0, 0, 0], [1, 0, 0, 1]]


def test_screw_motion_reaches_the_end_pose():
    q0 = (1, 0, 0, 0)
    q1 = (math.cos(0.6), 0, math.sin(0.6), 0)  # 1.2 rad about y
    t0, t1 = (1, 2, 3), (2, 1, 5)
    h = fcl._screw(tuple(map(Fraction, q0)), tuple(map(Fraction, t0)),
                   tuple(map(Fraction, q1)), tuple(map(Fraction, t1)))
    assert isinstance(h, ccd.Helical) and abs(h.rate - 1.2) < 1e-12
    f = h.frequency
    end = [b + v + c * math.cos(f) + s * math.sin(f) for b, v, c, s in zip(h.base, h.velocity, h.cos, h.sin)]
    start = [b + c for b, c in zip(h.base, h.cos)]
    assert max(abs(x - y) for x, y in zip(end, t1)) < 1e-12
    assert max(abs(x - y) for x, y in zip(start, t0)) < 1e-12
    o1 = fcl.CollisionObject(fcl.Ellipsoid(2, 1, 1), fcl.Transform(q0, t0))
    o2 = fcl.CollisionObject(fcl.Sphere(1), fcl.Transform([9, 9, 9]))
    result = fcl.ContinuousCollisionResult()
    request = fcl.ContinuousCollisionRequest(ccd_motion_type=fcl.CCDMotionType.CCDM_SCREW)
    fcl.continuousCollide(o1, fcl.Transform(q1, t1), o2, fcl.Transform([9, 9, 9]), request, result)
    assert result.is_collide is False and result.details.certified


def test_refusals():
    with pytest.raises(ValueError, match="quaternion"):
        fcl.Transform([[1, 0, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(ccd.SceneError):
        fcl.CollisionObject("box")
    o = fcl.CollisionObject(fcl.Sphere(1))
    request = fcl.ContinuousCollisionRequest(ccd_motion_type=fcl.CCDMotionType.CCDM_SPLINE)
    with pytest.raises(ValueError, match="CCDM_SPLINE|ccd_motion_type"):
        fcl.continuousCollide(o, fcl.Transform(), o, fcl.Transform(), request)
    with pytest.raises(ccd.SceneError, match="tf1_end.T"):
        fcl.continuousCollide(o, fcl.Transform(["x", 0, 0]), o, fcl.Transform())
