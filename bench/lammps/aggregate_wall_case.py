#!/usr/bin/env python3
"""LAMMPS twin of bench_dem_scaling's fractal aggregate hitting a wall (BM_DemAggregateWall,
docs/benchmarks_dem.md §5).

Reads the start state that BM_DemAggregateWall writes (AGGLO_AGGWALL_DUMP): a header "# dt primaries",
then "x y z r density vx vy vz" per particle: agglo's structure builder's aggregate, scaled to the JKR
equilibrium overlap, moving along +x onto the wall, a frozen layer of spheres of the same radius and
material and density 1e30 kg/m^3 (so they stay put and m* of a contact is the primary's mass). The
same contact law as the block (block_case.py: pair granular jkr ... damping tsuji tangential mindlin,
with the case's e = 0.7), fix nve/sphere on every particle as agglo integrates every particle.
Why not `fix wall/gran granular jkr`: in this LAMMPS (29 Sep 2021) a sphere reaching such a wall from a
gap turns into NaN the step it touches (any damping or tangential model), and a sphere at rest on it
has the equilibrium overlap of E* = E / (2 (1 - nu)), not E / (2 (1 - nu^2)).
Runs WARM steps, then STEPS timed steps (the same dt), and prints one JSON line as block_case.py, with
ke_end, the translational kinetic energy after the last step [J] (agglo's counter of the same name).

  aggregate_wall_case.py STATE_FILE [--steps 1000] [--warm 200] [--lmp lmp] [--workdir DIR]
"""
import argparse
import json
import os
import tempfile

from block_case import R_SPHERE, lammps_input, run_measured

E_REST_AGG = 0.7  # cases/breakage_wall_fractal.toml's restitution (the block's E_REST is 0.9)


def read_state(path):
    with open(path) as f:
        head = f.readline().split()
        dt, primaries = float(head[1]), int(head[2])
        rows = [[float(v) for v in line.split()] for line in f if line.strip()]
    return dt, primaries, rows


def write_data(path, rows, primaries):
    lo = [min(r[c] - r[3] for r in rows) - 2.0 * R_SPHERE for c in range(3)]
    hi = [max(r[c] + r[3] for r in rows) + 2.0 * R_SPHERE for c in range(3)]
    with open(path, "w") as f:
        f.write(f"agglo fractal aggregate of {primaries} primaries and its wall layer\n\n{len(rows)} atoms\n1 atom types\n\n")
        for c, name in enumerate("xyz"):
            f.write(f"{lo[c]!r} {hi[c]!r} {name}lo {name}hi\n")
        f.write("\nAtoms # sphere\n\n")
        for k, r in enumerate(rows):
            f.write(f"{k + 1} 1 {2.0 * r[3]!r} {r[4]!r} {r[0]!r} {r[1]!r} {r[2]!r}\n")
        f.write("\nVelocities\n\n")
        for k, r in enumerate(rows):
            f.write(f"{k + 1} {r[5]!r} {r[6]!r} {r[7]!r} 0 0 0\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("state")
    ap.add_argument("--steps", type=int, default=1000)
    ap.add_argument("--warm", type=int, default=200)
    ap.add_argument("--lmp", default=os.environ.get("LMP", "lmp"))
    ap.add_argument("--workdir", default=None)
    a = ap.parse_args()
    dt, primaries, rows = read_state(a.state)
    work = a.workdir or tempfile.mkdtemp(prefix="lmp_aggwall_")
    os.makedirs(work, exist_ok=True)
    write_data(os.path.join(work, "aggregate.data"), rows, primaries)
    with open(os.path.join(work, "in.aggregate"), "w") as f:
        f.write(lammps_input("aggregate.data", dt, a.warm, a.steps, E_REST_AGG, "aggregate_wall_case.py",
                             ("thermo_style custom step ke", "thermo_modify format float %.9g", "thermo 0")))
    print(json.dumps(dict(run_measured(a.lmp, work, "in.aggregate"), system="aggregate_wall",
                          primaries=primaries)))


if __name__ == "__main__":
    main()
