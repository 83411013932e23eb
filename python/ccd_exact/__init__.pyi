"""Type stubs of ``ccd_exact`` (docstrings in the modules)."""

from decimal import Decimal
from fractions import Fraction as Fraction
from typing import Any, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union

Number = Union[int, Fraction, Decimal, str, float]
Vec3 = Tuple[Fraction, Fraction, Fraction]
MAX_DIGITS: int
__version__: str

class SceneError(ValueError):
    field: Optional[str]
    def __init__(self, message: str, field: Optional[str] = ...) -> None: ...

class EffortError(RuntimeError):
    field: Optional[str]
    def __init__(self, message: str, field: Optional[str] = ...) -> None: ...

class Motion:
    kind: str
    def to_dict(self) -> Dict[str, Any]: ...

class Static(Motion):
    center: Optional[Sequence[Number]]
    orientation: Optional[Sequence[Number]]
    def __init__(self, center: Optional[Sequence[Number]] = ..., orientation: Optional[Sequence[Number]] = ...) -> None: ...

class Translation(Motion):
    center: Sequence[Sequence[Number]]
    weights: Optional[Sequence[Number]]
    orientation: Optional[Sequence[Number]]
    def __init__(
        self,
        center: Sequence[Sequence[Number]],
        weights: Optional[Sequence[Number]] = ...,
        orientation: Optional[Sequence[Number]] = ...,
    ) -> None: ...

class Rigid(Motion):
    orientation: Sequence[Sequence[Number]]
    center: Sequence[Sequence[Number]]
    weights: Optional[Sequence[Number]]
    def __init__(
        self,
        orientation: Sequence[Sequence[Number]],
        center: Sequence[Sequence[Number]],
        weights: Optional[Sequence[Number]] = ...,
    ) -> None: ...

class Affine(Motion):
    matrix: Sequence[Any]
    weights: Optional[Sequence[Number]]
    def __init__(self, matrix: Sequence[Any], weights: Optional[Sequence[Number]] = ...) -> None: ...

class Helical(Motion):
    axis: Sequence[Number]
    rate: Number
    orientation: Optional[Sequence[Number]]
    base: Optional[Sequence[Number]]
    velocity: Optional[Sequence[Number]]
    cos: Optional[Sequence[Number]]
    sin: Optional[Sequence[Number]]
    frequency: Optional[Number]
    def __init__(
        self,
        axis: Sequence[Number],
        rate: Number,
        orientation: Optional[Sequence[Number]] = ...,
        base: Optional[Sequence[Number]] = ...,
        velocity: Optional[Sequence[Number]] = ...,
        cos: Optional[Sequence[Number]] = ...,
        sin: Optional[Sequence[Number]] = ...,
        frequency: Optional[Number] = ...,
    ) -> None: ...

class Ellipsoid:
    radii: Sequence[Number]
    motion: Optional[Motion]
    def __init__(self, radii: Sequence[Number], motion: Optional[Motion] = ...) -> None: ...
    def to_dict(self) -> Dict[str, Any]: ...

class Scene:
    def __init__(self, a: Union[Ellipsoid, Mapping[str, Any]], b: Union[Ellipsoid, Mapping[str, Any]], span: Sequence[Number] = ...) -> None: ...
    @classmethod
    def from_toml(cls, text: str) -> Scene: ...
    @classmethod
    def from_dict(cls, scene: Mapping[str, Any]) -> Scene: ...
    @classmethod
    def from_json(cls, text: Union[str, bytes, Mapping[str, Any]]) -> Scene: ...
    def to_toml(self) -> str: ...

class Box:
    lo: Vec3
    hi: Vec3
    approx: Tuple[float, float, float]
    certified: bool

class Time:
    lo: Fraction
    hi: Fraction
    approx: float
    certified: bool
    @property
    def width(self) -> Fraction: ...
    def __contains__(self, t: object) -> bool: ...

