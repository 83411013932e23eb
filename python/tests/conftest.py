"""Shared fixtures: the repository, its shipped scenes, the CLI binary."""

from __future__ import annotations

import os
import re
import shutil
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
_WORLD = re.compile(r"^\s*(\[\[body\]\]|body\s*=)", re.M)
_FILES = sorted((ROOT / "tests" / "scenes").glob("*.toml"))
# Pair scenes (`[a]`, `[b]`) and world files (`[[body]]` tables).
SCENES = [p for p in _FILES if not _WORLD.search(p.read_text())]
WORLDS = [p for p in _FILES if _WORLD.search(p.read_text())]
PAIRS = Path(__file__).resolve().parent / "data" / "pairs.jsonl"


def _find_cli() -> str | None:
    given = os.environ.get("CCD_EXACT_BIN")
    if given:
        return given
    dirs = [os.environ.get("CARGO_TARGET_DIR"), str(ROOT / "target")]
    for d in filter(None, dirs):
        for profile in ("release", "debug"):
            p = Path(d) / profile / "ccd-exact"
            if p.exists():
                return str(p)
    return shutil.which("ccd-exact")


@pytest.fixture(scope="session")
def cli() -> str:
    """The `ccd-exact` binary (CCD_EXACT_BIN, else target/release or debug)."""
    path = _find_cli()
    if os.environ.get("CCD_EXACT_BIN") and not Path(path).exists():
        pytest.fail(f"CCD_EXACT_BIN={path} does not exist")
    if path is None:
        pytest.skip("the ccd-exact binary is not built (cargo build --release, or set CCD_EXACT_BIN)")
    return path
