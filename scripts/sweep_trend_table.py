#!/usr/bin/env python3
"""The trend table of a sweep with seeds (agglo sweep ... --seeds N), as in docs/acoustics.md "The trends
with error bars": for every point, the mean and standard error of a summary column (sweep_ensemble.csv),
member 0's value and its distance from the mean in standard errors, and the gain over the previous point
with the standard error of the N per-seed differences (the points share their seeds, so the differences
are paired). Usage: sweep_trend_table.py OUTDIR KEY [COLUMN=fine_efficiency] [SCALE=1]
(SCALE multiplies the swept value in the printout, e.g. 1e6 for metres -> micrometres)."""
import csv
import math
import sys


def mean_stderr(x):
    m = sum(x) / len(x)
    return m, math.sqrt(sum((v - m) ** 2 for v in x) / (len(x) - 1) / len(x))


def main(out, key, col="fine_efficiency", scale=1.0):
    runs = list(csv.DictReader(open(f"{out}/sweep.csv")))
    points = list(csv.DictReader(open(f"{out}/sweep_ensemble.csv")))
    n = int(points[0]["members"])
    previous = None
    for i, p in enumerate(points):
        x = [float(r[col]) for r in runs[n * i:n * i + n]]
        m, se = float(p[col + "_mean"]), float(p[col + "_stderr"])
        line = (f"{float(p[key]) * scale:g}: mean {m:.5f} ± {se:.5f} (s.d. {se * math.sqrt(n):.5f}); "
                f"member 0 {x[0]:.5f} ({(x[0] - m) / se:+.1f} s.e.)")
        if previous is not None:
            dm, dse = mean_stderr([a - b for a, b in zip(x, previous)])
            line += f"; gain {100 * dm:+.2f} ± {100 * dse:.2f} points (paired)"
        print(line)
        previous = x


if __name__ == "__main__":
    a = sys.argv[1:]
    main(a[0], a[1], a[2] if len(a) > 2 else "fine_efficiency", float(a[3]) if len(a) > 3 else 1.0)
