#!/usr/bin/env bash
# What would migrate per step between ranks if the cells of the acoustic DSMC were split into slabs
# (docs/scaling.md, "A DSMC run too large for one machine"): cases/seed002_baseline.toml run to T,
# snapshots of every sample at T and one collision step later; per direction x (the wave), y
# (across, neither wave nor gravity) and z (gravity) the displacement in that step and the fraction
# of samples that change slab for K slabs of the box (K = 64, 256 and, for y and z, the slab widths
# of the 1e9-sample geometry in docs/scaling.md).
#   bench/dsmc_migration.sh [AGGLO] [OUT_DIR]      T=0.1 (s; the case's step is 5e-5 s)
#   STEPS=1: steps between the two snapshots (e.g. 2000 to see the rare y moves of rebound kicks)
#   SMOKE=1: the smoke test (ctest -L bench): T=1e-4 (2 steps); the same run and analysis.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
AGGLO=${1:-$SRC/build/agglo}
OUT=${2:-$SRC/results/bench_dsmc_migration}
[ "${SMOKE:-0}" = 1 ] && T=${T:-1e-4}
T=${T:-0.1}
DT=5e-5
STEPS=${STEPS:-1}
T2=$(/usr/bin/python3 -c "print(round($T + $STEPS * $DT, 10))")
OMP_NUM_THREADS=1 "$AGGLO" acoustic "$SRC/cases/seed002_baseline.toml" --out "$OUT" --threads 1 --no-plots \
  --format csv --quiet --overwrite --set time.end="$T2" --set "output.psd_times=[0.0]" \
  --set "output.snapshot_times=[$T,$T2]" --set output.snapshot_x_fraction=1.0 --set output.efficiency_interval="$T"
/usr/bin/python3 - "$OUT" "$T" "$STEPS" <<'EOF'
import csv, math, sys
out, t1, steps = sys.argv[1], float(sys.argv[2]), int(sys.argv[3])
rows = list(csv.DictReader(open(f"{out}/snapshots.csv")))
a = [r for r in rows if abs(float(r["t_s"]) - t1) < 1e-12]
b = [r for r in rows if abs(float(r["t_s"]) - t1) >= 1e-12]
assert len(a) == len(b) and all(p["id"] == q["id"] for p, q in zip(a, b)), "sample order changed"
cfg = open(f"{out}/config.resolved.toml").read()
def key(name):  # value of a top-level key of [domain] in config.resolved.toml
    sec = cfg.split("[domain]", 1)[1]
    for line in sec.splitlines():
        if line.split("=")[0].strip() == name:
            return float(line.split("=")[1].split("#")[0])
L = {"x": key("length_x"), "y": key("length_y"), "z": key("length_z")}
n = len(a)
print(f"{n} samples, {steps} step(s) from {t1} s, box {L['x']:.6g} x {L['y']:.6g} x {L['z']:.6g} m")
for ax in "xyz":
    col = f"{ax}_m"
    for group in ("solid", "liquid+mixed"):
        sel = [(p, q) for p, q in zip(a, b) if (p["phase"] == "solid") == (group == "solid")]
        d = []
        for p, q in sel:
            x = float(q[col]) - float(p[col])
            x -= L[ax] * round(x / L[ax])  # periodic
            d.append(abs(x))
        if d:
            print(f"  {ax}, {group:12s} ({len(d)} samples): mean |d{ax}| {sum(d) / len(d) * 1e6:.3g} um, "
                  f"max {max(d) * 1e6:.3g} um")
    for K in (64, 256):
        W = L[ax] / K
        moved = sum(1 for p, q in zip(a, b) if math.floor(float(p[col]) / W) != math.floor(float(q[col]) / W))
        print(f"  {ax}-slabs, K = {K} (width {W * 1e3:.3g} mm): {moved} of {n} samples change slab = {moved / n:.2%}")
    nz = sum(1 for p, q in zip(a, b) if p[col] != q[col])
    print(f"  {ax}: {nz} of {n} samples have a different printed {ax}")
EOF
