#!/usr/bin/env python3
"""Figures of the fly-ash outcome study (docs/studies/flyash_outcomes.md) from the study.json of
scripts/studies/flyash_outcomes.py:

  flyash_outcomes_reductions.png  number (total, and below 2.5 um at the PSD times) and PM2.5 mass reductions
                                  against time per dry outcome model, mean over the seeds with error bars of
                                  one standard error, and Zhang et al. 2009's drops of the total number
                                  (68.4 %) and of the PM2.5 number (75.6 %) as horizontal lines
  flyash_outcomes_tables.png      P_stick of the tables against the normal speed for equal partners of
                                  1 um (and 2 um), with the closed-form critical velocity of the default model

    /usr/bin/python3 scripts/studies/plot_flyash_outcomes.py results/flyash_outcomes/study.json [more.json ...] docs/img
    ... --structure  (the variants of the study.json files only, as flyash_outcomes_structure.png: the
                      structure-aware samples against the aggregate table with compact samples)
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LABELS = {"default": "closed-form v_cr (default)", "spheres": "DEM spheres, fly ash",
          "spheres_seed": "DEM spheres, seed material", "aggregates": "DEM BPCA aggregates, fly ash",
          "aggregates_structured": "aggregates + fractal samples (D_f 2.23)",
          "aggregates_structured_273": "aggregates + fractal samples (D_f 2.73)"}
COLORS = {"default": "k", "spheres": "tab:red", "spheres_seed": "tab:blue", "aggregates": "tab:green",
          "aggregates_structured": "tab:purple", "aggregates_structured_273": "tab:orange"}
ZHANG = {"number_reduction": 0.684, "pm2_5": 0.756}  # Zhang et al. 2009, 1400 Hz, 147 dB: number concentrations


def critical_velocity_dry(d1, d2, rho=2500.0, hamaker=1e-19, e=0.6, z0=4e-10, pc=3e8):
    """The default's v_cr,dry [m/s] (Sgrott & Sommerfeld 2019 eq. 13; src/agglo/acoustics/outcomes.hpp)."""
    dmin, dmax = min(d1, d2), max(d1, d2)
    return hamaker * math.sqrt(1 - e * e) / (math.pi * dmin * z0 ** 2 * e * e
                                             * math.sqrt(6 * pc * rho * (1 + dmin / dmax)))


def plot_reductions(study, out, filename="flyash_outcomes_reductions.png"):
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.4))
    for v, r in study["variants"].items():
        t = r["times"]
        every = max(1, len(t) // 20)
        for ax, col, style in ((left, "number_reduction", "-"), (right, "pm2_5_vol_reduction", "-"),
                               (right, "pm2_5_aero_reduction", ":")):
            s = r["series"][col]
            label = LABELS[v] if style == "-" else None
            ax.errorbar(t, [x["mean"] * 100 for x in s], yerr=[x["se"] * 100 for x in s], errorevery=every,
                        color=COLORS[v], ls=style, lw=1.3, capsize=2, label=label)
        s = r["pm2_5_number_reduction"]
        left.errorbar(r["psd_times"], [x["mean"] * 100 for x in s], yerr=[x["se"] * 100 for x in s], fmt="o",
                      mfc="none", color=COLORS[v], capsize=2)
    left.axhline(ZHANG["number_reduction"] * 100, color="grey", ls="--", lw=1, label="Zhang et al. 2009: total 68.4 %")
    left.axhline(ZHANG["pm2_5"] * 100, color="grey", ls="-.", lw=1, label="Zhang et al. 2009: PM2.5 number 75.6 %")
    n = next(iter(study["variants"].values()))["dry"]["stuck"]["n"]
    left.set_title(f"number: total (lines), below 2.5 um (circles); {n} seeds, ± 1 s.e.", fontsize=10)
    right.set_title("PM2.5 mass: volume-equivalent (solid), aerodynamic (dotted)", fontsize=10)
    for ax, name in ((left, "number reduction 1 - N(t)/N(0) [%]"), (right, "PM2.5 mass reduction [%]")):
        ax.set_xlabel("t [s]")
        ax.set_ylabel(name)
        ax.set_ylim(0, 100)
        ax.grid(alpha=0.3)
    left.legend(fontsize=7.5, loc="upper left")
    right.legend(fontsize=7.5, loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(out, filename), dpi=110)


def plot_tables(study, out):
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for v, table in study["tables"].items():
        nodes = table["nodes"]
        sizes = sorted({float(r["diameter_1"]) for r in nodes})
        for d, style in ((min(sizes, key=lambda x: abs(math.log(x / 1e-6))), "o-"),
                         (min(sizes, key=lambda x: abs(math.log(x / 2e-6))), "s--")):
            pts = sorted((float(r["speed"]), float(r["p_stick"])) for r in nodes
                         if float(r["diameter_1"]) == d and float(r["diameter_2"]) == d)
            ax.semilogx([p[0] for p in pts], [p[1] for p in pts], style, color=COLORS[v], ms=4,
                        label=f"{LABELS[v]}, {d * 1e6:.2g} + {d * 1e6:.2g} um")
    for d, style in ((1e-6, "-"), (2e-6, "--")):
        vc = critical_velocity_dry(d, d)
        ax.axvline(vc, color="k", ls=style, lw=1, label=f"closed-form v_cr, {d * 1e6:.0f} + {d * 1e6:.0f} um: {vc:.3f} m/s")
    ax.set_xlabel("normal relative speed at contact [m/s]")
    ax.set_ylabel("P_stick")
    ax.set_ylim(-0.05, 1.05)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "flyash_outcomes_tables.png"), dpi=110)


def main():
    study = {"tables": {}, "variants": {}}
    args = [a for a in sys.argv[1:] if a != "--structure"]
    if "--structure" in sys.argv:
        for path in args[:-1]:
            study["variants"].update(json.load(open(path))["variants"])
        plot_reductions(study, args[-1], "flyash_outcomes_structure.png")
        return 0
    for path in sys.argv[1:-1]:  # several study.json (variants run apart) are merged
        part = json.load(open(path))
        study["tables"].update(part["tables"])
        study["variants"].update(part["variants"])
    out = sys.argv[-1]
    os.makedirs(out, exist_ok=True)
    plot_reductions(study, out)
    plot_tables(study, out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
