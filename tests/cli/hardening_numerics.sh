#!/usr/bin/env bash
# Numerical hardening (docs/dem.md and docs/acoustics.md, "Limits and checks"): absurd inputs end in
# a one-line error with the right exit code (2 = refused input, 3 = blow-up detected), never in a
# run that writes nan/inf or that does not end. $1 = agglo executable, $2 = source dir.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, AC, NT
TET="$SRC/cases/seed000_neutral_tetrahedron.toml"
ACO="$SRC/cases/seed002_baseline.toml"

# expect <exit code> <fragment> <command...>: the command fails with that code, one line naming
# <fragment>, and writes no nan/inf anywhere in its output folder $T/out.
expect() {
  local code=$1 frag=$2; shift 2
  rm -rf "$T/out"
  timeout 120 "$A" -q "$@" --out "$T/out" > "$T/stdout" 2> "$T/stderr"
  local rc=$?
  [ $rc -eq "$code" ] || fail "expected exit $code, got $rc for: $* ($(head -c 400 "$T/stderr"))"
  [ "$(wc -l < "$T/stderr")" -eq 1 ] || fail "error must be one line for $*: $(cat "$T/stderr")"
  grep -qF -- "$frag" "$T/stderr" || fail "message lacks '$frag' for $*: $(cat "$T/stderr")"
  if [ -d "$T/out" ] && grep -rqiE '(^|,)-?(nan|inf)' "$T/out" 2>/dev/null; then
    fail "non-finite values written for $*"
  fi
  echo "ok   $*: $(cat "$T/stderr")"
}

# Item 3: the time step above T0/10 is refused before the run (dt = 1e-6 s is about one contact period).
expect 2 "time.dt" collide "$TET" --set time.dt=1e-6
expect 2 "time.dt" collide "$TET" --set time.dt=1e300
# Values outside the physically plausible range are refused naming their own key (item 12).
expect 2 "material.density' = 1e+300" collide "$TET" --set material.density=1e300
expect 2 "projectile.radius' = 1e+300" collide "$TET" --set projectile.radius=1e300
# Blow-ups are detected before anything non-finite is recorded; the message names step, particle
# and the likely input cause (1000 m/s moves the projectile more than its radius per step).
expect 3 "particle 4" collide "$TET" --set projectile.speed=1000
expect 3 "time.dt" collide "$TET" --set projectile.speed=1000
# A time step just below the limit still runs and stays finite (no false alarm of the watchdog).
rm -rf "$T/ok"
"$A" -q collide "$TET" --out "$T/ok" --set time.steps_per_period=10 --set time.after_contact=2e-4 \
  > /dev/null 2> "$T/stderr" || fail "steps_per_period = 10 must run: $(cat "$T/stderr")"
grep -qiE '(^|,)-?(nan|inf)' "$T/ok/timeseries.csv" && fail "non-finite rows at steps_per_period = 10"

# Item 4: overlapping [[particles]] of a list agglomerate are refused, naming the entries.
list() {  # list <x of the second particle>
  printf '[agglomerate]\nshape = "list"\n[[particles]]\nposition = [0.0, 0.0, 0.0]\nradius = 1e-5\n'
  printf '[[particles]]\nposition = [%s, 0.0, 0.0]\nradius = 1e-5\n' "$1"
}
list 1e-5 > "$T/half.toml"
expect 2 "entries 0 and 1" collide "$T/half.toml"
list 0.0 > "$T/same.toml"
expect 2 "entries 0 and 1" collide "$T/same.toml"
list 2e-5 > "$T/touch.toml"
rm -rf "$T/touch"
"$A" -q collide "$T/touch.toml" --out "$T/touch" --set time.after_contact=1e-4 > /dev/null 2> "$T/stderr" \
  || fail "touching list particles must run: $(cat "$T/stderr")"

# Item 5: a vcrit tolerance below the relative floor is refused at once.
expect 2 "vcrit.tolerance" vcrit "$TET" --set vcrit.tolerance=1e-17

# Item 2: the total cell count is a 64-bit product, capped.
short=(--set time.end=0.001 --set "output.psd_times=[0.0,0.001]" --set "output.snapshot_times=[0.0]" --set output.plots=false)
expect 2 "domain.cells_z" acoustic "$ACO" "${short[@]}" --set domain.cells_y=65536 --set domain.cells_z=65536
expect 2 "1000000000000 cells" acoustic "$ACO" "${short[@]}" --set domain.cells_y=100000 --set domain.cells_z=100000
expect 2 "214748828100" acoustic "$ACO" "${short[@]}" --set domain.cells_y=46341 --set domain.cells_z=46341
# Item 12: errors name the real key. Out-of-range inputs are refused at their own key; a collision step
# the sampled state cannot meet names time.collision_dt and the population that needs the sub-cycles; a
# particle larger than the cells names its population.
expect 2 "population.1.density' = 1e+300" acoustic "$ACO" "${short[@]}" --set population.1.density=1e300
expect 2 "population.1.number_concentration' = 1e+300" acoustic "$ACO" "${short[@]}" \
  --set population.1.number_concentration=1e300
expect 2 "population.1.diameter' = 1e+300" acoustic "$ACO" "${short[@]}" --set population.1.diameter=1e300
expect 2 "time.collision_dt' = 1e+300" acoustic "$ACO" "${short[@]}" --set time.collision_dt=1e300 --set time.end=1e300 \
  --set time.motion_dt=1e300
expect 2 "time.collision_dt' = 5e-05: the Nanbu bound P_ij <= 1/N needs" acoustic "$ACO" "${short[@]}" \
  --set time.collision_dt=5e-5 --set time.motion_dt=5e-5 --set population.1.number_concentration=1e19
expect 2 "population 'droplets'" acoustic "$ACO" "${short[@]}" --set population.1.diameter=9e-3
echo "all hardening checks passed"
