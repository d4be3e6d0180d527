#!/usr/bin/python3
"""Kinetic energy history of one collision, agglo vs LAMMPS, on the same set-up.

    compare_trajectory.py AGGLO_OUT_DIR LAMMPS_WORKDIR [--png FILE]

AGGLO_OUT_DIR holds agglo's timeseries.csv (t since launch, kinetic_energy = translational +
rotational); LAMMPS_WORKDIR holds log.lammps of a run made with --thermo-every (columns step,
time, ke, c_rke). Prints the largest relative KE difference in successive time windows, which
shows how long the two integrations stay on the same trajectory.
"""
import argparse
import bisect
import csv


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
    return [r[1] for r in rows], [r[2] + r[3] for r in rows]


def interp(x, xp, fp):
    """numpy.interp for increasing xp (no numpy: its import is most of this script's cost)."""
    if x <= xp[0]:
        return fp[0]
    if x >= xp[-1]:
        return fp[-1]
    k = bisect.bisect_right(xp, x)
    w = (x - xp[k - 1]) / (xp[k] - xp[k - 1])
    return fp[k - 1] + w * (fp[k] - fp[k - 1])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("agglo_dir")
    ap.add_argument("lammps_dir")
    ap.add_argument("--png", default="")
    a = ap.parse_args()
    with open(f"{a.agglo_dir}/timeseries.csv") as f:
        rows = list(csv.DictReader(f))
    t_o = [float(r["t"]) for r in rows]
    ke_o = [float(r["kinetic_energy"]) for r in rows]
    t_l, ke_l = read_lammps_thermo(f"{a.lammps_dir}/log.lammps")
    ke0 = ke_o[0]
    rel = [abs(k - interp(t, t_l, ke_l)) / ke0 for t, k in zip(t_o, ke_o)]
    edges = [0, 1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 1e9]
    print("window [s]           max |KE_agglo - KE_lammps| / KE_0")
    for lo, hi in zip(edges[:-1], edges[1:]):
        m = [d for t, d in zip(t_o, rel) if lo <= t < hi and t <= t_l[-1]]
        if m:
            print(f"[{lo:.0e}, {hi:.0e})   {max(m):.3e}")
    print(f"final KE / KE_0: agglo {ke_o[-1] / ke0:.6f}, LAMMPS {ke_l[-1] / ke_l[0]:.6f}")
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 3.5))
        ax.plot([t * 1e3 for t in t_o], [k / ke0 for k in ke_o], label="agglo")
        ax.plot([t * 1e3 for t in t_l], [k / ke_l[0] for k in ke_l], "--", label="LAMMPS")
        ax.set_xlabel("t since launch [ms]")
        ax.set_ylabel("KE / KE_0")
        ax.legend()
        fig.tight_layout()
        fig.savefig(a.png, dpi=120)


if __name__ == "__main__":
    main()
