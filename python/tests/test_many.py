"""collide_many: the same answers as one by one, in order, on any number of
threads, with the GIL released."""

from __future__ import annotations

import threading
import time

import ccd_exact as ccd
from conftest import SCENES


def scenes():
    # The quick shipped scenes (the issue-18 stress scenes take seconds each).
    return [ccd.Scene.from_toml(p.read_text()) for p in SCENES if not p.name.startswith("issue-18")]


def test_the_same_answers_in_order_on_any_number_of_threads():
    quick = [s for s in scenes() if "helical" not in s.to_toml()]
    items = scenes() + quick * 4
    one_by_one = [ccd._run(s, ccd._options()).to_json() for s in items]
    for threads in (None, 1, 3):
        got = [r.to_json() for r in ccd.collide_many(items, threads=threads)]
        assert got == one_by_one, threads


def test_tuples_dicts_and_scenes_are_all_pairs():
    a = ccd.Ellipsoid([1, 1, 1])
    b = ccd.Ellipsoid([1, 1, 1], ccd.Translation([[4, 0, 0], [0, 0, 0]]))
    d = {"span": [0, 1], "a": {"radii": [1, 1, 1]},
         "b": {"radii": [1, 1, 1], "motion": {"kind": "translation", "center": [[4, 0, 0], [0, 0, 0]]}}}
    got = ccd.collide_many([(a, b), (a, b, (0, 1)), ccd.Scene(a, b), d], first_contact=True)
    assert len({r.to_json() for r in got}) == 1
    assert got[0].complete is False  # first contact only


def test_the_gil_is_released_while_it_runs():
    # The screw step (about 0.2 s a query) ten times, on one thread.
    items = [s for s in scenes() if "rate = 1.5" in s.to_toml()] * 10
    assert len(items) == 10
    ticks = 0
    worker = threading.Thread(target=ccd.collide_many, args=(items,), kwargs={"threads": 1})
    worker.start()
    while worker.is_alive():
        ticks += 1  # runs only while the native call does not hold the GIL
        time.sleep(0.001)
    worker.join()
    assert ticks > 20, ticks
