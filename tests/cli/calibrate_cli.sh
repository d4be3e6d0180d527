#!/usr/bin/env bash
# agglo calibrate on the real DEM: (1) fit e alone so that the neutral tetrahedron hits the v_crit that
# e = 0.9 gives (|de| <= 0.02; the range 0.6-0.98 holds the issue's start value 0.7, the grid method
# needs no start); (2) a two-parameter fit (E on a log scale, e) of the neutral and the kappa_p = 1
# (exact point charges) tetrahedron to targets generated at (E, e) = (2e9, 0.8): the generating point lies
# in the reported feasible set and the check runs meet both targets; (3) an interrupted fit (journal
# cut short, as a killed run leaves it) resumed with --resume gives the same calibration.json;
# (4) bad input: unknown key, empty range, unreachable target -> exit 2, one line; (5) a [[prediction]]
# at the best fit equals a plain vcrit run there.
# $1 = agglo executable, $2 = source dir.
. "$(dirname "$0")/lib.sh"  # A, SRC, T (removed on exit), fail
AGGLO=$A TMP=$T
SRC=$(cd "$SRC" && pwd)
fail=0
PY=/usr/bin/python3
neutral="$SRC/cases/seed000_neutral_tetrahedron.toml"
k1="$SRC/cases/seed000_charged_tetrahedron_k1.toml"
square="$SRC/cases/seed000_neutral_square.toml"
# The fits below were designed on the cases' earlier contacts and orientation (E = 1e9 Pa, offset across
# the hit edge); they are pinned there so that the shipped cases' calibration does not change what they test.
ACROSS=(--set 'agglomerate.orientation="edge_across"')
PINNED=(--set material.youngs_modulus=1e9 "${ACROSS[@]}")

vcrit_of() {  # case, extra --set args... -> prints v_crit
  local c=$1; shift
  local d="$TMP/vc_$RANDOM$RANDOM"
  "$AGGLO" -q --no-plots vcrit "$c" --out "$d" "$@" > /dev/null 2>&1
  $PY -c "import json,sys; print(json.load(open(sys.argv[1]))['v_crit'])" "$d/vcrit.json"
}

# (1) one parameter
v09=$(vcrit_of "$neutral" "${PINNED[@]}" --set material.restitution=0.9)
cat > "$TMP/e.toml" << EOF
[calibrate]
grid_points = 7
refine_rounds = 1
case_overrides = 'material.youngs_modulus=1e9; agglomerate.orientation="edge_across"'
[[parameter]]
key = "material.restitution"
lower = 0.6
upper = 0.98
[[target]]
case = "$neutral"
value = $v09
tolerance = 0.002
[[prediction]]
case = "$square"
EOF
"$AGGLO" -q --no-plots calibrate "$TMP/e.toml" --out "$TMP/e" > /dev/null 2>&1 || { echo "FAIL e-fit did not run"; fail=1; }
# The prediction at the best fit is the v_crit a plain vcrit run gives there (same runs, bit for bit).
best=$($PY -c "import json,sys; print(repr(json.load(open(sys.argv[1]))['parameters'][0]['best']))" "$TMP/e/calibration.json")
vsq=$(vcrit_of "$square" "${PINNED[@]}" --set "material.restitution=$best")
psq=$($PY -c "import json,sys; print(json.load(open(sys.argv[1]))['predictions'][0]['at_best'])" "$TMP/e/calibration.json")
if [ "$vsq" = "$psq" ]; then echo "ok   prediction at the best fit = vcrit there ($psq)"; else echo "FAIL prediction $psq != vcrit $vsq"; fail=1; fi
$PY - "$TMP/e/calibration.json" << 'EOF' || fail=1
import json, sys
c = json.load(open(sys.argv[1]))
e = c["parameters"][0]["best"]
ok = abs(e - 0.9) <= 0.02 and c["targets"][0]["met"]
print(("ok  " if ok else "FAIL") + f" e-fit: e = {e:.4f} (generated at 0.9), achieved {c['targets'][0]['achieved']:.5f}")
sys.exit(0 if ok else 1)
EOF

# (3) resume from a journal cut short gives the same result
cp "$TMP/e/calibration.json" "$TMP/e_full.json"
head -n 4 "$TMP/e/journal.jsonl" > "$TMP/j" && mv "$TMP/j" "$TMP/e/journal.jsonl"
"$AGGLO" -q --no-plots calibrate "$TMP/e.toml" --out "$TMP/e" --resume > /dev/null 2>&1 || { echo "FAIL resume did not run"; fail=1; }
if cmp -s "$TMP/e_full.json" "$TMP/e/calibration.json"; then echo "ok   resumed fit identical"; else echo "FAIL resumed fit differs"; fail=1; fi
# The fit's batches are fixed by the configuration, not the core count: one thread gives the same result.
"$AGGLO" -q --no-plots calibrate "$TMP/e.toml" --out "$TMP/e1" --threads 1 > /dev/null 2>&1 || { echo "FAIL --threads 1 did not run"; fail=1; }
if cmp -s "$TMP/e_full.json" "$TMP/e1/calibration.json"; then echo "ok   --threads 1 gives the same calibration.json"; else echo "FAIL --threads 1 differs"; fail=1; fi

