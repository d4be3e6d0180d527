#!/usr/bin/env python3
"""Table 2 and Figs. 3d/4d/5 of Ruan & Li (2022) from the outputs of scripts/reproduce_seed000.sh.
Usage: plot_seed000.py OUTDIR [TABLE2_WALL_SECONDS]"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

SEED = {"neutral": 0.176, "k1": 0.197, "k2p5": 0.216, "k15": 0.224}
LABEL = {"neutral": "neutral", "k1": "kappa_p = 1", "k2p5": "kappa_p = 2.5", "k15": "kappa_p = 15"}


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, path)


def main(out, wall):
    rows = []
    for k in SEED:
        f = os.path.join(out, f"vcrit_{k}", "vcrit.json")
        if not os.path.exists(f):
            continue
        r = json.load(open(f))
        rows.append({"case": k, "v_crit": r["v_crit"], "bracket_lo": r["bracket"][0], "bracket_hi": r["bracket"][1],
                     "runs": len(r["runs"]), "seed_v_crit": SEED[k], "warnings": len(r["warnings"])})
    neutral = next((r["v_crit"] for r in rows if r["case"] == "neutral"), None)
    for r in rows:
        r["ratio"] = r["v_crit"] / neutral if neutral else float("nan")
        r["seed_ratio"] = SEED[r["case"]] / SEED["neutral"]
    tmp = os.path.join(out, "table2.csv.tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, os.path.join(out, "table2.csv"))
    with open(os.path.join(out, "table2.json.tmp"), "w") as f:
        json.dump({"rows": rows, "wall_time_s": float(wall) if wall else None}, f, indent=2)
    os.replace(os.path.join(out, "table2.json.tmp"), os.path.join(out, "table2.json"))

    fig, ax = plt.subplots(figsize=(6, 4))
    x = np.arange(len(rows))
    ax.bar(x - 0.18, [r["ratio"] for r in rows], 0.36, label="agglo")
    ax.bar(x + 0.18, [r["seed_ratio"] for r in rows], 0.36, label="seed (Table 2)")
    ax.set_xticks(x, [LABEL[r["case"]] for r in rows])
    ax.set_ylabel("v_crit / v_crit,neutral")
    ax.legend()
    ax.grid(alpha=0.3, axis="y")
    fig.tight_layout()
    save(fig, os.path.join(out, "table2_ratios.png"))

    def load(name):
        p = os.path.join(out, name, "timeseries.csv")
        return np.genfromtxt(p, delimiter=",", names=True) if os.path.exists(p) else None

    fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
    for k, a in (("k1", ax[0]), ("k15", ax[1])):
        d = load(f"hist_{k}_0.18")
        if d is not None:
            a.plot(d["t"] * 1e3, d["U_over_U0"])
        a.set_title(f"U/U0, {LABEL[k]}, v_in = 0.18 m/s (seed Fig. {'3d' if k == 'k1' else '4d'})")
        a.set_xlabel("t [ms]")
        a.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, os.path.join(out, "energy_histories.png"))

    fig, ax = plt.subplots(figsize=(6, 4))
    for name, lab in (("hist_neutral_0.175", "neutral, 0.175 m/s"), ("hist_k1_0.18", "kappa_p = 1, 0.18 m/s"),
                      ("hist_k15_0.18", "kappa_p = 15, 0.18 m/s")):
        d = load(name)
        if d is not None:
            ax.plot(d["t"] * 1e3, d["radius_of_gyration_agglomerate"] / 10e-6, label=lab)
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("R_g / r_p (original 4 particles)")
    ax.set_title("radius of gyration of the agglomerate (seed Fig. 5)")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, os.path.join(out, "rg_histories.png"))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else None)
