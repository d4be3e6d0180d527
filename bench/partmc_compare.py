#!/usr/bin/python3
"""Analysis of bench/partmc_cases.sh: PartMC's coagulation benchmarks, agglo's DSMC against the
closed form (constant and additive kernels, exponential start) or agglo's sectional solver
(Brownian), with PartMC 2.9.0's own figures beside them.

  /usr/bin/python3 bench/partmc_compare.py OUT [--partmc-sectional tests/data/partmc/brown_sectional_N.csv]

Reads the jobs listed in OUT/jobs.txt: OUT/runs/<case>_<variant>_n<samples>_<selection>_s<seed>/{out/,time.txt},
OUT/sectional/brownian_<variant>/out/ and OUT/callgrind/<name>/callgrind.log; writes
OUT/partmc_runs.csv (one row per run) and OUT/partmc_cases.md (also printed).

Errors:
  N(T)  relative error (N_DSMC(T) - N_ref(T)) / N_ref(T); over the seeds: mean ± standard error, rms.
  L2    ||n - n_ref|| / ||n_ref|| over the bins of psd.csv at T (number per bin), and the same with
        each bin weighted by the volume at its centre diameter ("volume"; psd.csv holds numbers only).
        Per run, then averaged over the seeds; "of mean" is the L2 of the seed-averaged distribution
        (the bias part, the sampling noise averaged out).
References (tests/sectional/test_closed_form.cpp has the same formulas in C++):
  constant K, tau = K N0 t:   N = 2 N0/(2 + tau), n(v) = (N/vbar) exp(-v/vbar), vbar = N0 v0/N.
  additive b (v + v'), tau = b N0 v0 t, T = 1 - exp(-tau) (Golovin 1963):
      N = N0 exp(-tau), n(v) = N0 (1 - T)/(v sqrt(T)) exp(-(1 + T) v/v0) I_1(2 sqrt(T) v/v0).
  Brownian: `agglo sectional` on the same case (OUT/sectional), itself checked against PartMC's
      sectional N(t).
"""
import argparse
import csv
import math
import os
import re
import statistics
import sys
import tomllib

import numpy as np

# PartMC 2.9.0 particle-resolved runs on the same machine kind (2 cores, Debian 12, gfortran 12, CMake
# Release, one core; 3 timing runs each, output only at start and end; constant case with weight
# doubling): user CPU and wall ranges [s], peak resident memory [MiB], N(T) error over 10 seeds
# (mean, s.e., rms, %), size-distribution L2 (number, mass, %). Source: issue 10 and the same PartMC
# runs as tests/data/partmc/README.md. None: not measured.
PARTMC = {
    ("constant", 10000): dict(user=(0.99, 1.04), wall=(1.05, 1.15), rss=39, err=None, l2=None),
    ("constant", 100000): dict(user=(3.25, 4.22), wall=(3.97, 4.91), rss=160, err=(0.06, 0.10, 0.31), l2=None),
    ("additive", 100000): dict(user=(3.45, 3.93), wall=(4.66, 6.17), rss=170, err=(0.21, 0.34, 1.05),
                               l2=(3.4, 10.2)),
    ("brownian", 10000): dict(user=(6.34, 7.15), wall=(6.43, 9.27), rss=39, err=(-0.17, 0.27, 0.84), l2=None),
    ("brownian", 100000): dict(user=(8.86, 10.30), wall=(9.37, 11.66), rss=158, err=(-0.31, None, 0.36), l2=None),
}
PARTMC_END = {"constant": 18.0, "additive": 600.0, "brownian": 14400.0}
# PartMC at its best step (the largest step at which it keeps the accuracy of its test's step), where measured:
# user CPU range [s] and N(T) error mean ± s.e. [%] over 10 seeds, 1e5 particles. Brownian: PartMC 2.9.0 at
# agglo's 10 s step (1440 steps instead of 14400), recorded in issue 27 (same machine kind: 2 cores, Debian 12,
# gfortran 12, one core). Constant and additive: only their test's step was timed (PARTMC above).
PARTMC_BEST_STEP = {"brownian": dict(step=10.0, user=(2.6, 4.0), err=(0.04, 0.13))}
CASES = ("constant", "additive", "brownian")
RUN_NAME = re.compile(r"^(constant|additive|brownian)_(full|short)_n(\d+)_(\w+?)_s(\d+)$")


