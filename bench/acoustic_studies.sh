#!/usr/bin/env bash
# Runs the seed-002 studies behind docs/acoustics.md. Usage: bench/acoustic_studies.sh AGGLO OUTDIR [part]
# parts: integrator | diameter | concentration | validation | baseline | diameter_seeds |
# concentration_seeds | all (default all: the first five; the *_seeds parts are the two sweeps with 4 seeds
# per point and error bars, points with droplets only, docs/acoustics.md "Seed ensembles and error bars").
# Every case runs at its own steps (5e-5 s for the 2000 Hz cases, 10 steps per acoustic period; the
# exact integrator with drift correction, docs/acoustics.md sec. 3). Extra flags for every sweep can be
# given in BIG (e.g. BIG="--set time.collision_dt=1e-5 --set time.motion_dt=1e-5"). JOBS = threads,
# SEEDS = members per point of the *_seeds parts (default 4).
set -eu
AGGLO="$1"
OUT="$2"
PART="${3:-all}"
SRC="$(cd "$(dirname "$0")/.." && pwd)"
C="$SRC/cases"
read -r -a big <<<"${BIG-}"
mkdir -p "$OUT"
if [ "$PART" = integrator ] || [ "$PART" = all ]; then
  for s in 1 2 3 4; do
    "$AGGLO" -q acoustic "$C/seed002_integrator_check.toml" --overwrite --out "$OUT/int_exact_1e-5_s$s" --set seed=$s -j 1
    for dt in 5e-5 1e-4; do
      "$AGGLO" -q acoustic "$C/seed002_integrator_check.toml" --overwrite --out "$OUT/int_exact_${dt}_s$s" --set seed=$s -j 1 \
        --set time.collision_dt=$dt --set time.motion_dt=$dt
    done
    "$AGGLO" -q acoustic "$C/seed002_integrator_check.toml" --overwrite --out "$OUT/int_explicit_1e-7_s$s" --set seed=$s -j 1 \
      --set 'time.integrator="explicit"' --set time.motion_dt=1e-7
  done
fi
if [ "$PART" = diameter ] || [ "$PART" = all ]; then
  "$AGGLO" -q sweep "$C/seed002_droplet_diameter.toml" --param population.1.diameter \
    --values 0,10e-6,20e-6,30e-6,40e-6,50e-6 --overwrite --out "$OUT/droplet_diameter" "${big[@]}" -j "${JOBS:-1}"
fi
if [ "$PART" = concentration ] || [ "$PART" = all ]; then
  "$AGGLO" -q sweep "$C/seed002_droplet_concentration.toml" --param population.1.number_concentration \
    --values 0,1e8,5e8,1e9,2e9,3e9,5e9 --overwrite --out "$OUT/droplet_concentration" "${big[@]}" -j "${JOBS:-1}"
fi
if [ "$PART" = validation ] || [ "$PART" = all ]; then
  "$AGGLO" -q sweep "$C/seed002_validation.toml" --param population.1.number_concentration --values 0,1e9 \
    --overwrite --out "$OUT/validation" "${big[@]}" -j "${JOBS:-1}"
fi
if [ "$PART" = baseline ] || [ "$PART" = all ]; then
  "$AGGLO" -q acoustic "$C/seed002_baseline.toml" --overwrite --out "$OUT/baseline" -j "${JOBS:-1}"
fi
if [ "$PART" = diameter_seeds ]; then
  "$AGGLO" -q sweep "$C/seed002_droplet_diameter.toml" --param population.1.diameter \
    --values 10e-6,20e-6,30e-6,40e-6,50e-6 --seeds "${SEEDS:-4}" --overwrite --out "$OUT/droplet_diameter_seeds" \
    "${big[@]}" -j "${JOBS:-2}"
fi
if [ "$PART" = concentration_seeds ]; then
  "$AGGLO" -q sweep "$C/seed002_droplet_concentration.toml" --param population.1.number_concentration \
    --values 1e8,5e8,1e9,2e9,3e9,5e9 --seeds "${SEEDS:-4}" --overwrite --out "$OUT/droplet_concentration_seeds" \
    "${big[@]}" -j "${JOBS:-2}"
fi
