#!/usr/bin/python3
"""What LAMMPS' `pair granular jkr` means by its coefficients (Debian lammps, 29 Sep 2021 update 2).

Two spheres (r = 10 um, E = 1e9, nu = 0.33, gamma = 0.01, no damping): one at rest, the other moved
at constant speed with `fix move` (1) apart from an overlap of 2 delta_C, (2) towards it from a gap
of 0.67 delta_C. From the pair force on the resting sphere it prints, in units of docs/model.md §A.2
(F_C = 3 pi gamma R, delta_C = a0^2 / (2 6^(1/3) R), E* = E / (2 (1 - nu^2))):
  - the overlap where F = 0 (docs/model.md §A.4: delta0 = 1.21141 delta_C),
  - the force minimum and where the contact breaks (LAMMPS rule: -F_C at -0.48075 delta_C),
  - the overlap and force at first touch on approach (docs/model.md §A.4: delta = 0, F = -8/9 F_C).
Usage: check_jkr_lammps.py [WORKDIR]
"""
import math
import os
import subprocess
import sys

LMP = os.environ.get("LMP", "lmp")
r, E, nu, gamma, rho = 10e-6, 1e9, 0.33, 0.01, 2500.0
R = r / 2
Es = E / (2 * (1 - nu * nu))
Fc = 3 * math.pi * gamma * R
a0 = (9 * math.pi * gamma * R * R / Es) ** (1 / 3)
dC = a0 * a0 / (2 * 6 ** (1 / 3) * R)
dt = 2e-8


def lammps_input(name, delta_start, speed, nsteps):
    """One pull or push run; it logs to log.NAME (several runs share one lmp process, separated by `clear`)."""
    return f"""log log.{name}
units si
atom_style sphere
atom_modify map array
boundary m m m
newton off
comm_modify vel yes
region box block -1e-4 1e-4 -1e-4 1e-4 -1e-4 1e-4 units box
create_box 1 box
create_atoms 1 single 0 0 0 units box
create_atoms 1 single {2 * r - delta_start!r} 0 0 units box
set atom * diameter {2 * r!r}
set atom * density {rho!r}
pair_style granular {2.4 * r!r}
pair_coeff * * jkr {E!r} 0.0 {nu!r} {gamma!r} tangential mindlin NULL 1.0 0.3 damping velocity
neighbor {0.1 * r!r} nsq
neigh_modify every 1 delay 0 check yes
timestep {dt!r}
group two id 2
fix 1 two move linear {speed!r} 0 0
variable fx1 equal fx[1]
variable x2 equal x[2]
thermo_style custom step v_x2 v_fx1
thermo_modify format float %.15g
thermo 1
run {nsteps}
"""


def run(workdir, runs):
    """Runs {name: (delta_start, speed, nsteps)} in one lmp process (one start-up: ~0.15 s of CPU each)."""
    with open(os.path.join(workdir, "in.jkr_check"), "w") as f:
        f.write("clear\n".join(lammps_input(name, *args) for name, args in runs.items()))
    subprocess.run([LMP, "-in", "in.jkr_check", "-log", "none", "-screen", "none", "-nocite"], cwd=workdir,
                   check=True)
    return {name: read_log(os.path.join(workdir, f"log.{name}")) for name in runs}


def read_log(path):
    rows, on = [], False
    for line in open(path):
        s = line.split()
        if s[:1] == ["Step"]:
            on = True
            continue
        if on:
            try:
                rows.append([float(v) for v in s])
            except ValueError:
                on = False
    # overlap and repulsive-positive pair force (force on sphere 1 along +x is attraction)
    return [(2 * r - x2, -fx1) for _, x2, fx1 in rows]


def main():
    wd = sys.argv[1] if len(sys.argv) > 1 else "lmp_jkr_check"
    os.makedirs(wd, exist_ok=True)
    print(f"F_C = {Fc:.6e} N, delta_C = {dC:.6e} m, delta0 = {a0 * a0 / (3 * R):.6e} m")
    logs = run(wd, {"pull": (2.0 * dC, 1e-4, int(2.7 * dC / (1e-4 * dt))),
                    "push": (-0.67 * dC, -1e-4, int(1.0 * dC / (1e-4 * dt)))})
    pull, push = logs["pull"], logs["push"]
    zero = next(k for k in range(1, len(pull)) if pull[k - 1][1] > 0 >= pull[k][1])
    d1, f1 = pull[zero - 1]
    d2, f2 = pull[zero]
    d_eq = d1 - f1 * (d2 - d1) / (f2 - f1)
    kmin = min(range(len(pull)), key=lambda k: pull[k][1])
    brk = next(k for k in range(kmin, len(pull)) if pull[k][1] == 0.0)
    print(f"pull-off: F = 0 at delta = {d_eq / dC:.5f} delta_C (docs/model.md: 1.21141)")
    print(f"          min F = {pull[kmin][1] / Fc:.5f} F_C at delta = {pull[kmin][0] / dC:.5f} delta_C "
          f"(docs/model.md: -1 at -0.48075)")
    print(f"          force vanishes between delta = {pull[brk - 1][0] / dC:.5f} and {pull[brk][0] / dC:.5f} delta_C")
    first = next(k for k in range(len(push)) if push[k][1] != 0.0)
    print(f"approach: first force at delta = {push[first][0] / dC:.5f} delta_C (previous step "
          f"{push[first - 1][0] / dC:.5f}), F = {push[first][1] / Fc:.5f} F_C (docs/model.md: delta >= 0, -8/9 = -0.88889 "
          f"at delta = 0)")


if __name__ == "__main__":
    main()
