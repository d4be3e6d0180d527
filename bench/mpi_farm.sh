#!/usr/bin/env bash
# MPI task-farm benchmark (docs/scaling.md): one ensemble run as 1 process x 1 thread (the serial
# reference), 1 x 2 threads, 2 ranks x 1 thread and 4 ranks x 1 thread (oversubscribed on 2 cores).
# For each layout: wall time, jobs, time per job, load balance and parallel efficiency, as a markdown
# table on stdout; every layout's output files must equal the serial run's (run.json and journal.jsonl
# aside; timing fields stripped, as the output regression does: tests/regression/checksums.py), else the
# script fails.
#   bash bench/mpi_farm.sh AGGLO COMMAND CASE [agglo options...]
#   e.g. the kappa_p = 2.5 break-up curve of bench/README.md:
#   bash bench/mpi_farm.sh build/agglo breakup cases/seed000_charged_square_k2p5.toml \
#     --set 'breakup.speeds=[0.12,0.18,0.24,0.3]' --set breakup.samples=2
# Time per job = wall time of a job from journal.jsonl ("seconds"); busy(r) = sum of the job times of
# rank r; load balance = mean busy / max busy over the ranks; parallel efficiency = T(1 x 1) / (slots x T),
# slots = ranks x threads (speed-up per job slot against the serial run).
# No snapshots: output.snapshot_interval = 0 (impact commands) or output.snapshot_times = [] (acoustic
# cases), whichever the command accepts (tried with --dry-run).
#   LAYOUTS="1x2 2x1 4x1": the layouts (ranks x threads) after the serial reference.
#   SMOKE=1 with AGGLO alone: the smoke test (ctest -L bench): a 4-member seed ensemble of the seed-002
#   baseline cut to 2 steps with 200 + 20 samples, LAYOUTS=2x1 (the start of 4 ranks alone costs ~0.8 s of
#   CPU); the same comparisons and table.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
AGGLO=$(realpath "$1"); shift
if [ "${SMOKE:-0}" = 1 ] && [ $# = 0 ]; then
  set -- acoustic "$SRC/cases/seed002_baseline.toml" --seeds 4 --set time.end=1e-4 \
    --set population.0.samples=200 --set population.1.samples=20 --set sampling.min_samples_per_cell=0 \
    --set "output.psd_times=[0.0]"
  LAYOUTS=${LAYOUTS:-2x1}
fi
LAYOUTS=${LAYOUTS:-"1x2 2x1 4x1"}
MPIRUN=${MPIRUN:-mpirun}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
ARGS=("$@" -q --no-plots --format csv)
for no_snapshots in output.snapshot_interval=0 "output.snapshot_times=[]"; do
  if "$AGGLO" "${ARGS[@]}" --set "$no_snapshots" --dry-run > /dev/null 2>&1; then
    ARGS+=(--set "$no_snapshots")
    break
  fi
done

files() { (cd "$1" && find . -type f ! -name run.json ! -name journal.jsonl | sort); }
sums() { /usr/bin/python3 "$SRC/tests/regression/checksums.py" "$1" | grep -v ' \(.*/\)\?run\.json$'; }
same_files() {  # serial folder, other folder
  [ "$(files "$1")" = "$(files "$2")" ] || { echo "$2: not the files of the serial run" >&2; return 1; }
  [ -f "$T/serial.sums" ] || sums "$1" > "$T/serial.sums"
  sums "$2" | diff "$T/serial.sums" - >&2 || { echo "$2: the files above differ from the serial run" >&2; return 1; }
}

run_layout() {  # name ranks threads
  local start end
  start=$(date +%s.%N)
  if [ "$2" = 1 ]; then
    "$AGGLO" "${ARGS[@]}" --threads "$3" --out "$T/$1"
  else
    "$MPIRUN" -n "$2" --oversubscribe --bind-to none "$AGGLO" "${ARGS[@]}" --threads "$3" --out "$T/$1"
  fi > /dev/null
  end=$(date +%s.%N)
  echo "$1 $2 $3 $start $end" >> "$T/walls"
  [ "$1" = serial ] || same_files "$T/serial" "$T/$1"
}

run_layout serial 1 1
for layout in $LAYOUTS; do
  run_layout "$layout" "${layout%x*}" "${layout#*x}"
done

/usr/bin/python3 - "$T" << 'PY'
import json, sys
from collections import defaultdict
root = sys.argv[1]
walls = [(n, int(r), int(t), float(e) - float(s)) for n, r, t, s, e in (l.split() for l in open(f"{root}/walls"))]
serial = walls[0][3]
print("| layout (ranks x threads) | wall s | jobs | time per job s: mean (min-max) | load balance | parallel efficiency |")
print("|---|---|---|---|---|---|")
for name, ranks, threads, wall in walls:
    jobs = [json.loads(l) for l in open(f"{root}/{name}/journal.jsonl")]
    secs = [j["seconds"] for j in jobs]
    busy = defaultdict(float)
    for j in jobs:
        busy[j["rank"]] += j["seconds"]
    per_rank = [busy.get(r, 0.0) for r in range(ranks)]
    balance = (sum(per_rank) / ranks) / max(per_rank)
    eff = serial / (ranks * threads * wall)
    print(f"| {ranks} x {threads} | {wall:.1f} | {len(jobs)} | {sum(secs)/len(secs):.2f} ({min(secs):.2f}-{max(secs):.2f}) "
          f"| {balance:.2f} | {eff:.2f} |")
PY
