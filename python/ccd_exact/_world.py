"""Worlds of many bodies: building one in Python (``World``), and its answer
(``WorldResult``) read from the engine's JSON, the CLI's ``--json`` for a
world file (docs/scene-format.md, "World result")."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union

from ._errors import SceneError
from ._result import Result, Time, _mid
from ._scene import _BARE_KEY, Number, _body, _string, to_toml_value

Bodies = Union[Mapping[str, Any], Iterable[Tuple[str, Any]]]


def _body_path(i: int, name: Any) -> str:
    """The engine's field path of body ``i``: ``body[3] "arm-2"``."""
    if not isinstance(name, str):
        return f"body[{i}]"
    return f"body[{i}] {json.dumps(name, ensure_ascii=False)}"


class World:
    """A world: any number of named bodies over one ``span``, held as the
    exact text of a world file (``[[body]]`` tables; ``to_toml()``), which
    the CLI reads too.

    ``bodies`` is a mapping ``{name: Ellipsoid}`` (in its order) or an
    iterable of ``(name, Ellipsoid)`` pairs; a body may also be a mapping
    with ``radii`` and ``motion`` (a world file's ``[[body]]`` table without
    its ``name``). Names are checked by the engine (non-empty, unique).
    """

    def __init__(self, bodies: Bodies, span: Sequence[Number] = (0, 1)) -> None:
        items = list(bodies.items() if isinstance(bodies, Mapping) else bodies)
        lines = [f"span = {to_toml_value(span, 'span')}"]
        for i, item in enumerate(items):
            if not (isinstance(item, tuple) and len(item) == 2):
                raise SceneError(
                    f"field `body[{i}]`: expected a (name, Ellipsoid) pair, found {type(item).__name__}",
                    f"body[{i}]",
                )
            name, body = item
            path = _body_path(i, name)
            table = _body(body, path)
            lines.append("")
            lines.append("[[body]]")
            lines.append(f"name = {to_toml_value(name, f'body[{i}].name')}")
            for k, v in table.items():
                if not isinstance(k, str):
                    raise SceneError(f"field `{path}`: keys must be strings, found {k!r}", path)
                key = k if _BARE_KEY.match(k) else _string(k, f"{path}.{k}")
                lines.append(f"{key} = {to_toml_value(v, f'{path}.{k}')}")
        if not items:
            lines.append("body = []")
        self._toml = "\n".join(lines) + "\n"

    @classmethod
    def from_toml(cls, text: str) -> "World":
        """A world from a world file's text (checked when it is run)."""
        if not isinstance(text, str):
            raise SceneError(f"a world's TOML text is a str, found {type(text).__name__}")
        world = cls.__new__(cls)
        world._toml = text
        return world

    def to_toml(self) -> str:
        """The world file's text: ``ccd-exact FILE`` gives the same answer."""
        return self._toml

    def __eq__(self, other: object) -> bool:
        return isinstance(other, World) and self._toml == other._toml

    def __hash__(self) -> int:
        return hash(self._toml)

    def __repr__(self) -> str:
        return f"World.from_toml({self._toml!r})"


@dataclass(frozen=True)
class WorldContact(Time):
    """The world's earliest contact: an instant (``lo``, ``hi`` exact
    ``Fraction``s, ``approx``, ``certified``) and the ``pair`` of body names
    ``(a, b)`` (file order) that touch then. ``certified`` is ``False``
    when the pair's instant is not, or when an undecided pair might touch
    before ``hi``."""

    pair: Tuple[str, str] = ("", "")


@dataclass(frozen=True)
class BroadPhase:
    """What the certified broad phase did: ``candidates`` (pairs sent to the
    exact query), ``pruned`` (pairs **proven separate** throughout, never
    queried), ``box_overlaps`` (pairs whose boxes overlap in some slice),
    ``slices`` (the span's sub-intervals)."""

    candidates: int
    pruned: int
    box_overlaps: int
    slices: int


@dataclass(frozen=True)
class WorldPair:
    """One queried candidate pair: the bodies' names ``a`` and ``b`` (file
    order) and its pair ``result`` (a ``Result``; ``result.to_json()`` is
    what ``ccd-exact --json`` prints for the pair scene of the two bodies
    over the world's span), or ``result`` ``None`` and ``error`` saying why
    the pair's query has no answer (e.g. an effort bound)."""

    a: str
    b: str
    result: Optional[Result] = field(default=None, compare=False)
    error: Optional[str] = None

    @property
    def names(self) -> Tuple[str, str]:
        """``(a, b)``."""
        return (self.a, self.b)


class _PairQuery:
    """Pair ``k`` of an answered world, shaped as the pair ``Query`` a
    ``Result`` reads (its JSON and its pictures); it pickles as the world."""

    def __init__(self, world: "WorldResult", k: int) -> None:
        self._world = world
        self._k = k

    def json(self) -> str:
        text = self._world._native().pair_json(self._k)
        if text is None:
            raise ValueError(f"pair {self._k} of the world has no answer")
        return str(text)

    def svg(self, title: str = "") -> str:
        return str(self._world._native().pair_svg(self._k, title))

    def html(self, title: str = "") -> str:
        return str(self._world._native().pair_html(self._k, title))


