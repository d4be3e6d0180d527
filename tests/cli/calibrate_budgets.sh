#!/usr/bin/env bash
# agglo calibrate and the budgets (issue 23 item 10, docs/limits.md): --dry-run counts every vcrit
# search of the fit (before, "0 steps" for any grid): the maps (grid_points^d + refine_rounds x
# refine_points^d points) and the check, each a vcrit search bounded as `agglo vcrit --dry-run` bounds it
# at the costliest corner of the parameter box; --max-steps refuses the fit before any run (before, a
# budget of 1 step did not stop it); the same [[parameter]] key twice and an integer key are refused in
# one line (before, two different best values for one key, and a best vcrit.scan_points of 5.4).
# $1 = agglo executable, $2 = source dir.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, NT
unset AGGLO_MAX_STEPS AGGLO_MAX_MEMORY AGGLO_MAX_OUTPUT
NT="$(cd "$SRC" && pwd)/cases/seed000_neutral_tetrahedron.toml"  # target cases: relative to the fit

calibration() {  # calibration FILE KEY2 LOWER2 UPPER2: a 2-parameter fit of the neutral tetrahedron
  cat > "$1" << EOF
[calibrate]
grid_points = 101
refine_rounds = 10
refine_points = 101
[[parameter]]
key = "material.restitution"
lower = 0.6
upper = 0.98
[[parameter]]
key = "$2"
lower = $3
upper = $4
[[target]]
case = "$NT"
value = 0.17
tolerance = 0.002
EOF
}

steps_of() {  # steps_of DRY-RUN-OUTPUT: the step estimate of a --dry-run table
  awk '$1 == "steps" { print $2 }' "$1"
}

# The step estimate of the fit: (101^2 + 10 x 101^2 + 1 check) vcrit searches at the corner of the box
# with the most steps (the stiffest material: the shortest time step).
calibration "$T/fit.toml" material.youngs_modulus 1e8 1e10
$A -q calibrate "$T/fit.toml" --dry-run --max-steps 1e15 > "$T/dry" 2> "$T/err" || fail "dry run failed: $(cat "$T/err")"
$A -q vcrit "$NT" --dry-run --set material.youngs_modulus=1e10 > "$T/one" 2> "$T/err" || fail "vcrit dry run failed"
$A -q vcrit "$NT" --dry-run --set material.youngs_modulus=1e8 > "$T/soft" 2> "$T/err" || fail "vcrit dry run failed"
/usr/bin/python3 - "$(steps_of "$T/dry")" "$(steps_of "$T/one")" "$(steps_of "$T/soft")" << 'EOF' || fail "calibrate step estimate"
import sys
fit, one, soft = map(float, sys.argv[1:])
expected = (101 ** 2 + 10 * 101 ** 2 + 1) * one
assert one > soft, (one, soft)  # the corner matters
assert abs(fit / expected - 1) < 0.01, (fit, expected)  # both printed to 3 digits
print(f"ok   calibrate --dry-run: {fit:.3g} steps = 112212 vcrit searches of {one:.3g}")
EOF
grep -q "^  steps .*driven by calibrate.grid_points" "$T/dry" || fail "the fit's steps name calibrate.grid_points: $(cat "$T/dry")"
grep -q "^  time .*cost class" "$T/dry" || fail "the fit's dry run prints a time estimate"

# The default step budget (1e12) and --max-steps refuse the fit before it runs: no folder, one line.
rm -rf "$T/out"
timeout 20 $A -q calibrate "$T/fit.toml" --out "$T/out" > /dev/null 2> "$T/err"  # main ran the fit
[ $? -eq 2 ] || fail "a fit beyond the step budget exits 2"
[ "$(wc -l < "$T/err")" -eq 1 ] && grep -q "step budget 1e+12" "$T/err" || fail "refusal: $(cat "$T/err")"
[ ! -e "$T/out" ] || fail "a refused fit created its folder"
cat > "$T/small.toml" << EOF
[calibrate]
grid_points = 3
refine_rounds = 0
[[parameter]]
key = "material.restitution"
lower = 0.6
upper = 0.98
[[target]]
case = "$NT"
value = 0.17
tolerance = 0.002
EOF
start=$(date +%s%N)
timeout 20 $A -q calibrate "$T/small.toml" --out "$T/out" --max-steps 1 > /dev/null 2> "$T/err"
[ $? -eq 2 ] && grep -q "exceeds the step budget 1 steps" "$T/err" || fail "--max-steps 1: $(cat "$T/err")"
[ ! -e "$T/out" ] || fail "--max-steps 1 created the fit's folder"
ms=$(( ($(date +%s%N) - start) / 1000000 ))
[ "$ms" -lt 5000 ] || fail "--max-steps 1 took $ms ms (a run of the fit?)"
echo "ok   --max-steps 1 refuses the fit in $ms ms"

# The same key twice, and an integer key: one line naming parameter.1.key, exit 2, no folder.
calibration "$T/bad.toml" material.restitution 0.5 0.9
refused calibrate "parameter.1.key' = \"material.restitution\": is also the key of [[parameter]] 0" "duplicate key"
calibration "$T/bad.toml" vcrit.scan_points 4 12
refused calibrate "parameter.1.key' = \"vcrit.scan_points\": is a key of type integer" "integer key"
echo "calibrate_budgets: ok"
