#!/usr/bin/env bash
# Regenerates every number of docs/table4.md: the exact path (default and
# GMP builds) and the float mode on the benchmark scenes, then prints the
# comparison with the paper's Tables 3 and 4 as markdown (criterion medians).
#
#   bash benches/table4.sh > /tmp/table4.md
set -euo pipefail
cd "$(dirname "$0")/.."
cargo bench -q -p ccd-benches --bench ccd >&2
cargo bench -q -p ccd-benches --bench float >&2
CARGO_TARGET_DIR="$PWD/target/gmp" cargo bench -q -p ccd-benches --bench ccd --features gmp >&2
python3 - <<'PY'
import json, glob, os

def medians(root):
    out = {}
    for f in glob.glob(f"{root}/criterion/**/new/benchmark.json", recursive=True):
        b = json.load(open(f))
        est = json.load(open(os.path.join(os.path.dirname(f), "estimates.json")))
        out[(b["group_id"], b.get("function_id") or "")] = est["median"]["point_estimate"] / 1e6  # ms
    return out

exact, gmp = medians("target"), medians("target/gmp")

def fmt(ms):
    return "—" if ms is None else (f"{ms * 1000:.0f} µs" if ms < 1 else f"{ms:.2f} ms")

rows = [
    ("degree-2 rigid", "rigid-deg2", "4 / 24", 0.11, 18.2),
    ("degree-2 affine", "affine-deg2", "36 / 216", 0.691, 1328.683),
    ("degree-4 affine (rational degree-2 affine)", "affine-rational-deg2", "48 / 288", 12.909, None),
    ("degree 48 / 288 kept (rigid, quaternion degrees 5, 6)", "rigid-288", "48 / 288", 12.909, None),
    ("Example 5.1", "paper-example-5-1", "2 / (sr0 ≡ 0)", None, None),
    ("rigid-tumbling", "rigid-tumbling", "6 / 36", None, None),
]
print("| motion | paper deg f / sr0 | paper float total (T3) | paper exact total (T4) | our float total | our float first contact | our exact total | our exact first contact | our exact total, gmp | exact / float |")
print("|---|---|---|---|---|---|---|---|---|---|")
for label, key, pdeg, pfloat, pexact in rows:
    file = key + ".toml"
    et = exact.get(("ccd exact", f"{file} total"))
    ef = exact.get(("ccd exact", f"{file} first contact"))
    gt = gmp.get(("ccd exact", f"{file} total"))
    ft = exact.get((f"float {key}", "total"))
    ff = exact.get((f"float {key}", "total first contact"))
    ratio = f"{et / ft:.1f}×" if et and ft else "—"
    print(f"| {label} | {pdeg} | {fmt(pfloat)} | {fmt(pexact)} | {fmt(ft)} | {fmt(ff)} | {fmt(et)} | {fmt(ef)} | {fmt(gt)} | {ratio} |")
PY
