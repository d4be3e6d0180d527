#!/usr/bin/env bash
# Wall time of cases/seed002_baseline.toml (8403 sampled particles, 4 s simulated; issue goal <= 60 s on
# the 2-core machine). Runs the case REPS times (default 1) with all cores and prints the wall time of
# each run (summary.json wall_time_s, simulation only) and of the whole process.
#   bench/acoustic_baseline_wall_time.sh [AGGLO] [OUT_DIR]     (defaults: build/agglo, results/bench_baseline)
#   SMOKE=1: the smoke test (ctest -L bench): one run of 10 steps (time.end = 5e-4 s), one thread,
#   no snapshots, CSV outputs only (no results.nc); the same parsing and printing.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
AGGLO=${1:-$SRC/build/agglo}
shift $(( $# > 0 ? 1 : 0 ))
OUT=${1:-$SRC/results/bench_baseline}
shift $(( $# > 0 ? 1 : 0 ))
REPS=${REPS:-1}
if [ "${SMOKE:-0}" = 1 ]; then
  set -- --set time.end=5e-4 --set "output.psd_times=[0.0]" --set "output.snapshot_times=[]" --threads 1 \
    --format csv "$@"
fi
mkdir -p "$OUT"
for r in $(seq 1 "$REPS"); do
  t0=$(date +%s.%N)
  "$AGGLO" -q --no-plots acoustic "$SRC/cases/seed002_baseline.toml" --overwrite --out "$OUT/run_$r" "$@"
  t1=$(date +%s.%N)
  sim=$(/usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(f\"{d['wall_time_s']:.1f} s, fine efficiency {d['fine_efficiency']:.4f}\")" "$OUT/run_$r/summary.json")
  echo "run $r: simulation $sim; process $(/usr/bin/python3 -c "print(f'{$t1-$t0:.1f}')") s"
done
