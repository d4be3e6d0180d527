#!/usr/bin/env bash
# DEM cost per particle-step of the adhesive block at JKR equilibrium, agglo vs LAMMPS, in one run
# (issue 27 item 1; docs/benchmarks_dem.md §3):
#   - LAMMPS: bench/lammps/block_case.py (the same block, contact law and dt; Debian's `lammps`, installed
#     if missing), loop CPU time (loop wall time x LAMMPS' "% CPU use") of STEPS steps after WARM steps;
#   - agglo: bench_dem_scaling's BM_DemBlock (the same WARM + STEPS), process CPU time, the fast path (eight
#     pairs at a time where the CPU has AVX-512), the same path four pairs at a time ("four", what a CPU
#     without AVX-512 runs) and the reference twin (DemSystem::set_reference_kernel), rounds interleaved
#     with LAMMPS;
#   - threads: agglo's fast path on OMP_NUM_THREADS=1 and 2 (GOMP_SPINCOUNT=1000 as agglo sets it), wall time, speed-up;
#   - instructions (callgrind, block_steps() only) per particle-step of the fast path and the reference, of
#     the block at CG_SIZE and of the aggregate on the wall (valgrind has no AVX-512: the four-pair form).
# The second system, a fractal aggregate of AGG_N primaries hitting a wall (BM_DemAggregateWall, built by
# agglo's structure builder; its start state goes to bench/lammps/aggregate_wall_case.py, LAMMPS' wall is
# fix wall/gran with the same jkr law), is run the same way, rounds interleaved.
# Prints ns per particle-step of each code, LAMMPS / agglo and fast / reference ratios, per system.
#
#   bench/dem_block_vs_lammps.sh [OUT_DIR]            (default OUT_DIR: results/dem_block_vs_lammps)
# Environment: BUILD (build folder with AGGLO_BUILD_BENCH=ON, default build-bench), SIZES ("" skips the block; default
# "10000 100000"; BM_DemBlock has 1000, 10000, 100000), ROUNDS (3), STEPS (1000), WARM (200),
# THREADS ("1 2"; "" skips the thread comparison), CG_SIZE (10000; "" skips callgrind), CG_STEPS (20),
# AGG_N (primaries of the aggregate on the wall, 1000 or 100; default 1000, "" skips that system),
# BEFORE=REV (a commit): the callgrind counts also for bench_dem_scaling built from REV (fast path; REV's files
# exported to OUT/before_src (git archive) and built in OUT/before_src/build, with ccache when present; kept for
# the next run), printed as before/after.
# LMP (default lmp). LAMMPS is installed (Debian's `lammps`) and bench_dem_scaling built in BUILD if missing.
#   SMOKE=1: the smoke test (ctest -L bench): SIZES=1000 ROUNDS=1 STEPS=20 WARM=10 AGG_N=100 unless set, no callgrind
#   unless CG_SIZE is set (valgrind is not a test package; a callgrind run costs seconds), LAMMPS and
#   BUILD/bench_dem_scaling must exist (no apt-get, no build); the same runs, table and ratios.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
OUT=${1:-$SRC/results/dem_block_vs_lammps}
BUILD=${BUILD:-$SRC/build-bench}
if [ "${SMOKE:-0}" = 1 ]; then
  SIZES=${SIZES:-1000} ROUNDS=${ROUNDS:-1} STEPS=${STEPS:-20} WARM=${WARM:-10} CG_SIZE=${CG_SIZE-} AGG_N=${AGG_N-100}
  [ -n "$CG_SIZE" ] || echo "smoke: callgrind skipped (no instruction counts)"
  [ -z "${BEFORE:-}" ] || echo "smoke: BEFORE ignored (no rebuild of a previous commit)"
  unset BEFORE
