#!/usr/bin/env bash
# DEM benchmarks of issue 2 (docs/benchmarks_dem.md):
#   1. wall time of one 2 ms collision run (5 particles), agglo vs LAMMPS, same case and time step;
#   2. agglo's cost per particle-step for agglomerates of 1e2, 1e3, 1e4 particles (Google Benchmark,
#      single thread), the neighbour-list build, and the 5-particle collision without file output.
#
#   bench/dem_benchmarks.sh [--overwrite] [OUT_DIR]        (default OUT_DIR: results/dem_benchmarks)
# An existing OUT_DIR is refused unless --overwrite is given (then its files are replaced).
# Environment: BUILD (build folder with AGGLO_BUILD_BENCH=ON, default build-bench; agglo and
# bench_dem_scaling are built there if missing), REPS (default 10), LMP (LAMMPS binary, default lmp;
# installed from Debian's `lammps` if missing).
#   SMOKE=1: the smoke test (ctest -L bench): REPS=1 (one LAMMPS and one agglo collision, CSV output),
#   of the Google Benchmarks only BM_Collision2ms, 2 repetitions of at least 1 ms each; LAMMPS and
#   BUILD/agglo, BUILD/bench_dem_scaling must exist (no apt-get, no build); the same lines and ratios.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
overwrite=0
if [ "${1:-}" = --overwrite ]; then overwrite=1; shift; fi
OUT=${1:-$SRC/results/dem_benchmarks}
BUILD=${BUILD:-$SRC/build-bench}
REPS=${REPS:-10}
CASE=$SRC/cases/seed000_neutral_tetrahedron_e0p9.toml
PY=/usr/bin/python3
export LMP=${LMP:-lmp}
# bench_dem_scaling: every benchmark but BM_DemBlock (fixed 1000-step runs up to 1e5 particles, which belong
# to bench/dem_block_vs_lammps.sh), 3 repetitions of at least 1 s
BM_ARGS=(--benchmark_filter=-BM_DemBlock --benchmark_min_time=1 --benchmark_repetitions=3)
FORMAT=()
if [ "${SMOKE:-0}" = 1 ]; then
  REPS=1
  BM_ARGS=(--benchmark_filter=BM_Collision2ms --benchmark_min_time=0.001 --benchmark_repetitions=2)
  FORMAT=(--format csv)
  command -v "$LMP" >/dev/null || { echo "smoke: no LAMMPS binary '$LMP' (Debian package lammps)"; exit 2; }
  for x in agglo bench_dem_scaling; do
    [ -x "$BUILD/$x" ] || { echo "smoke: no $BUILD/$x (AGGLO_BUILD_BENCH=ON)"; exit 2; }
  done
fi
if [ -e "$OUT" ] && [ "$overwrite" = 0 ]; then
  echo "bench/dem_benchmarks.sh: $OUT exists; pass --overwrite to replace its files" >&2
  exit 2
fi

if ! command -v "$LMP" >/dev/null 2>&1; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -q && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q lammps
fi
if [ ! -x "$BUILD/agglo" ] || [ ! -x "$BUILD/bench_dem_scaling" ]; then
  cmake -S "$SRC" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=$PY -DAGGLO_BUILD_BENCH=ON >/dev/null
  cmake --build "$BUILD" -j2 --target agglo bench_dem_scaling
fi
mkdir -p "$OUT"
E_REST=$($PY -c "import tomllib,sys; print(tomllib.load(open(sys.argv[1],'rb')).get('material',{}).get('restitution',0.7))" "$CASE")
SETARGS=(--set contact.break_rule=lammps --set contact.tangential=marshall --set material.restitution=$E_REST
         --set material.friction=0.3 --set material.youngs_modulus=1.0e9 --set material.poisson_ratio=0.33
         --set material.surface_energy=0.01 --set material.density=2500.0)

echo "== machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "== 1. one collision run (v = 0.18 m/s, approach + 2 ms), agglo vs LAMMPS, $REPS repetitions"
$PY "$SRC/bench/lammps/time_collision.py" "$BUILD/agglo" "$CASE" --speed 0.18 "${SETARGS[@]}" --reps "$REPS" \
    --json "$OUT/collision_timing.json" "${FORMAT[@]}"

echo "== 2. cost per particle-step (OMP_NUM_THREADS=1; counters use CPU time)"
OMP_NUM_THREADS=1 "$BUILD/bench_dem_scaling" "${BM_ARGS[@]}" --benchmark_report_aggregates_only=true --benchmark_out="$OUT/bench_dem_scaling.json" \
    --benchmark_out_format=json 2>/dev/null | grep -E "^(BM_.*_median|Benchmark|---)" || true
$PY - "$OUT" <<'EOF'
import json, sys
out = sys.argv[1]
d = json.load(open(f"{out}/bench_dem_scaling.json"))
coll = json.load(open(f"{out}/collision_timing.json"))
rows = [b for b in d["benchmarks"] if b.get("aggregate_name") == "median"]
print(f"median of {rows[0]['repetitions'] if rows else 0} repetitions:")
for b in rows:
    c = {k: v for k, v in b.items() if k in ("ns_per_particle_step", "ns_per_particle", "ns_per_step")}
    print(f"  {b['run_name']:24s} cpu {b['cpu_time']:10.1f} {b['time_unit']}  " +
          "  ".join(f"{k} = {v:.1f}" for k, v in c.items()))
step = {b["run_name"]: b["ns_per_particle_step"] for b in rows if "ns_per_particle_step" in b}
if len(step) >= 2:
    v = list(step.values())
    print(f"  ns/particle-step ratio largest/smallest N: {v[-1] / v[0]:.2f} (1.0 = perfectly O(N))")
bc = [b for b in rows if b["run_name"].startswith("BM_Collision2ms")]
if bc:
    unit = {"ms": 1e-3, "us": 1e-6, "ns": 1e-9, "s": 1.0}[bc[0]["time_unit"]]
    wall, cpu = bc[0]["real_time"] * unit, bc[0]["cpu_time"] * unit
    lmp = coll["lammps_loop_s"]["median"]
    print(f"  pure simulation, one collision: agglo {cpu * 1e3:.1f} ms CPU / {wall * 1e3:.1f} ms wall (BM_Collision2ms) "
          f"vs LAMMPS loop {lmp * 1e3:.1f} ms (median) -> {lmp / cpu:.1f}x (CPU) / {lmp / wall:.1f}x (wall)")
EOF
