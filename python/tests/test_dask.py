"""The Dask example on a LocalCluster of 2 workers equals the single-process
run of the same package over the same file."""

from __future__ import annotations

import importlib.util
import json

import pytest

from conftest import PAIRS, ROOT

distributed = pytest.importorskip("dask.distributed")


def example():
    spec = importlib.util.spec_from_file_location("dask_shards", ROOT / "examples" / "dask_shards.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_two_workers_equal_the_single_process_batch():
    shards = example()
    lines = shards.read_lines(str(PAIRS))
    assert len(lines) == 1000
    # One bad line in the middle: reported in place, by line and field.
    lines = lines[:500] + ['{"a": {"radii": [1, 1, 0]}, "b": {"radii": [1, 1, 1]}}'] + lines[500:]
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        spread = client.run(lambda: 1)
        assert len(spread) == 2
        got = shards.run_on_cluster(client, lines, shard_size=37)
    want = shards.run_single_process(lines)
    assert got == want
    assert len(got) == len(lines)
    bad = json.loads(got[500])
    assert bad["line"] == 500 and bad["field"] == "a.radii[2]"
    answers = [json.loads(g) for g in got[:500] + got[501:]]
    assert all(a["format"] == 1 for a in answers)
    # Not all the same answer: the file has both kinds.
    assert {a["collision_free"] for a in answers} == {True, False}
