#!/usr/bin/env python3
"""Figures and table of the aggregate-wall breakage study (docs/studies/breakage_wall.md) from the runs of
scripts/studies/breakage_wall.py: every finished run of OUT/<shape>/v<speed>/journal.jsonl (a study stopped
early counts the runs it has). The orientations are the samples: each mean is given with its standard error
s / sqrt(n) over the n orientations of that speed.

    /usr/bin/python3 scripts/studies/plot_breakage_wall.py --study results/studies/breakage_wall \
        [--cohesion4 DIR]  [--figures docs/img]  [--table table.md]

--cohesion4: the compact aggregate with four times the surface energy (breakage_wall.py --shapes bpca
--set material.surface_energy=0.04), for the v^2 / v_s^2 collapse.
"""
import argparse
import glob
import json
import math
import os

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LABELS = {"fractal": "fractal, D_f = 1.8", "bpca": "compact (BPCA)", "bpca4": "compact, 4 x surface energy"}


def sticking_speed(gamma):
    """v_s = 1.3678 sqrt(F_C delta_C / m) of a primary on a wall of its material (R* = r, m* = m): 0.02514 m/s
    for the seed material (docs/dem.md "Gas and walls", tests/dem), scaled as gamma^(5/6) (F_C ~ gamma,
    delta_C ~ gamma^(2/3)) [m/s]: the cohesion scale of the collapse."""
    return 0.02514 * (gamma / 0.01) ** (5.0 / 6.0)


def load(folder):
    """{speed: [breakage dicts with 'seconds']} of the finished runs under folder (one shape)."""
    out = {}
    for journal in glob.glob(os.path.join(folder, "v*", "journal.jsonl")):
        runs = {}
        for line in open(journal):
            d = json.loads(line)
            b = dict(d["result"]["breakage"], seconds=d.get("seconds", float("nan")), steps=d["result"]["steps"],
                     primaries=d["result"]["breakage"]["initial_contacts"] + 1)
            runs[d["index"]] = b
        if runs:
            v = float(os.path.basename(os.path.dirname(journal))[1:])
            out[v] = list(runs.values())
    return dict(sorted(out.items()))


def mean_se(x):
    x = np.asarray(x, dtype=float)
    return x.mean(), (x.std(ddof=1) / math.sqrt(len(x)) if len(x) > 1 else float("nan"))


def stats(runs):
    """Per speed: n and (mean, standard error) of the observables over the orientations."""
    rows = []
    for v, rs in runs.items():
        row = {"v": v, "n": len(rs), "seconds": float(np.mean([r["seconds"] for r in rs]))}
        row["damage"] = mean_se([r["damage_ratio"] for r in rs])
        row["largest"] = mean_se([r["largest_fragment_fraction"] for r in rs])
        row["fragments"] = mean_se([len(r["fragment_primaries"]) for r in rs])
        row["rebound"] = mean_se([r["rebound_energy_fraction"] for r in rs])
        row["rebounded"] = float(np.mean([1.0 if r["rebounded"] else 0.0 for r in rs]))
        rows.append(row)
    return rows


def size_density(rs, edges):
    """Fragments per run per unit size in the size bins [edges[k], edges[k+1]) (log bins), pooled."""
    counts = np.zeros(len(edges) - 1)
    for r in rs:
        sizes = np.asarray(r["fragment_primaries"])
        counts += np.histogram(sizes, bins=edges)[0]
    return counts / np.diff(edges) / len(rs), counts


def slope(rs, edges, smax, rng):
    """Log-log slope of the fragment-size density over sizes < smax and its bootstrap standard error
    (runs resampled): -tau of n(s) ~ s^-tau."""
    centres = np.sqrt(edges[:-1] * (edges[1:] - 1))
    use = edges[1:] - 1 <= smax

    def fit(sample):
        dens, counts = size_density(sample, edges)
        ok = use & (counts > 0)
        return np.polyfit(np.log(centres[ok]), np.log(dens[ok]), 1)[0] if ok.sum() >= 3 else float("nan")

    boot = [fit([rs[k] for k in rng.integers(0, len(rs), len(rs))]) for _ in range(200)]
    return fit(rs), float(np.nanstd(boot))