def read_table(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"partmc_compare.py: {path}: no rows")
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def final_state(out):
    """(T, N(T) [1/m^3], initial liquid volume fraction) from efficiency.csv."""
    e = read_table(os.path.join(out, "efficiency.csv"))
    return e["t_s"][-1], e["n_total_cm3"][-1] * 1e6, e["liquid_volume_fraction"][0]


def psd_at(out, t):
    """Bin edges [m] and number per bin [1/m^3] of psd.csv at time t (the nearest output time)."""
    p = read_table(os.path.join(out, "psd.csv"))
    times = np.unique(p["t_s"])
    sel = p["t_s"] == times[np.argmin(abs(times - t))]
    lo, hi = p["d_lo_m"][sel], p["d_hi_m"][sel]
    return lo, hi, p["total_dNdlogd_cm3"][sel] * 1e6 * np.log10(hi / lo)


def scaled_bessel_i1(x):
    """exp(-x) I_1(x), x >= 0: (1/pi) int_0^pi exp(x (cos th - 1)) cos th dth (trapezoid, spectrally
    accurate for this periodic integrand) below 700, the large-x expansion above."""
    x = np.asarray(x, dtype=float)
    out = np.empty_like(x)
    small = x < 700.0
    th = np.linspace(0.0, math.pi, 4097)
    w = np.full(th.size, th[1]); w[[0, -1]] *= 0.5
    xs = x[small][:, None]
    out[small] = (np.exp(xs * (np.cos(th) - 1.0)) * np.cos(th)) @ w / math.pi
    y = 1.0 / (8.0 * x[~small])
    out[~small] = (1.0 - 3.0 * y - 7.5 * y**2 - 52.5 * y**3) / np.sqrt(2.0 * math.pi * x[~small])
    return out


def golovin_bins(n0, v0, tau, v_lo, v_hi, order=16):
    """Number per volume interval of Golovin's solution (Gauss-Legendre in ln v, `order` points)."""
    T = -math.expm1(-tau)
    s = math.sqrt(T)
    xg, wg = np.polynomial.legendre.leggauss(order)
    a, b = np.log(v_lo)[:, None], np.log(v_hi)[:, None]
    v = np.exp(0.5 * (a + b) + 0.5 * (b - a) * xg)
    z = 2.0 * s * v / v0
    dens = n0 * (1.0 - T) / (v * s) * np.exp(-(1.0 + T) * v / v0 + z) * scaled_bessel_i1(z.ravel()).reshape(z.shape)
    return (dens * v * 0.5 * (b - a)) @ wg


def closed_form(case, cfg, t, d_lo, d_hi):
    """N(t) and the number per diameter bin of the closed-form solution (exponential start)."""
    pop = cfg["population"][0]
    n0, v0 = pop["number_concentration"], pop["mean_volume"]
    v_lo, v_hi = math.pi / 6 * d_lo**3, math.pi / 6 * d_hi**3
    if case == "constant":
        tau = cfg["kernels"]["constant_coefficient"] * n0 * t
        n = 2.0 * n0 / (2.0 + tau)
        vbar = n0 * v0 / n
        return n, n * (np.exp(-v_lo / vbar) - np.exp(-v_hi / vbar))
    tau = cfg["kernels"]["additive_coefficient"] * n0 * v0 * t
    return n0 * math.exp(-tau), golovin_bins(n0, v0, tau, v_lo, v_hi)


def rel_l2(a, b, w=1.0):
    return float(np.sqrt(np.sum((w * (a - b)) ** 2) / np.sum((w * b) ** 2)))


