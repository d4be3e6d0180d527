#!/usr/bin/env python3
"""Maps of a calibration (agglo calibrate): each observable over the parameter range or plane, the
mapped runs (open markers: rejected by the robust surrogate), the target value with its tolerance band
or contours, and the best fit.
Usage: plot_calibration.py OUTDIR   (reads calibration.json, calibration_points.csv and
calibration_surface.csv, writes OUTDIR/calibration.png)"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from plot_save import save


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) if r[k] not in ("", "nan") else np.nan for r in rows]) for k in rows[0]}


def panel_1d(ax, k, cal, pts, surf):
    par, tgt = cal["parameters"][0], cal["targets"][k]
    x = surf["x0"]
    ax.plot(x, surf[f"surrogate{k}"], "k-", lw=1, label="surrogate")
    w = pts[f"weight{k}"]
    ax.scatter(pts["x0"][w > 0.5], pts[f"obs{k}"][w > 0.5], c="tab:blue", zorder=3, label="runs")
    ax.scatter(pts["x0"][w <= 0.5], pts[f"obs{k}"][w <= 0.5], facecolors="none", edgecolors="tab:red", zorder=3,
               label="runs rejected as off the trend")
    ax.axhspan(tgt["value"] - tgt["tolerance"], tgt["value"] + tgt["tolerance"], color="tab:green", alpha=0.2,
               label="target ± tolerance")
    ax.axvline(par["best"], color="k", ls="--", label=f"fit {par['best']:.4g}")
    if par["scale"] == "log":
        ax.set_xscale("log")
    ax.set_xlabel(par["key"])
    ax.set_ylabel(f"{tgt['observable']} [m/s]")
    ax.set_title(tgt["name"], fontsize=9)
    ax.legend(fontsize=7)


def panel_2d(ax, k, cal, pts, surf):
    p0, p1, tgt = cal["parameters"][0], cal["parameters"][1], cal["targets"][k]
    n = int(round(np.sqrt(len(surf["x0"]))))
    X, Y = surf["x0"].reshape(n, n), surf["x1"].reshape(n, n)
    Z = surf[f"surrogate{k}"].reshape(n, n)
    m = ax.pcolormesh(X, Y, Z, shading="auto", cmap="viridis")
    plt.colorbar(m, ax=ax, label=f"{tgt['observable']} [m/s]")
    ax.contour(X, Y, Z, levels=[tgt["value"]], colors="w", linewidths=1.5)
    ax.contour(X, Y, Z, levels=[tgt["value"] - tgt["tolerance"], tgt["value"] + tgt["tolerance"]], colors="w",
               linestyles="--", linewidths=0.8)
    w = pts[f"weight{k}"]
    ax.scatter(pts["x0"][w > 0.5], pts["x1"][w > 0.5], s=8, c="k")
    ax.scatter(pts["x0"][w <= 0.5], pts["x1"][w <= 0.5], s=16, facecolors="none", edgecolors="r")
    ax.plot([p0["best"]], [p1["best"]], "r*", ms=14, label="fit")
    for p, setter in ((p0, ax.set_xscale), (p1, ax.set_yscale)):
        if p["scale"] == "log":
            setter("log")
    ax.set_xlabel(p0["key"])
    ax.set_ylabel(p1["key"])
    ax.set_title(f"{tgt['name']}: target {tgt['value']:g} ± {tgt['tolerance']:g}", fontsize=9)


def main(outdir):
    with open(os.path.join(outdir, "calibration.json")) as f:
        cal = json.load(f)
    pts = read_csv(os.path.join(outdir, "calibration_points.csv"))
    surf = read_csv(os.path.join(outdir, "calibration_surface.csv"))
    nt, d = len(cal["targets"]), len(cal["parameters"])
    fig, axes = plt.subplots(1, nt, figsize=(5.2 * nt, 4.2), squeeze=False)
    for k in range(nt):
        (panel_1d if d == 1 else panel_2d)(axes[0][k], k, cal, pts, surf)
    fig.suptitle("calibration: " + ", ".join(f"{p['key']} = {p['best']:.4g}" for p in cal["parameters"])
                 + ("" if cal["feasible"] else "  (no point meets every target)"), fontsize=10)
    fig.tight_layout()
    save(fig, outdir, "calibration.png", 110)


if __name__ == "__main__":
    main(sys.argv[1])
