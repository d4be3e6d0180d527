#!/usr/bin/env bash
# PartMC's three coagulation benchmarks side by side (issue 10 item 5; bench/README.md "PartMC's
# coagulation benchmarks"): cases/partmc_constant.toml, partmc_additive.toml, partmc_brownian.toml,
# each at 1e4, 3e4, 5e4 and 1e5 samples (3e4 and 5e4: the equal-accuracy points against PartMC's 1e5), with both
# collision selections. Outputs as PartMC's timing runs: N(t) at 11 times, size distributions at the case's
# psd_times, no particle snapshots. Per run: N(T) error against the closed
# form (constant, additive) or `agglo sectional` (Brownian), size-distribution relative L2 error
# (number and volume-weighted), wall time, user CPU on one thread, peak memory. Optionally callgrind
# instruction counts. Analysis: bench/partmc_compare.py. Output: OUT/partmc_cases.md (the table, also
# printed), OUT/partmc_runs.csv (one row per run), OUT/runs/*, OUT/sectional/*, OUT/callgrind/*.
#
#   bench/partmc_cases.sh [OUT]                 (default OUT: results/partmc_cases)
#   QUICK=1 bench/partmc_cases.sh /tmp/pmc      (2 seeds, 1e4 only, Brownian cut to 600 s, no callgrind)
#   SMOKE=1 bench/partmc_cases.sh /tmp/pmc      (the smoke test, ctest -L bench: QUICK's settings with 1e3
#                                                samples, one seed, Brownian 120 s (shortened: 60 s), SECT_BPD=10,
#                                                JOBS=1, CSV outputs only: no results.nc)
#
# Environment (defaults in brackets; QUICK=1 changes the ones marked *):
#   AGGLO            agglo binary [build/agglo]
#   JOBS             runs at a time [2]; every run uses one thread (--threads 1, OMP_NUM_THREADS=1)
#   SAMPLES*         sample counts [10000 30000 50000 100000]; quick: 10000
#   SELECTIONS       collision selections, passed as --set time.selection=NAME [binned nanbu]
#   SELECTION_KEY    1: pass time.selection [1]; 0: pass nothing (an agglo without the key): SELECTIONS
#                    must then be one name, the label of the built-in method (e.g. SELECTIONS=nanbu)
#   SEEDS*           seeds 1..SEEDS of every full run [10]; quick: 2
#   NANBU_BROWN_SAMPLES  sample counts of the full-length Brownian nanbu runs [10000] (nanbu at 1e5 over
#                    the 4 h takes many minutes per run); the others get the shortened run only
#   NANBU_BROWN_SEEDS*   seeds of those runs [3]; quick: 2
#   BROWN_END*       time.end of the "full" Brownian runs [14400]; quick: 600
#   SHORT_END        time.end of the shortened Brownian runs, both selections, every sample count [120]
#   SHORT_SEEDS*     seeds of the shortened runs [3]; quick: 2
#   SHORT_RANGE      population.lognormal_range of the shortened runs [3.5]: the case file samples the whole
#                    distribution (5.5), whose 9 um tail raises nanbu's cell majorant ~100x (119 s instead of
#                    1 s for 120 s at 1e4); the ratio is measured on the same, shorter-tailed input
#   SECT_BPD         sectional.bins_per_decade of the Brownian reference [80]
#   CALLGRIND*       1: instruction counts with valgrind --tool=callgrind, 1e4 samples, seed 1, constant
#                    and additive full, Brownian shortened [1 if valgrind is installed]; quick: 0
#   CG_SAMPLES       sample counts of the callgrind runs [10000]; with more than 1e4 the Brownian one runs the
#                    full 4 h (BROWN_END) as well, e.g. CG_SAMPLES="50000 100000" SAMPLES=10000 SEEDS=2 SHORT_SEEDS=1
#                    (callgrind only: the three cases' instructions at the equal-accuracy sample counts)
#   BEFORE_AGGLO     an agglo built from an earlier commit: every callgrind run also with it (name _before),
#                    the instruction ratio after/before printed (bit-identical changes: same N(T))
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
OUT=${1:-$SRC/results/partmc_cases}
AGGLO=${AGGLO:-$SRC/build/agglo}
QUICK=${QUICK:-0}
if [[ ${SMOKE:-0} == 1 ]]; then
  QUICK=1 SAMPLES=${SAMPLES:-1000} SEEDS=${SEEDS:-1} SHORT_SEEDS=${SHORT_SEEDS:-1} NANBU_BROWN_SEEDS=${NANBU_BROWN_SEEDS:-1}
  BROWN_END=${BROWN_END:-120} SHORT_END=${SHORT_END:-60} SECT_BPD=${SECT_BPD:-10}
  JOBS=${JOBS:-1}
fi
if [[ $QUICK == 1 ]]; then
  q_samples=10000 q_seeds=2 q_nb_seeds=2 q_brown_end=600 q_short_seeds=2 q_callgrind=0
else
  q_samples="10000 30000 50000 100000" q_seeds=10 q_nb_seeds=3 q_brown_end=14400 q_short_seeds=3
  q_callgrind=$(command -v valgrind > /dev/null && echo 1 || echo 0)