class WorldResult:
    """The answer for a world (see docs/scene-format.md, "World result").

    Attributes:
        span: ``(t0, t1)`` as ``Fraction``s.
        bodies: the body names, in file order.
        colliding: the pairs of names proven to touch or overlap somewhere
            on the span, ordered by file order.
        undecided: the pairs neither proven separate nor proven colliding.
        first_contact: the world's earliest contact (a ``WorldContact``:
            ``lo``/``hi`` exact, ``pair``), ``None`` when no queried pair
            touches or overlaps.
        pairs: each queried candidate pair (a ``WorldPair`` with its pair
            ``Result``), ordered by file order.
        broad_phase: the broad phase's counts (a ``BroadPhase``).
        complete: every candidate pair was queried over the whole span
            (``False`` with ``first_contact=True``).
        certified: everything reported is proven.
    """

    _FIELDS = frozenset(
        ("span", "bodies", "colliding", "undecided", "first_contact", "pairs",
         "broad_phase", "complete", "certified")
    )

    def __init__(self, query: Any, world_toml: str, options: Dict[str, Any], threads: Optional[int] = None) -> None:
        self._query = query
        self._world_toml = world_toml
        self._options = dict(options)
        self._threads = threads

    def __getattr__(self, name: str) -> Any:
        if name == "_json":
            self._json = str(self._native().json())
            return self._json
        if name in WorldResult._FIELDS:
            self._read()
            return self.__dict__[name]
        raise AttributeError(name)

    def _native(self) -> Any:
        if self._query is None:  # unpickled: answer the same world again
            from . import _native

            self._query = _native.run_world_toml(self._world_toml, threads=self._threads, **self._options)
        return self._query

    def _read(self) -> None:
        d = json.loads(self._json)
        self.span: Tuple[Fraction, Fraction] = (Fraction(d["span"][0]), Fraction(d["span"][1]))
        self.bodies: List[str] = list(d["bodies"])
        self.colliding: List[Tuple[str, str]] = [(a, b) for a, b in d["colliding"]]
        self.undecided: List[Tuple[str, str]] = [(a, b) for a, b in d["undecided"]]
        fc = d["first_contact"]
        self.first_contact: Optional[WorldContact] = None
        if fc is not None:
            self.first_contact = WorldContact(
                Fraction(fc["lo"]), Fraction(fc["hi"]), _mid(fc), bool(fc["certified"]),
                pair=(fc["pair"][0], fc["pair"][1]),
            )
        self.pairs: List[WorldPair] = []
        for k, p in enumerate(d["pairs"]):
            if "error" in p:
                self.pairs.append(WorldPair(p["a"], p["b"], None, p["error"]))
                continue
            r = Result(_PairQuery(self, k), None, self._options)  # type: ignore[arg-type]
            self.pairs.append(WorldPair(p["a"], p["b"], r, None))
        b = d["broad_phase"]
        self.broad_phase: BroadPhase = BroadPhase(
            int(b["candidates"]), int(b["pruned"]), int(b["box_overlaps"]), int(b["slices"])
        )
        self.complete: bool = d["complete"]
        self.certified: bool = d["certified"]

    def pair(self, a: str, b: str) -> Optional[WorldPair]:
        """The queried pair of the bodies named ``a`` and ``b`` (either
        order), ``None`` when it was not queried (the broad phase proved it
        separate throughout or, with ``first_contact=True``, the search did
        not need it)."""
        for p in self.pairs:
            if (p.a, p.b) in ((a, b), (b, a)):
                return p
        return None

    def to_json(self) -> str:
        """The result as JSON: the text ``ccd-exact WORLD --json`` prints
        for the same world and options (without its final newline)."""
        return self._json

    def to_dict(self) -> Dict[str, Any]:
        """The JSON result as Python data (times as ``"p/q"`` strings)."""
        return json.loads(self._json)

    def world_toml(self) -> str:
        """The world file text that was run (``ccd-exact`` reads it too)."""
        return self._world_toml

    def __reduce__(self) -> Any:
        return (_unpickle, (self._json, self._world_toml, self._options, self._threads))

    def __repr__(self) -> str:
        n = len(self.bodies)
        fc = self.first_contact
        what = f"first contact t ≈ {fc.approx!r} ({fc.pair[0]}, {fc.pair[1]})" if fc else "no contact"
        proven = "certified" if self.certified else "NOT everything certified"
        return (
            f"<ccd_exact.WorldResult: {n} bodies; {len(self.colliding)} colliding pairs; "
            f"{what}; {proven}>"
        )

    def __str__(self) -> str:
        bp = self.broad_phase
        lines = [
            f"world of {len(self.bodies)} bodies, span [{self.span[0]}, {self.span[1]}]",
            f"broad phase: {bp.candidates} candidate pairs, {bp.pruned} proven separate",
        ]
        for a, b in self.colliding:
            lines.append(f"  colliding  {a} – {b}")
        for a, b in self.undecided:
            lines.append(f"  undecided  {a} – {b}")
        fc = self.first_contact
        if fc is not None:
            mark = "" if fc.certified else "  (NOT certified)"
            lines.append(f"first contact ≈ {fc.approx!r}: {fc.pair[0]} – {fc.pair[1]}{mark}\n    lo = {fc.lo}\n    hi = {fc.hi}")
        else:
            lines.append("no contact over the span")
        if not self.complete:
            lines.append("(first contact only: later contacts not searched)")
        return "\n".join(lines)


def _unpickle(text: str, world_toml: str, options: Dict[str, Any], threads: Optional[int]) -> WorldResult:
    r = WorldResult(None, world_toml, options, threads)
    r._json = text
    return r


__all__ = ["BroadPhase", "World", "WorldContact", "WorldPair", "WorldResult"]
