#!/usr/bin/env python3
"""Fly-ash outcome study (docs/studies/flyash_outcomes.md): acoustic agglomeration of fly ash at 1400 Hz and
147 dB (cases/flyash_147db.toml, 4 s) with four dry outcome models, each a seed ensemble of `agglo acoustic`:

  default      the seed's closed-form critical velocity (Hamaker formula, eq. 13 of docs/acoustics.md)
  spheres      a DEM sphere-sphere table of the fly-ash material (cases/outcomes_flyash_spheres.toml)
  spheres_seed the same grid with the seed material (E = 1 GPa, gamma = 0.01 J/m^2, e = 0.7, friction 0.3)
  aggregates   a DEM table of BPCA aggregates of 0.25 um fly-ash primaries (cases/outcomes_flyash_aggregates.toml),
               read by the DSMC over volume-equivalent diameters (its samples stay compact spheres)
  aggregates_structured  the same table with structure-aware samples (docs/acoustics.md §1.8): the population
               is fractal, 0.25 um primaries, D_f and k_f of the table's BPCA partners (SETS_OF below), so the
               kernels use the collision radius and the drag the mobility radius (= the collision radius)
  aggregates_structured_273  the same with BPCA's large-N D_f = 2.73 (a sensitivity to the extrapolation)

The tables are built first with `agglo outcomes -j THREADS`; the user and system CPU of each build (the
children's rusage) and its wall time are reported and written to OUT/study.json with, per variant and
output time, the mean, standard deviation and standard error over the seeds of the number reduction
1 - N(t)/N(0), of the PM2.5 mass reductions (volume-equivalent and aerodynamic diameter) and, at the PSD
times, of the number below 2.5 um (Zhang et al. 2009 report PM2.5 as a number concentration), the
fractions of dry collisions that stuck, bounced and broke, and the table queries that were clamped. A
table already in OUT/study.json is not built again (its measured cost is kept); finished members are reused.

    /usr/bin/python3 scripts/studies/flyash_outcomes.py --agglo build/agglo --out results/flyash_outcomes
    /usr/bin/python3 scripts/studies/plot_flyash_outcomes.py results/flyash_outcomes/study.json docs/img
"""
import argparse
import csv
import json
import math
import os
import resource
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CASE = "cases/flyash_147db.toml"
SEED_MATERIAL = ["material.youngs_modulus=1e9", "material.poisson_ratio=0.33", "material.surface_energy=0.01",
                 "material.restitution=0.7", "material.friction=0.3"]
TABLES = {  # variant: (table case, --set overrides)
    "spheres": ("cases/outcomes_flyash_spheres.toml", []),
    "spheres_seed": ("cases/outcomes_flyash_spheres.toml", SEED_MATERIAL),
    "aggregates": ("cases/outcomes_flyash_aggregates.toml", []),
}
# Structure-aware samples: D_f, k_f of the characteristic radius sqrt(5/3) R_g (R_g with each sphere's 3/5 a^2)
# of BPCA aggregates of the table's builder, a = 0.25 um, prefixes N = 2 ... 64 of 30 aggregates of 64
# (seeds 1-30, `agglo aggregate cases/aggregate_bpca.toml`), least squares of ln(a_c/a) on ln N: D_f = 2.23,
# k_f = 0.60; the sensitivity variant takes BPCA's D_f = 2.73 (docs/model.md §S.3) with k_f = 0.244 fitted
# to the same prefixes N = 16 ... 64.
def structure(df, kf):
    return ["population.0.structure=\"fractal\"", "population.0.primary_radius=0.25e-6",
            f"population.0.fractal_dimension={df}", f"population.0.fractal_prefactor={kf}"]
TABLE_OF = {"aggregates_structured": "aggregates", "aggregates_structured_273": "aggregates"}  # another's table
SETS_OF = {"aggregates_structured": structure(2.23, 0.60),  # further --set of a variant's DSMC runs
           "aggregates_structured_273": structure(2.73, 0.244)}
VARIANTS = ["default", "spheres", "spheres_seed", "aggregates", "aggregates_structured", "aggregates_structured_273"]
COLUMNS = ["number_reduction", "pm2_5_vol_reduction", "pm2_5_aero_reduction"]


