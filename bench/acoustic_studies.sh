#!/usr/bin/env bash
# Runs the seed-002 studies behind docs/acoustics.md. Usage: bench/acoustic_studies.sh AGGLO OUTDIR [part]
# parts: integrator | diameter | concentration | validation | baseline | diameter_seeds |
# concentration_seeds | all | every (default all: the first five; every: all seven; the *_seeds parts are
# the two sweeps with 4 seeds per point and error bars, points with droplets only, docs/acoustics.md "Seed
# ensembles and error bars").
# Every case runs at its own steps (5e-5 s for the 2000 Hz cases, 10 steps per acoustic period; the
# exact integrator with drift correction, docs/acoustics.md sec. 3). Extra flags for every sweep can be
# given in BIG (e.g. BIG="--set time.collision_dt=1e-5 --set time.motion_dt=1e-5"). JOBS = threads,
# SEEDS = members per point of the *_seeds parts (default 4).
# SMOKE=1: the smoke test (ctest -L bench): "all" runs every part, each case cut to 1e-4 s (two steps;
# the integrator check 10 steps of 1e-5 s, 1000 explicit ones), 200 + 20 samples (no clones), no snapshots,
# CSV outputs only (no results.nc), no plots, one seed of the integrator check, SEEDS=2, JOBS=1; the same
# cases, sweeps and options otherwise.
set -eu
AGGLO="$1"
OUT="$2"
PART="${3:-all}"
SRC="$(cd "$(dirname "$0")/.." && pwd)"
C="$SRC/cases"
read -r -a big <<<"${BIG-}"
int_seeds="1 2 3 4" int=() sm=() val=()
if [ "${SMOKE:-0}" = 1 ]; then
  int_seeds=1 SEEDS=${SEEDS:-2} JOBS=${JOBS:-1}
  # two steps of 5e-5 s (the validation case: of its 1/(14 f) step), 200 + 20 samples (no clones), psd only
  # at the start, no snapshots, no plots, no results.nc
  cut=(--set "output.psd_times=[0.0]" --set "output.snapshot_times=[]" --no-plots --format csv
       --set population.0.samples=200 --set population.1.samples=20 --set sampling.min_samples_per_cell=0)
  int=(--set time.end=1e-4 "${cut[@]}")
  sm=(--set time.end=1e-4 "${cut[@]}")
  val=(--set time.end=1.0204081632653062e-4 "${cut[@]}")
  [ "$PART" = all ] && PART=every
fi
mkdir -p "$OUT"
if [ "$PART" = integrator ] || [ "$PART" = all ] || [ "$PART" = every ]; then
  for s in $int_seeds; do
    "$AGGLO" -q acoustic "$C/seed002_integrator_check.toml" --overwrite --out "$OUT/int_exact_1e-5_s$s" --set seed=$s -j 1 \
      "${int[@]}"
    for dt in 5e-5 1e-4; do
      "$AGGLO" -q acoustic "$C/seed002_integrator_check.toml" --overwrite --out "$OUT/int_exact_${dt}_s$s" --set seed=$s -j 1 \
        --set time.collision_dt=$dt --set time.motion_dt=$dt "${int[@]}"
    done
    "$AGGLO" -q acoustic "$C/seed002_integrator_check.toml" --overwrite --out "$OUT/int_explicit_1e-7_s$s" --set seed=$s -j 1 \
      --set 'time.integrator="explicit"' --set time.motion_dt=1e-7 "${int[@]}"
  done
fi
if [ "$PART" = diameter ] || [ "$PART" = all ] || [ "$PART" = every ]; then
  "$AGGLO" -q sweep "$C/seed002_droplet_diameter.toml" --param population.1.diameter \
    --values 0,10e-6,20e-6,30e-6,40e-6,50e-6 --overwrite --out "$OUT/droplet_diameter" "${big[@]}" "${sm[@]}" -j "${JOBS:-1}"
fi
if [ "$PART" = concentration ] || [ "$PART" = all ] || [ "$PART" = every ]; then
  "$AGGLO" -q sweep "$C/seed002_droplet_concentration.toml" --param population.1.number_concentration \
    --values 0,1e8,5e8,1e9,2e9,3e9,5e9 --overwrite --out "$OUT/droplet_concentration" "${big[@]}" "${sm[@]}" -j "${JOBS:-1}"
fi
if [ "$PART" = validation ] || [ "$PART" = all ] || [ "$PART" = every ]; then
  "$AGGLO" -q sweep "$C/seed002_validation.toml" --param population.1.number_concentration --values 0,1e9 \
    --overwrite --out "$OUT/validation" "${big[@]}" "${val[@]}" -j "${JOBS:-1}"
fi
if [ "$PART" = baseline ] || [ "$PART" = all ] || [ "$PART" = every ]; then
  "$AGGLO" -q acoustic "$C/seed002_baseline.toml" --overwrite --out "$OUT/baseline" "${sm[@]}" -j "${JOBS:-1}"
fi
if [ "$PART" = diameter_seeds ] || [ "$PART" = every ]; then
  "$AGGLO" -q sweep "$C/seed002_droplet_diameter.toml" --param population.1.diameter \
    --values 10e-6,20e-6,30e-6,40e-6,50e-6 --seeds "${SEEDS:-4}" --overwrite --out "$OUT/droplet_diameter_seeds" \
    "${big[@]}" "${sm[@]}" -j "${JOBS:-2}"
fi
if [ "$PART" = concentration_seeds ] || [ "$PART" = every ]; then
  "$AGGLO" -q sweep "$C/seed002_droplet_concentration.toml" --param population.1.number_concentration \
    --values 1e8,5e8,1e9,2e9,3e9,5e9 --seeds "${SEEDS:-4}" --overwrite --out "$OUT/droplet_concentration_seeds" \
    "${big[@]}" "${sm[@]}" -j "${JOBS:-2}"
fi