def table(all_stats, vs):
    lines = ["| aggregate | v [m/s] | (v/v_s)^2 | runs | damage ratio | largest fragment / N | fragments | "
             "rebound KE / impact KE | rebounded | wall s per run |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for shape, rows in all_stats.items():
        for r in rows:
            f = lambda ms, d=3: f"{ms[0]:.{d}f} ± {ms[1]:.{d}f}"
            lines.append(f"| {LABELS[shape]} | {r['v']:g} | {(r['v'] / vs[shape]) ** 2:.3g} | {r['n']} | "
                         f"{f(r['damage'])} | {f(r['largest'])} | {f(r['fragments'], 1)} | {f(r['rebound'])} | "
                         f"{r['rebounded']:.2f} | {r['seconds']:.0f} |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--study", default=os.path.join(ROOT, "results", "studies", "breakage_wall"))
    ap.add_argument("--cohesion4", default=None)
    ap.add_argument("--figures", default=os.path.join(ROOT, "docs", "img"))
    ap.add_argument("--table", default=None, help="write the markdown table here (default: print it)")
    a = ap.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    runs = {s: load(os.path.join(a.study, s)) for s in ("fractal", "bpca")}
    vs = {"fractal": sticking_speed(0.01), "bpca": sticking_speed(0.01), "bpca4": sticking_speed(0.04)}
    if a.cohesion4:
        runs["bpca4"] = load(os.path.join(a.cohesion4, "bpca"))
    runs = {s: r for s, r in runs.items() if r}
    st = {s: stats(r) for s, r in runs.items()}
    os.makedirs(a.figures, exist_ok=True)
    style = {"fractal": "o-", "bpca": "s-", "bpca4": "^--"}

    fig, ax = plt.subplots(1, 3, figsize=(14, 4))
    for s, rows in st.items():
        v = [r["v"] for r in rows]
        for k, (key, name) in enumerate([("damage", "damage ratio"), ("largest", "largest fragment / N"),
                                         ("rebound", "rebound KE / impact KE")]):
            ax[k].errorbar(v, [r[key][0] for r in rows], yerr=[r[key][1] for r in rows], fmt=style[s],
                           capsize=3, label=LABELS[s])
            ax[k].set_xscale("log")
            ax[k].set_xlabel("impact speed v [m/s]")
            ax[k].set_ylabel(name)
    ax[0].legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.figures, "breakage_wall_vs_speed.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(6, 4))
    for s, rows in st.items():
        x = [(r["v"] / vs[s]) ** 2 for r in rows]
        ax.errorbar(x, [r["damage"][0] for r in rows], yerr=[r["damage"][1] for r in rows], fmt=style[s],
                    capsize=3, label=f"{LABELS[s]} (v_s = {vs[s]:.4f} m/s)")
    ax.set_xscale("log")
    ax.set_xlabel("(v / v_s)^2   (v_s: sticking speed of one primary on the wall)")
    ax.set_ylabel("damage ratio")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.figures, "breakage_wall_collapse.png"), dpi=110)

    rng = np.random.default_rng(1)
    edges = np.array([1, 2, 3, 5, 9, 17, 33, 65, 129, 257, 513])
    fig, ax = plt.subplots(figsize=(6, 4))
    slopes = []
    for s in ("fractal", "bpca"):
        for v, rs in runs.get(s, {}).items():
            if np.mean([len(r["fragment_primaries"]) for r in rs]) < 10 or len(rs) < 3:
                continue  # too few fragments or runs for a distribution
            dens, counts = size_density(rs, edges)
            ok = counts > 0
            centres = np.sqrt(edges[:-1] * (edges[1:] - 1))
            ax.loglog(centres[ok], dens[ok], style[s][0] + "-", label=f"{LABELS[s]}, {v:g} m/s", alpha=0.8)
            tau, tau_se = slope(rs, edges, 16, rng)
            slopes.append((s, v, len(rs), -tau, tau_se))
    x = np.array([1.0, 100.0])
    ax.loglog(x, 30.0 * x ** -1.5, "k--", label="s^-3/2")
    ax.set_xlabel("fragment size s [primaries]")
    ax.set_ylabel("fragments per run per unit size")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(a.figures, "breakage_wall_fragments.png"), dpi=110)

    text = table(st, vs) + "\n\nFragment-size exponent tau of n(s) ~ s^-tau over s <= 16 (log bins, bootstrap over "
    text += "orientations):\n\n| aggregate | v [m/s] | runs | tau |\n|---|---|---|---|\n"
    text += "\n".join(f"| {LABELS[s]} | {v:g} | {n} | {t:.2f} ± {e:.2f} |" for s, v, n, t, e in slopes)
    text += f"\n\nv_s = {vs['bpca']:.5f} m/s (gamma = 0.01 J/m^2), {vs['bpca4']:.5f} m/s (0.04 J/m^2)\n"
    # Cost: time steps x particles of every run (a tree of N primaries has N - 1 contacts).
    ps = sum(r["steps"] * r["primaries"] for rs in runs.values() for v in rs.values() for r in v)
    text += (f"\n{sum(len(v) for rs in runs.values() for v in rs.values())} runs, {ps:.4g} particle-steps "
             f"({ps * 7.5e-8 / 60:.0f} CPU-minutes at the measured 7.5e-8 s per particle-step)\n")
    if a.table:
        open(a.table, "w").write(text)
    print(text)


if __name__ == "__main__":
    main()
