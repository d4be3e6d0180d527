#!/usr/bin/env python3
"""Break-up probability vs projectile speed with Wilson 95 % intervals.
Usage: plot_breakup.py OUTDIR   (reads OUTDIR/breakup.json, writes OUTDIR/breakup.png)"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from plot_save import save


def main(outdir):
    with open(os.path.join(outdir, "breakup.json")) as f:
        r = json.load(f)
    v = [p["speed"] for p in r["points"]]
    p = [p["p_break"] for p in r["points"]]
    lo = [pt["p_break"] - pt["ci95"][0] for pt in r["points"]]
    hi = [pt["ci95"][1] - pt["p_break"] for pt in r["points"]]
    fig, ax = plt.subplots(figsize=(6, 3.8))
    ax.errorbar(v, p, yerr=[lo, hi], fmt="o-", capsize=3, label=f"{len(r['offsets_radii'])} offsets per speed")
    if r["v50"] is not None:
        ax.axvline(r["v50"], color="k", ls="--", label=f"v50 = {r['v50']:.4f} m/s")
    ax.set_ylim(-0.03, 1.03)
    ax.set_xlabel("projectile speed [m/s]")
    ax.set_ylabel("break-up probability")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right")
    fig.tight_layout()
    save(fig, outdir, "breakup.png", 110)


if __name__ == "__main__":
    main(sys.argv[1])
