#!/usr/bin/python3
"""LAMMPS twin of `agglo collide` for the particle-agglomerate collision (docs/model.md §A.3).

Reads the same case TOML as agglo (plus `--set key=value` overrides), rebuilds the same
initial state (geometry of src/agglo/impact/agglomerate.cpp: equal spheres, neighbour
centre distance L = 2r - delta0, delta0 = a0^2/(3R); projectile gap_radii*r before the
agglomerate, offset_radii*r along y, velocity along +x), writes a LAMMPS input
(units si, atom_style sphere, pair_style granular jkr ... tangential mindlin ... damping tsuji,
fix nve/sphere), runs `lmp`, and classifies the end state like agglo's classify():
contact graph of all particles, broken <=> the original particles are not in one component
and every detached fragment separates (d|x_F - x_rest|/dt > 0).

Contact graph from positions: a pair is in contact when delta >= -delta_pulloff, the LAMMPS
JKR break distance (force minimum -F_C, delta = -0.48075 delta_C). A pair inside the band
-delta_pulloff <= delta < 0 could also be a pair that never touched (contacts form only at
delta >= 0); such pairs are counted in "ambiguous_pairs" so the caller can see them.

Usage as a library (vcrit_lammps.py, lammps_compare.sh) or:
    lmp_case.py CASE.toml --speed 0.18 [--set section.key=value ...] [--workdir DIR]
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tomllib

LMP = os.environ.get("LMP", "lmp")


def set_key(table, dotted, text):
    """Apply one `section.key=value` override (value parsed as TOML scalar when possible)."""
    parts = dotted.split(".")
    t = table
    for p in parts[:-1]:
        t = t.setdefault(p, {})
    try:
        val = tomllib.loads("v = " + text)["v"]
    except tomllib.TOMLDecodeError:
        val = text
    t[parts[-1]] = val


def load_case(path, sets=()):
    with open(path, "rb") as f:
        cfg = tomllib.load(f)
    for s in sets:
        k, _, v = s.partition("=")
        set_key(cfg, k.strip(), v.strip())
    return cfg


class Setup:
    """All numbers of one collision set-up, computed exactly as agglo does."""

    def __init__(self, cfg):
        g = lambda sec, key, default: cfg.get(sec, {}).get(key, default)
        self.rho = float(g("material", "density", 2500.0))
        self.E = float(g("material", "youngs_modulus", 1.0e9))
        self.nu = float(g("material", "poisson_ratio", 0.33))
        self.gamma = float(g("material", "surface_energy", 0.01))
        self.e = float(g("material", "restitution", 0.7))
        self.mu = float(g("material", "friction", 0.3))
        self.tangential = g("contact", "tangential", "seed")
        self.break_rule = g("contact", "break_rule", "marshall")
        self.rolling = bool(g("contact", "rolling", False))
        self.twisting = bool(g("contact", "twisting", False))
        self.shape = g("agglomerate", "shape", "tetrahedron")
        self.r = float(g("agglomerate", "radius", 10e-6))
        self.rp = float(g("projectile", "radius", self.r))
        self.offset = float(g("projectile", "offset_radii", 0.05))
        self.gap = float(g("projectile", "gap_radii", 1.0))
        self.after_contact = float(g("time", "after_contact", 2e-3))
        self.extension = float(g("time", "extension", 1e-3))
        self.max_extensions = int(g("time", "max_extensions", 4))
        dt = float(g("time", "dt", 0.0))
        spp = float(g("time", "steps_per_period", 50.0))
        self.vc = {k: float(g("vcrit", k, d)) for k, d in
                   (("v_min", 0.02), ("v_max", 0.6), ("tolerance", 5e-4))}
        self.vc["scan_points"] = int(g("vcrit", "scan_points", 12))
        if self.shape not in ("tetrahedron", "square"):
            raise SystemExit(f"lmp_case.py: agglomerate.shape = {self.shape!r} not supported here")
        if self.rp != self.r:
            raise SystemExit("lmp_case.py: only a projectile of the agglomerate's radius is supported")
        if self.tangential != "marshall" or self.break_rule != "lammps" or self.rolling or self.twisting:
            print("lmp_case.py: warning: LAMMPS runs mindlin sliding + JKR pull-off break; the agglo run should use "
                  "contact.tangential=marshall contact.break_rule=lammps (no rolling/twisting)", file=sys.stderr)
        # JKR constants (docs/model.md §A.2); like materials: E* = E / (2 (1 - nu^2)).
        self.Estar = self.E / (2.0 * (1.0 - self.nu ** 2))
        R = 0.5 * self.r
        self.R = R
        self.Fc = 3.0 * math.pi * self.gamma * R
        self.a0 = (9.0 * math.pi * self.gamma * R * R / self.Estar) ** (1.0 / 3.0)
        self.deltaC = self.a0 ** 2 / (2.0 * 6.0 ** (1.0 / 3.0) * R)
        self.delta0 = self.a0 ** 2 / (3.0 * R)
        # LAMMPS pull-off (break) distance, as pair granular computes it.
        ap = (9.0 * math.pi * self.gamma * R * R / (4.0 * self.Estar)) ** (1.0 / 3.0)
        self.delta_pulloff = -(ap * ap / R - 2.0 * math.sqrt(math.pi * self.gamma * ap / self.Estar))
        self.m = 4.0 / 3.0 * math.pi * self.r ** 3 * self.rho
        mstar = 0.5 * self.m
        k0 = 0.9905 * self.Fc / self.deltaC
        self.T0 = 2.0 * math.pi * math.sqrt(mstar / k0)
        self.dt = dt if dt > 0.0 else self.T0 / spp
        # Geometry (agglomerate.cpp).
        L = 2.0 * self.r - self.delta0
        if self.shape == "tetrahedron":
            h = L / (2.0 * math.sqrt(2.0))
            self.pos = [(-h, 0.0, -L / 2), (-h, 0.0, L / 2), (h, -L / 2, 0.0), (h, L / 2, 0.0)]
        else:
            self.pos = [(-L / 2, -L / 2, 0.0), (L / 2, -L / 2, 0.0), (L / 2, L / 2, 0.0), (-L / 2, L / 2, 0.0)]
        c = [sum(p[k] for p in self.pos) / 4.0 for k in range(3)]
        xmin = min(p[0] for p in self.pos) - self.r
        self.proj0 = (xmin - self.gap * self.r - self.rp, c[1] + self.offset * self.r, c[2])

    def contact_steps(self, speed):
        """First step after which the free-flying projectile overlaps an agglomerate particle (delta >= 0)."""
        best = math.inf
        for p in self.pos:
            dy, dz = p[1] - self.proj0[1], p[2] - self.proj0[2]
            s2 = (self.r + self.rp) ** 2 - dy * dy - dz * dz
            if s2 <= 0:
                continue
            dx = p[0] - self.proj0[0] - math.sqrt(s2)
            best = min(best, dx / speed)
        if not math.isfinite(best):
            raise SystemExit("lmp_case.py: the projectile misses the agglomerate")
        return math.ceil(best / self.dt - 1e-9)

    def lammps_input(self, speed, nsteps, dump_file, thermo_every=0):
        f17 = lambda x: repr(float(x))
        ext = 20.0 * self.r
        lines = [
            "# generated by bench/lammps/lmp_case.py (agglo cross-check, docs/model.md §A.3)",
            "units si",
            "atom_style sphere",
            "atom_modify map array",
            "dimension 3",
            "boundary m m m",
            "newton off",
            "comm_modify vel yes",
            f"region box block {f17(-ext)} {f17(ext)} {f17(-ext)} {f17(ext)} {f17(-ext)} {f17(ext)} units box",
            "create_box 1 box",
        ]
        for p in self.pos + [self.proj0]:
            lines.append(f"create_atoms 1 single {f17(p[0])} {f17(p[1])} {f17(p[2])} units box")
        lines += [
            f"set atom * diameter {f17(2.0 * self.r)}",
            f"set atom * density {f17(self.rho)}",
            f"set atom {len(self.pos) + 1} vx {f17(speed)}",
            # pair granular: jkr E e nu gamma (E, damping coefficient = restitution for tsuji, Poisson, surface energy)
            f"pair_style granular {f17(2.0 * self.r + 0.4 * self.r)}",
            f"pair_coeff * * jkr {f17(self.E)} {f17(self.e)} {f17(self.nu)} {f17(self.gamma)} "
            f"tangential mindlin NULL 1.0 {f17(self.mu)} damping tsuji",
            f"neighbor {f17(0.1 * self.r)} nsq",
            "neigh_modify every 1 delay 0 check yes",
            f"timestep {f17(self.dt)}",
            "fix integ all nve/sphere",
            "compute rke all erotate/sphere",
            "thermo_style custom step time ke c_rke",
            "thermo_modify norm no format float %.12g",
            f"thermo {thermo_every if thermo_every > 0 else nsteps}",
            f"run {nsteps}",
            f"write_dump all custom {dump_file} id x y z vx vy vz omegax omegay omegaz radius mass "
            "modify format float %.17g",
        ]
        return "\n".join(lines) + "\n"


def read_dump(path):
    with open(path) as f:
        lines = f.read().splitlines()
    k = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    cols = lines[k].split()[2:]
    atoms = {}
    for l in lines[k + 1:]:
        if not l.strip():
            continue
        v = dict(zip(cols, map(float, l.split())))
        atoms[int(v["id"])] = v
    return [atoms[i] for i in sorted(atoms)]


def classify(atoms, n_agg, delta_break):
    """Same rule as agglo::impact::classify (neutral case)."""
    n = len(atoms)
    X = [(a["x"], a["y"], a["z"]) for a in atoms]
    parent = list(range(n))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    ambiguous = 0
    for i in range(n):
        for j in range(i + 1, n):
            d = math.dist(X[i], X[j])
            delta = atoms[i]["radius"] + atoms[j]["radius"] - d
            if delta >= -delta_break:
                parent[find(i)] = find(j)
                ambiguous += delta < 0.0
    groups = {}
    for k in range(n):
        groups.setdefault(find(k), []).append(k)
    comps = sorted(groups.values())
    originals = lambda g: sum(1 for k in g if k < n_agg)
    main = max(range(len(comps)), key=lambda g: (originals(comps[g]), -g))
    frags = []
    for gi, g in enumerate(comps):
        if gi == main or originals(g) == 0:
            continue
        inside = set(g)
        mf = mr = 0.0
        xf = [0.0] * 3; xr = [0.0] * 3; vf = [0.0] * 3; vr = [0.0] * 3
        for k, a in enumerate(atoms):
            m = a["mass"]
            tx, tv = (xf, vf) if k in inside else (xr, vr)
            for c, (p, v) in enumerate(zip(("x", "y", "z"), ("vx", "vy", "vz"))):
                tx[c] += m * a[p]
                tv[c] += m * a[v]
            if k in inside:
                mf += m
            else:
                mr += m
        dx = [xf[c] / mf - xr[c] / mr for c in range(3)]
        dv = [vf[c] / mf - vr[c] / mr for c in range(3)]
        rate = sum(a * b for a, b in zip(dx, dv)) / math.sqrt(sum(a * a for a in dx))
        frags.append({"members": g, "separation_rate_m_per_s": rate, "escaping": rate > 0.0})
    split = bool(frags)
    escaping = all(f["escaping"] for f in frags)
    return {"broken": split and escaping, "undecided": split and not escaping, "components": comps,
            "fragments": frags, "ambiguous_pairs": ambiguous}


def write_run(setup, speed, workdir, thermo_every=0, extra_time=0.0, dump="end.dump"):
    """Writes workdir/in.collision of one run; returns (contact step, steps)."""
    os.makedirs(workdir, exist_ok=True)
    n_contact = setup.contact_steps(speed)
    n_after = math.ceil((setup.after_contact + extra_time) / setup.dt - 1e-9)
    with open(os.path.join(workdir, "in.collision"), "w") as f:
        f.write(setup.lammps_input(speed, n_contact + n_after, dump, thermo_every))
    return n_contact, n_contact + n_after


def lammps_failed(proc, workdir):
    log = os.path.join(workdir, "log.lammps")
    tail = open(log).read()[-2000:] if os.path.exists(log) else proc.stderr
    return RuntimeError(f"lmp failed (rc {proc.returncode}) in {workdir}:\n{tail}")


def collect(setup, speed, workdir, n_contact, nsteps):
    """Classification of the end state of one run plus run info (its log.lammps and end.dump in workdir)."""
    loop = None
    for l in open(os.path.join(workdir, "log.lammps")):
        if l.startswith("Loop time of"):
            loop = float(l.split()[3])
    res = classify(read_dump(os.path.join(workdir, "end.dump")), len(setup.pos), setup.delta_pulloff)
    res.update({"speed_m_per_s": speed, "steps": nsteps, "contact_step": n_contact, "dt_s": setup.dt,
                "lammps_loop_time_s": loop})
    return res


def run_lammps(setup, speed, workdir, thermo_every=0, extra_time=0.0):
    """One LAMMPS collision run; returns the classification plus run info."""
    n_contact, nsteps = write_run(setup, speed, workdir, thermo_every, extra_time)
    proc = subprocess.run([LMP, "-in", "in.collision", "-log", "log.lammps", "-screen", "none", "-nocite"],
                          cwd=workdir, capture_output=True, text=True)
    if proc.returncode != 0 or not os.path.exists(os.path.join(workdir, "end.dump")):
        raise lammps_failed(proc, workdir)
    return collect(setup, speed, workdir, n_contact, nsteps)


def run_lammps_many(setup, speeds, workdirs):
    """Runs of several speeds in one lmp process (one start-up, ~0.15 s of CPU, instead of one per speed):
    a batch input in workdirs[0] that, per run, logs to its workdir's log.lammps, includes its in.collision
    (end.dump written there) and clears LAMMPS. Each result equals run_lammps' for that speed and workdir."""
    runs, batch = [], []
    for v, wd in zip(speeds, workdirs):
        wd = os.path.abspath(wd)
        runs.append((v, wd) + write_run(setup, v, wd, dump=os.path.join(wd, "end.dump")))
        batch += [f"log {os.path.join(wd, 'log.lammps')}", f"include {os.path.join(wd, 'in.collision')}", "clear"]
    with open(os.path.join(runs[0][1], "in.batch"), "w") as f:
        f.write("\n".join(batch) + "\n")
    proc = subprocess.run([LMP, "-in", "in.batch", "-log", "none", "-screen", "none", "-nocite"],
                          cwd=runs[0][1], capture_output=True, text=True)
    for v, wd, n_contact, nsteps in runs:
        if proc.returncode != 0 or not os.path.exists(os.path.join(wd, "end.dump")):
            raise lammps_failed(proc, wd)
    return [collect(setup, v, wd, n_contact, nsteps) for v, wd, n_contact, nsteps in runs]


def run_decided(setup, speed, workdir, thermo_every=0, first=None):
    """Like agglo: extend the run (by time.extension, up to time.max_extensions) while undecided. first: the
    result of the run without extension when already made (run_lammps_many)."""
    for ext in range(setup.max_extensions + 1):
        res = first if ext == 0 and first is not None else run_lammps(setup, speed, workdir, thermo_every,
                                                                       ext * setup.extension)
        res["extensions"] = ext
        if not res["undecided"]:
            break
    return res


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--speed", type=float, required=True)
    ap.add_argument("--set", action="append", default=[], dest="sets")
    ap.add_argument("--workdir", default="lmp_run")
    ap.add_argument("--thermo-every", type=int, default=0)
    a = ap.parse_args()
    s = Setup(load_case(a.case, a.sets))
    res = run_decided(s, a.speed, a.workdir, a.thermo_every)
    print(json.dumps(res, indent=1))


if __name__ == "__main__":
    main()
