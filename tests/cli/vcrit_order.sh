#!/usr/bin/env bash
# vcrit.order = "top_down" (impact/vcrit.hpp, docs/dem.md): the same v_crit, bracket and rounds as the full
# order, on the neutral seed tetrahedron (break-up, two threads) and on cases/sphere_wall.toml (sticking);
# its runs are a subset of the full order's holding every run at or above the bracket's lower end, and
# fewer; the key is written to the resolved config only when set; a bad value is refused (exit 2, one line,
# no folder).
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail

N="$SRC/cases/seed000_neutral_tetrahedron.toml"
NV=(--set vcrit.scan_points=8 --set vcrit.tolerance=0.002 --set time.after_contact=2e-4 --threads 2)
W="$SRC/cases/sphere_wall.toml"
WV=(--set 'vcrit.criterion="sticking"' --set vcrit.v_min=0.02 --set vcrit.v_max=0.1 --set vcrit.scan_points=5
    --set vcrit.tolerance=5e-4)
for o in full top_down; do
  $A -q --no-plots vcrit "$N" "${NV[@]}" --set "vcrit.order=\"$o\"" --out "$T/n_$o" > /dev/null 2>&1 || fail "neutral $o"
  $A -q --no-plots vcrit "$W" "${WV[@]}" --set "vcrit.order=\"$o\"" --out "$T/w_$o" > /dev/null 2>&1 || fail "wall $o"
done
for c in n w; do
  /usr/bin/python3 - "$T/${c}_full/vcrit.json" "$T/${c}_top_down/vcrit.json" <<'PY' || fail "$c: top_down differs"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
for k in ("v_crit", "bracket", "rounds"):
    assert a[k] == b[k], (k, a[k], b[k])
va = {r["v"] for r in a["runs"]}
vb = {r["v"] for r in b["runs"]}
assert vb <= va, vb - va
assert {v for v in va if v >= a["bracket"][0]} <= vb
assert len(vb) < len(va), (len(va), len(vb))
PY
done
grep -q '^order = .top_down.' "$T/n_top_down/config.resolved.toml" || fail "resolved config lacks vcrit.order"
grep -q '^order' "$T/n_full/config.resolved.toml" || fail "resolved config lacks an explicitly set vcrit.order"
$A -q --no-plots vcrit "$N" "${NV[@]}" --out "$T/n_none" > /dev/null 2>&1 || fail "neutral without the key"
grep -q '^order' "$T/n_none/config.resolved.toml" && fail "vcrit.order written without the key"
sed 's/^\[vcrit\]$/[vcrit]\norder = "bottom_up"/' "$N" > "$T/bad.toml"
refused vcrit "vcrit.order' = \"bottom_up\"" "vcrit.order = bottom_up"
echo "ok"
