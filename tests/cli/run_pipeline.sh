#!/usr/bin/env bash
# The run pipeline from the command line: `sweep` runs every command (and a grid of two keys), an
# ensemble resumed from its journal repeats only the missing jobs and gives the same result, and
# Ctrl-C (SIGINT) stops with exit 130 keeping the finished jobs.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, AC, NT
cd "$SRC" || exit 1
NT=cases/seed000_neutral_tetrahedron.toml
SHORT=(--set time.after_contact=2e-4 --set output.snapshot_interval=0)

# sweep over each command
$A -q --no-plots sweep $NT --command collide --param projectile.speed --values 0.1,0.3 "${SHORT[@]}" --out "$T/s1" \
  > /dev/null 2>&1 || fail "sweep collide"
head -1 "$T/s1/sweep.csv" | grep -q "^index,projectile.speed,case,.*broken" || fail "sweep collide table: $(head -1 "$T/s1/sweep.csv")"
[ "$(sed -n 3p "$T/s1/sweep.csv" | cut -d, -f1-3)" = "1,0.3,case_01_0.3" ] || fail "sweep collide row"
[ -f "$T/s1/case_00_0.1/result.json" ] || fail "sweep collide case folder"
$A -q --no-plots sweep $NT --command vcrit --param material.restitution --values 0.9 "${SHORT[@]}" \
  --set vcrit.scan_points=4 --set vcrit.v_min=0.05 --set vcrit.v_max=0.8 --set vcrit.tolerance=0.05 --out "$T/s2" \
  > /dev/null 2>&1 || fail "sweep vcrit"
grep -q "v_crit" "$T/s2/sweep.csv" || fail "sweep vcrit table"
$A -q --no-plots sweep $NT --command breakup --param breakup.samples --values 1,2 "${SHORT[@]}" \
  --set 'breakup.speeds=[0.1,0.4]' --out "$T/s3" > /dev/null 2>&1 || fail "sweep breakup"
grep -q "v50" "$T/s3/sweep.csv" || fail "sweep breakup table"
$A -q --no-plots sweep cases/electrostatics_two_spheres.toml --command electrostatics \
  --param electrostatics.solver --values coulomb,spectral --out "$T/s4" > /dev/null 2>&1 || fail "sweep electrostatics"
grep -q "energy_J" "$T/s4/sweep.csv" || fail "sweep electrostatics table"
[ -f "$T/s4/case_01_spectral/forces.csv" ] || fail "sweep electrostatics case folder"
# a grid over two keys of the acoustic command
$A -q --no-plots sweep cases/seed002_integrator_check.toml --command acoustic --set time.end=0.005 \
  --set 'output.psd_times=[0.0]' --param seed --values 1,2 --param time.collision_dt --values 1e-3,5e-4 \
  --out "$T/s5" > /dev/null 2>&1 || fail "sweep acoustic grid"
[ "$(wc -l < "$T/s5/sweep.csv")" -eq 5 ] || fail "grid of 2 x 2 must give 4 rows"
head -1 "$T/s5/sweep.csv" | grep -q "^index,seed,time.collision_dt,case," || fail "grid header"
[ -d "$T/s5/case_03_2_5e-4" ] || fail "grid folder name: $(ls "$T/s5")"
# the sweep folder's config.resolved.toml is the fully resolved base case (as many keys as a case's)
[ "$(grep -c ' = ' "$T/s5/config.resolved.toml")" -eq "$(grep -c ' = ' "$T/s5/case_00_1_1e-3/config.resolved.toml")" ] \
  || fail "sweep config.resolved.toml not fully resolved"
# mismatched --param/--values is bad input
$A -q sweep $NT --param a.b --values 1 --param c.d --out "$T/bad" > /dev/null 2> "$T/err"
[ $? -eq 2 ] || fail "mismatched --param/--values must exit 2"

# --resume: the journal holds every job; a resumed run repeats none and writes the same results
BU=(--set 'breakup.speeds=[0.12,0.3]' --set breakup.samples=2)
$A -q --no-plots breakup $NT "${SHORT[@]}" "${BU[@]}" --out "$T/b" > /dev/null 2>&1 || fail "breakup"
[ "$(wc -l < "$T/b/journal.jsonl")" -eq 4 ] || fail "journal must hold 4 jobs"
cp "$T/b/breakup.json" "$T/breakup_first.json"
$A -q --no-plots breakup $NT "${SHORT[@]}" "${BU[@]}" --out "$T/b" --resume > /dev/null 2>&1 || fail "resume"
[ "$(wc -l < "$T/b/journal.jsonl")" -eq 4 ] || fail "resume must not rerun finished jobs"
cmp -s "$T/b/breakup.json" "$T/breakup_first.json" || fail "resumed breakup.json differs"
# more speeds: only the new ones run
$A -q --no-plots breakup $NT "${SHORT[@]}" --set 'breakup.speeds=[0.12,0.3,0.5]' --set breakup.samples=2 \
  --out "$T/b" --resume > /dev/null 2>&1 || fail "resume with more speeds"
[ "$(wc -l < "$T/b/journal.jsonl")" -eq 6 ] || fail "only the 2 new jobs may run"

# Ctrl-C: exit 130, finished jobs kept, --resume completes with the uninterrupted answer
VC=(--set vcrit.scan_points=120 --set vcrit.tolerance=1e-4 --set time.early_stop=false --threads 1)
$A -q --no-plots vcrit $NT "${VC[@]}" --out "$T/v" > /dev/null 2>&1 &
pid=$!
for _ in $(seq 1 100); do [ -s "$T/v/journal.jsonl" ] && break; sleep 0.1; done
kill -INT $pid; wait $pid; rc=$?
[ $rc -eq 130 ] || fail "SIGINT must give exit 130, got $rc"
[ -f "$T/v/vcrit.json" ] && fail "an interrupted vcrit must not write vcrit.json"
n=$(wc -l < "$T/v/journal.jsonl")
[ "$n" -lt 120 ] || fail "the interruption came too late to test anything"
[ "$n" -ge 1 ] || fail "journal empty after interruption"
# SIGTERM (a batch scheduler's stop) likewise, with exit 143
$A -q --no-plots vcrit $NT "${VC[@]}" --out "$T/v" --resume > /dev/null 2>&1 &
pid=$!
for _ in $(seq 1 100); do [ "$(wc -l < "$T/v/journal.jsonl")" -gt "$n" ] && break; sleep 0.1; done
kill -TERM $pid; wait $pid; rc=$?
[ $rc -eq 143 ] || fail "SIGTERM must give exit 143, got $rc"
$A -q --no-plots vcrit $NT "${VC[@]}" --out "$T/v" --resume > /dev/null 2>&1 || fail "resume vcrit"
$A -q --no-plots vcrit $NT "${VC[@]}" --out "$T/v2" > /dev/null 2>&1 || fail "plain vcrit"
cmp -s "$T/v/vcrit.json" "$T/v2/vcrit.json" || fail "resumed vcrit.json differs from an uninterrupted run"
echo "run pipeline CLI: all checks passed"
