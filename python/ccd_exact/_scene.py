"""Scenes built in Python: ellipsoids, their motions, and the exact TOML text
they stand for.

Every scene reaches the engine as the text of a scene file (format 1,
docs/scene-format.md) in which each number is written exactly: an ``int``
as itself, a ``Fraction`` as ``"p/q"``, a ``float`` as the ``"p/q"`` of its
exact binary value, a ``Decimal`` or a ``str`` as its text. The engine's own
parser then reads it, so a Python scene is checked exactly like a file and
its errors name the same fields.
"""

from __future__ import annotations

import json
import numbers
import re
from decimal import Decimal
from fractions import Fraction
from typing import Any, Dict, Mapping, Optional, Sequence, Tuple, Union

from ._errors import SceneError

Number = Union[int, Fraction, Decimal, str, float]
"""A number of a scene: ``int``, ``Fraction``, ``Decimal``, a string such as
``"1/3"`` or ``"1e-20"``, or a ``float`` (taken as its exact binary value);
numpy scalars count as the corresponding Python numbers."""

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")
_I64 = 2**63


def _key(path: str, k: str) -> str:
    return f"{path}.{k}" if path else k


def _string(text: str, path: str) -> str:
    """``text`` as a TOML basic string."""
    out = ['"']
    for ch in text:
        o = ord(ch)
        if ch == '"':
            out.append('\\"')
        elif ch == "\\":
            out.append("\\\\")
        elif o < 0x20 or o == 0x7F:
            out.append(f"\\u{o:04X}")
        elif 0xD800 <= o <= 0xDFFF:
            raise SceneError(f"field `{path}`: not valid text (a lone surrogate)", path or None)
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


def _number(x: Any, path: str) -> Optional[str]:
    """The exact TOML text of the number ``x``, or ``None`` if it is not one."""
    if isinstance(x, bool):
        return None
    if isinstance(x, numbers.Integral):
        v = int(x)
        try:
            text = str(v)
        except ValueError:  # more digits than int → str allows
            raise SceneError(
                f"field `{path}`: too large (a number has at most 4096 characters)", path
            ) from None
        return text if -_I64 <= v < _I64 else f'"{text}"'
    if isinstance(x, Decimal):
        # Its own text is exact; NaN and Infinity are refused by the engine.
        return f'"{x}"'
    if isinstance(x, numbers.Rational):
        return f'"{Fraction(int(x.numerator), int(x.denominator))}"'
    if isinstance(x, numbers.Real) or hasattr(x, "as_integer_ratio"):
        try:
            p, q = x.as_integer_ratio()
        except (OverflowError, ValueError):  # inf, nan: the engine names them
            return _string(repr(float(x)), path)
        except AttributeError:
            return None
        return f'"{Fraction(p, q)}"'
    return None


def to_toml_value(value: Any, path: str) -> str:
    """``value`` as an inline TOML value: numbers exactly, strings, lists
    (and numpy arrays), tuples, and mappings as inline tables."""
    if getattr(value, "ndim", 0):
        value = list(value)  # a numpy array: its rows, or scalars of its dtype
    elif getattr(value, "shape", None) == ():
        value = value[()]  # a 0-d numpy array: its scalar
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return _string(value, path)
    if isinstance(value, Mapping):
        items = []
        for k, v in value.items():
            if not isinstance(k, str):
                raise SceneError(f"field `{path}`: keys must be strings, found {k!r}", path or None)
            key = k if _BARE_KEY.match(k) else _string(k, _key(path, k))
            items.append(f"{key} = {to_toml_value(v, _key(path, k))}")
        return "{ " + ", ".join(items) + " }" if items else "{}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(to_toml_value(v, f"{path}[{i}]") for i, v in enumerate(value)) + "]"
    text = _number(value, path)
    if text is None:
        raise SceneError(
            f"field `{path}`: expected a number, a string, a list or a table, "
            f"found {type(value).__name__} {value!r:.64}",
            path or None,
        )
    return text


