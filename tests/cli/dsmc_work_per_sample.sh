#!/usr/bin/env bash
# The acoustic DSMC's work per sample-step does not grow with the sample count at fixed physics (issue 23
# item 7; docs/acoustics.md §5.2). cases/flyash_147db.toml at 2000 and 8000 samples, 100 steps, one
# thread: every sample-step is one Nanbu trial (no sub-cycles), and the kernel evaluations per
# sample-step (trials that pass the cell majorant) at 4x the samples stay within 1.5x of the smaller
# run's (measured: 0.026 at 2000, 0.030 at 8000, 0.034 at 16000: the cell maxima approach the
# distribution's). Counters, never timing. (The issue's 30x per simulated second came from the threads:
# 2000 samples ran serially, 8000 on two spinning threads; tests/cli/omp_wait_policy.sh.)
source "$(dirname "$0")/lib.sh"

FA="$SRC/cases/flyash_147db.toml"
T_END=0.005102040816326531  # 100 steps of 1/(14 f)
# counters N: prints "particle_steps trials kernel_evals" of a run with N samples
counters() {
  "$A" acoustic "$FA" --out "$T/n$1" --threads 1 --no-plots --quiet --format csv --set time.end=$T_END \
    --set population.0.samples="$1" --set "output.psd_times=[0.0]" --set "output.snapshot_times=[]" \
    --set output.efficiency_interval=$T_END > /dev/null || fail "run with $1 samples failed"
  /usr/bin/python3 -c "import json,sys; s=json.load(open(sys.argv[1]))['nanbu']; \
print(s['particle_steps'], s['trials'], s['kernel_evals'])" "$T/n$1/summary.json"
}
read -r ps1 tr1 ke1 <<< "$(counters 2000)"
read -r ps4 tr4 ke4 <<< "$(counters 8000)"
[ "$ps1" -eq $((2000 * 100)) ] && [ "$ps4" -eq $((8000 * 100)) ] || fail "sample-steps $ps1, $ps4"
[ "$tr1" -eq "$ps1" ] && [ "$tr4" -eq "$ps4" ] || fail "trials per sample-step above 1: $tr1/$ps1, $tr4/$ps4"
/usr/bin/python3 -c "
import sys
a, b = $ke1 / $ps1, $ke4 / $ps4
print(f'kernel evaluations per sample-step: {a:.4f} at 2000 samples, {b:.4f} at 8000 ({b / a:.2f}x)')
sys.exit(0 if 0 < a and b <= 1.5 * a else 1)" || fail "kernel evaluations per sample-step grow with the sample count"
echo "PASS"
