#!/usr/bin/env bash
# --threads 1 against --threads 2 on the acoustic DSMC, measured in one script (issue 27 item 3;
# docs/acoustics.md §5.2): the fly-ash case at 8000 samples and the seed-002 baseline (9843 samples),
# each shortened to T, ROUNDS interleaved rounds of
#   j1        --threads 1
#   j2        --threads 2 (agglo's default: short OpenMP spin waits, apps/agglo/omp_wait/omp_wait.cpp, and the
#             step's thread count chosen by timed probes, src/agglo/core/thread_choice.hpp)
#   j2_fixed  --threads 2 with AGGLO_THREAD_PROBE=off: two threads at every step (agglo before the probes)
#   j2_spin   --threads 2 with GOMP_SPINCOUNT=300000, libgomp's own default (agglo before passive waits)
#   j2_passive --threads 2 with OMP_WAIT_POLICY=passive (agglo's default until session 48: sleep at once)
#   V_before  variant V (j1, j2, ...) of the agglo at BEFORE_AGGLO (another build, e.g. of the previous
#             commit: before and after in the same rounds); ratios and efficiency against j1_before
# under /usr/bin/time (wall and user CPU of the whole process), the variants' order rotated each round.
# Prints `uptime` before and after, every run (with the 1-min load average), then per case the median
# wall and user CPU of each variant, the ratios to j1 (> 1: slower than one thread) and, for the two-thread
# variants, the parallel efficiency wall(j1) / (2 wall(j2)) (1: perfect; 0.5: no gain; it means an
# efficiency only on two otherwise idle cores, so the load average is printed with it).
#   bench/dsmc_threads.sh [AGGLO] [OUT_DIR]     ROUNDS=3, T=0.1, VARIANTS="j1 j2 j2_fixed j2_spin",
#   FLYASH_SAMPLES=8000
# Timing only (never a test); on a shared machine only the ratios of one invocation mean anything.
#   SMOKE=1: the smoke test (ctest -L bench): ROUNDS=1, T=0.0025 (49 and 50 steps), FLYASH_SAMPLES=800 and
#   the baseline with 800 + 16 samples, both without clones (sampling.min_samples_per_cell = 0),
#   VARIANTS="j1 j2" (j2_fixed and j2_spin differ from j2 only by their environment); the same table,
#   medians and ratios.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
AGGLO=${1:-$SRC/build/agglo}
OUT=${2:-$SRC/results/bench_dsmc_threads}
smoke=() base_smoke=()
if [ "${SMOKE:-0}" = 1 ]; then
  ROUNDS=${ROUNDS:-1} T=${T:-0.0025} FLYASH_SAMPLES=${FLYASH_SAMPLES:-800} VARIANTS=${VARIANTS:-"j1 j2"}
  smoke=(--set sampling.min_samples_per_cell=0)
  base_smoke=(--set population.0.samples=800 --set population.1.samples=16)
fi
FLYASH_SAMPLES=${FLYASH_SAMPLES:-8000}
ROUNDS=${ROUNDS:-3}
T=${T:-0.1}
VARIANTS=${VARIANTS:-"j1 j2 j2_fixed j2_spin"}
mkdir -p "$OUT"
echo "before: $(uptime)"
table="$OUT/threads.tsv"
printf 'case\tvariant\tround\twall_s\tuser_s\tload\n' > "$table"
common=(--no-plots --quiet --format csv --overwrite --set time.end="$T" --set "output.psd_times=[0.0]"
        --set "output.snapshot_times=[]" --set output.efficiency_interval="$T" "${smoke[@]}")
run() {  # run CASE_LABEL CASE_FILE VARIANT ROUND [extra args]
  local label=$1 file=$2 v=$3 r=$4; shift 4
  local j=2 envs=(-u OMP_WAIT_POLICY -u GOMP_SPINCOUNT -u AGGLO_THREAD_PROBE) agglo=$AGGLO
  [ "${v%_before}" = "$v" ] || agglo=${BEFORE_AGGLO:?variant $v needs BEFORE_AGGLO}
  case ${v%_before} in
    j1) j=1 ;;
    j2) ;;
    j2_fixed) envs+=(AGGLO_THREAD_PROBE=off) ;;
    j2_spin) envs+=(GOMP_SPINCOUNT=300000 AGGLO_THREAD_PROBE=off) ;;
    j2_passive) envs+=(OMP_WAIT_POLICY=passive) ;;
    *) echo "unknown variant $v" >&2; exit 2 ;;
  esac
  env "${envs[@]}" /usr/bin/time -f "%e %U" -o "$OUT/time" "$agglo" acoustic "$file" --out "$OUT/run_${label}_$v" \
    --threads "$j" "${common[@]}" "$@" > /dev/null
  read -r wall user < "$OUT/time"
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$label" "$v" "$r" "$wall" "$user" "$(cut -d' ' -f1 /proc/loadavg)" | tee -a "$table"
}
read -r -a vars <<< "$VARIANTS"
for r in $(seq 1 "$ROUNDS"); do
  for k in $(seq 0 $((${#vars[@]} - 1))); do  # the order rotates by one variant per round (a load trend
    v=${vars[$(((k + r - 1) % ${#vars[@]}))]}  # over the rounds then favours none)
    run "flyash_$FLYASH_SAMPLES" "$SRC/cases/flyash_147db.toml" "$v" "$r" --set population.0.samples="$FLYASH_SAMPLES"
    run seed002_baseline "$SRC/cases/seed002_baseline.toml" "$v" "$r" "${base_smoke[@]}"
  done
done
echo "after: $(uptime)"
/usr/bin/python3 - "$table" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1]), delimiter="\t"))
for case in dict.fromkeys(r["case"] for r in rows):
    med = {}
    for v in dict.fromkeys(r["variant"] for r in rows):
        rs = [r for r in rows if r["case"] == case and r["variant"] == v]
        med[v] = (statistics.median(float(r["wall_s"]) for r in rs), statistics.median(float(r["user_s"]) for r in rs))
    j1 = med.get("j1")
    loads = [float(r["load"]) for r in rows if r["case"] == case]
    print(f"{case}: median over {len(rs)} rounds (1-min load average {min(loads):.1f}-{max(loads):.1f})")
    for v, (w, u) in med.items():
        base = med.get("j1_before") if v.endswith("_before") else j1
        div = lambda a, b: f"{a / b:.2f}x" if b > 0 else "-"  # - : j1 under 0.01 s
        ratio = f"  wall {div(w, base[0])}, user {div(u, base[1])} of j1" if base else ""
        eff = f"; parallel efficiency {base[0] / (2 * w):.2f}" if base and not v.startswith("j1") and w > 0 else ""
        print(f"  {v:8s} wall {w:6.2f} s  user {u:6.2f} s{ratio}{eff}")
PY
