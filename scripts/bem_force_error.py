#!/usr/bin/env python3
"""Force error of an electrostatic solver along a recorded impact (issue 11 item 3, docs/seed000.md).

Reads the VTK snapshots of an `agglo collide` run (positions, radii, charges), solves every frame again with
`agglo electrostatics` three ways -- a converged spectral reference, the case's spectral setting and the
seed's method (BEM, 2000 patches per sphere, GMRES tolerance 1e-4 by default) -- and writes per frame the
relative error of each particle's force against the reference (force_error.csv) and a plot.

Usage: bem_force_error.py RUN_DIR OUT_DIR [--agglo build/agglo] [--every N] [--set key=value ...]
  RUN_DIR   an `agglo collide` output folder (snapshots/*.vtp and config.resolved.toml)
  --set     extra settings for the BEM solves (e.g. electrostatics.patches_per_sphere=500)
"""
import argparse
import csv
import os
import subprocess
import sys
import tomllib

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtk_read import read  # noqa: E402  (binary VTK files, docs/outputs.md)


def read_vtp(path):
    """Positions (N x 3), radii, charges of one snapshot."""
    v = read(path)
    return v["Points/Points"], v["PointData/radius"][:, 0], v["PointData/charge"][:, 0]


def case_toml(x, r, q, kappa, medium, min_gap, solver, extra):
    lines = ["[electrostatics]", f'solver = "{solver}"', f"min_gap = {min_gap!r}", f"medium_permittivity = {medium!r}"]
    lines += [f"{k} = {v}" for k, v in extra]
    for i in range(len(r)):
        lines += ["", "[[particles]]", f"position = [{x[i, 0]!r}, {x[i, 1]!r}, {x[i, 2]!r}]", f"radius = {r[i]!r}",
                  f"charge = {q[i]!r}", f"permittivity = {kappa[i]!r}"]
    return "\n".join(lines) + "\n"


def solve(agglo, toml_text, work, name, sets):
    path = os.path.join(work, name + ".toml")
    out = os.path.join(work, name)
    done = os.path.exists(os.path.join(out, "forces.csv")) and os.path.exists(path) and open(path).read() == toml_text
    if not done or sets:  # an interrupted or repeated study reuses the solves it already has
        with open(path, "w") as f:
            f.write(toml_text)
        run(agglo, path, out, sets)
    f = np.genfromtxt(os.path.join(out, "forces.csv"), delimiter=",", names=True)
    return np.column_stack([f["fx"], f["fy"], f["fz"]])


def run(agglo, path, out, sets):
    cmd = [agglo, "-q", "--no-plots", "electrostatics", path, "--out", out, "--overwrite", "--threads", "1"]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run_dir")
    ap.add_argument("out_dir")
    ap.add_argument("--agglo", default="build/agglo")
    ap.add_argument("--every", type=int, default=1, help="use every N-th snapshot")
    ap.add_argument("--set", action="append", default=[], dest="sets")
    a = ap.parse_args()
    cfg = tomllib.load(open(os.path.join(a.run_dir, "config.resolved.toml"), "rb"))
    es = cfg["electrostatics"]
    kappa_agg = cfg["agglomerate"]["permittivity"]
    kappa_proj = cfg["projectile"]["permittivity"]
    snaps = sorted(f for f in os.listdir(os.path.join(a.run_dir, "snapshots")) if f.endswith(".vtp"))[:: a.every]
    work = os.path.join(a.out_dir, "solves")
    os.makedirs(work, exist_ok=True)
    spectral_case = [("target_accuracy", repr(es["target_accuracy"]))]
    reference = [("target_accuracy", "1e-7"), ("max_degree_limit", "120"), ("tolerance", "1e-10")]
    bem = [("patches_per_sphere", "2000"), ("tolerance", "1e-4")]
    rows = []
    for k, name in enumerate(snaps):
        x, r, q = read_vtp(os.path.join(a.run_dir, "snapshots", name))
        kappa = np.full(len(r), kappa_agg)
        kappa[-1] = kappa_proj  # the projectile is the last particle
        gap = min(np.linalg.norm(x[i] - x[j]) - r[i] - r[j] for i in range(len(r)) for j in range(i))
        args = (x, r, q, kappa, es["medium_permittivity"], es["min_gap"])
        f_ref = solve(a.agglo, case_toml(*args, "spectral", reference), work, f"ref_{k}", [])
        f_spec = solve(a.agglo, case_toml(*args, "spectral", spectral_case), work, f"spec_{k}", [])
        f_bem = solve(a.agglo, case_toml(*args, "bem", bem), work, f"bem_{k}", a.sets)
        scale = np.linalg.norm(f_ref, axis=1).max()
        row = {"frame": name, "min_surface_gap_over_r": gap / r.min(), "max_force_N": scale}
        for label, f in (("spectral", f_spec), ("bem", f_bem)):
            row[f"max_error_{label}"] = np.linalg.norm(f - f_ref, axis=1).max() / scale
            # > 1: the solver's forces are stronger than the reference along the reference forces
            row[f"projected_ratio_{label}"] = float(np.sum(f * f_ref) / np.sum(f_ref * f_ref))
        rows.append(row)
        print(f"{name}: gap/r {row['min_surface_gap_over_r']:.3g}, max force error spectral "
              f"{row['max_error_spectral']:.2e}, bem {row['max_error_bem']:.2e}", flush=True)
    tmp = os.path.join(a.out_dir, "force_error.csv.tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, os.path.join(a.out_dir, "force_error.csv"))
    for label in ("spectral", "bem"):
        e = np.array([r[f"max_error_{label}"] for r in rows])
        q = np.array([r[f"projected_ratio_{label}"] for r in rows])
        print(f"{label}: max force error median {np.median(e):.3g}, range {e.min():.3g}-{e.max():.3g}; "
              f"projected force ratio median {np.median(q):.3g}, range {q.min():.3g}-{q.max():.3g} ({len(rows)} frames)")
    plot(rows, a.out_dir)


def plot(rows, out_dir):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    i = np.arange(len(rows))
    ax.semilogy(i, [r["max_error_bem"] for r in rows], "o-", label="BEM, 2000 patches, tol 1e-4 (seed's method)")
    ax.semilogy(i, [r["max_error_spectral"] for r in rows], "s-", label="spectral, case setting")
    ax.set_xlabel("snapshot")
    ax.set_ylabel("max |F - F_ref| / max |F_ref|")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    tmp = os.path.join(out_dir, "force_error.tmp.png")
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, os.path.join(out_dir, "force_error.png"))


if __name__ == "__main__":
    sys.exit(main())
