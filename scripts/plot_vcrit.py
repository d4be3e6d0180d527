#!/usr/bin/env python3
"""Outcome of every run of a v_crit search (broken / not broken vs speed).
Usage: plot_vcrit.py OUTDIR   (reads OUTDIR/vcrit.json, writes OUTDIR/vcrit.png)"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from plot_save import save


def main(outdir):
    with open(os.path.join(outdir, "vcrit.json")) as f:
        r = json.load(f)
    v = [x["v"] for x in r["runs"]]
    b = [1 if x["broken"] else 0 for x in r["runs"]]
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.6))
    for a, (lo, hi) in zip(ax, [(min(v), max(v)), (r["bracket"][0] - 10 * (r["bracket"][1] - r["bracket"][0]),
                                                  r["bracket"][1] + 10 * (r["bracket"][1] - r["bracket"][0]))]):
        a.scatter(v, b, c=["tab:red" if x else "tab:blue" for x in b], zorder=3)
        a.axvline(r["v_crit"], color="k", ls="--", label=f"v_crit = {r['v_crit']:.4f} m/s")
        a.set_xlim(lo, hi)
        a.set_yticks([0, 1], ["intact", "broken"])
        a.set_xlabel("projectile speed [m/s]")
        a.grid(alpha=0.3)
    ax[0].legend(loc="center right")
    ax[1].set_title("zoom on the bracket")
    fig.tight_layout()
    save(fig, outdir, "vcrit.png", 110)


if __name__ == "__main__":
    main(sys.argv[1])
