#!/usr/bin/env bash
# The MPI task farm (docs/scaling.md): `mpirun -n 2` and `-n 3 --oversubscribe` give the same outputs as
# one process for vcrit (also top-down: vcrit.json), breakup, calibrate, outcomes, sweep, a seed ensemble (acoustic --seeds) and a sweep with seeds (every file; results.nc by content with timing
# aside; journal.jsonl as a set of results; run.json records the rank count). A single-run command under
# mpirun is refused with one line. $1 = agglo, $2 = source dir, $3 = mpirun.
. "$(dirname "$0")/lib.sh"
NT=cases/seed000_neutral_tetrahedron.toml
SHORT=(-q --no-plots --set time.after_contact=2e-4 --set output.snapshot_interval=0)

check() {  # name, args...: one process on 2 threads vs 2 and 3 ranks of 1 thread
  local name=$1; shift
  "$AGGLO" "$@" --threads 2 --out "$TMP/$name.1" > /dev/null 2>&1 || fail "$name: one process"
  for k in 2 3; do
    run_mpi $k "$@" --threads 1 --out "$TMP/$name.$k" > "$TMP/$name.$k.log" 2>&1 ||
      fail "$name: $k ranks: $(tail -3 "$TMP/$name.$k.log")"
    same_outputs "$TMP/$name.1" "$TMP/$name.$k" || fail "$name: $k ranks differ from one process"
    [ "$(ranks_of "$TMP/$name.$k")" = "$k" ] || fail "$name: run.json ranks"
  done
  [ "$(ranks_of "$TMP/$name.1")" = 1 ] || fail "$name: run.json ranks of one process"
  no_scratch_left
  echo "ok $name"
}

check vcrit vcrit $NT "${SHORT[@]}" --set vcrit.scan_points=5 --set vcrit.v_min=0.05 --set vcrit.v_max=0.8 \
  --set vcrit.tolerance=0.01
check breakup breakup $NT "${SHORT[@]}" --set 'breakup.speeds=[0.1,0.15,0.2,0.3,0.4]' --set breakup.samples=3
check sweep sweep $NT --command collide --param projectile.speed --values 0.1,0.2,0.3,0.4 \
  --param material.restitution --values 0.8,0.9 "${SHORT[@]}"
cat > "$TMP/cal.toml" << CAL
[calibrate]
grid_points = 5
refine_rounds = 1
[[parameter]]
key = "material.restitution"
lower = 0.6
upper = 0.98
[[target]]
case = "$SRC/$NT"
value = 0.2
tolerance = 0.01
CAL
check calibrate calibrate "$TMP/cal.toml" -q --no-plots
check outcomes outcomes cases/outcomes_sphere_sphere.toml -q --set "outcome_grid.speeds=[0.1, 0.8]" \
  --set "outcome_grid.diameters=[1e-6, 2e-6]" --set outcome_grid.impacts=3
check seeds acoustic cases/seed002_baseline.toml --seeds 4 -q --no-plots --set time.end=0.01 \
  --set "output.psd_times=[0.0,0.01]" --set "output.snapshot_times=[0.0]" --set output.plots=false \
  --set population.0.samples=1500 --set population.1.samples=50
check sweep_seeds sweep cases/seed002_baseline.toml --param population.1.diameter --values 20e-6,40e-6 --seeds 3 \
  -q --no-plots --set time.end=0.01 --set "output.psd_times=[0.0,0.01]" --set "output.snapshot_times=[0.0]" \
  --set population.0.samples=1500 --set population.1.samples=50

# vcrit.order = "top_down": one process skips the jobs of a batch after its first non-break, the ranks run
# them all and keep the same prefix, so the journals differ; vcrit.json must not.
TD=(vcrit $NT "${SHORT[@]}" --set vcrit.scan_points=8 --set vcrit.tolerance=0.002 --set 'vcrit.order="top_down"')
"$AGGLO" "${TD[@]}" --threads 2 --out "$TMP/td.1" > /dev/null 2>&1 || fail "top_down: one process"
run_mpi 3 "${TD[@]}" --threads 1 --out "$TMP/td.3" > "$TMP/td.3.log" 2>&1 || fail "top_down: 3 ranks: $(tail -3 "$TMP/td.3.log")"
cmp -s "$TMP/td.1/vcrit.json" "$TMP/td.3/vcrit.json" || fail "top_down: vcrit.json of 3 ranks differs from one process"
no_scratch_left
echo "ok vcrit top_down"

# A single run is not an ensemble: refused on every rank, reported once, nothing written.
run_mpi 2 collide $NT "${SHORT[@]}" --out "$TMP/single" > "$TMP/single.out" 2> "$TMP/single.err"
rc=$?
[ $rc -eq 2 ] || fail "collide under mpirun: exit $rc, expected 2"
[ "$(grep -c "agglo: error: collide is a single run" "$TMP/single.err")" = 1 ] ||
  fail "collide under mpirun: message: $(cat "$TMP/single.err")"
[ -e "$TMP/single" ] && fail "collide under mpirun left a folder"
echo "ok single run refused"
