"""Type stubs of ``ccd_exact.fcl`` (a python-fcl-shaped entry; docs in the module)."""

from typing import Any, Optional, Sequence, Tuple

from . import Result

class CCDMotionType:
    CCDM_TRANS: int
    CCDM_LINEAR: int
    CCDM_SCREW: int
    CCDM_SPLINE: int

class CCDSolverType:
    CCDC_NAIVE: int
    CCDC_CONSERVATIVE_ADVANCEMENT: int
    CCDC_RAY_SHOOTING: int
    CCDC_POLYNOMIAL_SOLVER: int

class GJKSolverType:
    GST_LIBCCD: int
    GST_INDEP: int

class Ellipsoid:
    radii: Tuple[Any, Any, Any]
    def __init__(self, a: Any, b: Any, c: Any) -> None: ...

class Sphere(Ellipsoid):
    radius: Any
    def __init__(self, radius: Any) -> None: ...

class Transform:
    q: Tuple[Any, ...]
    T: Tuple[Any, ...]
    def __init__(self, *args: Any) -> None: ...
    def getQuatRotation(self) -> Tuple[Any, ...]: ...
    def getTranslation(self) -> Tuple[Any, ...]: ...
    def setQuatRotation(self, q: Sequence[Any]) -> None: ...
    def setTranslation(self, t: Sequence[Any]) -> None: ...

class CollisionObject:
    geom: Ellipsoid
    tf: Transform
    def __init__(self, geom: Ellipsoid, tf: Optional[Transform] = ...) -> None: ...
    def getTransform(self) -> Transform: ...
    def setTransform(self, tf: Transform) -> None: ...
    def getTranslation(self) -> Tuple[Any, ...]: ...
    def getQuatRotation(self) -> Tuple[Any, ...]: ...
    def setTranslation(self, t: Sequence[Any]) -> None: ...
    def setQuatRotation(self, q: Sequence[Any]) -> None: ...

class ContinuousCollisionRequest:
    num_max_iterations: int
    toc_err: float
    ccd_motion_type: int
    gjk_solver_type: int
    ccd_solver_type: int
    def __init__(
        self,
        num_max_iterations: int = ...,
        toc_err: float = ...,
        ccd_motion_type: int = ...,
        gjk_solver_type: int = ...,
        ccd_solver_type: int = ...,
    ) -> None: ...

class ContinuousCollisionResult:
    is_collide: bool
    time_of_contact: float
    details: Optional[Result]
    def __init__(self, is_collide: bool = ..., time_of_contact: float = ...) -> None: ...

def continuousCollide(
    o1: CollisionObject,
    tf1_end: Transform,
    o2: CollisionObject,
    tf2_end: Transform,
    request: Optional[ContinuousCollisionRequest] = ...,
    result: Optional[ContinuousCollisionResult] = ...,
) -> float: ...
