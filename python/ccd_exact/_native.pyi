"""Type stubs of the Rust half (``ccd_exact._native``); use ``ccd_exact``."""

from typing import List, Optional

__version__: str

class Query:
    """One answered query (opaque): its JSON and its pictures."""

    def json(self) -> str: ...
    def svg(self, title: str = "") -> str: ...
    def html(self, title: str = "") -> str: ...

class WorldQuery:
    """One answered world (opaque): its JSON, and each queried pair's JSON and pictures."""

    def json(self) -> str: ...
    def pair_json(self, k: int) -> Optional[str]: ...
    def pair_svg(self, k: int, title: str = "") -> str: ...
    def pair_html(self, k: int, title: str = "") -> str: ...

def run_toml(
    text: str,
    first_contact: bool = False,
    digits: int = 15,
    arithmetic: str = "exact",
    geometry: bool = True,
    raycast: bool = False,
) -> Query: ...
def run_many(
    texts: List[str],
    threads: Optional[int] = None,
    first_contact: bool = False,
    digits: int = 15,
    arithmetic: str = "exact",
    geometry: bool = True,
    raycast: bool = False,
) -> List[Query]: ...
def run_world_toml(
    text: str,
    threads: Optional[int] = None,
    first_contact: bool = False,
    digits: int = 15,
    arithmetic: str = "exact",
    geometry: bool = True,
    raycast: bool = False,
) -> WorldQuery: ...
def median_run_seconds(text: str, reps: int = 100) -> float: ...
