#!/usr/bin/python3
"""Kinetic energy history of one collision, agglo vs LAMMPS, on the same set-up.

    compare_trajectory.py AGGLO_OUT_DIR LAMMPS_WORKDIR [--png FILE]

AGGLO_OUT_DIR holds agglo's timeseries.csv (t since launch, kinetic_energy = translational +
rotational); LAMMPS_WORKDIR holds log.lammps of a run made with --thermo-every (columns step,
time, ke, c_rke). Prints the largest relative KE difference in successive time windows, which
shows how long the two integrations stay on the same trajectory.
"""
import argparse
import csv

import numpy as np


def read_lammps_thermo(path):
    rows, on = [], False
    for line in open(path):
        s = line.split()
        if s[:2] == ["Step", "Time"]:
            on = True
            continue
        if on:
            try:
                rows.append([float(v) for v in s])
            except ValueError:
                on = False
    a = np.array(rows)
    return a[:, 1], a[:, 2] + a[:, 3]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("agglo_dir")
    ap.add_argument("lammps_dir")
    ap.add_argument("--png", default="")
    a = ap.parse_args()
    with open(f"{a.agglo_dir}/timeseries.csv") as f:
        rows = list(csv.DictReader(f))
    t_o = np.array([float(r["t"]) for r in rows])
    ke_o = np.array([float(r["kinetic_energy"]) for r in rows])
    t_l, ke_l = read_lammps_thermo(f"{a.lammps_dir}/log.lammps")
    ke_li = np.interp(t_o, t_l, ke_l)
    ke0 = ke_o[0]
    rel = np.abs(ke_o - ke_li) / ke0
    edges = [0, 1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 1e9]
    print("window [s]           max |KE_agglo - KE_lammps| / KE_0")
    for lo, hi in zip(edges[:-1], edges[1:]):
        m = (t_o >= lo) & (t_o < hi) & (t_o <= t_l[-1])
        if m.any():
            print(f"[{lo:.0e}, {hi:.0e})   {rel[m].max():.3e}")
    print(f"final KE / KE_0: agglo {ke_o[-1] / ke0:.6f}, LAMMPS {ke_l[-1] / ke_l[0]:.6f}")
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 3.5))
        ax.plot(t_o * 1e3, ke_o / ke0, label="agglo")
        ax.plot(t_l * 1e3, ke_l / ke_l[0], "--", label="LAMMPS")
        ax.set_xlabel("t since launch [ms]")
        ax.set_ylabel("KE / KE_0")
        ax.legend()
        fig.tight_layout()
        fig.savefig(a.png, dpi=120)


if __name__ == "__main__":
    main()