fi
JOBS=${JOBS:-2}
SAMPLES=${SAMPLES:-$q_samples}
SELECTIONS=${SELECTIONS:-binned nanbu}
SELECTION_KEY=${SELECTION_KEY:-1}
SEEDS=${SEEDS:-$q_seeds}
NANBU_BROWN_SAMPLES=${NANBU_BROWN_SAMPLES:-10000}
NANBU_BROWN_SEEDS=${NANBU_BROWN_SEEDS:-$q_nb_seeds}
BROWN_END=${BROWN_END:-$q_brown_end}
SHORT_END=${SHORT_END:-120}
SHORT_RANGE=${SHORT_RANGE:-3.5}
SHORT_SEEDS=${SHORT_SEEDS:-$q_short_seeds}
SECT_BPD=${SECT_BPD:-80}
CALLGRIND=${CALLGRIND:-$q_callgrind}
CG_SAMPLES=${CG_SAMPLES:-10000}
BEFORE_AGGLO=${BEFORE_AGGLO:-}
[[ -z $BEFORE_AGGLO || -x $BEFORE_AGGLO ]] || die_early=1

die() { echo "partmc_cases.sh: $*" >&2; exit 1; }
[[ -z ${die_early:-} ]] || die "BEFORE_AGGLO=$BEFORE_AGGLO is not an executable"
[[ -x $AGGLO ]] || die "no agglo binary at $AGGLO (build it: cmake --build build --target agglo)"
[[ -x /usr/bin/time ]] || die "/usr/bin/time is missing (apt-get install time)"
read -r -a sel_list <<< "$SELECTIONS"
[[ ${#sel_list[@]} -ge 1 ]] || die "SELECTIONS is empty"
if [[ $SELECTION_KEY == 0 ]]; then
  [[ ${#sel_list[@]} == 1 ]] || die "SELECTION_KEY=0 runs the built-in method only: give one label, e.g. SELECTIONS=nanbu"
else
  for s in "${sel_list[@]}"; do  # the key and each value must be known to this agglo before hours of runs
    "$AGGLO" -q acoustic "$SRC/cases/partmc_constant.toml" --dry-run --set "time.selection=$s" > /dev/null 2>&1 ||
      die "$AGGLO does not accept --set time.selection=$s: $("$AGGLO" -q acoustic "$SRC/cases/partmc_constant.toml" \
        --dry-run --set "time.selection=$s" 2>&1 | tail -1)
  (an agglo without the key: SELECTION_KEY=0 SELECTIONS=nanbu)"
  done
fi
if [[ $CALLGRIND == 1 ]] && ! command -v valgrind > /dev/null; then die "CALLGRIND=1 but valgrind is not installed"; fi

mkdir -p "$OUT/runs" "$OUT/sectional" "$OUT/callgrind"
# The settings, for the header of the table (partmc_compare.py prints them).
cat > "$OUT/settings.txt" << END_SETTINGS
$("$AGGLO" --version 2>/dev/null | tail -1), script commit $(git -C "$SRC" rev-parse --short HEAD 2>/dev/null || echo unknown)
host $(uname -n), $(nproc) cores, JOBS=$JOBS runs at a time, one thread each, QUICK=$QUICK
SELECTIONS="${sel_list[*]}" SELECTION_KEY=$SELECTION_KEY SEEDS=$SEEDS
NANBU_BROWN_SAMPLES="$NANBU_BROWN_SAMPLES" NANBU_BROWN_SEEDS=$NANBU_BROWN_SEEDS BROWN_END=$BROWN_END
SHORT_END=$SHORT_END SHORT_SEEDS=$SHORT_SEEDS SECT_BPD=$SECT_BPD CALLGRIND=$CALLGRIND CG_SAMPLES="$CG_SAMPLES"
${BEFORE_AGGLO:+BEFORE_AGGLO: $("$BEFORE_AGGLO" --version 2>/dev/null | tail -1)}
END_SETTINGS
jobs_file="$OUT/jobs.txt"
: > "$jobs_file"

# One job line: KIND NAME CASE SELECTION SAMPLES SEED END. KIND: run (timed), sect (reference), cg (callgrind).
add_job() { echo "$*" >> "$jobs_file"; }
is_in() { local x=$1; shift; for y in "$@"; do [[ $x == "$y" ]] && return 0; done; return 1; }
read -r -a samples_list <<< "$SAMPLES"
read -r -a nb_samples_list <<< "$NANBU_BROWN_SAMPLES"

for sel in "${sel_list[@]}"; do
  for n in "${samples_list[@]}"; do
    for case in constant additive; do
      for seed in $(seq 1 "$SEEDS"); do add_job run "${case}_full_n${n}_${sel}_s${seed}" "$case" "$sel" "$n" "$seed" -; done
    done
    brown_seeds=$SEEDS
    if [[ $sel == nanbu ]]; then brown_seeds=0; is_in "$n" "${nb_samples_list[@]}" && brown_seeds=$NANBU_BROWN_SEEDS; fi
    for seed in $(seq 1 "$brown_seeds"); do add_job run "brownian_full_n${n}_${sel}_s${seed}" brownian "$sel" "$n" "$seed" "$BROWN_END"; done
    for seed in $(seq 1 "$SHORT_SEEDS"); do add_job run "brownian_short_n${n}_${sel}_s${seed}" brownian "$sel" "$n" "$seed" "$SHORT_END"; done
  done
  if [[ $CALLGRIND == 1 ]]; then
    for n in $CG_SAMPLES; do
      for kind in cg ${BEFORE_AGGLO:+cgb}; do
        sfx=$([[ $kind == cgb ]] && echo _before || true)
        add_job "$kind" "constant_full_n${n}_${sel}$sfx" constant "$sel" "$n" 1 -
        add_job "$kind" "additive_full_n${n}_${sel}$sfx" additive "$sel" "$n" 1 -
        add_job "$kind" "brownian_short_n${n}_${sel}$sfx" brownian "$sel" "$n" 1 "$SHORT_END"
        [[ $n -gt 10000 ]] && add_job "$kind" "brownian_full_n${n}_${sel}$sfx" brownian "$sel" "$n" 1 "$BROWN_END"
      done
    done
  fi
done
add_job sect brownian_full brownian - 0 1 "$BROWN_END"
add_job sect brownian_short brownian - 0 1 "$SHORT_END"

# One job: the agglo command line of the job, run under /usr/bin/time (or callgrind) into its folder.
run_job() {
  local kind=$1 name=$2 case=$3 sel=$4 n=$5 seed=$6 end=$7
  local dir args=(--threads 1 --overwrite --set "seed=$seed")
  [[ ${SMOKE:-0} == 1 ]] && args+=(--format csv)
  [[ $end != - ]] && args+=(--set "time.end=$end" --set "output.psd_times=[0.0,$end]")
  if [[ $kind == sect ]]; then
    dir="$OUT/sectional/$name"
    args+=(--set "sectional.bins_per_decade=$SECT_BPD")
    cmd=(sectional)
  else
    dir="$OUT/$([[ $kind == cg* ]] && echo callgrind || echo runs)/$name"
    args+=(--set "population.0.samples=$n" --set "output.snapshot_times=[]")
    local t_end=$end
    [[ $t_end == - ]] && t_end=$(sed -n 's/^end = \([0-9.e+]*\).*/\1/p' "$SRC/cases/partmc_$case.toml" | head -1)
    [[ -n $t_end ]] && args+=(--set "output.efficiency_interval=$(awk -v t="$t_end" 'BEGIN { print t / 10 }')")
    [[ $name == brownian_short* ]] && args+=(--set "population.0.lognormal_range=$SHORT_RANGE")
    [[ $SELECTION_KEY != 0 ]] && args+=(--set "time.selection=$sel")
    cmd=(acoustic)
  fi
  mkdir -p "$dir"
  local pre=(/usr/bin/time -o "$dir/time.txt" -f '%e %U %S %M')
  [[ $kind == cg* ]] && pre=(valgrind --tool=callgrind --callgrind-out-file="$dir/callgrind.out" --log-file="$dir/callgrind.log")
  local bin=$AGGLO
  [[ $kind == cgb ]] && bin=$BEFORE_AGGLO
  if ! OMP_NUM_THREADS=1 "${pre[@]}" "$bin" -q --no-plots "${cmd[@]}" "$SRC/cases/partmc_$case.toml" \
      --out "$dir/out" "${args[@]}" > "$dir/stdout.txt" 2> "$dir/stderr.txt"; then
    echo "FAILED: $name ($AGGLO -q --no-plots ${cmd[*]} cases/partmc_$case.toml ${args[*]}): $(tail -1 "$dir/stderr.txt")" >&2
    return 1
  fi
  rm -f "$dir/callgrind.out"  # the total is in callgrind.log; the profile itself is large
}
export -f run_job
export OUT SRC AGGLO BEFORE_AGGLO SECT_BPD SELECTION_KEY SHORT_RANGE

n_jobs=$(wc -l < "$jobs_file")
echo "partmc_cases.sh: $n_jobs jobs, $JOBS at a time, into $OUT (selections: ${sel_list[*]}; samples: ${samples_list[*]}; seeds: $SEEDS)" >&2
t0=$(date +%s)
# References and timed runs first, callgrind after them (slow; it would share the cores with timed runs).
for kinds in 'sect|run' 'cg|cgb'; do
  if ! { grep -E "^($kinds) " "$jobs_file" || true; } | xargs -r -P "$JOBS" -L 1 bash -c 'run_job "$@"' _; then
    die "some runs failed (lines FAILED above; each run's stderr.txt is in its folder under $OUT)"
  fi
done
echo "partmc_cases.sh: all runs done in $(( $(date +%s) - t0 )) s" >&2

/usr/bin/python3 "$SRC/bench/partmc_compare.py" "$OUT" --partmc-sectional "$SRC/tests/data/partmc/brown_sectional_N.csv"