# A fit run without its predictions, then resumed with them, reuses the map (job keys carry the case, not the
# [calibrate] settings) and ends with the same calibration.json as the fit run at once.
"$AGGLO" -q --no-plots calibrate "$TMP/e.toml" --out "$TMP/ep" --set 'calibrate.predict="none"' > /dev/null 2>&1 || { echo "FAIL predict=none did not run"; fail=1; }
maps=$(wc -l < "$TMP/ep/journal.jsonl")
npred=$($PY -c "import json,sys; print(len(json.load(open(sys.argv[1]))['predictions']))" "$TMP/ep/calibration.json")
"$AGGLO" -q --no-plots calibrate "$TMP/e.toml" --out "$TMP/ep" --resume > /dev/null 2>&1 || { echo "FAIL resume with predictions did not run"; fail=1; }
added=$(( $(wc -l < "$TMP/ep/journal.jsonl") - maps ))
npts=$($PY -c "import json,sys; print(len(json.load(open(sys.argv[1]))['predictions'][0]['points']))" "$TMP/ep/calibration.json")
if [ "$npred" = 0 ] && [ "$added" = "$npts" ] && cmp -s "$TMP/e_full.json" "$TMP/ep/calibration.json"; then
  echo "ok   predictions added on resume: $added new runs (the $npts prediction points), same calibration.json"
else
  echo "FAIL predictions on resume: $npred predictions without, $added new runs for $npts points, json $(cmp -s "$TMP/e_full.json" "$TMP/ep/calibration.json" && echo same || echo differs)"; fail=1
fi

# (2) two parameters, targets generated at (2e9, 0.8). The targets and the fit's runs share shorter v_crit
# settings (6 scan points, bisection to 2 mm/s, 1 ms after contact; the target tolerance is 5 mm/s): the
# check is that the fit finds the point the targets were made at, which needs the same runs on both sides,
# not the shipped settings (26 -> 11 s of CPU).
SHORT2='vcrit.scan_points=6; vcrit.tolerance=0.002; time.after_contact=1e-3'
SHORT2_SET=(--set vcrit.scan_points=6 --set vcrit.tolerance=0.002 --set time.after_contact=1e-3)
tn=$(vcrit_of "$neutral" "${ACROSS[@]}" "${SHORT2_SET[@]}" --set material.youngs_modulus=2e9 --set material.restitution=0.8)
tk=$(vcrit_of "$k1" "${ACROSS[@]}" "${SHORT2_SET[@]}" --set material.youngs_modulus=2e9 --set material.restitution=0.8)
cat > "$TMP/ee.toml" << EOF
[calibrate]
grid_points = 5
refine_rounds = 1
refine_points = 5
case_overrides = 'agglomerate.orientation="edge_across"; $SHORT2'
[[parameter]]
key = "material.youngs_modulus"
lower = 5e8
upper = 8e9
scale = "log"
[[parameter]]
key = "material.restitution"
lower = 0.5
upper = 0.98
[[target]]
case = "$neutral"
value = $tn
tolerance = 0.005
[[target]]
case = "$k1"
value = $tk
tolerance = 0.005
EOF
"$AGGLO" -q --no-plots calibrate "$TMP/ee.toml" --out "$TMP/ee" > /dev/null 2>&1 || { echo "FAIL 2-parameter fit did not run"; fail=1; }
$PY - "$TMP/ee/calibration.json" << 'EOF' || fail=1
import json, sys
c = json.load(open(sys.argv[1]))
E, e = c["parameters"]
inside = c["feasible"] and E["feasible_lo"] <= 2e9 <= E["feasible_hi"] and e["feasible_lo"] <= 0.8 <= e["feasible_hi"]
met = all(t["met"] for t in c["targets"])
print(("ok  " if inside and met else "FAIL") + f" 2-parameter fit: best E = {E['best']:.3g}, e = {e['best']:.3f}; feasible "
      f"E [{E['feasible_lo']:.3g}, {E['feasible_hi']:.3g}], e [{e['feasible_lo']:.3f}, {e['feasible_hi']:.3f}] (generated at 2e9, 0.8); met {met}")
sys.exit(0 if inside and met else 1)
EOF

# (4) bad input
expect_error() {  # name, expected substring, file
  local name="$1" pat="$2" file="$3"
  "$AGGLO" -q --no-plots calibrate "$file" --out "$TMP/$name" > /dev/null 2> "$TMP/$name.err"
  local rc=$? lines
  lines=$(wc -l < "$TMP/$name.err")
  if [ "$rc" -ne 2 ] || ! grep -q -- "$pat" "$TMP/$name.err" || [ "$lines" -ne 1 ] || [ -e "$TMP/$name" ]; then
    echo "FAIL $name: exit $rc, $lines lines, folder $([ -e "$TMP/$name" ] && echo left || echo none):"; cat "$TMP/$name.err"; fail=1
  else
    echo "ok   $name: $(cat "$TMP/$name.err")"
  fi
}
sed 's/material.restitution/material.restitutio/' "$TMP/e.toml" > "$TMP/bad_key.toml"
expect_error unknown_key "parameter.0.key" "$TMP/bad_key.toml"
sed 's/upper = 0.98/upper = 0.5/' "$TMP/e.toml" > "$TMP/bad_range.toml"
expect_error empty_range "parameter.0.upper" "$TMP/bad_range.toml"
sed "s/value = $v09/value = 5.0/" "$TMP/e.toml" > "$TMP/bad_target.toml"
expect_error unreachable "unreachable" "$TMP/bad_target.toml"
exit $fail
