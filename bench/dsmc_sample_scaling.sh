#!/usr/bin/env bash
# Cost of the acoustic DSMC against its sample count at fixed physics (issue 23 item 7; docs/acoustics.md
# §5.2): cases/flyash_147db.toml (147 dB, 1400 Hz, 1 um fly ash, 5e5 cm^-3, no droplets) with
# SAMPLES samples, one thread:
#  1. user CPU per simulated second (runs to T2 minus runs to T1: start-up and output removed) and the
#     engine's work counters per sample-step from summary.json (Nanbu trials, kernel evaluations);
#  2. callgrind instructions per sample-step (difference of a CG_T1 and a CG_T2 run) at CG_SAMPLES.
#   bench/dsmc_sample_scaling.sh [AGGLO] [OUT_DIR]
#   SAMPLES="1000 2000 4000 8000", T1=0.0510204 (1000 steps), T2=0.2040816 (4000 steps),
#   CALLGRIND=1, CG_SAMPLES="2000 8000", CG_T1=0.0102041 (200 steps), CG_T2=0.0204082 (400 steps)
#   SMOKE=1: the smoke test (ctest -L bench): SAMPLES="200 400" without clones (sampling.min_samples_per_cell
#   = 0), T1 and T2 of 2 and 4 steps, part 2
#   (callgrind) skipped unless CALLGRIND=1 (a callgrind run costs ~3 s even at 10 steps).
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
AGGLO=${1:-$SRC/build/agglo}
OUT=${2:-$SRC/results/bench_dsmc_sample_scaling}
if [ "${SMOKE:-0}" = 1 ]; then
  SAMPLES=${SAMPLES:-"200 400"} T1=${T1:-1.0204081632653062e-4} T2=${T2:-2.0408163265306123e-4}
  CALLGRIND=${CALLGRIND:-0} smoke="--set sampling.min_samples_per_cell=0"
  [ "$CALLGRIND" = 1 ] || echo "smoke: part 2 (callgrind) skipped"
fi
SAMPLES=${SAMPLES:-"1000 2000 4000 8000"}
T1=${T1:-0.0510204081632653}
T2=${T2:-0.2040816326530612}
CALLGRIND=${CALLGRIND:-1}
CG_SAMPLES=${CG_SAMPLES:-"2000 8000"}
CG_T1=${CG_T1:-0.0102040816326531}
CG_T2=${CG_T2:-0.0204081632653061}
CASE="$SRC/cases/flyash_147db.toml"
mkdir -p "$OUT"
export OMP_NUM_THREADS=1
opts() {  # opts SAMPLES T
  echo "--threads 1 --no-plots --quiet --format csv --overwrite --set time.end=$2 --set population.0.samples=$1 \
 --set output.psd_times=[0.0] --set output.snapshot_times=[] --set output.efficiency_interval=$2 ${smoke:-}"
}
table="$OUT/scaling.tsv"
printf 'samples\tT_s\twall_s\tuser_s\n' > "$table"
for n in $SAMPLES; do
  for t in "$T1" "$T2"; do
    # shellcheck disable=SC2046
    /usr/bin/time -f "%e %U" -o "$OUT/time" "$AGGLO" acoustic "$CASE" --out "$OUT/n${n}_t$t" $(opts "$n" "$t") > /dev/null
    read -r wall user < "$OUT/time"
    printf '%s\t%s\t%s\t%s\n' "$n" "$t" "$wall" "$user" >> "$table"
  done
done
/usr/bin/python3 - "$OUT" "$table" "$T1" "$T2" <<'PY'
import csv, json, sys
out, table, t1, t2 = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
rows = list(csv.DictReader(open(table), delimiter="\t"))
first = None
# "samples" is what the run held: fewer than sampling.min_samples_per_cell x cells are cloned up to it
print("requested  samples  user CPU per simulated s  per sample  trials/sample-step  kernel evals/sample-step  collisions/s")
for n in dict.fromkeys(r["samples"] for r in rows):
    a, b = (next(r for r in rows if r["samples"] == n and abs(float(r["T_s"]) - t) < 1e-12) for t in (t1, t2))
    per_s = (float(b["user_s"]) - float(a["user_s"])) / (t2 - t1)
    summary = json.load(open(f"{out}/n{n}_t{b['T_s']}/summary.json"))
    s, m = summary["nanbu"], summary["samples"]
    steps = s["particle_steps"]
    first = first or (m, per_s)
    ratio = f"{per_s / first[1]:5.2f}x" if first[1] > 0 else "    -"  # - : no CPU difference measured
    print(f"{n:>9}  {m:>7}  {per_s:8.2f} s ({ratio} for {m / first[0]:.0f}x samples)  "
          f"{per_s / m * 1e3:6.3f} ms  {s['trials'] / steps:8.4f}  {s['kernel_evals'] / steps:8.4f}  "
          f"{s['collisions'] / t2:9.0f}")
PY
[ "$CALLGRIND" = 1 ] || exit 0
for n in $CG_SAMPLES; do
  tot=()
  for t in "$CG_T1" "$CG_T2"; do
    # shellcheck disable=SC2046
    valgrind --tool=callgrind --callgrind-out-file="$OUT/cg_${n}_$t.out" "$AGGLO" acoustic "$CASE" \
      --out "$OUT/cg_${n}_$t" $(opts "$n" "$t") > /dev/null 2> "$OUT/cg_${n}_$t.log"
    tot+=("$(sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$OUT/cg_${n}_$t.log")")
  done
  /usr/bin/python3 -c "
n, a, b, t1, t2 = $n, ${tot[0]}, ${tot[1]}, $CG_T1, $CG_T2
steps = round((t2 - t1) / 5.102040816326531e-05)
print(f'callgrind {n} samples: {(b - a) / (n * steps):.0f} instructions per sample-step ({steps} steps: {a:.4g} -> {b:.4g})')"
done
