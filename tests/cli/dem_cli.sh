#!/usr/bin/env bash
# CLI contract of the DEM commands: help/version, bad input -> exit 2 with one line naming
# file/key/value, no output folder content on failure, and a good run writing its files.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, AC, NT

$A --help >/dev/null || fail "--help"
$A --version | grep -q "agglo" || fail "--version"
$A collide --help | grep -q -- "--set" || fail "collide --help"
$A vcrit --help | grep -q -- "--out" || fail "vcrit --help"
$A breakup --help | grep -q -- "--out" || fail "breakup --help"

bad() {  # bad <expected fragment> <toml text> [extra args]
  local frag=$1 text=$2; shift 2
  printf '%s\n' "$text" > "$T/bad.toml"
  rm -rf "$T/out"
  $A collide "$T/bad.toml" --out "$T/out" "$@" > "$T/stdout" 2> "$T/stderr"
  local rc=$?
  [ $rc -eq 2 ] || fail "expected exit 2, got $rc for: $text $*"
  [ "$(wc -l < "$T/stderr")" -eq 1 ] || fail "error must be one line: $(cat "$T/stderr")"
  grep -qF -- "$frag" "$T/stderr" || fail "message lacks '$frag': $(cat "$T/stderr")"
  grep -qF "bad.toml" "$T/stderr" || [ "$frag" = "--set" ] || fail "message lacks file name: $(cat "$T/stderr")"
  [ -z "$(ls -A "$T/out" 2>/dev/null)" ] || fail "output written despite the error: $(ls "$T/out")"
}
bad "agglomerate.radius' = -1e-06" $'[agglomerate]\nradius = -1e-6'
bad "material.restitution' = 1.5" $'[material]\nrestitution = 1.5'
bad "unknown key 'material.colour'" $'[material]\ncolour = "red"'
bad "material.density' = nan" $'[material]\ndensity = nan'
bad "projectile.speed' = \"fast\"" $'[projectile]\nspeed = "fast"'
bad "contact.break_rule" $'[contact]\nbreak_rule = "never"'
bad "material.restitution' = 0" '' --set material.restitution=0
bad "--set" '' --set novalue
bad "breakup.samples' = 0" $'[breakup]\nsamples = 0'
bad "breakup.offset_spread' = -1" $'[breakup]\noffset_spread = -1.0'
bad "breakup.speeds' = []" $'[breakup]\nspeeds = []'

# A good, short run writes the documented files.
$A -q collide "$SRC/cases/seed000_neutral_tetrahedron.toml" --out "$T/good" --set time.after_contact=2e-4 \
  > /dev/null 2>&1 || fail "good run failed"
for f in timeseries.csv result.json config.resolved.toml run.json particles.pvd; do
  [ -s "$T/good/$f" ] || fail "missing $f"
done
head -1 "$T/good/timeseries.csv" | grep -q '^t,kinetic_energy,electrostatic_energy,U_over_U0,radius_of_gyration,n_contacts' \
  || fail "timeseries header"
grep -q '"broken"' "$T/good/result.json" || fail "result.json lacks broken"
# run.json names the CPU level the run ran on (what its wall time depends on)
grep -Eq '"cpu_level": "(x86-64-v4|x86-64-v3|x86-64-v2|x86-64|other)"' "$T/good/run.json" || fail "run.json lacks cpu_level"
ls "$T/good" | grep -q 'tmp-' && fail "temporary files left behind"
# The resolved config reproduces the run.
$A -q collide "$T/good/config.resolved.toml" --out "$T/again" > /dev/null 2>&1 || fail "resolved config does not run"
cmp -s <(grep -v wall "$T/good/result.json") <(grep -v wall "$T/again/result.json") || fail "rerun differs"

# A small break-up ensemble writes its table and JSON.
$A -q --no-plots breakup "$SRC/cases/seed000_neutral_tetrahedron.toml" --out "$T/bu" \
  --set 'breakup.speeds=[0.12,0.3]' --set breakup.samples=2 > /dev/null 2>&1 || fail "breakup run failed"
for f in breakup.csv breakup.json config.resolved.toml run.json; do
  [ -s "$T/bu/$f" ] || fail "breakup: missing $f"
done
[ "$(wc -l < "$T/bu/breakup.csv")" -eq 3 ] || fail "breakup.csv must have a header and 2 rows"
grep -q '^0.3,2,2,' "$T/bu/breakup.csv" || fail "breakup: 0.3 m/s must break for both offsets"
echo "ok"
