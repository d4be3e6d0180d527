#!/usr/bin/env python3
"""Plots of an `agglo sweep` run.
Acoustic sweeps over one key (like seed 002 Figs. 5-6): sweep.png with (a) the final size
distribution of the solid fines of every case and (b) the final fine efficiency vs the swept value,
and sweep_time.png with the efficiency vs time of every case.
Any other sweep: sweep.png with the headline result of the command (v_crit, v50, broken, energy,
fine efficiency) vs the first key, one line per value of the second key when there is one.
Usage: plot_sweep.py OUTDIR KEY [KEY2 ...]"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


HEADLINE = ["fine_efficiency", "v_crit", "v50", "energy_J", "broken"]


def number(x):
    try:
        return float(x)
    except ValueError:
        return None


def generic(out, keys, rows):
    col = next((c for c in HEADLINE if c in rows[0]), None)
    if col is None:
        return
    groups = {}
    for r in rows:
        groups.setdefault(r[keys[1]] if len(keys) > 1 else "", []).append(r)
    fig, ax = plt.subplots(figsize=(5, 3.6))
    for label, rs in groups.items():
        xs = [number(r[keys[0]]) for r in rs]
        ys = [number(r[col]) if r[col] != "" else None for r in rs]
        pts = [(x, y) for x, y in zip(xs, ys) if x is not None and y is not None]
        if not pts:
            continue
        ax.plot(*zip(*pts), "o-", label=f"{keys[1]} = {label}" if label else None)
    ax.set_xlabel(keys[0])
    ax.set_ylabel(col)
    if len(groups) > 1:
        ax.legend(frameon=False, fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "sweep.png"), dpi=120)
    plt.close(fig)


def main(out, keys):
    rows = read(os.path.join(out, "sweep.csv"))
    if not rows:
        return
    if len(keys) > 1 or "fine_efficiency" not in rows[0] or number(rows[0][keys[0]]) is None:
        generic(out, keys, rows)
        return
    key = keys[0]
    vals = [float(r[key]) for r in rows]
    eff = [100 * float(r["fine_efficiency"]) for r in rows]
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
    axs[1].plot(vals, eff, "ko-")
    axs[1].set_xlabel(key)
    axs[1].set_ylabel("fine efficiency / %")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "sweep.png"), dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(5, 3.6))
    for r in rows:
        p = os.path.join(out, r["case"], "efficiency.csv")
        if not os.path.exists(p):
            continue
        e = read(p)
        ax.plot([float(q["t_s"]) for q in e], [100 * float(q["fine_efficiency"]) for q in e], label=r[key])
    ax.set_xlabel("t / s")
    ax.set_ylabel("fine efficiency / %")
    ax.legend(frameon=False, fontsize=7, title=key.split(".")[-1])
    fig.tight_layout()
    fig.savefig(os.path.join(out, "sweep_time.png"), dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2:])
