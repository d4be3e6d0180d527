#!/usr/bin/env bash
# Runs every shipped case (cases/*.toml) with the command(s) it is meant for, shortened where the
# case is long, on 2 threads and without plots, into OUTROOT/<case>-<command>/.
# Usage: run_cases.sh AGGLO_EXECUTABLE SOURCE_DIR OUTROOT   (case paths are given as cases/<name>.toml
# relative to SOURCE_DIR, so that run.json does not depend on where the checkout lives)
# Used by the output regression test (check.sh) and by scripts/regression_compare.sh, which runs it
# with the executable of an older commit so that outputs can be compared on one machine.
# AGGLO_SKIP_RUNS (space-separated <command>:<case stem>) leaves those runs out (the sanitizer
# regression, tests/sanitizers/regression_skipped_runs.txt).
set -u
A=$(realpath "$1"); O=$(realpath -m "$3"); cd "$2" || exit 2; C=cases
mkdir -p "$O"
status=0
run() {  # run <command> <case stem> [args...]
  local t0=$SECONDS
  local cmd=$1 stem=$2; shift 2
  case " ${AGGLO_SKIP_RUNS:-} " in *" $cmd:$stem "*) return 0 ;; esac
  local dir="$O/$stem-$cmd"
  rm -rf "$dir"
  if ! "$A" -q --no-plots "$cmd" "$C/$stem.toml" --out "$dir" --threads 2 "$@" >"$O/$stem-$cmd.stdout" 2>"$O/$stem-$cmd.stderr"; then
    echo "run_cases: $cmd $stem failed: $(head -c 300 "$O/$stem-$cmd.stderr")" >&2
    status=1
  fi
  rm -f "$O/$stem-$cmd.stdout" "$O/$stem-$cmd.stderr"
  [ -n "${VERBOSE:-}" ] && echo "$cmd $stem $((SECONDS - t0)) s" >&2
}
SHORT_DEM=(--set time.after_contact=2e-4 --set output.snapshot_interval=5e-5)
# The charged squares are undecided at the end of the short run and were extended by time.extension = 1 ms
# twice (about 16 700 solves, 9.8 and 8.6 s of CPU); extensions of 2e-5 s reach the same code (four extensions,
# then "undecided") in 1.3 and 2.0 s.
SHORT_CHARGED=(--set time.after_contact=4e-5 --set output.snapshot_interval=2e-5 --set projectile.gap_radii=0.3
               --set time.extension=2e-5)
for c in "$C"/seed000_neutral_*.toml "$C"/seed000_charged_*_k1.toml; do
  run collide "$(basename "$c" .toml)" "${SHORT_DEM[@]}"
done
for c in "$C"/seed000_charged_*_k2p5.toml "$C"/seed000_charged_*_k15.toml; do
  run collide "$(basename "$c" .toml)" "${SHORT_CHARGED[@]}"
done
VC=(--set vcrit.scan_points=4 --set vcrit.v_min=0.05 --set vcrit.v_max=0.8 --set vcrit.tolerance=0.03)
run vcrit seed000_neutral_tetrahedron "${SHORT_DEM[@]}" "${VC[@]}"
run vcrit seed000_charged_tetrahedron_k1 "${SHORT_DEM[@]}" "${VC[@]}"
BU=(--set 'breakup.speeds=[0.12,0.4]' --set breakup.samples=2)
run breakup seed000_neutral_square "${SHORT_DEM[@]}" "${BU[@]}"
run breakup seed000_charged_square_k1 "${SHORT_DEM[@]}" "${BU[@]}"
for c in "$C"/electrostatics_*.toml; do
  run electrostatics "$(basename "$c" .toml)"
done
run electrostatics electrostatics_tetrahedron --set electrostatics.solver=bem --set electrostatics.patches_per_sphere=200
mv "$O/electrostatics_tetrahedron-electrostatics" "$O/electrostatics_tetrahedron_bem-electrostatics" 2>/dev/null
run electrostatics electrostatics_tetrahedron
# The structure builder (docs/model.md Part S): a lognormal fractal aggregate and a BPCA aggregate.
run aggregate aggregate_fractal
run aggregate aggregate_bpca
# Walls (docs/dem.md "Gas and walls"): a sphere sticking on a wall of its material, the tetrahedron in air
# hitting a rigid wall at 30 degrees, and the breakage study's 500-primary BPCA aggregate at 2 m/s.
run collide sphere_wall
run collide agglomerate_wall_gas
run collide breakage_wall_bpca --set projectile.speed=2 --set time.after_contact=1.1e-4
# The sphere-sphere outcome table of agglo outcomes (docs/outcomes.md), 288 impacts.
run outcomes outcomes_sphere_sphere
# The aggregate-aggregate outcome table (docs/outcomes.md "Aggregate tables"), 240 impacts, 0.8 s.
run outcomes outcomes_aggregates
for c in "$C"/seed002_*.toml; do
  run acoustic "$(basename "$c" .toml)" --set time.end=0.02 --set "output.snapshot_times=[0.0,0.01]" --set "output.psd_times=[0.0,0.02]"
done
run sweep seed002_baseline --param population.1.diameter --values 10e-6,30e-6 --set time.end=0.01 --set "output.snapshot_times=[0.0]" --set "output.psd_times=[0.0,0.01]"
# The calibration's v_crit runs shortened as the vcrit runs above (13 s of CPU with the cases' own settings, 1.6 s).
run calibrate calibrate_seed000_tetrahedron --set calibrate.predict=\"none\" --set calibrate.grid_points=3 --set calibrate.refine_rounds=0 --set calibrate.fine_points=11 \
  --set 'calibrate.case_overrides="agglomerate.orientation=\"edge_along\";vcrit.tolerance=0.03;vcrit.scan_points=4;vcrit.v_min=0.05;vcrit.v_max=0.8;time.after_contact=2e-4"'
run sectional partmc_constant
run sectional partmc_brownian
run sectional partmc_additive --set time.end=150 --set "output.psd_times=[0.0,150.0]"
# The binned selection: a shortened DSMC run of the Brownian case (the case sets it), and the acoustic
# baseline with it (into seed002_baseline_binned-acoustic; the default run's folder is set aside meanwhile).
run acoustic partmc_brownian --set population.0.samples=2000 --set time.end=3600 --set "output.psd_times=[0.0,3600.0]"
# PartMC's constant and additive kernels through the DSMC (binned selection, no motion), whole runs at 2000
# samples (0.02 s of CPU each): their outputs were in no regression run.
run acoustic partmc_constant --set population.0.samples=2000
run acoustic partmc_additive --set population.0.samples=2000
mv "$O/seed002_baseline-acoustic" "$O/.nanbu" 2>/dev/null
run acoustic seed002_baseline --set time.selection=binned --set time.end=0.02 --set "output.snapshot_times=[0.0,0.01]" --set "output.psd_times=[0.0,0.02]"
rm -rf "$O/seed002_baseline_binned-acoustic"
mv "$O/seed002_baseline-acoustic" "$O/seed002_baseline_binned-acoustic" 2>/dev/null
mv "$O/.nanbu" "$O/seed002_baseline-acoustic" 2>/dev/null
exit $status
