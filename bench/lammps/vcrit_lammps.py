#!/usr/bin/python3
"""Critical break-up velocity with LAMMPS, by the same search as `agglo vcrit`
(src/agglo/impact/vcrit.cpp): a scan of vcrit.scan_points speeds on [v_min, v_max], then rounds
of `parallel` equally spaced speeds inside the bracket above the highest non-breaking speed, until
the bracket is narrower than vcrit.tolerance; v_crit = upper end of the bracket.

    vcrit_lammps.py CASE.toml [--set key=value ...] [--workdir DIR] [--parallel 2] [--json OUT]
"""
import argparse
import json
import os
import sys
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_case  # noqa: E402


def find_vcrit(setup, workdir, parallel=2, log=print):
    vc = setup.vc
    runs = []
    counter = [0]

    def run_all(speeds):
        dirs = []
        for v in speeds:
            dirs.append(os.path.join(workdir, f"run{counter[0]:03d}"))
            counter[0] += 1
        # the speeds in `parallel` batches, each one lmp process (lmp_case.run_lammps_many), then the
        # undecided ones extended one by one
        chunks = [(speeds[k::parallel], dirs[k::parallel]) for k in range(min(parallel, len(speeds)))]
        with ThreadPoolExecutor(max_workers=parallel) as ex:
            firsts = list(ex.map(lambda c: lmp_case.run_lammps_many(setup, *c), chunks))
        by_dir = {d: r for c, rs in zip(chunks, firsts) for d, r in zip(c[1], rs)}
        with ThreadPoolExecutor(max_workers=parallel) as ex:
            res = list(ex.map(lambda a: lmp_case.run_decided(setup, a[0], a[1], first=by_dir[a[1]]),
                              zip(speeds, dirs)))
        for r in res:
            log(f"  LAMMPS v = {r['speed_m_per_s']:.6f} m/s -> "
                f"{'broken' if r['broken'] else ('undecided' if r['undecided'] else 'not broken')}")
        return res

    n = vc["scan_points"]
    scan = [vc["v_min"] + (vc["v_max"] - vc["v_min"]) * k / (n - 1) for k in range(n)]
    runs += run_all(scan)
    rounds = 0
    while True:
        runs.sort(key=lambda r: r["speed_m_per_s"])
        nb = [r for r in runs if not r["broken"]]
        if not nb:
            raise SystemExit("vcrit_lammps: every speed breaks; lower vcrit.v_min")
        lo = nb[-1]["speed_m_per_s"]
        above = [r for r in runs if r["speed_m_per_s"] > lo]
        if not above:
            raise SystemExit("vcrit_lammps: no break-up up to v_max")
        hi = above[0]["speed_m_per_s"]
        if hi - lo <= vc["tolerance"]:
            break
        runs += run_all([lo + (hi - lo) * (k + 1) / (parallel + 1) for k in range(parallel)])
        rounds += 1
    warnings = []
    for r in runs:
        if r["broken"] and r["speed_m_per_s"] < lo:
            warnings.append(f"non-monotonic: v = {r['speed_m_per_s']:.6g} m/s breaks but v = {lo:.6g} m/s does not")
        if r["undecided"]:
            warnings.append(f"undecided outcome at v = {r['speed_m_per_s']:.6g} m/s (counted as not broken)")
        if r["ambiguous_pairs"]:
            warnings.append(f"{r['ambiguous_pairs']} pair(s) in the JKR tension band at the end, v = "
                            f"{r['speed_m_per_s']:.6g} m/s")
    return {"v_crit": hi, "bracket": [lo, hi], "rounds": rounds, "dt_s": setup.dt,
            "runs": [{"v": r["speed_m_per_s"], "broken": r["broken"], "undecided": r["undecided"],
                      "lammps_loop_time_s": r["lammps_loop_time_s"], "steps": r["steps"]} for r in runs],
            "warnings": warnings}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--set", action="append", default=[], dest="sets")
    ap.add_argument("--workdir", default="lmp_vcrit")
    ap.add_argument("--parallel", type=int, default=2)
    ap.add_argument("--json", default="")
    a = ap.parse_args()
    setup = lmp_case.Setup(lmp_case.load_case(a.case, a.sets))
    res = find_vcrit(setup, a.workdir, max(2, a.parallel))
    text = json.dumps(res, indent=1)
    if a.json:
        with open(a.json, "w") as f:
            f.write(text + "\n")
    print(f"LAMMPS v_crit = {res['v_crit']:.6f} m/s, bracket [{res['bracket'][0]:.6f}, {res['bracket'][1]:.6f}]")
    for w in res["warnings"]:
        print("warning:", w)


if __name__ == "__main__":
    main()
