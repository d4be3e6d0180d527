#!/usr/bin/env bash
# --dry-run prints a time estimate (issue 23 item 1; docs/limits.md, "Time estimate"): the step
# estimate times the command's measured seconds per step of one thread, with its cost class. It is
# printed for a single run, a seed ensemble and a sweep, follows the steps (monotone in time.end and in
# the GMRES iterations allowed), takes the solver's rate for electrostatics, and says "not estimated"
# for a command without a rate instead of printing 0.
source "$(dirname "$0")/lib.sh"

# seconds CMD CASE [ARGS...]: appends the one-thread seconds of the time line to ts (fails without one)
seconds() {
  local out line
  out=$("$A" "$@" --dry-run) || fail "dry run failed: $*: $out"
  line=$(grep '^  time ' <<< "$out") || fail "no time line: $*: $out"
  grep -q 'cost class \(seconds\|minutes\|hours\|days\|months or more\)' <<< "$line" || fail "no cost class: $line"
  ts+=("$(sed -n 's/.*(\([0-9.e+-]*\) s of one thread.*/\1/p' <<< "$line")")
  [ -n "${ts[-1]}" ] || fail "no seconds in the time line: $line"
}
# increasing A B C ...: each value above the one before
increasing() {
  local prev=""
  for v in "$@"; do
    [ -z "$prev" ] || /usr/bin/python3 -c "import sys; sys.exit(0 if $v > $prev else 1)" ||
      fail "time estimate not increasing with the steps: $*"
    prev=$v
  done
}

S=(--set output.psd_times=[0] --set output.snapshot_times=[0])
ts=()
for end in 0.25 0.5 1 2 4; do seconds acoustic "$AC" "${S[@]}" --set time.end=$end; done
increasing "${ts[@]}"
# the time is the step estimate times one rate: doubling time.end doubles both
/usr/bin/python3 -c "import sys; r = ${ts[4]} / ${ts[3]}; sys.exit(0 if abs(r - 2) < 0.01 else 1)" ||
  fail "acoustic: time.end 2 -> 4 s changed the time estimate by ${ts[3]} -> ${ts[4]}, not 2x"
ts=()
for it in 10 100 1000; do
  seconds electrostatics "$SRC/cases/electrostatics_tetrahedron.toml" --set electrostatics.max_iterations=$it
done
increasing "${ts[@]}"
# the solvers' own rates: the BEM (FMM) solve of the tetrahedron is estimated far above the spectral one
ts=()
seconds electrostatics "$SRC/cases/electrostatics_tetrahedron.toml"
seconds electrostatics "$SRC/cases/electrostatics_tetrahedron.toml" --set electrostatics.solver=bem
increasing "${ts[@]}"
ts=()
for v in 0.1 0.1,0.2 0.1,0.2,0.3,0.4; do
  seconds sweep "$NT" --command collide --param projectile.speed --values $v
done
increasing "${ts[@]}"
ts=()
for n in 2 4; do seconds acoustic "$AC" "${S[@]}" --set time.end=0.5 --seeds $n; done
increasing "${ts[@]}"
# A command without a rate says so.
out=$("$A" sectional "$SRC/cases/partmc_brownian.toml" --dry-run) || fail "sectional dry run: $out"
grep -q '^  time    not estimated' <<< "$out" || fail "sectional: $out"
echo "PASS dry_run_time"
