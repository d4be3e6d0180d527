#!/usr/bin/env python3
"""Plot of a seed ensemble (`agglo acoustic CASE --seeds N`): ensemble.png, the ensemble mean with a
band of +-1 standard error of the mean (ensemble_timeseries.csv) for the fine agglomeration efficiency
and the fraction of pure droplets, and for the number concentrations; a third panel shows the
standard errors themselves (often too narrow to see as bands): of the efficiency in percentage points,
of the solid number concentration and of the solid and liquid volume fractions (mass) in percent of
the mean.
Usage: plot_ensemble.py OUTDIR"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from plot_save import save


def column(rows, name):
    return [float(r[name]) if r[name] not in ("", "nan") else math.nan for r in rows]


def band(ax, t, rows, name, scale=1.0, label=None, color=None, rel=False):
    """Mean line and +-stderr band of `name`; scaled, or relative to its first mean value when rel."""
    m, e = column(rows, name + "_mean"), column(rows, name + "_stderr")
    if rel:
        scale = 1.0 / m[0] if m and m[0] else 1.0
    m = [scale * x for x in m]
    e = [scale * (0.0 if math.isnan(x) else x) for x in e]
    line, = ax.plot(t, m, "-", color=color, label=label, lw=1.2)
    ax.fill_between(t, [a - b for a, b in zip(m, e)], [a + b for a, b in zip(m, e)], color=line.get_color(),
                    alpha=0.3, lw=0)


def members(out):
    with open(os.path.join(out, "ensemble_summary.csv")) as f:
        rows = list(csv.DictReader(f))
    return rows[0]["n"] if rows else "?"


def main(out):
    with open(os.path.join(out, "ensemble_timeseries.csv")) as f:
        rows = list(csv.DictReader(f))
    t = column(rows, "t_s")
    fig, axs = plt.subplots(1, 3, figsize=(11, 3.3))
    band(axs[0], t, rows, "fine_efficiency", 100, "fine efficiency", "k")
    band(axs[0], t, rows, "pure_droplet_fraction", 100, "pure droplets left", "tab:blue")
    axs[0].set_ylabel("%")
    axs[0].set_ylim(0, 100)
    for name, label in (("n_solid_cm3", "solid"), ("n_total_cm3", "all"), ("n_liquid_cm3", "liquid"),
                        ("n_mixed_cm3", "mixed")):
        band(axs[1], t, rows, name, 1.0, label)
    axs[1].set_yscale("log")
    axs[1].set_ylabel("N / cm^-3")
    def relative(name):
        return [100 * e / m if m else math.nan for m, e in zip(column(rows, name + "_mean"), column(rows, name + "_stderr"))]
    axs[2].plot(t, [100 * x for x in column(rows, "fine_efficiency_stderr")], "k-", label="efficiency / points")
    axs[2].plot(t, relative("n_solid_cm3"), "-", color="tab:blue", label="solid N / %")
    axs[2].plot(t, relative("solid_volume_fraction"), ":", color="0.4", label="solid volume / %")
    axs[2].plot(t, relative("liquid_volume_fraction"), "--", color="tab:cyan", label="liquid volume / %")
    axs[2].set_ylabel("standard error")
    for a in axs:
        a.set_xlabel("t / s")
        a.legend(frameon=False, fontsize=8)
    fig.suptitle(f"mean +- standard error over {members(out)} seeds", fontsize=9)
    fig.tight_layout()
    save(fig, out, "ensemble.png", 100)
    plt.close(fig)


if __name__ == "__main__":
    main(sys.argv[1])
