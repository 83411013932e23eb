"""One run of `examples/speed` (examples/speed.rs), parsed: the timings
that benches/compare/compare.py and benches/targets.py read.

`speed` prints a header line, then per scene: name, exact total, exact
first contact, float total (µs, medians), the ratio, deg f, deg sr0,
whether sr0 was formed, `--raycast` total and first contact, and the path
that answered `--raycast` (`raycast`, or `exact` where it handed the query
on; `error`).
"""

import os
import subprocess
import sys

# The timing columns (after the scene's name), by what they hold.
COLUMNS = {"exact": 1, "first": 2, "float": 3, "ray": 8, "ray_first": 9}
RAYCAST_PATH = 10


def speed(binary, reps, paths, root):
    """One run of `binary` (`examples/speed`) with `--reps reps` over
    `paths` (relative to `root`): {scene file name: {column of COLUMNS: µs,
    "path": the path that answered --raycast}}. `speed` leaves out a scene
    it cannot run (and says so on stderr): that ends the caller, with its
    message, rather than a table over fewer scenes."""
    out = subprocess.run(
        [binary, "--reps", str(reps), *paths], cwd=root, capture_output=True, text=True, check=True
    )
    rows = {}
    for line in out.stdout.splitlines()[1:]:
        cols = line.split("\t")
        row = {key: float(cols[i]) for key, i in COLUMNS.items()}
        row["path"] = cols[RAYCAST_PATH]
        rows[cols[0]] = row
    missing = [p for p in paths if os.path.basename(p) not in rows]
    if missing or any(row["path"] == "error" for row in rows.values()):
        sys.exit(f"examples/speed did not time {', '.join(missing) or 'every mode'}:\n{out.stderr}")
    return rows
