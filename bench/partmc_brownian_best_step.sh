#!/usr/bin/env bash
# PartMC's Brownian case at PartMC's best step (issue 27 item 2; docs/acoustics.md §5.7): the exact command
# of the comparison (cases/partmc_brownian.toml, 5e4 samples: PartMC's 1e5 accuracy; one thread; N(t) at 11
# times, no snapshots, results.nc written), user CPU of the whole process from getrusage, rounds of
# interleaved runs of this build and (BEFORE_AGGLO) an earlier one, each seed in both. Prints every run,
# the means and ranges, the ratio after/before, the ratio against PartMC 2.9.0 at its best step (10 s:
# 2.6-4.0 s user, PARTMC_BEST_STEP in bench/partmc_compare.py, recorded on this machine kind), and the N(4 h)
# error of each build against `agglo sectional` (80 pivots per decade; mean and standard error over the runs).
#   bench/partmc_brownian_best_step.sh [OUT]               # default results/partmc_brownian_best_step
# Environment: AGGLO (build/agglo), BEFORE_AGGLO (an agglo of an earlier commit; none: after only),
#   SEEDS ("1 2 3"), ROUNDS (3), SAMPLES (50000), CALLGRIND=1 (instructions of seed 1 for each build).
# SMOKE=1 (tests/bench/script_smoke.sh): 500 samples, 600 s (60 steps), one seed, one round, CSV outputs.
# Timing is meaningful on an idle core only (`uptime` is printed before and after).
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
OUT=${1:-results/partmc_brownian_best_step}
AGGLO=${AGGLO:-$SRC/build/agglo}
SEEDS=${SEEDS:-1 2 3} ROUNDS=${ROUNDS:-3} SAMPLES=${SAMPLES:-50000} CALLGRIND=${CALLGRIND:-0}
EXTRA=()
if [ "${SMOKE:-0}" = 1 ]; then
  SEEDS=1 ROUNDS=1 SAMPLES=500
  EXTRA=(--set time.end=600 --set "output.psd_times=[0.0,600.0]" --format csv)
fi
mkdir -p "$OUT"
CASE=$SRC/cases/partmc_brownian.toml
echo "uptime before: $(uptime)"
"$AGGLO" -q --no-plots sectional "$CASE" --set sectional.bins_per_decade=80 --set output.efficiency_interval=1440 \
  "${EXTRA[@]}" -o "$OUT/sectional" --overwrite > /dev/null
/usr/bin/python3 - "$OUT" "$CASE" "$AGGLO" "${BEFORE_AGGLO:-}" "$ROUNDS" "$SAMPLES" "$CALLGRIND" "$SEEDS" \
  "${EXTRA[@]}" <<'EOF'
import csv, math, os, resource, statistics as st, subprocess, sys
out, case, after, before, rounds, samples, cg, seeds = sys.argv[1:9]
extra = sys.argv[9:]
builds = [("after", after)] + ([("before", before)] if before else [])
partmc = (2.6, 4.0)  # PartMC 2.9.0 at its best step (10 s), user CPU [s]: PARTMC_BEST_STEP in bench/partmc_compare.py

def last_n(folder):
    with open(os.path.join(folder, "efficiency.csv")) as f:
        return float(list(csv.DictReader(f))[-1]["n_total_cm3"])

def command(agglo, seed, folder):
    return [agglo, "-q", "--no-plots", "acoustic", case, "--threads", "1", "--set", f"seed={seed}",
            "--set", f"population.0.samples={samples}", "--set", "output.snapshot_times=[]",
            "--set", "output.efficiency_interval=1440", *extra, "-o", folder, "--overwrite"]

ref = last_n(os.path.join(out, "sectional"))
runs = {name: [] for name, _ in builds}
for r in range(int(rounds)):
    for s in seeds.split():
        order = builds if (r + int(s)) % 2 == 0 else builds[::-1]  # alternate which build goes first
        for name, agglo in order:
            folder = os.path.join(out, f"{name}_s{s}")
            r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
            subprocess.run(command(agglo, s, folder), check=True, stdout=subprocess.DEVNULL,
                           env=dict(os.environ, OMP_NUM_THREADS="1"))
            r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
            user, err = r1.ru_utime - r0.ru_utime, 100.0 * (last_n(folder) / ref - 1.0)
            runs[name].append((user, err, s))
            print(f"round {r + 1} seed {s} {name}: user {user:.3f} s, sys {r1.ru_stime - r0.ru_stime:.3f} s, "
                  f"N(T) error {err:+.3f} %", flush=True)
for name, rs in runs.items():
    us = [max(u, 1e-3) for u, _, _ in rs]  # (1 ms floor: a smoke run may read 0)
    es = list({s: e for _, e, s in rs}.values())  # one per seed: the rounds repeat the same runs
    se = st.stdev(es) / math.sqrt(len(es)) if len(es) > 1 else float("nan")
    print(f"{name}: user mean {st.mean(us):.3f} s, range {min(us):.3f}-{max(us):.3f} s; "
          f"N(T) error {st.mean(es):+.3f} +- {se:.3f} % ({len(es)} seeds)")
    print(f"PartMC best step ({partmc[0]}-{partmc[1]} s) / agglo {name}: {partmc[0] / max(us):.1f}-"
          f"{partmc[1] / min(us):.1f}x (against agglo's mean {partmc[0] / st.mean(us):.1f}-{partmc[1] / st.mean(us):.1f}x)")
if before:
    a, b = [max(u, 1e-3) for u, _, _ in runs["after"]], [max(u, 1e-3) for u, _, _ in runs["before"]]
    print(f"after/before user CPU: means {st.mean(a) / st.mean(b):.3f}, medians {st.median(a) / st.median(b):.3f}")
if cg == "1":
    counts = {}
    for name, agglo in builds:
        log = os.path.join(out, f"callgrind_{name}.log")
        subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}/callgrind_{name}.out",
                        *command(agglo, seeds.split()[0], os.path.join(out, f"cg_{name}"))],
                       check=True, stdout=subprocess.DEVNULL, stderr=open(log, "w"))
        counts[name] = next(int(l.split()[-1].replace(",", "")) for l in open(log) if "refs:" in l)
        print(f"callgrind seed {seeds.split()[0]} {name}: {counts[name] / 1e9:.4f}e9 instructions")
    if before:
        print(f"callgrind after/before: {counts['after'] / counts['before']:.3f}")
EOF
echo "uptime after: $(uptime)"
