"""ccd_exact: exact, certified continuous collision detection for moving
ellipsoids (after Jia, Choi, Mourrain & Wang, CAGD 2011), from Python.

Build two moving ellipsoids and ask when they touch::

    >>> import ccd_exact as ccd
    >>> a = ccd.Ellipsoid([2, 1, 1], ccd.Translation([[11, 0, 0], [-1, 0, 0]]))
    >>> b = ccd.Ellipsoid([2, 1, 1], ccd.Translation([[3, -2, -4], [3, 2, 0]]))
    >>> r = ccd.collide(a, b)                     # the paper's Example 5.1
    >>> [s.state for s in r.timeline]
    ['separate', 'touch', 'overlap', 'touch', 'separate']
    >>> t1 = r.contacts[0]                        # lo, hi: exact Fractions
    >>> t1.lo <= ccd.Fraction(5395042868, 10**10) <= t1.hi + ccd.Fraction(1, 10**10)
    True

Numbers are exact: ``int``, ``Fraction``, ``Decimal``, strings such as
``"1/3"`` or ``"1e-20"``, and ``float`` taken as its exact binary value
(``0.1`` is 3602879701896397/36028797018963968; write ``"0.1"`` for 1/10).
Control points may be lists or numpy arrays. Every scene goes to the engine
as a scene file's text (``Scene(a, b).to_toml()``), so ``ccd-exact FILE``
gives the same answer, and a bad scene raises ``SceneError`` (a
``ValueError``) naming the field, e.g. ``a.radii[0]``.

A **world** of many named bodies (a world file's ``[[body]]`` tables,
docs/worlds.md) is answered by ``collide_world({"left": a, "right": b,
...})`` or ``collide_world_toml(text)``: a certified broad phase, then the
exact pair query on every candidate pair on all cores::

    >>> w = ccd.collide_world({"left": a, "right": b, "far": ccd.Ellipsoid([1, 1, 1], ccd.Static([50, 0, 0]))})
    >>> w.colliding, w.first_contact.pair, w.broad_phase.pruned
    ([('left', 'right')], ('left', 'right'), 2)

``from ccd_exact import fcl`` is a python-fcl-shaped entry
(``continuousCollide`` over ``Ellipsoid``, ``Transform``,
``CollisionObject``).
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any, Iterable, List, Optional, Sequence, Union

from . import _native
from ._errors import EffortError, SceneError
from ._result import Box, Contact, Gap, Result, Segment, Time
from ._scene import (
    Affine,
    Ellipsoid,
    Helical,
    Motion,
    Number,
    Rigid,
    Scene,
    Static,
    Translation,
)
from ._world import BroadPhase, World, WorldContact, WorldPair, WorldResult

__all__ = [
    "Affine", "Box", "BroadPhase", "Contact", "EffortError", "Ellipsoid",
    "Fraction", "Gap", "Helical", "Motion", "Number", "Result", "Rigid",
    "Scene", "SceneError", "Segment", "Static", "Time", "Translation", "World",
    "WorldContact", "WorldPair", "WorldResult", "collide", "collide_json",
    "collide_many", "collide_toml", "collide_world", "collide_world_toml",
]
__version__: str = _native.__version__

MAX_DIGITS = 1000
"""The largest ``digits`` accepted (as the CLI's ``--digits``)."""


def _options(
    first_contact: Any = False, digits: Any = 15, arithmetic: Any = "exact", geometry: Any = True, raycast: Any = False
) -> dict:
    """The query options, checked; a bad one raises ``ValueError`` naming it."""
    for name, value in (("first_contact", first_contact), ("geometry", geometry), ("raycast", raycast)):
        if not isinstance(value, bool):
            raise ValueError(f"option `{name}`: expected True or False, found {value!r}")
    if isinstance(digits, bool) or not isinstance(digits, int) or not 0 <= digits <= MAX_DIGITS:
        raise ValueError(f"option `digits`: expected a whole number from 0 to {MAX_DIGITS}, found {digits!r}")
    if arithmetic not in ("exact", "float"):
        raise ValueError(f'option `arithmetic`: expected "exact" or "float", found {arithmetic!r}')
    return {
        "first_contact": first_contact,
        "digits": digits,
        "arithmetic": arithmetic,
        "geometry": geometry,
        "raycast": raycast,
    }


def _scene(item: Any) -> Scene:
    if isinstance(item, Scene):
        return item
    if isinstance(item, tuple) and len(item) in (2, 3):
        return Scene(*item)
    if isinstance(item, dict):
        return Scene.from_dict(item)
    raise SceneError(
        f"expected a Scene, an (a, b) or (a, b, span) tuple, or a scene dict, found {type(item).__name__}"
    )


def collide(
    a: Ellipsoid,
    b: Ellipsoid,
    span: Sequence[Number] = (0, 1),
    first_contact: bool = False,
    digits: int = 15,
    arithmetic: str = "exact",
    geometry: bool = True,
    raycast: bool = False,
) -> Result:
    """When do the moving ellipsoids ``a`` and ``b`` touch or overlap over
    ``span = (t0, t1)``?

    Args:
        a, b: the two ``Ellipsoid``s (their fields are named ``a.…``/``b.…``
            in errors).
        span: the time interval, ``t0 < t1``.
        first_contact: stop at the earliest instant they are not separate.
        digits: enclose each contact instant to ``10**-digits`` of the span.
        arithmetic: ``"exact"`` (every answer certified) or ``"float"`` (the
            paper's f64 solver: faster, NOT certified; rational motions only).
        geometry: compute each contact's point and normal.
        raycast: bodies that only translate along straight lines are
            answered by a certified ray cast into their Minkowski difference
            (microseconds; instants with float ends), the rest, and what it
            cannot prove, by the exact path (docs/raycast.md).

    Returns:
        a ``Result``; ``result.to_json()`` is what ``ccd-exact --json`` prints.

    Raises:
        SceneError: an invalid scene (``ValueError``; ``.field`` names it).
        ValueError: an option out of range.
        EffortError: the exact path's documented effort bound was reached.
    """
    return _run(Scene(a, b, span), _options(first_contact, digits, arithmetic, geometry, raycast))


def collide_toml(text: str, **options: Any) -> Result:
    """``collide`` on a pair scene file's text (TOML, docs/scene-format.md),
    with the same keyword options as ``collide``. A world file (``[[body]]``
    tables) raises ``SceneError`` (field ``body``) naming
    ``collide_world_toml``, which answers it."""
    return _run(Scene.from_toml(text), _options(**options))


def collide_json(scene: Union[str, bytes, dict], **options: Any) -> Result:
    """``collide`` on a scene given as JSON text (e.g. one line of a JSON
    Lines file) or a dict with the structure of a scene file:
    ``{"span": [0, 1], "a": {"radii": [...], "motion": {...}}, "b": {...}}``.
    Same keyword options as ``collide``."""
    return _run(Scene.from_json(scene), _options(**options))


def collide_many(
    pairs: Iterable[Any], threads: Optional[int] = None, **options: Any
) -> List[Result]:
    """Answers many pair queries in parallel on ``threads`` threads (default:
    one per core), with the GIL released; results in the order given.

    Each item is a ``Scene``, an ``(a, b)`` or ``(a, b, span)`` tuple, or a
    scene dict. Keyword options as ``collide``. The first invalid scene (in
    order) raises, its index in the message (``pairs[3]: field …``).
    For many bodies that may all meet each other, a world
    (``collide_world``) proves most pairs separate without querying them.
    """
    _threads(threads)
    opts = _options(**options)
    scenes = []
    for i, item in enumerate(pairs):
        try:
            scenes.append(_scene(item))
        except SceneError as e:
            raise SceneError(f"pairs[{i}]: {e}", e.field) from None
    texts = [s.to_toml() for s in scenes]
    queries = _native.run_many(texts, threads=threads, **opts)
    return [Result(q, t, opts) for q, t in zip(queries, texts)]


def collide_world(
    bodies: Any,
    span: Sequence[Number] = (0, 1),
    threads: Optional[int] = None,
    **options: Any,
) -> WorldResult:
    """Every pair of a world of many moving ellipsoids over ``span``: which
    pairs ever touch or overlap, when the world's first contact is and
    between whom, and each candidate pair's full result.

    Args:
        bodies: ``{name: Ellipsoid}`` (in its order) or an iterable of
            ``(name, Ellipsoid)`` pairs; names are non-empty and unique
            (errors name the body: ``body[3] "arm-2".motion.center[1]``).
        span: the time interval, ``t0 < t1``.
        threads: worker threads for the pairs (default: one per core).
        **options: as ``collide``; ``first_contact=True`` finds the world's
            earliest contact and queries only the pairs that search needs.

    Returns:
        a ``WorldResult``; ``to_json()`` is what ``ccd-exact WORLD --json``
        prints for ``World(bodies, span).to_toml()``.

    Raises:
        SceneError, ValueError, EffortError: as ``collide`` (``EffortError``
        also when more pairs than the broad phase's cap of 500000 cannot
        be proven separate).
    """
    return _run_world(World(bodies, span), threads, options)


def collide_world_toml(text: str, threads: Optional[int] = None, **options: Any) -> WorldResult:
    """``collide_world`` on a world file's text (TOML with ``[[body]]``
    tables, docs/scene-format.md), the same keyword options. A pair file
    (``[a]``, ``[b]``) raises ``SceneError`` (field ``body``) naming
    ``collide_toml``."""
    return _run_world(World.from_toml(text), threads, options)


def _threads(threads: Any) -> None:
    if threads is not None and (isinstance(threads, bool) or not isinstance(threads, int) or threads < 1):
        raise ValueError(f"option `threads`: expected None or a whole number >= 1, found {threads!r}")


def _run_world(world: World, threads: Optional[int], options: dict) -> WorldResult:
    _threads(threads)
    opts = _options(**options)
    text = world.to_toml()
    return WorldResult(_native.run_world_toml(text, threads=threads, **opts), text, opts, threads)


def _run(scene: Scene, opts: dict) -> Result:
    text = scene.to_toml()
    return Result(_native.run_toml(text, **opts), text, opts)
