#!/usr/bin/python3
"""Wall time of one collision run (approach + 2 ms after first contact, 5 particles): agglo vs LAMMPS.

    time_collision.py AGGLO_EXE CASE.toml --speed 0.18 [--set key=value ...] [--reps 10] [--json OUT]
                      [--format csv]   (agglo's output format; default: agglo's default, results.nc)

Each repetition runs, alternately, one `lmp` process on the input written by lmp_case.py and one
`agglo collide` process (-j 1, output.snapshot_interval = 0 so that it, like LAMMPS, writes only the
end state and a small time series). Reports per code the median and minimum of
  - process wall time (start-up, input, run, output; agglo's also includes its plot script), and
  - simulation time: LAMMPS "Loop time", agglo run.json wall_time_s minus nothing (it covers the
    case set-up, the run and the CSV/JSON output, not the plot script).
Both codes run serially with the same time step and number of steps.
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lmp_case  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("agglo")
    ap.add_argument("case")
    ap.add_argument("--speed", type=float, default=0.18)
    ap.add_argument("--set", action="append", default=[], dest="sets")
    ap.add_argument("--reps", type=int, default=10)
    ap.add_argument("--json", default="")
    ap.add_argument("--format", default="")
    a = ap.parse_args()

    setup = lmp_case.Setup(lmp_case.load_case(a.case, a.sets))
    work = tempfile.mkdtemp(prefix="agglo_timing_")
    nsteps = setup.contact_steps(a.speed) + int(-(-setup.after_contact // setup.dt))
    with open(os.path.join(work, "in.collision"), "w") as f:
        f.write(setup.lammps_input(a.speed, nsteps, "end.dump"))
    agglo_cmd = [os.path.abspath(a.agglo), "--no-plots", "collide", os.path.abspath(a.case), "--speed", repr(a.speed), "-j", "1",
                 "--set", "time.early_stop=false",  # same simulated time as LAMMPS
                 "--set", "output.snapshot_interval=0", "--out", os.path.join(work, "agglo_out"),
                 "--overwrite"]  # every repetition writes into the same folder
    for s in a.sets:
        agglo_cmd += ["--set", s]
    if a.format:
        agglo_cmd += ["--format", a.format]
    lmp_cmd = [lmp_case.LMP, "-in", "in.collision", "-log", "log.lammps", "-screen", "none", "-nocite"]
    env = dict(os.environ, OMP_NUM_THREADS="1")

    t = {"lammps_process_s": [], "lammps_loop_s": [], "agglo_process_s": [], "agglo_run_json_s": []}
    agglo_steps = None
    for rep in range(a.reps):
        t0 = time.perf_counter()
        subprocess.run(lmp_cmd, cwd=work, check=True, env=env, stdout=subprocess.DEVNULL)
        t["lammps_process_s"].append(time.perf_counter() - t0)
        for line in open(os.path.join(work, "log.lammps")):
            if line.startswith("Loop time of"):
                t["lammps_loop_s"].append(float(line.split()[3]))
        t0 = time.perf_counter()
        subprocess.run(agglo_cmd, cwd=work, check=True, env=env, stdout=subprocess.DEVNULL)
        t["agglo_process_s"].append(time.perf_counter() - t0)
        with open(os.path.join(work, "agglo_out", "run.json")) as f:
            t["agglo_run_json_s"].append(json.load(f)["wall_time_s"])
        with open(os.path.join(work, "agglo_out", "result.json")) as f:
            agglo_steps = json.load(f)["steps"]
    shutil.rmtree(work, ignore_errors=True)

    summary = {k: {"median": statistics.median(v), "min": min(v), "all": v} for k, v in t.items()}
    summary["steps_lammps"] = nsteps
    summary["steps_agglo"] = agglo_steps
    summary["dt_s"] = setup.dt
    summary["speed_m_per_s"] = a.speed
    summary["ratio_process_median"] = summary["lammps_process_s"]["median"] / summary["agglo_process_s"]["median"]
    summary["ratio_simulation_median"] = summary["lammps_loop_s"]["median"] / summary["agglo_run_json_s"]["median"]
    print(f"one collision run, v = {a.speed} m/s, {nsteps} LAMMPS steps / {agglo_steps} agglo steps, "
          f"dt = {setup.dt:.6g} s, {a.reps} repetitions (median / min):")
    for k in t:
        print(f"  {k:18s} {summary[k]['median']:.4f} s / {summary[k]['min']:.4f} s")
    print(f"  speed-up of agglo, process wall time:   {summary['ratio_process_median']:.2f}x")
    print(f"  speed-up of agglo, simulation (LAMMPS loop / agglo run.json): "
          f"{summary['ratio_simulation_median']:.2f}x")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(summary, f, indent=1)


if __name__ == "__main__":
    main()