def reference(out_dir, case, variant, cfg, t, lo, hi):
    """(N_ref(T), number per bin, initial volume fraction or None) of a run's reference."""
    if case != "brownian":
        n, bins = closed_form(case, cfg, t, lo, hi)
        return n, bins, None
    sect = os.path.join(out_dir, "sectional", f"brownian_{variant}", "out")
    ts, n, vol0 = final_state(sect)
    if abs(ts - t) > 1e-9 * max(t, 1.0):
        raise SystemExit(f"partmc_compare.py: {sect} ends at {ts} s, the DSMC run at {t} s")
    slo, shi, bins = psd_at(sect, t)
    if not (np.allclose(slo, lo) and np.allclose(shi, hi)):
        raise SystemExit(f"partmc_compare.py: {sect}: psd bins differ from the DSMC run's")
    return n, bins, vol0


def read_time(path):
    """(wall, user, sys [s], peak RSS [kB]) from a /usr/bin/time -f '%e %U %S %M' file."""
    with open(path) as f:
        last = f.read().split("\n")
    vals = [ln for ln in last if ln.strip()][-1].split()
    return float(vals[0]), float(vals[1]), float(vals[2]), float(vals[3])


def job_names(out_dir, kind):
    """Names of the jobs of one kind (run, cg, sect) in OUT/jobs.txt: folders of earlier runs are ignored."""
    with open(os.path.join(out_dir, "jobs.txt")) as f:
        return [ln.split()[1] for ln in f if ln.split() and ln.split()[0] == kind]


def read_runs(out_dir):
    runs = []
    runs_dir = os.path.join(out_dir, "runs")
    for name in job_names(out_dir, "run"):
        m = RUN_NAME.match(name)
        if not m:
            raise SystemExit(f"partmc_compare.py: unexpected run name {name}")
        case, variant, n, sel, seed = m.group(1), m.group(2), int(m.group(3)), m.group(4), int(m.group(5))
        out = os.path.join(runs_dir, name, "out")
        with open(os.path.join(out, "config.resolved.toml"), "rb") as f:
            cfg = tomllib.load(f)
        t, n_t, vol0 = final_state(out)
        lo, hi, bins = psd_at(out, t)
        n_ref, ref_bins, ref_vol0 = reference(out_dir, case, variant, cfg, t, lo, hi)
        v_mid = math.pi / 6 * (lo * hi) ** 1.5
        wall, user, sys_s, rss = read_time(os.path.join(runs_dir, name, "time.txt"))
        runs.append(dict(case=case, variant=variant, samples=n, selection=sel, seed=seed, t_end=t,
                         N_T_m3=n_t, N_ref_m3=n_ref, rel_err=n_t / n_ref - 1.0,
                         l2_number=rel_l2(bins, ref_bins), l2_volume=rel_l2(bins, ref_bins, v_mid),
                         wall_s=wall, user_s=user, sys_s=sys_s, peak_rss_kB=rss,
                         volume0_ratio=(vol0 / ref_vol0 if ref_vol0 else 1.0),
                         _bins=bins, _ref=ref_bins, _w=v_mid))
    if not runs:
        raise SystemExit(f"partmc_compare.py: no runs under {runs_dir}")
    return runs


def group_stats(rs):
    e = np.array([r["rel_err"] for r in rs])
    mean_bins = np.mean([r["_bins"] for r in rs], axis=0)
    se = float(np.std(e, ddof=1) / math.sqrt(len(e))) if len(e) > 1 else float("nan")
    return dict(n=len(rs), t=rs[0]["t_end"], mean=float(e.mean()), se=se, rms=float(np.sqrt(np.mean(e**2))),
                l2n=float(np.mean([r["l2_number"] for r in rs])), l2v=float(np.mean([r["l2_volume"] for r in rs])),
                l2n_mean=rel_l2(mean_bins, rs[0]["_ref"]), l2v_mean=rel_l2(mean_bins, rs[0]["_ref"], rs[0]["_w"]),
                user=[r["user_s"] for r in rs], wall=[r["wall_s"] for r in rs],
                rss=max(r["peak_rss_kB"] for r in rs) / 1024, vol0=rs[0]["volume0_ratio"])