def timed(cmd):
    """Runs cmd; returns (user + system CPU of the child [s], wall [s])."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    subprocess.run(cmd, check=True, cwd=ROOT)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return after.ru_utime - before.ru_utime, after.ru_stime - before.ru_stime, time.monotonic() - t0


def build_table(args, variant):
    case, sets = TABLES[variant]
    out = os.path.join(args.out, "table_" + variant)
    earlier = os.path.join(args.out, "study.json")
    if os.path.exists(earlier) and variant in json.load(open(earlier))["tables"]:
        return json.load(open(earlier))["tables"][variant]  # built before: keep its measured cost
    cmd = [args.agglo, "-q", "--no-plots", "outcomes", case, "--out", out, "--threads", str(args.threads)]
    cmd += [a for s in sets for a in ("--set", s)]
    cmd += ["--resume"] if os.path.exists(os.path.join(out, "journal.jsonl")) else ["--overwrite"]
    user, system, wall = timed(cmd)
    rows = list(csv.DictReader(open(os.path.join(out, "outcomes.csv"))))
    run = [r for r in rows if float(r["diameter_1"]) <= float(r["diameter_2"])]  # (d2, d1) copies (d1, d2)
    print(f"table {variant}: {len(run)} nodes, {sum(int(r['impacts']) for r in run)} impacts, "
          f"{user:.1f} s user + {system:.1f} s sys CPU, {wall:.1f} s wall on {args.threads} threads", flush=True)
    return {"case": case, "sets": sets, "user_s": user, "sys_s": system, "wall_s": wall, "threads": args.threads,
            "impacts": sum(int(r["impacts"]) for r in run), "nodes": rows}


def pm2_5_number(folder):
    """{psd time: number concentration [cm^-3] of the particles below 2.51 um} from psd.csv: the bins of
    10^(1/15) (dN/dlog10 d) whose upper edge is at most 10^-5.6 m = 2.512 um (volume-equivalent diameter)."""
    out = {}
    for r in csv.DictReader(open(os.path.join(folder, "psd.csv"))):
        lo, hi = float(r["d_lo_m"]), float(r["d_hi_m"])
        if hi <= 2.512e-6 * (1 + 1e-6):
            t = float(r["t_s"])
            out[t] = out.get(t, 0.0) + float(r["total_dNdlogd_cm3"]) * math.log10(hi / lo)
    return out


def member_series(folder):
    """{time: {column: value}} of one member's efficiency.csv, {psd time: reduction of the number below
    2.5 um}, and its dry outcome fractions."""
    rows = list(csv.DictReader(open(os.path.join(folder, "efficiency.csv"))))
    n0 = float(rows[0]["n_total_cm3"])
    series = {}
    for r in rows:
        series[float(r["t_s"])] = {"number_reduction": 1.0 - float(r["n_total_cm3"]) / n0,
                                   "pm2_5_vol_reduction": float(r["pm2_5_vol_reduction"]),
                                   "pm2_5_aero_reduction": float(r["pm2_5_aero_reduction"])}
    small = pm2_5_number(folder)
    psd = {t: 1.0 - small[t] / small[0.0] for t in sorted(small)}
    dry = next(r for r in csv.DictReader(open(os.path.join(folder, "outcomes_by_pair.csv"))) if r["pair_type"] == "dry")
    nanbu = json.load(open(os.path.join(folder, "summary.json"))).get("nanbu", {})
    return series, psd, {"collisions": int(dry["pair_collisions"]), "stuck": float(dry["stuck_fraction"]),
                    "bounced": float(dry["bounced_fraction"]), "broke": float(dry["broke_fraction"]),
                    "queries": nanbu.get("outcome_table_queries", 0), "clamped": nanbu.get("outcome_table_clamped", 0)}


def stats(values):
    n = len(values)
    mean = sum(values) / n
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1)) if n > 1 else 0.0
    return {"mean": mean, "sd": sd, "se": sd / math.sqrt(n), "n": n}


def run_variant(args, variant, table):
    out = os.path.join(args.out, "dsmc_" + variant)
    cmd = [args.agglo, "-q", "--no-plots", "acoustic", CASE, "--out", out, "--seeds", str(args.seeds),
           "--threads", str(args.threads)]
    if args.end:
        cmd += ["--set", f"time.end={args.end}", "--set", f"output.psd_times=[0.0,{args.end}]",
                "--set", "output.snapshot_times=[0.0]"]
    if table is not None:
        tables = args.tables_from or args.out
        name = TABLE_OF.get(variant, variant)
        cmd += ["--set", "outcomes.dry_model=table",
                "--set", f'outcomes.table="{os.path.join(tables, "table_" + name, "results.nc")}"']
    cmd += [a for s in SETS_OF.get(variant, []) for a in ("--set", s)]
    cmd += ["--resume"] if os.path.exists(os.path.join(out, "journal.jsonl")) else ["--overwrite"]
    user, system, wall = timed(cmd)
    members = sorted(d for d in os.listdir(out) if d.startswith("case_"))
    runs = [member_series(os.path.join(out, m)) for m in members]
    times, psd_times = sorted(runs[0][0]), sorted(runs[0][1])
    result = {"members": members, "user_s": user, "sys_s": system, "wall_s": wall, "times": times,
              "series": {c: [stats([r[0][t][c] for r in runs]) for t in times] for c in COLUMNS},
              "psd_times": psd_times, "pm2_5_number_reduction": [stats([r[1][t] for r in runs]) for t in psd_times],
              "dry": {k: stats([r[2][k] for r in runs]) for k in runs[0][2]}}
    last = {c: result["series"][c][-1] for c in COLUMNS}
    print(f"{variant}: {len(members)} seeds, t = {times[-1]} s: number -{last['number_reduction']['mean']:.3f} "
          f"(s.e. {last['number_reduction']['se']:.4f}), PM2.5 vol -{last['pm2_5_vol_reduction']['mean']:.3f} "
          f"(s.e. {last['pm2_5_vol_reduction']['se']:.4f}), aero -{last['pm2_5_aero_reduction']['mean']:.3f}, "
          f"number below 2.5 um -{result['pm2_5_number_reduction'][-1]['mean']:.3f}; dry stuck "
          f"{result['dry']['stuck']['mean']:.3f} broke {result['dry']['broke']['mean']:.3f}; "
          f"{user:.0f} s user CPU", flush=True)
    return result


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--agglo", default=os.path.join(ROOT, "build", "agglo"))
    p.add_argument("--out", default=os.path.join(ROOT, "results", "flyash_outcomes"))
    p.add_argument("--seeds", type=int, default=6)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--end", type=float, default=None, help="shorter simulated time [s] (default: the case's 4 s)")
    p.add_argument("--variants", default=",".join(VARIANTS))
    p.add_argument("--tables-only", action="store_true", help="build the tables and report their cost")
    p.add_argument("--tables-from", default=None,
                   help="use the tables of this earlier study folder (its study.json) instead of building them")
    args = p.parse_args()
    args.agglo, args.out = os.path.abspath(args.agglo), os.path.abspath(args.out)
    args.tables_from = os.path.abspath(args.tables_from) if args.tables_from else None
    os.makedirs(args.out, exist_ok=True)
    variants = args.variants.split(",")
    study = {"case": CASE, "seeds": args.seeds, "tables": {}, "variants": {}}
    path = os.path.join(args.out, "study.json")
    for v in dict.fromkeys(TABLE_OF.get(v, v) for v in variants):
        if v in TABLES:
            study["tables"][v] = earlier_table(args.tables_from, v) if args.tables_from else build_table(args, v)
            save(study, path)
    if not args.tables_only:
        for v in variants:
            study["variants"][v] = run_variant(args, v, study["tables"].get(TABLE_OF.get(v, v)))
            save(study, path)
    return 0


def earlier_table(folder, variant):
    """The table entry of an earlier study folder: from its study.json, else its nodes alone (cost unknown)."""
    path = os.path.join(folder, "study.json")
    tables = json.load(open(path))["tables"] if os.path.exists(path) else {}
    if variant in tables:
        return tables[variant]
    rows = list(csv.DictReader(open(os.path.join(folder, "table_" + variant, "outcomes.csv"))))
    return {"case": TABLES[variant][0], "sets": TABLES[variant][1], "nodes": rows, "cost": "not measured here"}


def save(study, path):
    with open(path + ".tmp", "w") as f:
        json.dump(study, f, indent=1)
    os.replace(path + ".tmp", path)


if __name__ == "__main__":
    sys.exit(main())
