#!/usr/bin/env bash
# vcrit.criterion = "sticking" (docs/dem.md "Gas and walls"): the sphere of cases/sphere_wall.toml
# (e = 0.7, dt = T0/50) stays on the wall up to 0.0504 m/s (continuous-time value g(0.7) x 0.02514 =
# 0.0499 m/s); vcrit.json says which criterion; a bad criterion is refused (exit 2, one line, no folder).
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail

S="$SRC/cases/sphere_wall.toml"
V=(--set 'vcrit.criterion="sticking"' --set vcrit.v_min=0.02 --set vcrit.v_max=0.1 --set vcrit.scan_points=5
   --set vcrit.tolerance=2e-4)
$A -q --no-plots vcrit "$S" "${V[@]}" --out "$T/vs" > /dev/null 2>&1 || fail "vcrit sticking failed"
/usr/bin/python3 - "$T/vs/vcrit.json" <<'PY' || fail "vcrit sticking result"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["criterion"] == "sticking", r
assert 0.0495 <= r["v_crit"] <= 0.0510, r["v_crit"]
assert r["v_crit"] == r["bracket"][0], r
assert all(run["stuck"] == (run["v"] <= r["v_crit"]) for run in r["runs"]), r["runs"]
PY
grep -q '^criterion = .sticking.' "$T/vs/config.resolved.toml" || fail "resolved config lacks vcrit.criterion"
# Without the key the resolved config and vcrit.json stay as they were.
$A -q --no-plots vcrit "$SRC/cases/seed000_neutral_tetrahedron.toml" --set vcrit.scan_points=3 --set vcrit.tolerance=0.05 \
  --set time.after_contact=2e-4 --out "$T/vb" > /dev/null 2>&1 || fail "vcrit breakup failed"
grep -q 'criterion' "$T/vb/config.resolved.toml" "$T/vb/vcrit.json" && fail "criterion written without the key"
rm -rf "$T/out"
$A vcrit "$S" --set 'vcrit.criterion="rebound"' --out "$T/out" > /dev/null 2> "$T/stderr"
[ $? -eq 2 ] || fail "bad criterion: expected exit 2"
[ "$(wc -l < "$T/stderr")" -eq 1 ] || fail "error must be one line: $(cat "$T/stderr")"
grep -qF "vcrit.criterion' = \"rebound\"" "$T/stderr" || fail "message: $(cat "$T/stderr")"
[ ! -e "$T/out" ] || fail "output folder created despite the error"
echo "ok"
