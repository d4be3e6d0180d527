#!/usr/bin/python3
"""Break-up probability map over impact speeds x particle permittivities, farmed out with Dask.

A neutral particle hits the charged square agglomerate of cases/seed000_charged_square_k1.toml. For
every impact speed v [m/s] and relative permittivity kappa_p of the particles, `--offsets` collisions
at lateral offsets spread over [0, --max-offset] particle radii each decide broken / not broken; the
probability of break-up is the broken fraction. Every collision is one task (agglo.collide on one
thread) of a dask.distributed cluster: a LocalCluster of worker processes here, or any scheduler given
with --scheduler (workers on other machines need the same agglo build importable).

  /usr/bin/python3 examples/dask_breakup_map.py --speeds 0.1,0.2,0.3,0.4 --permittivities 1,2.5,15 \
      --offsets 4 --workers 2 --out breakup_map.csv

writes the map as CSV (speed, permittivity, samples, broken, probability) and, with matplotlib, a PNG
beside it. docs/python.md explains the example.
"""
import argparse
import csv
import pathlib
import sys

import agglo

CASE = pathlib.Path(__file__).resolve().parents[1] / "cases" / "seed000_charged_square_k1.toml"
SHORT = {"time.after_contact": 2e-4, "output.snapshot_interval": 0}  # a short run: enough to tell break-up


def base_case(path=CASE, short=True):
    """The case every task starts from, as TOML text (cases travel to the workers as text)."""
    case = agglo.Case.load(path)
    for key, value in (SHORT if short else {}).items():
        case.set(key, value)
    return case.to_toml()


def collide_broken(case_text, speed, permittivity, offset):
    """One task: does the agglomerate break at this speed [m/s], permittivity and offset [radii]?"""
    case = agglo.Case.from_toml(case_text, "breakup_map")
    case.set("agglomerate.permittivity", permittivity).set("projectile.offset_radii", offset)
    return bool(agglo.collide(case, speed=speed, threads=1).summary["broken"])


def offsets_of(count, max_offset):
    return [max_offset * k / max(count - 1, 1) for k in range(count)]


def tasks_of(speeds, permittivities, offsets):
    return [(v, k, o) for v in speeds for k in permittivities for o in offsets]


def probability_map(results, speeds, permittivities, offsets):
    """Rows (speed, permittivity, samples, broken, probability) from the task results in task order."""
    rows, it = [], iter(results)
    for v in speeds:
        for k in permittivities:
            broken = sum(next(it) for _ in offsets)
            rows.append((v, k, len(offsets), broken, broken / len(offsets)))
    return rows


def run_serial(case_text, speeds, permittivities, offsets):
    results = [collide_broken(case_text, v, k, o) for v, k, o in tasks_of(speeds, permittivities, offsets)]
    return probability_map(results, speeds, permittivities, offsets)


def run_dask(client, case_text, speeds, permittivities, offsets):
    tasks = tasks_of(speeds, permittivities, offsets)
    futures = client.map(collide_broken, [case_text] * len(tasks), *zip(*tasks), pure=False)
    return probability_map(client.gather(futures), speeds, permittivities, offsets)


def write_csv(rows, path):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["speed", "permittivity", "samples", "broken", "probability"])
        w.writerows(rows)


def plot(rows, speeds, permittivities, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing: no PNG", file=sys.stderr)
        return
    grid = [[r[4] for r in rows if r[1] == k] for k in permittivities]
    fig, ax = plt.subplots(figsize=(5, 3.5))
    im = ax.imshow(grid, origin="lower", aspect="auto", vmin=0, vmax=1, cmap="viridis")
    ax.set_xticks(range(len(speeds)), [f"{v:g}" for v in speeds])
    ax.set_yticks(range(len(permittivities)), [f"{k:g}" for k in permittivities])
    ax.set_xlabel("impact speed [m/s]")
    ax.set_ylabel("particle permittivity kappa_p")
    fig.colorbar(im, label="break-up probability")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def numbers(text):
    return [float(x) for x in text.split(",")]


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--speeds", type=numbers, default=numbers("0.1,0.2,0.3,0.4"), help="impact speeds [m/s]")
    p.add_argument("--permittivities", type=numbers, default=numbers("1,2.5,15"), help="relative permittivities")
    p.add_argument("--offsets", type=int, default=4, help="collisions per map cell (lateral offsets)")
    p.add_argument("--max-offset", type=float, default=0.5, help="largest lateral offset [particle radii]")
    p.add_argument("--workers", type=int, default=2, help="worker processes of the LocalCluster")
    p.add_argument("--scheduler", help="address of a running dask scheduler (instead of a LocalCluster)")
    p.add_argument("--full", action="store_true", help="the case's full run length (slower)")
    p.add_argument("--out", default="breakup_map.csv", help="CSV file (the PNG goes beside it)")
    a = p.parse_args(argv)
    from dask.distributed import Client, LocalCluster
    offsets = offsets_of(a.offsets, a.max_offset)
    if a.scheduler:
        client = Client(a.scheduler)
    else:
        client = Client(LocalCluster(n_workers=a.workers, threads_per_worker=1, processes=True))
    with client:
        rows = run_dask(client, base_case(short=not a.full), a.speeds, a.permittivities, offsets)
    write_csv(rows, a.out)
    plot(rows, a.speeds, a.permittivities, pathlib.Path(a.out).with_suffix(".png"))
    for r in rows:
        print(f"v = {r[0]:g} m/s, kappa_p = {r[1]:g}: {r[3]}/{r[2]} broken")


if __name__ == "__main__":
    main()
