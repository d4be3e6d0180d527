#!/usr/bin/env python3
"""Table 2 and Figs. 3d/4d/5 of Ruan & Li (2022) from the outputs of scripts/reproduce_seed000.sh, with the
calibration that set the contact parameters (OUTDIR/calibration) and the predictions over its fitted set.
Usage: plot_seed000.py OUTDIR [CALIBRATION_AND_PREDICTION_WALL_SECONDS [CALIBRATION_WALL_SECONDS]] [--no-figures]
--no-figures: table2.csv and table2.json only (the smoke test, SMOKE=1 scripts/reproduce_seed000.sh)."""
import csv
import json
import os
import sys
import tomllib

SEED = {"neutral": 0.176, "k1": 0.197, "k2p5": 0.216, "k15": 0.224}
LABEL = {"neutral": "neutral", "k1": "kappa_p = 1", "k2p5": "kappa_p = 2.5", "k15": "kappa_p = 15"}


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, path)


def calibration_summary(out):
    """The fit (best point, fitted set) and whether the shipped cases' (E, e) lies in the fitted set."""
    f = os.path.join(out, "calibration", "calibration.json")
    if not os.path.exists(f):
        return None
    c = json.load(open(f))
    case = os.path.join(os.path.dirname(__file__), "..", "cases", "seed000_neutral_tetrahedron.toml")
    shipped = tomllib.load(open(case, "rb"))
    summary = {"chi2": c["chi2"], "feasible": c["feasible"], "parameters": [], "predictions": c.get("predictions", [])}
    inside = c["feasible"]
    for p in c["parameters"]:
        section, key = p["key"].split(".")
        value = shipped[section][key]
        lo, hi = p["feasible_lo"], p["feasible_hi"]
        inside = inside and lo is not None and lo <= value <= hi
        summary["parameters"].append({"key": p["key"], "best": p["best"], "fitted_lo": lo, "fitted_hi": hi,
                                      "shipped": value})
    summary["shipped_inside_fitted_box"] = inside
    # "achieved" and "met" come from the check runs at the best fit: none with calibrate.check = false
    summary["targets"] = [{k: t.get(k) for k in ("name", "value", "tolerance", "predicted", "achieved", "met")}
                          for t in c["targets"]]
    return summary


def plot_predictions(plt, out, rows, summary):
    """kappa_p = 2.5 and 15: the shipped cases' v_crit, the range over the fitted set (when run), the seed."""
    fig, ax = plt.subplots(figsize=(6, 4))
    names = {"k2p5": "seed000_charged_tetrahedron_k2p5 v_crit", "k15": "seed000_charged_tetrahedron_k15 v_crit"}
    preds = {p["name"]: p for p in (summary or {}).get("predictions", [])}
    for i, k in enumerate(names):
        row = next((r for r in rows if r["case"] == k), None)
        if row:
            ax.plot(i - 0.1, row["v_crit"], "o", color="C0", label="agglo, shipped cases" if i == 0 else None)
        p = preds.get(names[k])
        if p and p["min"] is not None:
            ax.vlines(i, p["min"], p["max"], color="C1", lw=4, label="agglo, over the fitted set" if i == 0 else None)
        ax.plot(i + 0.1, SEED[k], "s", color="C2", label="seed (Table 2)" if i == 0 else None)
    ax.set_xticks([0, 1], [LABEL[k] for k in names])
    ax.set_xlim(-0.6, 1.6)
    ax.set_ylabel("predicted v_crit [m/s]")
    ax.legend()
    ax.grid(alpha=0.3, axis="y")
    fig.tight_layout()
    save(fig, os.path.join(out, "predictions.png"))


def main(out, wall, calibration_wall, figures=True):
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
        summary = calibration_summary(out)
        json.dump({"rows": rows, "calibration": summary, "wall_time_s": float(wall) if wall else None,
                   "calibration_wall_time_s": float(calibration_wall) if calibration_wall else None}, f, indent=2)
    os.replace(os.path.join(out, "table2.json.tmp"), os.path.join(out, "table2.json"))
    if figures:
        draw_figures(out, rows, summary)


def draw_figures(out, rows, summary):
    """predictions.png, table2_ratios.png, energy_histories.png, rg_histories.png."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    plot_predictions(plt, out, rows, summary)
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
    args = [a for a in sys.argv[1:] if a != "--no-figures"]
    main(args[0], args[1] if len(args) > 1 else None, args[2] if len(args) > 2 else None,
         figures="--no-figures" not in sys.argv)
