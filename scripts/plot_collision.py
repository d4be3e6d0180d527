#!/usr/bin/env python3
"""Plots of one collision run: kinetic energy, U/U0, radius of gyration and contact count vs time.
Usage: plot_collision.py OUTDIR   (reads OUTDIR/timeseries.csv, writes OUTDIR/histories.png)"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from plot_save import save


def main(outdir):
    d = np.genfromtxt(os.path.join(outdir, "timeseries.csv"), delimiter=",", names=True)
    t = d["t"] * 1e3
    fig, ax = plt.subplots(2, 2, figsize=(9, 6.5), sharex=True)
    ax[0, 0].plot(t, d["kinetic_energy"] * 1e15)
    ax[0, 0].set_ylabel("kinetic energy [fJ]")
    ax[0, 1].plot(t, d["U_over_U0"])
    ax[0, 1].set_ylabel("U / U0")
    ax[1, 0].plot(t, d["radius_of_gyration"] * 1e6, label="all particles")
    ax[1, 0].plot(t, d["radius_of_gyration_agglomerate"] * 1e6, label="original agglomerate")
    ax[1, 0].set_ylabel("radius of gyration [um]")
    ax[1, 0].legend()
    ax[1, 1].step(t, d["n_contacts"], where="post")
    ax[1, 1].set_ylabel("contacts")
    for a in ax[1]:
        a.set_xlabel("t [ms]")
    for a in ax.flat:
        a.grid(alpha=0.3)
    fig.suptitle(os.path.basename(os.path.normpath(outdir)))
    fig.tight_layout()
    save(fig, outdir, "histories.png", 110)


if __name__ == "__main__":
    main(sys.argv[1])
