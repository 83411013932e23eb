"""A python-fcl-shaped entry to ccd_exact: switch by changing an import.

::

    from ccd_exact import fcl          # instead of: import fcl

    o1 = fcl.CollisionObject(fcl.Ellipsoid(2, 1, 1), fcl.Transform([11, 0, 0]))
    o2 = fcl.CollisionObject(fcl.Ellipsoid(2, 1, 1), fcl.Transform([3, -2, -4]))
    request = fcl.ContinuousCollisionRequest()
    result = fcl.ContinuousCollisionResult()
    toc = fcl.continuousCollide(o1, fcl.Transform([-1, 0, 0]),
                                o2, fcl.Transform([3, 2, 0]), request, result)
    # result.is_collide == True, toc ≈ 0.5395042868 (Example 5.1)

The motion between the start pose (the object's transform) and the end pose
(``tf_end``) over the time step ``[0, 1]``, by ``request.ccd_motion_type``:

- ``CCDM_TRANS`` (python-fcl's default): the centre on the straight line,
  the start orientation throughout (as FCL's translation motion);
- ``CCDM_LINEAR``: the centre on the straight line and the orientation on
  the **linear quaternion curve** ``q(t) = (1 − t)·q0 + t·q1`` (``q1``
  negated first if ``q0·q1 < 0``, the same end pose). That is an exact
  rational rotation through both poses, answered exactly; it is **not**
  slerp: it turns through the same rotations, but not at a constant rate;
- ``CCDM_SCREW``: the screw motion through both poses (constant angular and
  linear velocity about and along one axis), as the ``helical`` kind: its
  axis, angle and pitch are computed from the poses in floating point (the
  motion then reaches the end pose to float precision), and its contacts are
  certified by interval enclosures for that motion;
- ``CCDM_SPLINE`` is not supported (``ValueError``).

Numbers are kept exact as in ``ccd_exact`` (floats are their binary
values). ``Transform`` takes a quaternion ``[w, x, y, z]`` and/or a
translation, not a rotation matrix: a matrix of floats has no exact
rational quaternion in general, so it is refused rather than rounded.
The request's solver settings (``num_max_iterations``, ``gjk_solver_type``,
``ccd_solver_type``) are accepted and ignored: the answer is exact.
``time_of_contact`` is the largest float not above the certified lower end
of the first contact (never late), the start of the first undecided piece
when there is no proven contact before it, ``1.0`` when the bodies stay
separate, and the full answer is ``result.details`` (a ``ccd_exact.Result``).
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any, Optional, Sequence, Tuple

from . import Ellipsoid as _Body
from . import Helical, Result, Rigid, Scene, SceneError, Static, Translation
from . import _options, _run

__all__ = [
    "CCDMotionType", "CCDSolverType", "CollisionObject", "ContinuousCollisionRequest",
    "ContinuousCollisionResult", "Ellipsoid", "GJKSolverType", "Sphere", "Transform",
    "continuousCollide",
]


class CCDMotionType:
    """The motion between two poses (python-fcl's names and values)."""

    CCDM_TRANS = 0
    CCDM_LINEAR = 1
    CCDM_SCREW = 2
    CCDM_SPLINE = 3


class CCDSolverType:
    """python-fcl's solver kinds: accepted and ignored (the answer is exact)."""

    CCDC_NAIVE = 0
    CCDC_CONSERVATIVE_ADVANCEMENT = 1
    CCDC_RAY_SHOOTING = 2
    CCDC_POLYNOMIAL_SOLVER = 3


class GJKSolverType:
    """python-fcl's GJK kinds: accepted and ignored."""

    GST_LIBCCD = 0
    GST_INDEP = 1


class Ellipsoid:
    """An ellipsoid with semi-axes ``a``, ``b``, ``c`` along its body x, y, z."""

    def __init__(self, a: Any, b: Any, c: Any) -> None:
        self.radii = (a, b, c)

    def __repr__(self) -> str:
        return f"Ellipsoid{self.radii!r}"


class Sphere(Ellipsoid):
    """A sphere of ``radius`` (an ellipsoid with three equal semi-axes)."""

    def __init__(self, radius: Any) -> None:
        super().__init__(radius, radius, radius)
        self.radius = radius


def _fraction(x: Any, field: str) -> Fraction:
    try:
        if isinstance(x, bool):
            raise TypeError
        if hasattr(x, "as_integer_ratio") and not isinstance(x, (int, Fraction)):
            p, q = x.as_integer_ratio()
            return Fraction(p, q)
        return Fraction(int(x)) if hasattr(x, "__index__") else Fraction(x)
    except (TypeError, ValueError, OverflowError, ZeroDivisionError):
        raise SceneError(f"field `{field}`: expected a finite number, found {x!r:.64}", field) from None


def _vector(v: Any, n: int, field: str) -> Tuple[Any, ...]:
    try:
        items = tuple(v)
    except TypeError:
        raise SceneError(f"field `{field}`: expected {n} numbers, found {v!r:.64}", field) from None
    if len(items) != n:
        raise SceneError(f"field `{field}`: expected {n} numbers, found {len(items)}", field)
    return items


class Transform:
    """A pose: rotation quaternion ``q = [w, x, y, z]`` (need not be unit)
    and translation ``T``. ``Transform()``, ``Transform(q)``,
    ``Transform(T)``, ``Transform(q, T)`` or ``Transform(other)``."""

    def __init__(self, *args: Any) -> None:
        q: Sequence[Any] = (1, 0, 0, 0)
        t: Sequence[Any] = (0, 0, 0)
        if len(args) == 1 and isinstance(args[0], Transform):
            q, t = args[0].q, args[0].T
        elif len(args) == 1:
            n = len(args[0])
            if n == 4:
                q = args[0]
            elif n == 3 and not _is_row(args[0][0]):
                t = args[0]
            else:
                raise ValueError(_NO_MATRIX)
        elif len(args) == 2:
            if len(args[0]) != 4:
                raise ValueError(_NO_MATRIX)
            q, t = args
        elif args:
            raise TypeError("Transform() takes (), (q), (T) or (q, T)")
        self.q = _vector(q, 4, "q")
        self.T = _vector(t, 3, "T")

    def getQuatRotation(self) -> Tuple[Any, ...]:
        """The quaternion ``[w, x, y, z]`` as given."""
        return self.q

    def getTranslation(self) -> Tuple[Any, ...]:
        """The translation as given."""
        return self.T

    def setQuatRotation(self, q: Sequence[Any]) -> None:
        """Sets the rotation quaternion ``[w, x, y, z]``."""
        self.q = _vector(q, 4, "q")

    def setTranslation(self, t: Sequence[Any]) -> None:
        """Sets the translation."""
        self.T = _vector(t, 3, "T")

    def __repr__(self) -> str:
        return f"Transform(q={self.q!r}, T={self.T!r})"


def _is_row(x: Any) -> bool:
    return hasattr(x, "__len__") and not isinstance(x, (str, bytes))


_NO_MATRIX = (
    "Transform: give the rotation as a quaternion [w, x, y, z]; a rotation matrix "
    "is not accepted (a matrix of floats has no exact rational quaternion in general)"
)


class CollisionObject:
    """A geometry (``Ellipsoid`` or ``Sphere``) at a pose (``Transform``)."""

    def __init__(self, geom: Ellipsoid, tf: Optional[Transform] = None) -> None:
        if not isinstance(geom, Ellipsoid):
            raise SceneError(
                f"CollisionObject: ccd_exact handles ellipsoids (and spheres), found {type(geom).__name__}",
                "geom",
            )
        self.geom = geom
        self.tf = Transform(tf) if tf is not None else Transform()

    def getTransform(self) -> Transform:
        """The pose."""
        return self.tf

    def setTransform(self, tf: Transform) -> None:
        """Sets the pose."""
        self.tf = Transform(tf)

    def getTranslation(self) -> Tuple[Any, ...]:
        """The pose's translation."""
        return self.tf.T

    def getQuatRotation(self) -> Tuple[Any, ...]:
        """The pose's quaternion."""
        return self.tf.q

    def setTranslation(self, t: Sequence[Any]) -> None:
        """Sets the pose's translation."""
        self.tf.setTranslation(t)

    def setQuatRotation(self, q: Sequence[Any]) -> None:
        """Sets the pose's quaternion."""
        self.tf.setQuatRotation(q)


class ContinuousCollisionRequest:
    """python-fcl's request, with its defaults. ``ccd_motion_type`` chooses
    the motion; ``toc_err`` asks for at least that accuracy (the enclosure is
    at least 1e-15 of the step anyway); the other settings are ignored."""

    def __init__(
        self,
        num_max_iterations: int = 10,
        toc_err: float = 0.0001,
        ccd_motion_type: int = CCDMotionType.CCDM_TRANS,
        gjk_solver_type: int = GJKSolverType.GST_LIBCCD,
        ccd_solver_type: int = CCDSolverType.CCDC_CONSERVATIVE_ADVANCEMENT,
    ) -> None:
        self.num_max_iterations = num_max_iterations
        self.toc_err = toc_err
        self.ccd_motion_type = ccd_motion_type
        self.gjk_solver_type = gjk_solver_type
        self.ccd_solver_type = ccd_solver_type


class ContinuousCollisionResult:
    """python-fcl's result: ``is_collide`` and ``time_of_contact`` (a float in
    ``[0, 1]``), plus ``details``, the full ``ccd_exact.Result`` (exact
    enclosure of the first contact, timeline, contact point and normal).

    ``is_collide`` is ``False`` only when separation over the step is
    proven; on a helical (screw) step left undecided within the effort
    budget it is ``True`` (the safe answer for a motion planner), with
    ``details.collision_free`` ``None`` and the reason in
    ``details.collision_free_reason``."""

    def __init__(self, is_collide: bool = False, time_of_contact: float = 1.0) -> None:
        self.is_collide = is_collide
        self.time_of_contact = time_of_contact
        self.details: Optional[Result] = None


def _linear(q0: Tuple[Fraction, ...], t0: Tuple[Fraction, ...],
            q1: Tuple[Fraction, ...], t1: Tuple[Fraction, ...], turn: bool) -> Any:
    if not turn or q0 == q1:
        if t0 == t1:
            return Static(center=list(t0), orientation=list(q0))
        return Translation([list(t0), list(t1)], orientation=list(q0))
    if sum(a * b for a, b in zip(q0, q1)) < 0:
        q1 = tuple(-x for x in q1)  # the same rotation, the shorter way
    return Rigid([list(q0), list(q1)], [list(t0), list(t1)])


def _screw(q0: Tuple[Fraction, ...], t0: Tuple[Fraction, ...],
           q1: Tuple[Fraction, ...], t1: Tuple[Fraction, ...]) -> Any:
    """The screw motion through both poses (floats; see the module docs)."""
    f = [float(x) for x in q0]
    g = [float(x) for x in q1]
    n0, n1 = math.sqrt(sum(x * x for x in f)), math.sqrt(sum(x * x for x in g))
    w0, x0, y0, z0 = (x / n0 for x in f)
    w1, x1, y1, z1 = (x / n1 for x in g)
    # q_rel = q1 ⊗ conj(q0): the rotation from the start to the end pose.
    w = w1 * w0 + x1 * x0 + y1 * y0 + z1 * z0
    v = (
        -w1 * x0 + x1 * w0 - y1 * z0 + z1 * y0,
        -w1 * y0 + x1 * z0 + y1 * w0 - z1 * x0,
        -w1 * z0 - x1 * y0 + y1 * x0 + z1 * w0,
    )
    if w < 0:
        w, v = -w, tuple(-c for c in v)
    s = math.sqrt(sum(c * c for c in v))
    theta = 2 * math.atan2(s, w)
    if s == 0 or theta == 0:
        return _linear(q0, t0, q1, t1, turn=False)
    axis = tuple(c / s for c in v)
    u = tuple(float(b - a) for a, b in zip(t0, t1))
    d = sum(a * b for a, b in zip(u, axis))
    perp = tuple(c - d * a for c, a in zip(u, axis))
    cross = lambda a, b: (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])  # noqa: E731
    k = 2 - 2 * math.cos(theta)
    au = cross(axis, perp)
    # r = c0 − p, the centre's offset from the screw axis: (R − I)·r = perp.
    r = tuple(((math.cos(theta) - 1) * p - math.sin(theta) * c) / k for p, c in zip(perp, au))
    return Helical(
        axis=list(axis), rate=theta, orientation=list(q0),
        base=[float(c) - a for c, a in zip(t0, r)], velocity=[d * a for a in axis],
        cos=list(r), sin=list(cross(axis, r)), frequency=theta,
    )


