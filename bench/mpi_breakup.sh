#!/usr/bin/env bash
# MPI task-farm benchmark (docs/scaling.md): one break-up curve run as 1 process x 1 thread (the serial
# reference), 1 x 2 threads, 2 ranks x 1 thread and 4 ranks x 1 thread (oversubscribed on 2 cores).
# For each layout: wall time, jobs, time per job, load balance and parallel efficiency, as a markdown
# table on stdout; every layout's outputs are checked to equal the serial run's (tests/mpi/lib.sh).
#   bash bench/mpi_breakup.sh AGGLO [CASE] [SPEEDS] [SAMPLES]
# default: cases/seed000_charged_square_k2p5.toml, speeds [0.12,0.18,0.24,0.3], 2 samples (8 jobs).
# Time per job = mean wall time of a job from journal.jsonl (its "seconds"); busy(r) = sum of the job
# times of rank r; load balance = mean busy / max busy over ranks; parallel efficiency =
# T(1 x 1) / (slots x T), slots = ranks x threads (the speed-up per core against the serial run).
set -euo pipefail
AGGLO=$(realpath "$1"); SRC=$(cd "$(dirname "$0")/.." && pwd)
CASE=${2:-$SRC/cases/seed000_charged_square_k2p5.toml}
SPEEDS=${3:-[0.12,0.18,0.24,0.3]}
SAMPLES=${4:-2}
MPIRUN=${MPIRUN:-mpirun}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
ARGS=(breakup "$CASE" -q --no-plots --set output.snapshot_interval=0 --set "breakup.speeds=$SPEEDS"
      --set "breakup.samples=$SAMPLES" --format csv)

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
  if [ "$1" != serial ]; then cmp -s "$T/serial/breakup.json" "$T/$1/breakup.json" || { echo "$1: breakup.json differs" >&2; exit 1; }; fi
}

run_layout serial 1 1
run_layout 1x2 1 2
run_layout 2x1 2 1
run_layout 4x1 4 1

/usr/bin/python3 - "$T" << 'PY'
import json, sys
from collections import defaultdict
root = sys.argv[1]
walls = [l.split() for l in open(f"{root}/walls")]
walls = [(n, r, t, float(e) - float(s)) for n, r, t, s, e in walls]
serial = walls[0][3]
print("| layout (ranks x threads) | wall s | jobs | time per job s (mean, min-max) | load balance | parallel efficiency |")
print("|---|---|---|---|---|---|")
for name, ranks, threads, wall in walls:
    ranks, threads = int(ranks), int(threads)
    jobs = [json.loads(l) for l in open(f"{root}/{name}/journal.jsonl")]
    secs = [j["seconds"] for j in jobs]
    busy = defaultdict(float)
    for j in jobs:
        busy[j["rank"]] += j["seconds"]
    per_rank = [busy.get(r, 0.0) for r in range(ranks)]
    balance = (sum(per_rank) / ranks) / max(per_rank)
    eff = serial / (ranks * threads * wall)
    print(f"| {name} ({ranks} x {threads}) | {wall:.1f} | {len(jobs)} | {sum(secs)/len(secs):.1f} ({min(secs):.1f}-{max(secs):.1f}) "
          f"| {balance:.2f} | {eff:.2f} |")
PY
