"""The answer of a query, as Python objects with exact ``Fraction`` times.

Built from the engine's JSON (the CLI's ``--json``, docs/scene-format.md),
so ``Result.to_json()`` is that text and every field here is read from it.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Dict, List, Optional, Tuple

Vec3 = Tuple[Fraction, Fraction, Fraction]


@dataclass(frozen=True)
class Box:
    """A box ``lo <= x <= hi`` (componentwise, exact) holding a point or a
    vector; ``approx`` the midpoint's coordinates as floats."""

    lo: Vec3
    hi: Vec3
    approx: Tuple[float, float, float]
    certified: bool

    @staticmethod
    def _read(d: Dict[str, Any]) -> "Box":
        return Box(
            lo=tuple(Fraction(x) for x in d["lo"]),  # type: ignore[arg-type]
            hi=tuple(Fraction(x) for x in d["hi"]),  # type: ignore[arg-type]
            approx=tuple(float(x) for x in d["approx"]),  # type: ignore[arg-type]
            certified=bool(d["certified"]),
        )


@dataclass(frozen=True)
class Time:
    """An instant known by the enclosure ``lo <= t <= hi`` (exact
    ``Fraction`` ends; ``lo == hi`` when it is known exactly). ``certified``:
    the enclosure is proven to hold the instant. ``approx``: a float of it."""

    lo: Fraction
    hi: Fraction
    approx: float
    certified: bool

    @property
    def width(self) -> Fraction:
        """``hi - lo``."""
        return self.hi - self.lo

    def __contains__(self, t: object) -> bool:
        return bool(self.lo <= t <= self.hi)  # type: ignore[operator]


@dataclass(frozen=True)
class Contact(Time):
    """An isolated instant of external touching, with its contact ``point``
    and A's outward ``normal`` (scaled so its largest component is ±1) as
    certified boxes when they were computed; ``None`` otherwise, with
    ``point_note`` saying why."""

    point: Optional[Box] = None
    normal: Optional[Box] = None
    point_note: Optional[str] = None


def _mid(d: Dict[str, Any]) -> float:
    """The float nearest the enclosure's midpoint (the JSON's ``approx`` text
    has 12 to 16 decimals; the float carries all a float can)."""
    return float((Fraction(d["lo"]) + Fraction(d["hi"])) / 2)


def _time(d: Dict[str, Any]) -> Time:
    return Time(Fraction(d["lo"]), Fraction(d["hi"]), _mid(d), bool(d["certified"]))


def _contact(d: Dict[str, Any]) -> Contact:
    box = lambda k: Box._read(d[k]) if d.get(k) else None  # noqa: E731
    return Contact(
        Fraction(d["lo"]), Fraction(d["hi"]), _mid(d), bool(d["certified"]),
        point=box("point"), normal=box("normal"), point_note=d.get("point_note"),
    )


@dataclass(frozen=True)
class Segment:
    """A piece of the timeline with one ``state`` (``"separate"``,
    ``"touch"`` or ``"overlap"``) from ``start`` to ``end``; an isolated
    contact is a ``"touch"`` segment with ``start == end``."""

    state: str
    start: Time
    end: Time
    certified: bool


@dataclass(frozen=True)
class Gap:
    """A piece ``[lo, hi]`` of the span left undecided within the effort
    budget (helical scenes only), with ``reason``; ``witness`` is ``None``
    or ``(t, state)``: a proven touch/overlap at the exact instant ``t``."""

    lo: Fraction
    hi: Fraction
    reason: str
    witness: Optional[Tuple[Fraction, str]]


