"""Shard a JSON Lines file of pair scenes across a Dask cluster.

Each line is one pair scene with the structure of a scene file, e.g.
``{"span": [0, 1], "a": {"radii": [2, 1, 1], "motion": {...}}, "b": {...}}``
(numbers as JSON integers, decimals read exactly, or "p/q" strings). The
file is cut into shards of consecutive lines; each Dask task answers one
shard with ``ccd_exact.collide_many`` and returns one compact JSON result
per line (the CLI's ``--json`` object, or ``{"line": n, "error": ...,
"field": ...}`` for a bad line); the results are gathered in file order.

    # a local cluster of 2 worker processes (the test does this):
    python examples/dask_shards.py python/tests/data/pairs.jsonl --workers 2
    # a real cluster: the same code, given the scheduler's address
    python examples/dask_shards.py pairs.jsonl --scheduler tcp://host:8786 --out results.jsonl

Every worker needs the ``ccd_exact`` package installed (``pip install ./python``).
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from typing import Any, Dict, List, Sequence, Tuple

Shard = Tuple[int, List[str]]


def read_lines(path: str) -> List[str]:
    """The non-blank lines of a JSON Lines file."""
    with open(path, encoding="utf-8") as f:
        return [line for line in f.read().splitlines() if line.strip()]


def shards(lines: Sequence[str], size: int) -> List[Shard]:
    """Consecutive pieces of ``size`` lines, each with its first line's index."""
    return [(i, list(lines[i : i + size])) for i in range(0, len(lines), size)]


def answer_shard(shard: Shard, options: Dict[str, Any]) -> List[str]:
    """One compact JSON result per line of the shard (runs on a worker)."""
    import ccd_exact

    first, lines = shard
    compact = lambda text: json.dumps(json.loads(text), separators=(",", ":"))  # noqa: E731
    try:
        scenes = [ccd_exact.Scene.from_json(line) for line in lines]
        return [compact(r.to_json()) for r in ccd_exact.collide_many(scenes, threads=1, **options)]
    except ccd_exact.SceneError:
        pass  # some line is bad: answer line by line, reporting the bad ones
    out = []
    for n, line in enumerate(lines, first):
        try:
            out.append(compact(ccd_exact.collide_json(line, **options).to_json()))
        except (ccd_exact.SceneError, ccd_exact.EffortError) as e:
            out.append(json.dumps({"line": n, "error": str(e), "field": e.field}, separators=(",", ":")))
    return out


def run_on_cluster(client: Any, lines: Sequence[str], shard_size: int = 50, **options: Any) -> List[str]:
    """The results of all lines, computed by the cluster behind ``client``."""
    futures = client.map(answer_shard, shards(lines, shard_size), options=options, pure=False)
    return [r for part in client.gather(futures) for r in part]


def run_single_process(lines: Sequence[str], **options: Any) -> List[str]:
    """The same results in this process: the baseline the cluster must equal."""
    return answer_shard((0, list(lines)), options)


def main(argv: Sequence[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("pairs", help="JSON Lines file of pair scenes")
    p.add_argument("--scheduler", help="address of a running Dask scheduler (default: a LocalCluster)")
    p.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (default 2)")
    p.add_argument("--shard-size", type=int, default=50, help="lines per task (default 50)")
    p.add_argument("--digits", type=int, default=15)
    p.add_argument("--out", help="write the results here (JSON Lines, in input order)")
    args = p.parse_args(argv)

    from dask.distributed import Client, LocalCluster

    lines = read_lines(args.pairs)
    if args.scheduler:
        client = Client(args.scheduler)
        cluster = None
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True)
        client = Client(cluster)
    try:
        workers = len(client.scheduler_info()["workers"])
        run_on_cluster(client, lines[: args.shard_size], args.shard_size, digits=args.digits)  # warm up
        start = time.perf_counter()
        results = run_on_cluster(client, lines, args.shard_size, digits=args.digits)
        secs = time.perf_counter() - start
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    rate = len(lines) / secs
    print(f"{len(lines)} pairs on {workers} worker(s) in {secs:.2f} s: "
          f"{rate:.0f} pairs/s, {rate / workers:.0f} pairs/s per worker", file=sys.stderr)
    text = "\n".join(results) + "\n"
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