def dict_to_toml(scene: Mapping[str, Any]) -> str:
    """A scene given as a mapping (the structure of a scene file) as TOML text."""
    if not isinstance(scene, Mapping):
        raise SceneError(f"a scene is a mapping of `span`, `a` and `b`, found {type(scene).__name__}")
    lines = []
    for k, v in scene.items():
        if not isinstance(k, str):
            raise SceneError(f"scene keys must be strings, found {k!r}")
        key = k if _BARE_KEY.match(k) else _string(k, k)
        lines.append(f"{key} = {to_toml_value(v, k)}")
    return "\n".join(lines) + "\n"


class Motion:
    """A motion of the scene format: ``Static``, ``Translation``, ``Rigid``,
    ``Affine`` or ``Helical``. Values are kept as given and read exactly
    when the scene is run; fields left ``None`` take the format's default."""

    kind = ""
    _fields: Tuple[str, ...] = ()

    def __init__(self, **fields: Any) -> None:
        for name in self._fields:
            setattr(self, name, fields.get(name))

    def to_dict(self) -> Dict[str, Any]:
        """The motion table of a scene file, as a dict (``None`` fields left out)."""
        d: Dict[str, Any] = {"kind": self.kind}
        d.update({k: getattr(self, k) for k in self._fields if getattr(self, k) is not None})
        return d

    def __repr__(self) -> str:
        args = ", ".join(
            f"{k}={getattr(self, k)!r}" for k in self._fields if getattr(self, k) is not None
        )
        return f"{type(self).__name__}({args})"

    def __eq__(self, other: object) -> bool:
        return type(self) is type(other) and self.to_dict() == other.to_dict()  # type: ignore[attr-defined]


class Static(Motion):
    """Fixed placement: ``center`` (3-vector, default the origin) and
    ``orientation`` (quaternion ``[w, x, y, z]``, default the identity)."""

    kind = "static"
    _fields = ("center", "orientation")

    def __init__(self, center: Optional[Sequence[Number]] = None, orientation: Optional[Sequence[Number]] = None) -> None:
        super().__init__(center=center, orientation=orientation)


class Translation(Motion):
    """Fixed ``orientation``; the centre on a Bézier curve over the span
    (``center``: control points, optional ``weights`` make it rational)."""

    kind = "translation"
    _fields = ("center", "weights", "orientation")

    def __init__(
        self,
        center: Sequence[Sequence[Number]],
        weights: Optional[Sequence[Number]] = None,
        orientation: Optional[Sequence[Number]] = None,
    ) -> None:
        super().__init__(center=center, weights=weights, orientation=orientation)


class Rigid(Motion):
    """``R(t) = R(q(t))`` for a Bézier quaternion curve ``orientation`` (a
    rational rotation of degree 2m) and a Bézier ``center`` (optional
    ``weights``); the body turns about its own centre."""

    kind = "rigid"
    _fields = ("orientation", "center", "weights")

    def __init__(
        self,
        orientation: Sequence[Sequence[Number]],
        center: Sequence[Sequence[Number]],
        weights: Optional[Sequence[Number]] = None,
    ) -> None:
        super().__init__(orientation=orientation, center=center, weights=weights)


class Affine(Motion):
    """``X = (L(t)·Xbody + d(t)) / w(t)``: ``matrix`` is the Bézier curve of
    3×4 matrices ``[L | d]`` (3 rows of 4), ``weights`` its optional weights."""

    kind = "affine"
    _fields = ("matrix", "weights")

    def __init__(self, matrix: Sequence[Any], weights: Optional[Sequence[Number]] = None) -> None:
        super().__init__(matrix=matrix, weights=weights)