class Result:
    """The answer of one query (see docs/scene-format.md for the meaning of
    each field).

    Attributes:
        collision_free: ``True`` when separation over the span is proven,
            ``False`` when a collision is, ``None`` when neither is.
        collision_free_reason: why neither was proven, or ``None``.
        first_contact: the earliest instant the bodies are not separate
            (a ``Contact`` when it is an isolated touch, else a ``Time``),
            ``None`` when they are separate throughout.
        contacts: the isolated instants of external touching, in order.
        timeline: the span cut into ``Segment``s of one state.
        gaps: undecided pieces of the span (helical scenes only).
        complete: the timeline covers the span with no gap.
        certified: everything reported is proven.
        span: ``(t0, t1)`` as ``Fraction``s.
        stats: the engine's counters (a dict).
    """

    _FIELDS = frozenset(
        ("span", "collision_free", "collision_free_reason", "contacts", "first_contact",
         "timeline", "gaps", "complete", "certified", "stats")
    )

    def __init__(self, query: Any, scene_toml: Optional[str], options: Dict[str, Any]) -> None:
        self._query = query
        self._scene_toml = scene_toml
        self._options = dict(options)

    def __getattr__(self, name: str) -> Any:
        # The JSON is written, and the fields read from it, on first use: a
        # caller that only wants to_json() (a batch, a Dask worker) pays
        # nothing for the fields, one that only draws nothing for either.
        if name == "_json":
            self._json = self._query.json()
            return self._json
        if name in Result._FIELDS:
            self._read()
            return self.__dict__[name]
        raise AttributeError(name)

    def _read(self) -> None:
        d = json.loads(self._json)
        self.span: Tuple[Fraction, Fraction] = (Fraction(d["span"][0]), Fraction(d["span"][1]))
        self.collision_free: Optional[bool] = d["collision_free"]
        self.collision_free_reason: Optional[str] = d["collision_free_reason"]
        self.contacts: List[Contact] = [_contact(c) for c in d["contacts"]]
        fc = d["first_contact"]
        self.first_contact: Optional[Time] = None
        if fc is not None:
            t = _time(fc)
            same = (c for c in self.contacts if (c.lo, c.hi) == (t.lo, t.hi))
            self.first_contact = next(same, t)
        self.timeline: List[Segment] = [
            Segment(s["state"], _time(s["start"]), _time(s["end"]), bool(s["certified"]))
            for s in d["timeline"]
        ]
        self.gaps: List[Gap] = [
            Gap(
                Fraction(g["lo"]), Fraction(g["hi"]), g["reason"],
                (Fraction(g["witness"]["t"]), g["witness"]["state"]) if g["witness"] else None,
            )
            for g in d["gaps"]
        ]
        self.complete: bool = d["complete"]
        self.certified: bool = d["certified"]
        self.stats: Dict[str, Any] = d["stats"]

    def to_json(self) -> str:
        """The result as JSON: the text ``ccd-exact SCENE --json`` prints for
        the same scene and options (without its final newline)."""
        return self._json

    def to_dict(self) -> Dict[str, Any]:
        """The JSON result as Python data (times as ``"p/q"`` strings)."""
        return json.loads(self._json)

    def _native(self) -> Any:
        if self._query is None:  # unpickled: answer the same query again
            assert self._scene_toml is not None
            from . import _native

            self._query = _native.run_toml(self._scene_toml, **self._options)
        return self._query

    def to_svg(self, title: str = "") -> str:
        """An SVG picture: the timeline strip (separate / touch / overlap
        coloured, each contact's enclosure marked, the first contact
        labelled) and, per contact, the two ellipsoids cut by the plane
        through the contact point, with the point and the normal."""
        return self._native().svg(title)

    def to_html(self, title: str = "") -> str:
        """A self-contained HTML page animating the two bodies over the span
        (time slider, bodies coloured by state, contacts marked)."""
        return self._native().html(title)

    def plot(self, path: Optional[str] = None, title: str = "") -> str:
        """The SVG picture (``to_svg``), also written to ``path`` when given
        (``.html`` in the name writes the HTML page instead). Needs no
        plotting library; in Jupyter a ``Result`` shows itself as this SVG."""
        text = self.to_html(title) if path and path.endswith(".html") else self.to_svg(title)
        if path:
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
        return text

    def _repr_svg_(self) -> str:
        return self.to_svg()

    def scene_toml(self) -> Optional[str]:
        """The scene file text that was run (``ccd-exact`` reads it too);
        ``None`` for a pair of a world (``WorldResult.world_toml()`` is
        the world's)."""
        return self._scene_toml

    def __reduce__(self) -> Any:
        # A pair of a world keeps its world (which pickles as its text and
        # JSON), for the pictures; a pair query is answered again from its text.
        world_pair = self._query if self._scene_toml is None else None
        return (_unpickle, (self._json, self._scene_toml, self._options, world_pair))

    def __repr__(self) -> str:
        if self.first_contact is not None:
            what = f"first contact t ≈ {self.first_contact.approx!r}"
        elif self.collision_free:
            what = "collision-free"
        else:
            what = "collision-free: not decided"
        contacts = ", ".join(repr(c.approx) for c in self.contacts)
        proven = "certified" if self.certified else "NOT everything certified"
        return f"<ccd_exact.Result: {what}; contacts [{contacts}]; {proven}>"

    def __str__(self) -> str:
        lines = [f"span [{self.span[0]}, {self.span[1]}]"]
        for s in self.timeline:
            mark = "" if s.certified else "  (not proven)"
            lines.append(f"  {s.state:<9} {s.start.approx:>20.12f}  {s.end.approx:>20.12f}{mark}")
        for g in self.gaps:
            lines.append(f"  undecided {float(g.lo):>20.12f}  {float(g.hi):>20.12f}  ({g.reason})")
        if not self.contacts:
            lines.append("contacts: none")
        for k, c in enumerate(self.contacts, 1):
            mark = "" if c.certified else "  (NOT certified)"
            lines.append(f"contact {k} ≈ {c.approx!r}{mark}\n    lo = {c.lo}\n    hi = {c.hi}")
            if c.point is not None and c.normal is not None:
                lines.append(f"    point  ≈ {c.point.approx}\n    normal ≈ {c.normal.approx}")
        if self.first_contact is not None:
            lines.append(f"first contact ≈ {self.first_contact.approx!r}")
        elif self.collision_free:
            lines.append("collision-free over the span")
        if self.collision_free is None:
            lines.append(f"collision-free: NOT decided ({self.collision_free_reason})")
        return "\n".join(lines)


def _unpickle(text: str, scene_toml: Optional[str], options: Dict[str, Any], query: Any = None) -> Result:
    r = Result.__new__(Result)
    r._query = query
    r._scene_toml = scene_toml
    r._options = dict(options)
    r._json = text
    return r
