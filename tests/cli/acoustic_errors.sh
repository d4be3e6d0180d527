#!/usr/bin/env bash
# agglo acoustic: bad input gives exit code 2 and a one-line message naming the key; a short valid
# run writes every output file. $1 = agglo executable, $2 = source dir.
. "$(dirname "$0")/lib.sh"  # A, SRC, T (removed on exit), fail
AGGLO=$A TMP=$T
fail=0
base="$SRC/cases/seed002_baseline.toml"
short=(--set time.end=0.001 --set "output.psd_times=[0.0,0.001]" --set "output.snapshot_times=[0.0]" --set output.plots=false)

expect_error() {  # name, expected substring, args...
  local name="$1" pat="$2"
  shift 2
  "$AGGLO" -q acoustic "$base" --out "$TMP/$name" "${short[@]}" "$@" >"$TMP/$name.out" 2>"$TMP/$name.err"
  local rc=$?
  local lines
  lines=$(wc -l <"$TMP/$name.err")
  if [ "$rc" -ne 2 ]; then
    echo "FAIL $name: exit $rc (expected 2)"; cat "$TMP/$name.err"; fail=1
  elif ! grep -q -- "$pat" "$TMP/$name.err"; then
    echo "FAIL $name: message lacks '$pat':"; cat "$TMP/$name.err"; fail=1
  elif [ "$lines" -ne 1 ]; then
    echo "FAIL $name: message has $lines lines"; cat "$TMP/$name.err"; fail=1
  else
    echo "ok   $name: $(cat "$TMP/$name.err")"
  fi
}

expect_error negative_concentration "population.0.number_concentration" --set "population.0.number_concentration=-5e11"
expect_error sigma_below_one "population.0.geometric_std" --set "population.0.geometric_std=0.8"
expect_error absurd_sound_level "sound.level_db" --set "sound.level_db=220"
expect_error cells_too_few_per_wavelength "domain.cells_x" --set "domain.cells_x=20"
expect_error cells_smaller_than_droplet "domain.cells_x" --set "domain.cells_x=8000" --set "population.1.diameter=50e-6"
expect_error length_not_whole_wavelengths "domain.length_x" --set "domain.length_x=0.1"
expect_error nanbu_bound_strict "Nanbu bound" --set "time.nanbu_guard=\"strict\"" --set "time.collision_dt=1e-3" --set "time.end=0.002" --set "sound.level_db=150"
expect_error nanbu_bound_subcycles "Nanbu bound" --set "time.max_subcycles=1" --set "time.collision_dt=1e-3" --set "time.end=0.002" --set "sound.level_db=150"
expect_error explicit_unstable "time.motion_dt" --set "time.integrator=\"explicit\"" --set "time.motion_dt=1e-7"
expect_error unknown_key "typo_key" --set "kernels.typo_key=1"
expect_error bad_integrator "time.integrator" --set "time.integrator=\"rk4\""

# A valid short run writes all outputs.
"$AGGLO" -q acoustic "$base" --out "$TMP/ok" "${short[@]}" >/dev/null 2>"$TMP/ok.err"
rc=$?
if [ $rc -ne 0 ]; then echo "FAIL valid run: exit $rc"; cat "$TMP/ok.err"; fail=1; fi
for f in efficiency.csv psd.csv summary.json run.log config.resolved.toml run.json snapshots.csv; do
  [ -s "$TMP/ok/$f" ] || { echo "FAIL valid run: $f missing"; fail=1; }
done
grep -q "nanbu guard" "$TMP/ok/run.log" || { echo "FAIL run.log lacks the Nanbu guard statistics"; fail=1; }
grep -q '"fine_efficiency"' "$TMP/ok/summary.json" || { echo "FAIL summary.json lacks fine_efficiency"; fail=1; }
exit $fail
