#!/usr/bin/env python3
"""Plots of an `agglo acoustic` run (like seed 002 Figs. 4a-c):
psd.png (dN/dlog d of the solid fines and of all particles at the PSD times), efficiency.png
(fine agglomeration efficiency and fraction of pure droplets vs time), snapshots.png (samples with
0 <= x <= snapshot fraction of the wavelength; liquid drawn 40x, solid 120x as in Fig. 4c).
Usage: plot_acoustic.py OUTDIR"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from plot_save import save


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main(out):
    eff = read(os.path.join(out, "efficiency.csv"))
    t = [float(r["t_s"]) for r in eff]
    fig, ax = plt.subplots(figsize=(5, 3.6))
    ax.plot(t, [100 * float(r["fine_efficiency"]) for r in eff], "k-", label="fine efficiency")
    ax.plot(t, [100 * float(r["pure_droplet_fraction"]) for r in eff], "b--", label="pure droplets left")
    ax.set_xlabel("t / s")
    ax.set_ylabel("%")
    ax.set_ylim(0, 100)
    ax.legend(frameon=False)
    fig.tight_layout()
    save(fig, out, "efficiency.png", 120)
    plt.close(fig)

    psd = read(os.path.join(out, "psd.csv"))
    times = sorted({float(r["t_s"]) for r in psd})
    fig, axs = plt.subplots(1, 2, figsize=(9, 3.6))
    for tt in times:
        rows = [r for r in psd if float(r["t_s"]) == tt]
        d = [1e6 * float(r["d_mid_m"]) for r in rows]
        axs[0].plot(d, [float(r["solid_dNdlogd_cm3"]) for r in rows], label=f"t = {tt:g} s")
        axs[1].plot(d, [float(r["total_dNdlogd_cm3"]) for r in rows], label=f"t = {tt:g} s")
    for a, title in zip(axs, ["solid fines", "all particles"]):
        a.set_xscale("log")
        a.set_yscale("log")
        a.set_ylim(bottom=1.0)
        a.set_xlabel("d / um")
        a.set_ylabel("dN/dlog d / cm^-3")
        a.set_title(title)
    axs[0].legend(frameon=False, fontsize=8)
    fig.tight_layout()
    save(fig, out, "psd.png", 120)
    plt.close(fig)

    snap_path = os.path.join(out, "snapshots.csv")
    if os.path.exists(snap_path):
        snap = read(snap_path)
        stimes = sorted({float(r["t_s"]) for r in snap})
        if stimes:
            fig, axs = plt.subplots(len(stimes), 1, figsize=(8, 1.6 * len(stimes) + 0.4), squeeze=False)
            for a, tt in zip(axs[:, 0], stimes):
                rows = [r for r in snap if float(r["t_s"]) == tt]
                for phase, color, mag in (("liquid", "tab:blue", 40.0), ("mixed", "tab:blue", 40.0),
                                          ("solid", "0.5", 120.0)):
                    sel = [r for r in rows if r["phase"] == phase]
                    if not sel:
                        continue
                    x = [100 * float(r["x_m"]) for r in sel]
                    z = [100 * float(r["z_m"]) for r in sel]
                    # marker diameter in points ~ magnified particle diameter (axes in cm)
                    s = [(mag * float(r["d_m"]) * 1e2 * 72 / 2.54 * 2.0) ** 2 for r in sel]
                    a.scatter(x, z, s=s, c=color, alpha=0.6 if phase != "solid" else 0.8, linewidths=0)
                    if phase == "mixed":  # solid core of mixed particles
                        ds = [(6 * float(r["solid_volume_m3"]) / 3.141592653589793) ** (1 / 3) for r in sel]
                        a.scatter(x, z, s=[(120 * d * 1e2 * 72 / 2.54 * 2.0) ** 2 for d in ds], c="0.3",
                                  linewidths=0)
                a.set_ylabel("z / cm")
                a.set_title(f"t = {tt:g} s", fontsize=9)
                a.set_aspect("equal")
            axs[-1, 0].set_xlabel("x / cm")
            fig.tight_layout()
            save(fig, out, "snapshots.png", 90)
            plt.close(fig)


if __name__ == "__main__":
    main(sys.argv[1])
