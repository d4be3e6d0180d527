#!/usr/bin/env bash
# Runs that cannot observe the impact experiment are errors, never outcomes (issue 23 item 2;
# docs/limits.md): a target that is not one agglomerate (a list particle touching nothing), a target
# whose contacts change during the relaxation (a field tears it apart), and an impact that never happens
# (the projectile passes beside). Each ends with exit 3, one line naming the cause, run.json "failed"
# and no result file; vcrit and breakup report it as a job failure instead of writing p = 0. Also the
# words of issue 23 item 6 that the impact commands print.
source "$(dirname "$0")/lib.sh"
TET="$SRC/cases/seed000_charged_tetrahedron_k2p5.toml"
SHORT=(--set time.after_contact=1e-4 --set time.max_extensions=0 --no-plots)

# expect CODE FRAGMENT COMMAND CASE [ARGS...]: exit CODE, one line on stderr containing FRAGMENT.
expect() {
  local code=$1 frag=$2 cmd=$3; shift 3
  rm -rf "$T/out"
  timeout 300 "$A" -q "$cmd" "$@" --out "$T/out" > "$T/stdout" 2> "$T/stderr"
  local rc=$?
  [ $rc -eq "$code" ] || fail "expected exit $code, got $rc for $cmd $*: $(head -c 600 "$T/stderr")"
  [ "$(wc -l < "$T/stderr")" -eq 1 ] || fail "message not one line for $cmd $*: $(cat "$T/stderr")"
  grep -qF -- "$frag" "$T/stderr" || fail "message lacks '$frag' for $cmd $*: $(cat "$T/stderr")"
}
# failed_without_results: run.json says failed and no outcome file was written.
failed_without_results() {
  grep -q '"status": *"failed"' "$T/out/run.json" || fail "run.json not failed: $(cat "$T/out/run.json")"
  for f in result.json breakup.csv vcrit.json timeseries.csv; do
    [ ! -e "$T/out/$f" ] || fail "$f written by an invalid run"
  done
}

# 1. A list agglomerate whose third particle touches nothing: neutral (checked at the launch) and
#    charged (checked before the relaxation).
three() {  # three CHARGE
  printf '[agglomerate]\nshape = "list"\nradius = 1e-5\n'
  printf '[[particles]]\nposition = [0.0, 0.0, 0.0]\nradius = 1e-5\ncharge = %s\n' "$1"
  printf '[[particles]]\nposition = [2e-5, 0.0, 0.0]\nradius = 1e-5\n'
  printf '[[particles]]\nposition = [0.0, 1e-4, 0.0]\nradius = 1e-5\n'
}
three 0.0 > "$T/loose.toml"
expect 3 "not one agglomerate (at the launch of the projectile)" collide "$T/loose.toml" "${SHORT[@]}"
grep -qF "(index 2)" "$T/stderr" || fail "the detached particle is not named: $(cat "$T/stderr")"
failed_without_results
three 1e-15 > "$T/loose_charged.toml"
expect 3 "not one agglomerate (as built, before the relaxation)" collide "$T/loose_charged.toml" "${SHORT[@]}"
failed_without_results
echo "ok   a list particle touching nothing: exit 3"

# 2. A field that tears the charged tetrahedron apart during the relaxation (point charges: a
#    fast solve; 5e7 V/m pulls the +/- particles apart with more than their pull-off force).
FIELD=(--set electrostatics.solver=coulomb --set "electrostatics.external_field=[5e7, 0.0, 0.0]")
expect 3 "contact graph changed during the relaxation" collide "$TET" "${FIELD[@]}" "${SHORT[@]}"
grep -qF "electrostatics.external_field" "$T/stderr" || fail "the field is not named: $(cat "$T/stderr")"
failed_without_results
expect 3 "contact graph changed during the relaxation" breakup "$TET" "${FIELD[@]}" "${SHORT[@]}" \
  --set "breakup.speeds=[0.2]" --set breakup.samples=2
failed_without_results
echo "ok   a field tearing the agglomerate apart before the launch: exit 3"