def _motion(obj: CollisionObject, tf_end: Transform, kind: int, name: str) -> Any:
    q0 = tuple(_fraction(x, f"{name}.q[{i}]") for i, x in enumerate(obj.tf.q))
    t0 = tuple(_fraction(x, f"{name}.T[{i}]") for i, x in enumerate(obj.tf.T))
    q1 = tuple(_fraction(x, f"{name}_end.q[{i}]") for i, x in enumerate(tf_end.q))
    t1 = tuple(_fraction(x, f"{name}_end.T[{i}]") for i, x in enumerate(tf_end.T))
    if kind == CCDMotionType.CCDM_TRANS:
        return _linear(q0, t0, q1, t1, turn=False)
    if kind == CCDMotionType.CCDM_LINEAR:
        return _linear(q0, t0, q1, t1, turn=True)
    if kind == CCDMotionType.CCDM_SCREW:
        return _screw(q0, t0, q1, t1)
    raise ValueError(f"ccd_motion_type {kind!r}: ccd_exact supports CCDM_TRANS, CCDM_LINEAR and CCDM_SCREW")


def continuousCollide(
    o1: CollisionObject,
    tf1_end: Transform,
    o2: CollisionObject,
    tf2_end: Transform,
    request: Optional[ContinuousCollisionRequest] = None,
    result: Optional[ContinuousCollisionResult] = None,
) -> float:
    """Continuous collision of ``o1`` moving from its pose to ``tf1_end``
    and ``o2`` from its pose to ``tf2_end`` over the step ``[0, 1]``.
    Fills ``result`` (when given) and returns its ``time_of_contact``."""
    request = request or ContinuousCollisionRequest()
    result = result if result is not None else ContinuousCollisionResult()
    kind = request.ccd_motion_type
    a = _Body(list(o1.geom.radii), _motion(o1, tf1_end, kind, "tf1"))
    b = _Body(list(o2.geom.radii), _motion(o2, tf2_end, kind, "tf2"))
    digits = 15
    if request.toc_err and 0 < request.toc_err < 1e-15:
        digits = min(1000, math.ceil(-math.log10(request.toc_err)))
    details = _run(Scene(a, b, (0, 1)), _options(first_contact=True, digits=digits))
    result.details = details
    result.is_collide = details.collision_free is not True
    toc = 1.0
    if details.first_contact is not None:
        lo = details.first_contact.lo
        toc = float(lo)
        if Fraction(toc) > lo:
            toc = math.nextafter(toc, -math.inf)
    elif details.gaps:
        toc = float(details.gaps[0].lo)
    result.time_of_contact = toc
    return toc
