"""Minima of `examples/speed` medians over alternated passes, as a table.

Input lines are `LABEL<TAB>` followed by a line of `speed`'s output (scene,
exact µs, first contact µs, float µs, …); one row per label and one column
per scene, both in order of first appearance, each cell the minimum over
the passes of the exact and the float medians and their ratio (this host
has slow spells lasting seconds, which the minimum of short alternated
medians rides out). Used by benches/pgo.sh and benches/layouts.sh.

    python3 benches/minima.py FILE.tsv
"""

import collections
import sys


def minima(path):
    """{label: {scene: (exact, float)}}, the minima over the passes."""
    runs = collections.defaultdict(lambda: collections.defaultdict(lambda: ([], [])))
    with open(path) as lines:
        for line in lines:
            f = line.split("\t")
            exact, float_ = runs[f[0]][f[1]]
            exact.append(float(f[2]))
            float_.append(float(f[4]))
    return {
        label: {s: (min(e), min(fl)) for s, (e, fl) in scenes.items()}
        for label, scenes in runs.items()
    }


def print_table(table, rows="build"):
    """The markdown table of `minima`'s result (its labels headed `rows`),
    with its legend."""
    scenes = list(dict.fromkeys(s for row in table.values() for s in row))
    print(f"| {rows} | " + " | ".join(s.replace(".toml", "") for s in scenes) + " |")
    print("|---|" + "---|" * len(scenes))
    for label, row in table.items():
        cells = [f"{row[s][0]:.1f} / {row[s][1]:.1f} = {row[s][0] / row[s][1]:.2f}" for s in scenes]
        print(f"| {label} | " + " | ".join(cells) + " |")
    print()
    print("exact µs / float µs = ratio (minima over the passes of the medians)")


if __name__ == "__main__":
    print_table(minima(sys.argv[1]))
