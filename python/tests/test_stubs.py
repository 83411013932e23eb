"""The type stubs cover the public API: every exported name is declared."""

from __future__ import annotations

import ast
from pathlib import Path

import ccd_exact
from ccd_exact import _native, fcl


def declared(module) -> set:
    stub = Path(module.__file__).with_suffix(".pyi")
    if stub.name.startswith("_native"):
        stub = Path(ccd_exact.__file__).parent / "_native.pyi"
    tree = ast.parse(stub.read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            names.add(node.name)
        elif isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            names |= {t.id for t in targets if isinstance(t, ast.Name)}
        elif isinstance(node, ast.ImportFrom):
            names |= {a.asname or a.name for a in node.names}
    return names


def test_every_public_name_has_a_stub():
    for module in (ccd_exact, fcl):
        missing = set(module.__all__) - declared(module)
        assert not missing, (module.__name__, missing)
    native = {n for n in dir(_native) if not n.startswith("_")} | {"__version__"}
    assert native - declared(_native) == set()


def test_the_stub_files_ship_in_the_package():
    here = Path(ccd_exact.__file__).parent
    for name in ("__init__.pyi", "fcl.pyi", "_native.pyi", "py.typed"):
        assert (here / name).exists(), name