fi
SIZES=${SIZES-10000 100000}
ROUNDS=${ROUNDS:-3}
STEPS=${STEPS:-1000}
WARM=${WARM:-200}
THREADS=${THREADS-1 2}
CG_SIZE=${CG_SIZE-10000}
CG_STEPS=${CG_STEPS:-20}
AGG_N=${AGG_N-1000}
PY=/usr/bin/python3
export LMP=${LMP:-lmp}

if [ "${SMOKE:-0}" = 1 ]; then
  command -v "$LMP" >/dev/null || { echo "smoke: no LAMMPS binary '$LMP' (Debian package lammps)"; exit 2; }
  [ -x "$BUILD/bench_dem_scaling" ] || { echo "smoke: no $BUILD/bench_dem_scaling (AGGLO_BUILD_BENCH=ON)"; exit 2; }
fi
if ! command -v "$LMP" >/dev/null 2>&1; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -q && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q lammps
fi
if [ ! -x "$BUILD/bench_dem_scaling" ]; then
  cmake -S "$SRC" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=$PY -DAGGLO_BUILD_BENCH=ON >/dev/null
  cmake --build "$BUILD" -j2 --target bench_dem_scaling
fi
mkdir -p "$OUT"
RES=$OUT/results.jsonl
: > "$RES"
export AGGLO_BLOCK_STEPS=$STEPS AGGLO_BLOCK_WARM=$WARM

# One BM_DemBlock (system block) or BM_DemAggregateWall (system aggregate_wall) run -> a JSON line
# {code, system, n, kernel, threads, cpu_s, wall_s, ns_per_particle_step, ...}.
agglo_block() {  # n kernel(0 fast | 1 reference | 2 fast, four pairs at a time) threads [system]
  local js=$OUT/bm.json sys=${4:-block} bm=BM_DemBlock
  [ "$sys" = aggregate_wall ] && bm=BM_DemAggregateWall
  OMP_NUM_THREADS=$3 "$BUILD/bench_dem_scaling" --benchmark_filter="^$bm/$1/$2/" \
      --benchmark_out="$js" --benchmark_out_format=json >/dev/null 2>&1
  $PY - "$js" "$1" "$2" "$3" "$STEPS" "$sys" <<'EOF'
import json, sys
b = json.load(open(sys.argv[1]))["benchmarks"][0]
n, kernel, th, steps = int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
unit = {"ms": 1e-3, "us": 1e-6, "ns": 1e-9, "s": 1.0}[b["time_unit"]]
cpu, wall = b["cpu_time"] * unit, b["real_time"] * unit
extra = {k: b[k] for k in ("wall_contacts", "ke_end", "wide_lanes") if k in b}
if "particles" in b:  # the aggregate: n primaries, and the wall spheres; per particle = per atom as LAMMPS
    extra["primaries"], n = n, int(b["particles"])
print(json.dumps({"code": "agglo", "system": sys.argv[6], "n": n, "kernel": ["fast", "reference", "four"][kernel],
                  "threads": th, "cpu_s": cpu, "wall_s": wall, "contacts": b.get("contacts"),
                  "ns_per_particle_step": cpu / (n * steps) * 1e9} | extra))
EOF
}

echo "== machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "== commit $(git -C "$SRC" rev-parse --short HEAD 2>/dev/null || echo '?'); block: $WARM warm-up + $STEPS timed steps"
for n in $SIZES; do
  for r in $(seq 1 "$ROUNDS"); do
    echo "-- N = $n, round $r"
    $PY "$SRC/bench/lammps/block_case.py" "$n" --steps "$STEPS" --warm "$WARM" --workdir "$OUT/lammps_$n" | tee -a "$RES"
    agglo_block "$n" 0 1 | tee -a "$RES"
    agglo_block "$n" 1 1 | tee -a "$RES"
    agglo_block "$n" 2 1 | tee -a "$RES"
  done
  if [ -n "$THREADS" ]; then
    # short OpenMP spin waits, as the agglo CLI sets them (apps/agglo/omp_wait): long spins on a shared
    # machine take the cores of the others, sleeping at once costs a wake-up per barrier
    for th in $THREADS; do GOMP_SPINCOUNT=${GOMP_SPINCOUNT:-1000} agglo_block "$n" 0 "$th" | sed 's/"code": "agglo"/"code": "agglo_threads"/' | tee -a "$RES"; done
  fi
