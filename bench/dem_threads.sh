#!/usr/bin/env bash
# One thread against two on the DEM, measured in one script (issue 27 item 3; docs/benchmarks_dem.md §7):
#   block_N   BM_DemBlock/N/0 of bench_dem_scaling (the adhesive block at JKR equilibrium, WARM untimed
#             steps, then STEPS timed ones: wall and CPU of the timed steps), for each N of SIZES (1000,
#             10000 or 100000; the parallel path needs more than 4096 pairs: 10000 and 100000)
#   collide   agglo collide of cases/breakage_wall_fractal.toml (a shipped 500-primary structure-builder
#             aggregate on its wall; wall and user CPU of the whole process, /usr/bin/time)
# in ROUNDS interleaved rounds of the variants (their order rotated by one each round)
#   t1        one thread (OMP_NUM_THREADS=1 / --threads 1), GOMP_SPINCOUNT=1000 (agglo's default)
#   t2        two threads, agglo's defaults: short spin waits, the step's thread count chosen by timed probes
#             (core/thread_choice.hpp)
#   t2_fixed  two threads at every step (AGGLO_THREAD_PROBE=off), short spin waits
#   t2_spin   two threads at every step, GOMP_SPINCOUNT=300000 (libgomp's own default: spinning waits)
#   t2_passive two threads, probes, OMP_WAIT_POLICY=passive (agglo's default until session 48)
#   V_before  variant V of the build at BEFORE_BUILD (its bench_dem_scaling and agglo; e.g. main's build:
#             before and after in the same rounds); ratios against t1_before
# Prints `uptime` before and after, every run (with the 1-min load average), then (bench/threads_summary.py)
# per system the median wall and CPU of each variant, the speed-up wall(t1) / wall(V) and CPU(V) / CPU(t1) (the extra CPU of the
# second thread: waits, fork/joins). On two otherwise idle cores the speed-up is the parallel one; on a
# shared machine only the ratios of one invocation mean anything. Timing only (never a test).
#   bench/dem_threads.sh [OUT_DIR]    BUILD=build, SIZES="10000 100000", WARM=200, STEPS=1000, ROUNDS=3,
#   VARIANTS="t1 t2 t2_fixed t2_spin", COLLIDE=1 (0: no collide)
#   SMOKE=1: the smoke test (ctest -L bench): SIZES=10000, WARM=10, STEPS=20, ROUNDS=1, VARIANTS="t1 t2",
#   the collide shortened to time.after_contact = 2e-5 s.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
OUT=${1:-$SRC/results/bench_dem_threads}
BUILD=${BUILD:-$SRC/build}
short=()
if [ "${SMOKE:-0}" = 1 ]; then
  SIZES=${SIZES:-10000} WARM=${WARM:-10} STEPS=${STEPS:-20} ROUNDS=${ROUNDS:-1} VARIANTS=${VARIANTS:-"t1 t2"}
  short=(--set time.after_contact=2e-5)
fi
SIZES=${SIZES-10000 100000}
WARM=${WARM:-200}
STEPS=${STEPS:-1000}
ROUNDS=${ROUNDS:-3}
VARIANTS=${VARIANTS:-"t1 t2 t2_fixed t2_spin"}
COLLIDE=${COLLIDE:-1}
mkdir -p "$OUT"
echo "before: $(uptime)"
table="$OUT/threads.tsv"
printf 'system\tvariant\tround\twall_s\tcpu_s\tload\n' > "$table"
row() { printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4" "$5" "$(cut -d' ' -f1 /proc/loadavg)" | tee -a "$table"; }
run() {  # run SYSTEM VARIANT ROUND
  local system=$1 v=$2 r=$3 build=$BUILD threads=2
  local envs=(-u OMP_WAIT_POLICY -u GOMP_SPINCOUNT -u AGGLO_THREAD_PROBE GOMP_SPINCOUNT=1000)
  [ "${v%_before}" = "$v" ] || build=${BEFORE_BUILD:?variant $v needs BEFORE_BUILD}
  case ${v%_before} in
    t1) threads=1 ;;
    t2) ;;
    t2_fixed) envs+=(AGGLO_THREAD_PROBE=off) ;;
    t2_spin) envs=(-u OMP_WAIT_POLICY -u GOMP_SPINCOUNT GOMP_SPINCOUNT=300000 AGGLO_THREAD_PROBE=off) ;;
    t2_passive) envs=(-u OMP_WAIT_POLICY -u GOMP_SPINCOUNT -u AGGLO_THREAD_PROBE OMP_WAIT_POLICY=passive) ;;
    *) echo "unknown variant $v" >&2; exit 2 ;;
  esac
  if [ "$system" = collide ]; then
    env "${envs[@]}" /usr/bin/time -f "%e %U" -o "$OUT/time" "$build/agglo" -q --no-plots collide \
      "$SRC/cases/breakage_wall_fractal.toml" --threads "$threads" --format csv --overwrite \
      --out "$OUT/collide_$v" "${short[@]}" > /dev/null
    read -r wall cpu < "$OUT/time"
  else
    env "${envs[@]}" OMP_NUM_THREADS=$threads AGGLO_BLOCK_WARM="$WARM" AGGLO_BLOCK_STEPS="$STEPS" "$build/bench_dem_scaling" \
      --benchmark_filter="^BM_DemBlock/${system#block_}/0/" --benchmark_format=json > "$OUT/bench.json"
    read -r wall cpu < <(/usr/bin/python3 -c 'import json, sys
b = json.load(open(sys.argv[1]))["benchmarks"][0]
s = {"ms": 1e-3, "us": 1e-6, "ns": 1e-9, "s": 1.0}[b["time_unit"]]
print("%.4f %.4f" % (b["real_time"] * s, b["cpu_time"] * s))' "$OUT/bench.json")
  fi
  row "$system" "$v" "$r" "$wall" "$cpu"
}
systems=()
for n in $SIZES; do systems+=("block_$n"); done
[ "$COLLIDE" = 1 ] && systems+=(collide)
read -r -a vars <<< "$VARIANTS"
for r in $(seq 1 "$ROUNDS"); do  # round r starts at variant r - 1 (so that a load trend favours none)
  shift_by=$(((r - 1) % ${#vars[@]}))
  for v in "${vars[@]:shift_by}" "${vars[@]:0:shift_by}"; do
    for s in "${systems[@]}"; do run "$s" "$v" "$r"; done
  done
done
echo "after: $(uptime)"
/usr/bin/python3 "$SRC/bench/threads_summary.py" "$table"
