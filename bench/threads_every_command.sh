#!/usr/bin/env bash
# --threads 1 against --threads 2 on every command that computes, measured in one script (issue 27 item 3:
# "threads must help, never hurt", also on a shared machine). Each command runs a shipped case, shortened
# so that one thread takes about 0.2-13 s:
#   collide_k15       collide of the κ_p = 15 seed tetrahedron at 0.18 m/s, 30 µs after contact (spectral
#                     solves in the DEM loop)
#   collide_wall500   collide of the 500-primary fractal on its wall (cases/breakage_wall_fractal.toml), 0.1 ms
#                     after contact
#   vcrit_neutral     vcrit of the neutral seed tetrahedron (runs of the bisection side by side)
#   breakup_bpca      breakup of the BPCA aggregate on its wall, 4 orientations (impacts side by side)
#   calibrate_3x3     calibrate of the seed-000 tetrahedra on a 3 x 3 map without refinement or check
#   electrostatics    electrostatics of the charged tetrahedron (cases/electrostatics_tetrahedron.toml)
#   outcomes_agg      outcomes table of aggregate pairs (cases/outcomes_aggregates.toml)
#   acoustic_base     acoustic of the seed-002 baseline, 0.2 s
#   acoustic_flyash   acoustic of the fly-ash case, 1 s
#   sectional         sectional of PartMC's constant-kernel case
# in ROUNDS interleaved rounds of t1 (--threads 1) and t2 (--threads 2; agglo's defaults: short spin OpenMP
# waits, thread counts by timed probes), their order swapped every round, under /usr/bin/time (wall and
# user CPU of the whole process). Prints `uptime` before and after, every run (with the 1-min load
# average), then per command the median wall and CPU of each and the ratios (bench/threads_summary.py):
# speed-up wall(t1) / wall(t2) (≥ 1: two threads not slower) and CPU(t2) / CPU(t1).
#   bench/threads_every_command.sh [AGGLO] [OUT_DIR]     ROUNDS=3, ONLY=<regex of command labels>
# Timing only (never a test); on a shared machine only the ratios of one invocation mean anything.
#   SMOKE=1: the smoke test (ctest -L bench): ROUNDS=1, only the four quickest commands, shortened further.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
AGGLO=${1:-$SRC/build/agglo}
OUT=${2:-$SRC/results/bench_threads_every_command}
ROUNDS=${ROUNDS:-3}
ONLY=${ONLY:-.}
k15_after=3e-5 wall_after=1e-4 base_end=0.2 flyash_end=1.0
if [ "${SMOKE:-0}" = 1 ]; then
  ROUNDS=1 ONLY='^(collide_k15|vcrit_neutral|electrostatics|acoustic_base)$'
  k15_after=2e-6 base_end=0.002
fi
C="$SRC/cases"
declare -A cmd=(
  [collide_k15]="collide $C/seed000_charged_tetrahedron_k15.toml --speed 0.18 --set time.after_contact=$k15_after"
  [collide_wall500]="collide $C/breakage_wall_fractal.toml --set time.after_contact=$wall_after"
  [vcrit_neutral]="vcrit $C/seed000_neutral_tetrahedron.toml"
  [breakup_bpca]="breakup $C/breakage_wall_bpca.toml --set breakup.orientations=4"
  [calibrate_3x3]="calibrate $C/calibrate_seed000_tetrahedron.toml --set calibrate.grid_points=3
    --set calibrate.refine_rounds=0 --set calibrate.check=false --set calibrate.predict=\"none\""
  [electrostatics]="electrostatics $C/electrostatics_tetrahedron.toml"
  [outcomes_agg]="outcomes $C/outcomes_aggregates.toml"
  [acoustic_base]="acoustic $C/seed002_baseline.toml --set time.end=$base_end --set output.psd_times=[0.0,$base_end]
    --set output.snapshot_times=[0.0]"
  [acoustic_flyash]="acoustic $C/flyash_147db.toml --set time.end=$flyash_end --set output.psd_times=[0.0,$flyash_end]
    --set output.snapshot_times=[0.0]"
  [sectional]="sectional $C/partmc_constant.toml"
)
order=(collide_k15 collide_wall500 vcrit_neutral breakup_bpca calibrate_3x3 electrostatics outcomes_agg acoustic_base
       acoustic_flyash sectional)
mkdir -p "$OUT"
echo "before: $(uptime)"
table="$OUT/threads.tsv"
printf 'command\tvariant\tround\twall_s\tuser_s\tload\n' > "$table"
run() {  # run LABEL VARIANT ROUND
  local label=$1 v=$2 r=$3 args
  read -r -a args <<< "$(tr '\n' ' ' <<< "${cmd[$label]}")"
  env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT -u AGGLO_THREAD_PROBE -u OMP_NUM_THREADS \
    /usr/bin/time -f "%e %U" -o "$OUT/time" "$AGGLO" -q --no-plots "${args[@]}" --threads "${v#t}" \
    --out "$OUT/run_${label}_$v" --overwrite > /dev/null
  read -r wall user < "$OUT/time"
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$label" "$v" "$r" "$wall" "$user" "$(cut -d' ' -f1 /proc/loadavg)" | tee -a "$table"
}
for r in $(seq 1 "$ROUNDS"); do
  vars=(t1 t2)
  [ $((r % 2)) = 1 ] || vars=(t2 t1)  # a load trend over the rounds then favours neither
  for label in "${order[@]}"; do
    [[ $label =~ $ONLY ]] || continue
    for v in "${vars[@]}"; do run "$label" "$v" "$r"; done
  done
done
echo "after: $(uptime)"
/usr/bin/python3 "$SRC/bench/threads_summary.py" "$table" --system command --cpu user_s