done
if [ -n "$AGG_N" ]; then
  # the start state of BM_DemAggregateWall (agglo's structure builder) for its LAMMPS twin
  AGGLO_AGGWALL_DUMP=$OUT/aggregate_wall.state AGGLO_BLOCK_STEPS=0 AGGLO_BLOCK_WARM=0 OMP_NUM_THREADS=1 \
      "$BUILD/bench_dem_scaling" --benchmark_filter="^BM_DemAggregateWall/$AGG_N/0/" >/dev/null
  for r in $(seq 1 "$ROUNDS"); do
    echo "-- fractal aggregate of $AGG_N primaries on a wall, round $r"
    $PY "$SRC/bench/lammps/aggregate_wall_case.py" "$OUT/aggregate_wall.state" --steps "$STEPS" --warm "$WARM" \
        --workdir "$OUT/lammps_aggregate_wall" | tee -a "$RES"
    agglo_block "$AGG_N" 0 1 aggregate_wall | tee -a "$RES"
    agglo_block "$AGG_N" 1 1 aggregate_wall | tee -a "$RES"
    agglo_block "$AGG_N" 2 1 aggregate_wall | tee -a "$RES"
  done
fi
if [ -n "$CG_SIZE" ] && [ -n "${BEFORE:-}" ]; then
  bsrc=$OUT/before_src
  rev=$(git -C "$SRC" rev-parse --short "$BEFORE")
  if [ ! -x "$bsrc/build/bench_dem_scaling" ] || [ "$(cat "$bsrc/build/rev" 2>/dev/null)" != "$rev" ]; then
    rm -rf "$bsrc" && mkdir -p "$bsrc"
    git -C "$SRC" archive "$rev" | tar -x -C "$bsrc"
    launcher=()
    command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    cmake -S "$bsrc" -B "$bsrc/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=$PY \
        -DAGGLO_BUILD_BENCH=ON "${launcher[@]}" >"$OUT/before_cmake.log"
    cmake --build "$bsrc/build" -j2 --target bench_dem_scaling >"$OUT/before_build.log"
    echo "$rev" >"$bsrc/build/rev"
  fi
