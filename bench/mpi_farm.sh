#!/usr/bin/env bash
# MPI task-farm benchmark (docs/scaling.md): one ensemble run as 1 process x 1 thread (the serial
# reference), 1 x 2 threads, 2 ranks x 1 thread and 4 ranks x 1 thread (oversubscribed on 2 cores).
# For each layout: wall time, jobs, time per job, load balance and parallel efficiency, as a markdown
# table on stdout; every layout's output files must equal the serial run's (run.json and journal.jsonl
# aside), else the script fails.
#   bash bench/mpi_farm.sh AGGLO COMMAND CASE [agglo options...]
#   e.g. the kappa_p = 2.5 break-up curve of bench/README.md:
#   bash bench/mpi_farm.sh build/agglo breakup cases/seed000_charged_square_k2p5.toml \
#     --set 'breakup.speeds=[0.12,0.18,0.24,0.3]' --set breakup.samples=2
# Time per job = wall time of a job from journal.jsonl ("seconds"); busy(r) = sum of the job times of
# rank r; load balance = mean busy / max busy over the ranks; parallel efficiency = T(1 x 1) / (slots x T),
# slots = ranks x threads (speed-up per job slot against the serial run).
set -euo pipefail
AGGLO=$(realpath "$1"); shift
MPIRUN=${MPIRUN:-mpirun}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
ARGS=("$@" -q --no-plots --set output.snapshot_interval=0 --format csv)

same_files() {  # serial folder, other folder
  local f
  for f in $(cd "$1" && find . -type f ! -name run.json ! -name journal.jsonl | sort); do
    cmp -s "$1/$f" "$2/$f" || { echo "$2: $f differs from the serial run" >&2; return 1; }
  done
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
run_layout 1x2 1 2
run_layout 2x1 2 1
run_layout 4x1 4 1

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