def fmt_range(xs, digits=2):
    lo, hi = min(xs), max(xs)
    return f"{lo:.{digits}f}" if f"{lo:.{digits}f}" == f"{hi:.{digits}f}" else f"{lo:.{digits}f}–{hi:.{digits}f}"


def samples_str(n):
    return f"{n:.0e}".replace("e+0", "e")


def ratio_str(x):
    return f"{x:.1f}" if x >= 1 else f"{x:.2f}"


def ratio_range(lo_hi, den):
    """'a–b×' for the range lo_hi divided by den; '–' when den is zero (a run below the timer's 10 ms)."""
    return f"{ratio_str(lo_hi[0] / den)}–{ratio_str(lo_hi[1] / den)}×" if den > 0 else "– (below 10 ms)"


def pct(x, digits=2):
    return "–" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{100 * x:+.{digits}f}"


def callgrind_counts(out_dir):
    counts = {}
    for name in job_names(out_dir, "cg") + job_names(out_dir, "cgb"):
        log = os.path.join(out_dir, "callgrind", name, "callgrind.log")
        m = re.search(r"Collected\s*:\s*(\d+)", open(log).read())
        if not m:
            raise SystemExit(f"partmc_compare.py: {log}: no 'Collected' line")
        counts[name] = int(m.group(1))
    return counts


