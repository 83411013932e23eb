"""Pictures from Python, and results that travel (pickle, as Dask does)."""

from __future__ import annotations

import pickle

import ccd_exact as ccd
from conftest import SCENES


def result():
    return ccd.collide_toml((SCENES[0].parent / "paper-example-5-1.toml").read_text())


def test_svg_and_html(tmp_path):
    r = result()
    svg = r.to_svg("Example 5.1")
    assert svg.startswith("<svg") and "Example 5.1" in svg
    assert svg.count('class="panel"') == len(r.contacts) == 2
    assert "first contact t ≈ 0.539504286780" in svg
    assert r.plot() == r.to_svg() == r._repr_svg_()
    r.plot(str(tmp_path / "q.svg"))
    assert (tmp_path / "q.svg").read_text() == svg.replace("Example 5.1", "ccd-exact")
    r.plot(str(tmp_path / "q.html"))
    assert (tmp_path / "q.html").read_text().startswith("<!doctype html>")


def test_a_result_survives_pickling():
    r = result()
    back = pickle.loads(pickle.dumps(r))
    assert back.to_json() == r.to_json() and back.contacts == r.contacts
    assert back.to_svg() == r.to_svg()  # answered again, the same