class Contact(Time):
    point: Optional[Box]
    normal: Optional[Box]
    point_note: Optional[str]

class Segment:
    state: str
    start: Time
    end: Time
    certified: bool

class Gap:
    lo: Fraction
    hi: Fraction
    reason: str
    witness: Optional[Tuple[Fraction, str]]

class Result:
    span: Tuple[Fraction, Fraction]
    collision_free: Optional[bool]
    collision_free_reason: Optional[str]
    first_contact: Optional[Time]
    contacts: List[Contact]
    timeline: List[Segment]
    gaps: List[Gap]
    complete: bool
    certified: bool
    stats: Dict[str, Any]
    def to_json(self) -> str: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def to_svg(self, title: str = ...) -> str: ...
    def to_html(self, title: str = ...) -> str: ...
    def plot(self, path: Optional[str] = ..., title: str = ...) -> str: ...
    def scene_toml(self) -> Optional[str]: ...

Bodies = Union[Mapping[str, Union[Ellipsoid, Mapping[str, Any]]], Iterable[Tuple[str, Union[Ellipsoid, Mapping[str, Any]]]]]

class World:
    def __init__(self, bodies: Bodies, span: Sequence[Number] = ...) -> None: ...
    @classmethod
    def from_toml(cls, text: str) -> World: ...
    def to_toml(self) -> str: ...

class WorldContact(Time):
    pair: Tuple[str, str]

class BroadPhase:
    candidates: int
    pruned: int
    box_overlaps: int
    slices: int
    def __init__(self, candidates: int, pruned: int, box_overlaps: int, slices: int) -> None: ...

class WorldPair:
    a: str
    b: str
    result: Optional[Result]
    error: Optional[str]
    @property
    def names(self) -> Tuple[str, str]: ...

class WorldResult:
    span: Tuple[Fraction, Fraction]
    bodies: List[str]
    colliding: List[Tuple[str, str]]
    undecided: List[Tuple[str, str]]
    first_contact: Optional[WorldContact]
    pairs: List[WorldPair]
    broad_phase: BroadPhase
    complete: bool
    certified: bool
    def pair(self, a: str, b: str) -> Optional[WorldPair]: ...
    def to_json(self) -> str: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def world_toml(self) -> str: ...

def collide(
    a: Ellipsoid,
    b: Ellipsoid,
    span: Sequence[Number] = ...,
    first_contact: bool = ...,
    digits: int = ...,
    arithmetic: str = ...,
    geometry: bool = ...,
    raycast: bool = ...,
) -> Result: ...
def collide_toml(
    text: str,
    *,
    first_contact: bool = ...,
    digits: int = ...,
    arithmetic: str = ...,
    geometry: bool = ...,
    raycast: bool = ...,
) -> Result: ...
def collide_json(
    scene: Union[str, bytes, Mapping[str, Any]],
    *,
    first_contact: bool = ...,
    digits: int = ...,
    arithmetic: str = ...,
    geometry: bool = ...,
    raycast: bool = ...,
) -> Result: ...
def collide_many(
    pairs: Iterable[Union[Scene, Tuple[Any, ...], Mapping[str, Any]]],
    threads: Optional[int] = ...,
    *,
    first_contact: bool = ...,
    digits: int = ...,
    arithmetic: str = ...,
    geometry: bool = ...,
    raycast: bool = ...,
) -> List[Result]: ...
def collide_world(
    bodies: Bodies,
    span: Sequence[Number] = ...,
    threads: Optional[int] = ...,
    *,
    first_contact: bool = ...,
    digits: int = ...,
    arithmetic: str = ...,
    geometry: bool = ...,
    raycast: bool = ...,
) -> WorldResult: ...
def collide_world_toml(
    text: str,
    threads: Optional[int] = ...,
    *,
    first_contact: bool = ...,
    digits: int = ...,
    arithmetic: str = ...,
    geometry: bool = ...,
    raycast: bool = ...,
) -> WorldResult: ...
