#!/usr/bin/env python3
"""Plots of an `agglo sweep` run.
Acoustic sweeps over one key (like seed 002 Figs. 5-6): sweep.png with (a) the final size
distribution of the solid fines of every case and (b) the final fine efficiency vs the swept value,
and sweep_time.png with the efficiency vs time of every case.
Any other sweep: sweep.png with the headline result of the command (v_crit, v50, broken, energy,
fine efficiency) vs the first key, one line per value of the second key when there is one.
With --seeds (agglo sweep --seeds N; the last key is the seed): the points' means with error bars of one
standard error (sweep_ensemble.csv), the size distributions of member 0 (the case's own seed) and each
point's mean efficiency vs time with a band of +-1 standard error (ensemble_timeseries.csv of the point's
folder point_<index>_<values>).
Usage: plot_sweep.py OUTDIR [--seeds] KEY [KEY2 ...]"""
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from plot_save import save


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


HEADLINE = ["fine_efficiency", "v_crit", "v50", "energy_J", "broken"]


def number(x):
    try:
        return float(x)
    except ValueError:
        return None


def mean_of(rows, col):
    """sweep_ensemble.csv rows: col -> col_mean (the plain column when there is no ensemble)."""
    return col + "_mean" if col + "_mean" in rows[0] else col


def error_bars(rows, col, scale=1.0):
    name = col + "_stderr"
    if name not in rows[0]:
        return None
    return [scale * (number(r[name]) or 0.0) if r[name] not in ("", "nan") else 0.0 for r in rows]


def generic(out, keys, rows):
    col = next((c for c in HEADLINE if mean_of(rows, c) in rows[0]), None)
    if col is None:
        return
    groups = {}
    for r in rows:
        groups.setdefault(r[keys[1]] if len(keys) > 1 else "", []).append(r)
    fig, ax = plt.subplots(figsize=(5, 3.6))
    for label, rs in groups.items():
        xs = [number(r[keys[0]]) for r in rs]
        ys = [number(r[mean_of(rows, col)]) if r[mean_of(rows, col)] != "" else None for r in rs]
        es = error_bars(rs, col) or [0.0] * len(rs)
        pts = [(x, y, e) for x, y, e in zip(xs, ys, es) if x is not None and y is not None]
        if not pts:
            continue
        x, y, e = zip(*pts)
        ax.errorbar(x, y, yerr=e, fmt="o-", capsize=3, label=f"{keys[1]} = {label}" if label else None)
    ax.set_xlabel(keys[0])
    ax.set_ylabel(col)
    if len(groups) > 1:
        ax.legend(frameon=False, fontsize=7)
    fig.tight_layout()
    save(fig, out, "sweep.png", 120)
    plt.close(fig)


def point_efficiency(out, index):
    """The mean and standard error of the efficiency vs time of sweep point `index` (its folder's
    ensemble_timeseries.csv), in %; (None, None, None) when the point has none."""
    found = glob.glob(os.path.join(out, f"point_{index:02d}_*", "ensemble_timeseries.csv"))
    if len(found) != 1:
        return None, None, None
    rows = read(found[0])
    if not rows or "fine_efficiency_mean" not in rows[0]:
        return None, None, None
    t = [float(q["t_s"]) for q in rows]
    m = [100 * float(q["fine_efficiency_mean"]) for q in rows]
    e = [100 * (number(q["fine_efficiency_stderr"]) or 0.0) for q in rows]
    return t, m, e


def mean_efficiency(out, folders):
    """The efficiency vs time averaged over member folders (the members share their output times)."""
    curves = []
    for f in folders:
        p = os.path.join(out, f, "efficiency.csv")
        if os.path.exists(p):
            curves.append(read(p))
    if not curves:
        return None, None
    n = min(len(c) for c in curves)
    t = [float(q["t_s"]) for q in curves[0][:n]]
    return t, [100 * sum(float(c[i]["fine_efficiency"]) for c in curves) / len(curves) for i in range(n)]


def main(out, keys, seeds=False):
    runs = read(os.path.join(out, "sweep.csv"))
    rows = read(os.path.join(out, "sweep_ensemble.csv")) if seeds else runs
    if seeds:
        keys = keys[:-1]  # the last key is the seed
    if not rows:
        return
    if len(keys) > 1 or mean_of(rows, "fine_efficiency") not in rows[0] or number(rows[0][keys[0]]) is None:
        generic(out, keys, rows)
        return
    key = keys[0]
    vals = [float(r[key]) for r in rows]
    eff = [100 * float(r[mean_of(rows, "fine_efficiency")]) for r in rows]
    fig, axs = plt.subplots(1, 2, figsize=(10, 3.8))
    for r in rows:
        p = os.path.join(out, r["case"], "psd.csv")
        if not os.path.exists(p):
            continue
        psd = read(p)
        tmax = max(float(q["t_s"]) for q in psd)
        sel = [q for q in psd if float(q["t_s"]) == tmax]
        axs[0].plot([1e6 * float(q["d_mid_m"]) for q in sel], [float(q["solid_dNdlogd_cm3"]) for q in sel],
                    label=f"{key.split('.')[-1]} = {r[key]}")
    axs[0].set_xscale("log")
    axs[0].set_xlim(0.01, 10)
    axs[0].set_xlabel("d / um")
    axs[0].set_ylabel("solid dN/dlog d / cm^-3 (final)")
    axs[0].legend(frameon=False, fontsize=7)
    axs[1].errorbar(vals, eff, yerr=error_bars(rows, "fine_efficiency", 100.0), fmt="ko-", capsize=3)
    axs[1].set_xlabel(key)
    axs[1].set_ylabel(f"fine efficiency / % (mean ± s.e., {rows[0]['members']} seeds)" if seeds
                      else "fine efficiency / %")
    fig.tight_layout()
    save(fig, out, "sweep.png", 120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(5, 3.6))
    for r in rows:
        t, m, e = point_efficiency(out, int(r["index"])) if seeds else (None, None, None)
        if t is not None:
            line, = ax.plot(t, m, label=r[key])
            ax.fill_between(t, [a - b for a, b in zip(m, e)], [a + b for a, b in zip(m, e)], color=line.get_color(),
                            alpha=0.25, linewidth=0)
            continue
        t, m = mean_efficiency(out, [q["case"] for q in runs if q[key] == r[key]] if seeds else [r["case"]])
        if t is not None:
            ax.plot(t, m, label=r[key])
    ax.set_xlabel("t / s")
    ax.set_ylabel(f"fine efficiency / % (mean ± s.e. of {rows[0]['members']} seeds)" if seeds
                  else "fine efficiency / %")
    ax.legend(frameon=False, fontsize=7, title=key.split(".")[-1])
    fig.tight_layout()
    save(fig, out, "sweep_time.png", 120)
    plt.close(fig)


if __name__ == "__main__":
    if len(sys.argv) > 2 and sys.argv[2] == "--seeds":
        main(sys.argv[1], sys.argv[3:], seeds=True)
    else:
        main(sys.argv[1], sys.argv[2:])
