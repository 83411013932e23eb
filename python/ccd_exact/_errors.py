"""The exceptions of ``ccd_exact`` (raised by the Python half and the Rust half alike)."""

from __future__ import annotations

from typing import Optional


class SceneError(ValueError):
    """An invalid scene or body: the message names the field.

    ``field`` is the offending field as a dotted path with indices, the same
    as the scene file format's (``"a.radii[0]"``, ``"b.motion.center[1][2]"``,
    ``"span"``), or ``None`` when the text is not TOML/JSON at all.
    """

    def __init__(self, message: str, field: Optional[str] = None) -> None:
        super().__init__(message)
        self.field = field


class EffortError(RuntimeError):
    """The exact path reached one of its documented bounds (docs/termination.md):
    the scene's numbers are too long for its degrees to be answered exactly."""

    def __init__(self, message: str, field: Optional[str] = None) -> None:
        super().__init__(message)
        self.field = field
