#!/usr/bin/env python3
"""Aggregate-wall breakage study (docs/studies/breakage_wall.md): runs `agglo breakup` for a fractal and a
compact (BPCA) aggregate at each speed, every run one of `orientations` stratified rotations of the aggregate.

For each shape the structure is first written by `agglo aggregate` (same [agglomerate] table) to find the
radius R_b of the sphere about the centroid that holds every primary; the wall plane is put at
x = R_b + 0.05 r (no orientation cuts it) and each speed v is observed for t = x_wall / v after the first
wall contact (the time the centroid needs to reach the wall plane at the launch speed), without extensions.
Every breakup runs with --threads 1 under `nice -n 19`, `--jobs` of them at a time, longest first;
an existing folder is continued with --resume (finished runs are kept). Results: OUT/<shape>/v<speed>/.

    /usr/bin/python3 scripts/studies/breakage_wall.py                   # the documented study
    /usr/bin/python3 scripts/studies/breakage_wall.py --primaries 1000  # the issue's upper size
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CASES = {"fractal": "cases/breakage_wall_fractal.toml", "bpca": "cases/breakage_wall_bpca.toml"}
SPEEDS = [0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 4.0]  # m/s


def bounding_radius(agglo, case, primaries):
    """R_b [m] and the primary radius [m] of the case's structure (agglo aggregate of its [agglomerate])."""
    with tempfile.TemporaryDirectory() as tmp:
        table, lines = None, []
        for line in open(case):
            s = line.strip()
            if s.startswith("["):
                table = s
            if s.startswith("name") or table == "[agglomerate]":
                lines.append(line)
        path = os.path.join(tmp, "structure.toml")
        with open(path, "w") as f:
            f.writelines(lines)
        subprocess.run([agglo, "-q", "aggregate", path, "--out", os.path.join(tmp, "a"), "--no-plots", "--threads",
                        "1", "--set", f"agglomerate.primaries={primaries}"], check=True)
        rows = list(csv.DictReader(open(os.path.join(tmp, "a", "aggregate.csv"))))
    rb = max(math.sqrt(sum(float(r[k]) ** 2 for k in "xyz")) + float(r["radius"]) for r in rows)
    return rb, max(float(r["radius"]) for r in rows)


def run(job):
    cmd, out, log = job
    t0 = time.time()
    with open(log, "w") as f:
        rc = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT).returncode
    print(f"{'ok ' if rc == 0 else 'FAILED'} {out} ({time.time() - t0:.0f} s)", flush=True)
    return rc


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--agglo", default=os.path.join(ROOT, "build", "agglo"))
    ap.add_argument("--out", default=os.path.join(ROOT, "results", "studies", "breakage_wall"))
    ap.add_argument("--shapes", default="fractal,bpca")
    ap.add_argument("--speeds", default=",".join(f"{v:g}" for v in SPEEDS), help="m/s, comma-separated")
    ap.add_argument("--primaries", type=int, default=500)
    ap.add_argument("--orientations", type=int, default=16)
    ap.add_argument("--jobs", type=int, default=2, help="breakup runs at a time (each --threads 1)")
    ap.add_argument("--set", action="append", default=[], help="extra key=value for every run")
    ap.add_argument("--cheapest-first", action="store_true",
                    help="run the fast (high-speed) points first, so that a study stopped early has them all; "
                         "the journals keep every finished run")
    ap.add_argument("--skip", default="", help="shape:speed points to leave out, comma-separated (e.g. bpca:0.02)")
    a = ap.parse_args()
    speeds = [float(v) for v in a.speeds.split(",")]
    jobs = []
    for shape in a.shapes.split(","):
        case = os.path.join(ROOT, CASES[shape])
        rb, r = bounding_radius(a.agglo, case, a.primaries)
        xw = rb + 0.05 * r
        print(f"{shape}: N = {a.primaries}, R_b = {rb * 1e6:.2f} um, wall at {xw * 1e6:.2f} um", flush=True)
        for v in speeds:
            if f"{shape}:{v:g}" in a.skip.split(","):
                continue
            out = os.path.join(a.out, shape, f"v{v:g}")
            os.makedirs(os.path.dirname(out), exist_ok=True)
            sets = [f"agglomerate.primaries={a.primaries}", f"wall.position=[{xw:.9g},0,0]",
                    f"time.after_contact={xw / v:.9g}", f"breakup.speeds=[{v:g}]",
                    f"breakup.orientations={a.orientations}", *a.set]
            cmd = ["nice", "-n", "19", a.agglo, "-q", "breakup", case, "--out", out, "--threads", "1", "--no-plots"]
            cmd += ["--resume"] if os.path.exists(os.path.join(out, "journal.jsonl")) else ["--overwrite"]
            for s in sets:
                cmd += ["--set", s]
            jobs.append((xw / v, (cmd, out, out + ".log")))
    jobs.sort(key=lambda j: j[0] if a.cheapest_first else -j[0])  # default: longest first
    with ThreadPoolExecutor(max_workers=a.jobs) as pool:
        codes = list(pool.map(run, [j for _, j in jobs]))
    sys.exit(1 if any(codes) else 0)


if __name__ == "__main__":
    main()