class Helical(Motion):
    """Spin at ``rate`` radians per unit of t about ``axis`` (through the
    body's centre) after ``orientation``, the centre at
    ``base + velocity·t + cos·cos(frequency·t) + sin·sin(frequency·t)``
    (``t`` the time itself). Not rational: answered by certified interval
    enclosures; a screw motion is ``axis``/``rate`` with ``velocity`` along
    the axis and ``cos``/``sin`` for the centre's turn about the screw axis."""

    kind = "helical"
    _fields = ("orientation", "axis", "rate", "base", "velocity", "cos", "sin", "frequency")
    _center = ("base", "velocity", "cos", "sin", "frequency")

    def __init__(
        self,
        axis: Sequence[Number],
        rate: Number,
        orientation: Optional[Sequence[Number]] = None,
        base: Optional[Sequence[Number]] = None,
        velocity: Optional[Sequence[Number]] = None,
        cos: Optional[Sequence[Number]] = None,
        sin: Optional[Sequence[Number]] = None,
        frequency: Optional[Number] = None,
    ) -> None:
        super().__init__(
            axis=axis, rate=rate, orientation=orientation, base=base,
            velocity=velocity, cos=cos, sin=sin, frequency=frequency,
        )

    def to_dict(self) -> Dict[str, Any]:
        d = super().to_dict()
        center = {k: d.pop(k) for k in self._center if k in d}
        if center:
            d["center"] = center
        return d


class Ellipsoid:
    """An ellipsoid with semi-axes ``radii`` (along its body x, y, z axes,
    each > 0) and a ``motion`` (default: static at the origin, unrotated)."""

    def __init__(self, radii: Sequence[Number], motion: Optional[Motion] = None) -> None:
        self.radii = radii
        self.motion = motion

    def to_dict(self) -> Dict[str, Any]:
        """The body table of a scene file, as a dict."""
        d: Dict[str, Any] = {"radii": self.radii}
        if self.motion is not None:
            if not isinstance(self.motion, Motion):
                return {"radii": self.radii, "motion": self.motion}
            d["motion"] = self.motion.to_dict()
        return d

    def __repr__(self) -> str:
        if self.motion is None:
            return f"Ellipsoid({self.radii!r})"
        return f"Ellipsoid({self.radii!r}, {self.motion!r})"


def _body(body: Any, name: str) -> Any:
    if isinstance(body, Ellipsoid):
        return body.to_dict()
    if isinstance(body, Mapping):
        return body
    raise SceneError(
        f"field `{name}`: expected an Ellipsoid (or a mapping with `radii` and `motion`), "
        f"found {type(body).__name__}",
        name,
    )


class Scene:
    """A pair scene: two bodies ``a`` and ``b`` over ``span``, held as the
    exact text of a scene file (``to_toml()``), which the CLI reads too."""

    def __init__(self, a: Any, b: Any, span: Sequence[Number] = (0, 1)) -> None:
        self._toml = dict_to_toml({"span": span, "a": _body(a, "a"), "b": _body(b, "b")})

    @classmethod
    def from_toml(cls, text: str) -> "Scene":
        """A scene from a scene file's text (checked when it is run)."""
        if not isinstance(text, str):
            raise SceneError(f"a scene's TOML text is a str, found {type(text).__name__}")
        scene = cls.__new__(cls)
        scene._toml = text
        return scene

    @classmethod
    def from_dict(cls, scene: Mapping[str, Any]) -> "Scene":
        """A scene from a mapping with the structure of a scene file."""
        return cls.from_toml(dict_to_toml(scene))

    @classmethod
    def from_json(cls, text: Union[str, bytes, Mapping[str, Any]]) -> "Scene":
        """A scene from JSON text (one line of a JSON Lines file) with the
        structure of a scene file: ``{"span": [...], "a": {"radii": [...],
        "motion": {...}}, "b": {...}}``. JSON numbers are read exactly from
        their text (``0.1`` is 1/10, as in TOML); strings such as ``"1/3"``
        work as in a scene file."""
        if isinstance(text, Mapping):
            return cls.from_dict(text)
        try:
            data = json.loads(text, parse_float=Decimal, parse_constant=lambda c: c)
        except (json.JSONDecodeError, UnicodeDecodeError, TypeError) as e:
            where = f" (line {e.lineno}, column {e.colno})" if isinstance(e, json.JSONDecodeError) else ""
            msg = e.msg if isinstance(e, json.JSONDecodeError) else str(e)
            raise SceneError(f"not JSON{where}: {msg}") from None
        return cls.from_dict(data)

    def to_toml(self) -> str:
        """The scene file's text: ``ccd-exact FILE`` gives the same answer."""
        return self._toml

    def __repr__(self) -> str:
        return f"Scene.from_toml({self._toml!r})"