def accuracy_table(groups):
    lines = ["| case | samples | selection | T [s] | seeds | N(T) error mean ± s.e. [%] | rms [%] "
             "| L2 number per run / of mean [%] | L2 volume per run / of mean [%] | user CPU [s] | wall [s] "
             "| peak RSS [MiB] |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for (case, variant, n, sel), g in groups.items():
        se = "–" if math.isnan(g["se"]) else f"{100 * g['se']:.2f}"
        lines.append(
            f"| {case} | {samples_str(n)} | {sel} | {g['t']:g} | {g['n']} | {pct(g['mean'])} ± {se} | {100 * g['rms']:.2f} "
            f"| {100 * g['l2n']:.1f} / {100 * g['l2n_mean']:.1f} | {100 * g['l2v']:.1f} / {100 * g['l2v_mean']:.1f} "
            f"| {fmt_range(g['user'])} | {fmt_range(g['wall'])} | {g['rss']:.0f} |")
    return lines


def speed_table(groups, sels, counts):
    """Per case and sample count: selection ratio (user CPU, instructions) and PartMC beside agglo."""
    ratio_name = f"{sels[0]}/{sels[1]}" if len(sels) > 1 else None
    head = ["case", "samples", "T [s]"]
    if ratio_name:
        head += [f"{ratio_name} user CPU", f"{ratio_name} instructions (1e4)"]
    head += [f"agglo {s} user CPU [s]" for s in sels] + [f"agglo {s} N(T) rms [%]" for s in sels]
    head += ["PartMC user CPU [s]", "PartMC wall [s]", "PartMC peak RSS [MiB]", "PartMC N(T) error ± s.e. / rms [%]"]
    head += [f"PartMC/agglo {s}" for s in sels]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    keys = sorted({(c, v, n) for (c, v, n, _) in groups}, key=lambda k: (CASES.index(k[0]), k[1], k[2]))
    for case, variant, n in keys:
        gs = {s: groups.get((case, variant, n, s)) for s in sels}
        t = next(g["t"] for g in gs.values() if g)
        row = [case, samples_str(n), f"{t:g}"]
        if ratio_name:
            a, b = gs[sels[0]], gs[sels[1]]
            row.append(f"{statistics.mean(a['user']) / statistics.mean(b['user']):.3f}"
                       if a and b and statistics.mean(b["user"]) > 0 else "–")  # – : nanbu under 0.01 s
            ca, cb = (counts.get(f"{case}_{variant}_n{n}_{s}") for s in sels[:2])
            row.append(f"{ca / cb:.3f} ({ca / 1e9:.2f} G / {cb / 1e9:.2f} G)" if ca and cb else "–")
        row += [fmt_range(gs[s]["user"]) if gs[s] else "–" for s in sels]
        row += [f"{100 * gs[s]['rms']:.2f}" if gs[s] else "–" for s in sels]
        p = PARTMC.get((case, n)) if t == PARTMC_END[case] else None
        if p:
            err = p["err"]
            row += [fmt_range(p["user"]), fmt_range(p["wall"]), f"{p['rss']}",
                    "–" if err is None else f"{err[0]:+.2f}" + (f" ± {err[1]:.2f}" if err[1] else "") + f" / {err[2]:.2f}"]
            row += [f"{ratio_str(p['user'][0] / statistics.mean(gs[s]['user']))}–"
                    f"{ratio_str(p['user'][1] / statistics.mean(gs[s]['user']))}×" if gs[s] else "–" for s in sels]
        else:
            row += ["–"] * (4 + len(sels))
        lines.append("| " + " | ".join(row) + " |")
    return lines


def equal_error_table(groups, sels):
    """Work at equal accuracy: per case and selection, the smallest sample count (full-length runs) whose N(T)
    rms plus one standard error of that rms is at or below PartMC's rms at 1e5 (conservative: agglo's rms over
    n seeds has a relative standard error of about 1/sqrt(2n)), and its CPU against PartMC's 1e5 run."""
    head = ["case", "selection", "PartMC 1e5 rms [%]", "agglo samples", "agglo rms ± s.e. of rms [%]",
            "agglo user CPU [s]", "PartMC 1e5 user CPU [s]", "PartMC/agglo", "PartMC best step: step [s], user CPU [s]",
            "PartMC best step/agglo"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for case in CASES:
        p = PARTMC.get((case, 100000))
        if not p or not p["err"]:
            continue
        for s in sels:
            cands = sorted((n, g) for (c, v, n, sel), g in groups.items()
                           if c == case and v == "full" and sel == s and g["t"] == PARTMC_END[case])
            hit = next(((n, g) for n, g in cands if 100 * g["rms"] * (1 + 1 / math.sqrt(2 * g["n"])) <= p["err"][2]),
                       None)
            if not hit:
                lines.append(f"| {case} | {s} | {p['err'][2]:.2f} | none of {[samples_str(n) for n, _ in cands]} | – | – "
                             f"| {fmt_range(p['user'])} | – | – | – |")
                continue
            n, g = hit
            mean_cpu = statistics.mean(g["user"])
            best = PARTMC_BEST_STEP.get(case)
            best_cols = (f"{best['step']:g}, {fmt_range(best['user'])} | {ratio_range(best['user'], mean_cpu)}"
                         if best else "not measured | –")
            lines.append(f"| {case} | {s} | {p['err'][2]:.2f} | {samples_str(n)} | {100 * g['rms']:.2f} ± "
                         f"{100 * g['rms'] / math.sqrt(2 * g['n']):.2f} | {fmt_range(g['user'])} | {fmt_range(p['user'])} "
                         f"| {ratio_range(p['user'], mean_cpu)} | {best_cols} |")
    return lines


def sectional_check(out_dir, partmc_csv):
    """Largest relative difference of agglo's sectional N(t) from PartMC's sectional N(t)."""
    sect = os.path.join(out_dir, "sectional", "brownian_full", "out", "efficiency.csv")
    if not (partmc_csv and os.path.exists(sect)):
        return None
    a, p = read_table(sect), read_table(partmc_csv)
    common, ia, ip = np.intersect1d(a["t_s"], p["time_s"], return_indices=True)
    if common.size == 0:
        return None
    d = a["n_total_cm3"][ia] * 1e6 / p["N_m3"][ip] - 1.0
    return float(np.max(abs(d))), float(common[-1]), float(d[-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--partmc-sectional", default=None, help="PartMC's sectional N(t) of the Brownian case")
    args = ap.parse_args()
    runs = read_runs(args.out)
    sels = list(dict.fromkeys(r["selection"] for r in runs))
    with open(os.path.join(args.out, "partmc_runs.csv"), "w", newline="") as f:
        cols = [k for k in runs[0] if not k.startswith("_")]
        w = csv.DictWriter(f, fieldnames=cols, extrasaction="ignore")
        w.writeheader()
        w.writerows(runs)
    order = lambda r: (CASES.index(r["case"]), r["variant"], r["samples"], sels.index(r["selection"]))
    groups = {}
    for r in sorted(runs, key=order):
        groups.setdefault((r["case"], r["variant"], r["samples"], r["selection"]), []).append(r)
    groups = {k: group_stats(v) for k, v in groups.items()}
    counts = callgrind_counts(args.out)

    md = ["## PartMC's coagulation benchmarks: agglo DSMC (bench/partmc_cases.sh)", ""]
    settings = os.path.join(args.out, "settings.txt")
    if os.path.exists(settings):
        md += ["```", open(settings).read().strip(), "```", ""]
    md += ["Accuracy and cost per run (user CPU, wall and peak memory of the whole process, one thread; "
           "ranges over the seeds):", ""] + accuracy_table(groups)
    md += ["", "Speed: selections compared in the same script, and PartMC 2.9.0 (same machine kind, one core, "
           "3 runs; PartMC/agglo = PartMC's user CPU range over agglo's mean):", ""]
    md += speed_table(groups, sels, counts)
    md += ["", "Equal accuracy: the fewest samples (of those run) whose N(T) rms over the seeds, plus one standard "
           "error of that rms (relative 1/sqrt(2 seeds)), is at or below PartMC's rms at 1e5, and their CPU against "
           "PartMC's 1e5 run at its test's step and, where it was timed, at its best step (PARTMC_BEST_STEP: the "
           "Brownian case at 10 s, as accurate as at 1 s, recorded in issue 27; PartMC is not run by the script):", ""]
    md += equal_error_table(groups, sels)
    if counts:
        md += ["", "Instructions (valgrind --tool=callgrind, whole process, seed 1): "
               + ", ".join(f"{k} {v / 1e9:.3f} G" for k, v in counts.items())]
        pairs = [(k, counts[k], counts[k + "_before"]) for k in counts if k + "_before" in counts]
        if pairs:
            md += ["", "Before/after (BEFORE_AGGLO, the same runs): "
                   + ", ".join(f"{k} {b / 1e9:.3f} → {a / 1e9:.3f} G ({a / b:.3f}×)" for k, a, b in pairs)]
    chk = sectional_check(args.out, args.partmc_sectional)
    notes = ["", "Notes:",
             "- Reference: closed form (constant, additive); `agglo sectional` for the Brownian case "
             "(run by the script on the same case file)."]
    if chk:
        notes.append(f"- agglo sectional vs PartMC's sectional N(t) (every 60 s up to {chk[1]:g} s): largest "
                     f"relative difference {chk[0]:.1e}, {chk[2]:+.1e} at {chk[1]:g} s.")
    for label, variant in (("full", "full"), ("shortened", "short")):
        vols = {g["vol0"] for (c, v, _, _), g in groups.items() if c == "brownian" and v == variant}
        if vols:
            notes.append(f"- Brownian ({label} runs): the DSMC's initial volume is {100 * (min(vols) - 1):+.1f} % of the "
                         "sectional's (the DSMC samples the lognormal on d_g σ_g^±population.lognormal_range: 5.5 in "
                         "the case file, SHORT_RANGE for the shortened runs; the sectional takes it whole).")
    md += notes
    text = "\n".join(md) + "\n"
    with open(os.path.join(args.out, "partmc_cases.md"), "w") as f:
        f.write(text)
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
