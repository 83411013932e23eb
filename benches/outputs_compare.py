#!/usr/bin/env python3
"""Compares two `benches/outputs.sh` files by meaning, for a change that
is allowed to move rational bounds but not answers.

    python3 benches/outputs_compare.py OLD.txt NEW.txt

Exact and first-contact runs: the same JSON apart from the rational bounds
and `approx` strings; each old and new interval (instants, point and
normal boxes) intersect (both hold the same true value); every contact
instant meets the default goal (width <= 1e-15 of the span [0, 1]).
Float runs (not certified): the verdict and contact count against the
exact run of the same scene, old and new, and the first contact's distance
to the exact one. Exit status 1 when an exact run breaks a rule.
"""
import json
import sys
from fractions import Fraction as F


def blocks(path):
    runs, cur = {}, None
    for line in open(path):
        if line.startswith("== "):
            cur = line[3:].rstrip("\n").strip()
            runs[cur] = []
        else:
            runs[cur].append(line)
    return {k: "".join(v) for k, v in runs.items()}


def parse(text):
    try:
        return json.loads(text.rsplit("exit", 1)[0])
    except ValueError:
        return None


def walk(a, b, path, out):
    """Differences between old `a` and new `b` beyond rational bounds."""
    if isinstance(a, dict) and isinstance(b, dict):
        if set(a) != set(b):
            out["problems"].append(f"{path}: keys differ")
            return
        if "lo" in a and "hi" in a:
            los = a["lo"] if isinstance(a["lo"], list) else [a["lo"]]
            his = a["hi"] if isinstance(a["hi"], list) else [a["hi"]]
            nlos = b["lo"] if isinstance(b["lo"], list) else [b["lo"]]
            nhis = b["hi"] if isinstance(b["hi"], list) else [b["hi"]]
            for la, ha, lb, hb in zip(los, his, nlos, nhis):
                la, ha, lb, hb = map(F, (la, ha, lb, hb))
                if max(la, lb) > min(ha, hb):
                    out["problems"].append(f"{path}: old and new intervals disjoint")
                if not isinstance(a["lo"], list):
                    out["widths"].append((path, hb - lb))
            rest = [k for k in a if k not in ("lo", "hi", "approx")]
        else:
            rest = list(a)
        for k in rest:
            walk(a[k], b[k], f"{path}.{k}", out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out["problems"].append(f"{path}: lengths differ")
            return
        for i, (x, y) in enumerate(zip(a, b)):
            walk(x, y, f"{path}[{i}]", out)
    elif a != b:
        out["problems"].append(f"{path}: {a!r} -> {b!r}")


def main(old_path, new_path):
    old, new = blocks(old_path), blocks(new_path)
    changed = [k for k in old if old[k] != new.get(k)]
    print(f"{len(old)} runs, {len(changed)} changed")
    bad, flips = 0, []
    for k in changed:
        a, b = parse(old[k]), parse(new.get(k, ""))
        if a is None or b is None:
            print(f"  {k}: not JSON")
            bad += 1
            continue
        if "--arithmetic float" not in k:
            out = {"problems": [], "widths": []}
            walk(a, b, k, out)
            wide = [p for p, w in out["widths"] if w > F(1, 10**15)]
            widest = max((w for _, w in out["widths"]), default=0)
            print(f"  exact {k}: {len(out['widths'])} instants, widest {float(widest):.2g}, "
                  f"{len(out['problems'])} differences, {len(wide)} past the goal")
            for p in out["problems"][:5] + wide[:5]:
                print(f"    {p}")
            bad += len(out["problems"]) + len(wide)
            continue
        exact = parse(new.get(k.replace(" --arithmetic float", ""), ""))
        if exact is None:
            continue
        truth = (exact["collision_free"], len(exact["contacts"]))
        before = (a["collision_free"], len(a["contacts"]))
        after = (b["collision_free"], len(b["contacts"]))
        if before != after:
            flips.append((k, before == truth, after == truth))
    right_before = sum(1 for _, x, _ in flips if x)
    right_after = sum(1 for _, _, y in flips if y)
    print(f"float answers changed on {len(flips)} runs: right before {right_before}, after {right_after}")
    for k, x, y in flips:
        print(f"  {k}: {'right' if x else 'wrong'} -> {'right' if y else 'wrong'}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))