fi
if [ -n "$CG_SIZE" ]; then
  # the block at CG_SIZE, and the aggregate on its wall layer (AGG_N primaries) when it ran; kernel 0 = fast,
  # 1 = reference twin, before = the fast path of BEFORE
  for cg in "block BM_DemBlock/$CG_SIZE $CG_SIZE" ${AGG_N:+"aggregate_wall BM_DemAggregateWall/$AGG_N"}; do
    set -- $cg
    for ref in 0 1 ${BEFORE:+before}; do
      log=$OUT/callgrind.$1.$ref.log bin=$BUILD/bench_dem_scaling kernel=fast
      [ "$ref" = 1 ] && kernel=reference
      [ "$ref" = before ] && bin=$OUT/before_src/build/bench_dem_scaling kernel=before
      AGGLO_BLOCK_STEPS=$CG_STEPS AGGLO_BLOCK_WARM=$WARM OMP_NUM_THREADS=1 valgrind --tool=callgrind \
          --callgrind-out-file="$OUT/callgrind.$1.$ref" --collect-atstart=no --toggle-collect='*block_steps*' \
          "$bin" --benchmark_filter="^$2/${ref/before/0}/" >/dev/null 2>"$log"
      ir=$(sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$log")
      # particles: the block's N; the aggregate's from its LAMMPS row (primaries + wall spheres)
      np=${3:-$(grep -m1 '"system": "aggregate_wall"' "$RES" | sed -n 's/.*"n": \([0-9]*\).*/\1/p')}
      echo "{\"code\": \"callgrind\", \"system\": \"$1\", \"n\": $np, \"kernel\": \"$kernel\", \"steps\": $CG_STEPS, \"instructions\": $ir}" | tee -a "$RES"
    done
  done
fi

$PY - "$RES" <<'EOF'
import json, statistics, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
def ns(code, system, n, kernel=None):
    return [r["ns_per_particle_step"] for r in rows if r["code"] == code and r["n"] == n and
            r.get("system") == system and (kernel is None or r.get("kernel") == kernel)]
rng = lambda v: f"{min(v):.0f}-{max(v):.0f}" if len(v) > 1 else f"{v[0]:.0f}"
wide = any(r.get("wide_lanes") for r in rows if r["code"] == "agglo" and r.get("kernel") == "fast")
print("\nns per particle-step (CPU time, one core; min-max over the rounds) and ratios of the medians; agglo's fast")
print("path " + ("eight pairs at a time (this CPU has AVX-512), 'four' the same path four at a time:" if wide else
                 "four pairs at a time (no AVX-512 here: 'four' is the same code):"))
print(f"{'system':>14} {'N':>7} {'LAMMPS':>11} {'agglo fast':>11} {'agglo four':>11} {'agglo ref':>11} {'LAMMPS/fast':>12} "
      f"{'LAMMPS/four':>12} {'ref/fast':>9}")
for system, n in sorted({(r["system"], r["n"]) for r in rows if r["code"] == "lammps"}):
    l, f, rf = ns("lammps", system, n), ns("agglo", system, n, "fast"), ns("agglo", system, n, "reference")
    fo = ns("agglo", system, n, "four") or f
    med = statistics.median
    print(f"{system:>14} {n:>7} {rng(l):>11} {rng(f):>11} {rng(fo):>11} {rng(rf):>11} {med(l) / med(f):>11.2f}x "
          f"{med(l) / med(fo):>11.2f}x {med(rf) / med(f):>8.2f}x")
seen = set()
for r in rows:  # the same system in both codes: translational kinetic energy after the last step (first round)
    if r.get("system") == "aggregate_wall" and "ke_end" in r and (r["code"], r.get("kernel")) not in seen:
        seen.add((r["code"], r.get("kernel")))
        print(f"aggregate on the wall, {r['code']} {r.get('kernel', '')}: KE after the last step {r['ke_end']:.6e} J"
              + (f", {r['wall_contacts']:.0f} wall contacts, {r['contacts']:.0f} contacts" if r["code"] == "agglo" else ""))
th = [r for r in rows if r["code"] == "agglo_threads"]
for n in sorted({r["n"] for r in th}):
    w = {r["threads"]: r["wall_s"] for r in th if r["n"] == n}
    if 1 in w and 2 in w:
        print(f"threads, N = {n}: wall {w[1]:.3f} s on 1, {w[2]:.3f} s on 2 -> speed-up {w[1] / w[2]:.2f}x")
for system in ("block", "aggregate_wall"):
    cg = {r["kernel"]: r for r in rows if r["code"] == "callgrind" and r.get("system", "block") == system}
    if "fast" in cg and "reference" in cg:
        per = {k: v["instructions"] / (v["n"] * v["steps"]) for k, v in cg.items()}
        print(f"callgrind, {system}, N = {cg['fast']['n']}, {cg['fast']['steps']} steps: instructions per particle-step "
              f"fast {per['fast']:.0f}, reference {per['reference']:.0f} -> {per['reference'] / per['fast']:.3f}x")
        if "before" in per:
            print(f"callgrind, {system}: before (BEFORE's fast path) {per['before']:.0f} -> now {per['fast']:.0f} "
                  f"instructions per particle-step ({per['before'] / per['fast']:.3f}x)")
EOF