# 3. An impact that never happens: the projectile passes 10 r_p beside the neutral tetrahedron.
expect 3 "the projectile never touched the agglomerate" collide "$NT" --set projectile.offset_radii=10 "${SHORT[@]}"
grep -qF "projectile.offset_radii" "$T/stderr" || fail "the offset is not named: $(cat "$T/stderr")"
failed_without_results
expect 3 "the projectile never touched the agglomerate" breakup "$NT" --set projectile.offset_radii=10 \
  --set "breakup.speeds=[0.2, 0.3]" --set breakup.samples=2 "${SHORT[@]}"
grep -qF "jobs failed" "$T/stderr" || fail "breakup does not report the job failure: $(cat "$T/stderr")"
failed_without_results
expect 3 "the projectile never touched the agglomerate" vcrit "$NT" --set projectile.offset_radii=10 \
  --set vcrit.scan_points=3 "${SHORT[@]}"
failed_without_results
echo "ok   an impact that never happens: exit 3 (collide, breakup, vcrit)"

# Item 6: keys a list agglomerate would ignore are refused; --dry-run names the entries' permittivity;
# U_over_U0 is NaN (undefined) for a list agglomerate.
two() {  # two PERMITTIVITY: two touching charged spheres
  printf 'name = "two"\n[agglomerate]\nshape = "list"\nradius = 1e-5\n'
  for x in 0.0 2e-5; do
    printf '[[particles]]\nposition = [%s, 0.0, 0.0]\nradius = 1e-5\ncharge = 1e-15\npermittivity = %s\n' $x "$1"
  done
}
two 1.0 > "$T/two.toml"
for kv in agglomerate.permittivity=3.8 agglomerate.charged=true agglomerate.charge_density=2e-5; do
  expect 2 "applies to the built-in shapes only" collide "$T/two.toml" --set "$kv"
  grep -qF "${kv%%=*}" "$T/stderr" || fail "the key ${kv%%=*} is not named: $(cat "$T/stderr")"
done
two 3.8 > "$T/two_k.toml"
"$A" -q collide "$T/two_k.toml" --dry-run > "$T/dry" 2> "$T/stderr" || fail "dry run: $(cat "$T/stderr")"
grep -q "particles.permittivity" "$T/dry" || fail "dry run does not name particles.permittivity: $(cat "$T/dry")"
! grep -q "agglomerate.permittivity" "$T/dry" || fail "dry run names agglomerate.permittivity: $(cat "$T/dry")"
rm -rf "$T/two"
"$A" -q collide "$T/two.toml" --out "$T/two" "${SHORT[@]}" > /dev/null 2> "$T/stderr" || fail "two: $(cat "$T/stderr")"
/usr/bin/python3 - "$T/two/timeseries.csv" <<'PY' || fail "U_over_U0 of a list agglomerate must be NaN"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert rows and all(math.isnan(float(r["U_over_U0"])) for r in rows), rows[:2]
PY
echo "ok   list agglomerate: ignored keys refused, --dry-run names particles.permittivity, U_over_U0 NaN"

# Item 6: a field that dominates is named as the cause of the overlap it drives (not the impact speed).
expect 3 "the applied field electrostatics.external_field (|E| = 1e+09 V/m) dominates" collide "$TET" \
  --set "electrostatics.external_field=[0.0, 0.0, 1e9]" "${SHORT[@]}"
echo "ok   a dominating field is named as the cause"

# Item 6: a finished acoustic run prints its summary line.
"$A" acoustic "$AC" --out "$T/ac" --no-plots --set time.end=0.001 --set "output.psd_times=[0.0, 0.001]" \
  --set "output.snapshot_times=[0.0]" --set output.plots=false > "$T/stdout" 2> "$T/stderr" || fail "acoustic: $(cat "$T/stderr")"
grep -q "fine-particle removal efficiency" "$T/stdout" || fail "acoustic printed no summary line: $(cat "$T/stdout")"
echo "ok   acoustic prints its summary line"
echo "PASS invalid_runs"
