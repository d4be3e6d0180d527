#!/usr/bin/env bash
# CLI contract of [wall] and [gas] in impact cases (docs/dem.md "Gas and walls"): bad input -> one line
# naming file and key, exit 2, no output folder; a sphere sticks to a wall below its sticking velocity
# and rebounds above it; an agglomerate hits a wall obliquely in air.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail

bad() {  # bad <expected fragment> <sed expression applied to cases/sphere_wall.toml>
  sed "$2" "$SRC/cases/sphere_wall.toml" > "$T/bad.toml"
  refused collide "$1" "$2"
}
# The sphere moved so that the wall plane cuts it.
bad "wall.position" 's/^position = \[0.0, 0.0, 0.0\]/position = [5e-6, 0.0, 0.0]/'
grep -qF "the wall plane cuts particle 0" "$T/stderr" || fail "wall through the sphere: $(cat "$T/stderr")"
bad "wall.material' = \"glass\"" 's/^material = "same"/material = "glass"/'
bad "wall.normal" 's/^normal = \[-1.0, 0.0, 0.0\]/normal = [0.0, 0.0, 0.0]/'
bad "wall.normal" 's/^normal = \[-1.0, 0.0, 0.0\]/normal = [1.0, 0.0, 0.0]/'  # facing away from the motion
bad "unknown key 'wall.colour'" 's/^impact = true/impact = true\ncolour = "red"/'
bad "gas.viscosity' = -1" 's/^\[time\]/[gas]\nviscosity = -1.0\n\n[time]/'
bad "shape = \"list\" needs at least two" 's/^impact = true/impact = false/'
bad "electrostatics.external_field" 's/^impact = true/impact = true\ngrounded = true/; s/^\[time\]/[electrostatics]\nexternal_field = [1e5, 0.0, 0.0]\n\n[time]/'

# Below the sticking velocity (0.0499 m/s with e = 0.7, docs/dem.md) the sphere stays on the wall; above it,
# it rebounds.
for v in 0.04 0.07; do
  $A -q --no-plots collide "$SRC/cases/sphere_wall.toml" --speed $v --out "$T/sw_$v" > /dev/null 2>&1 \
    || fail "sphere_wall at $v m/s failed"
done
grep -q '"wall_contacts_at_end": 1' "$T/sw_0.04/result.json" || fail "sphere must stick at 0.04 m/s"
grep -q '"wall_contacts_at_end": 0' "$T/sw_0.07/result.json" || fail "sphere must rebound at 0.07 m/s"
# A charged sphere and a grounded wall: its image holds it at 0.07 m/s.
$A -q --no-plots collide "$SRC/cases/sphere_wall_grounded.toml" --out "$T/swg" > /dev/null 2>&1 \
  || fail "sphere_wall_grounded failed"
grep -q '"wall_contacts_at_end": 1' "$T/swg/result.json" || fail "charged sphere must stick to the grounded wall"
$A -q --no-plots collide "$SRC/cases/sphere_wall_grounded.toml" --set wall.grounded=false --out "$T/swn" \
  > /dev/null 2>&1 || fail "sphere_wall_grounded without grounding failed"
grep -q '"wall_contacts_at_end": 0' "$T/swn/result.json" || fail "without images the sphere must rebound at 0.07 m/s"
# A case without [wall] has no such entry (its result.json is unchanged).
$A -q --no-plots collide "$SRC/cases/seed000_neutral_tetrahedron.toml" --out "$T/nowall" --set time.after_contact=1e-4 \
  > /dev/null 2>&1 || fail "tetrahedron run failed"
grep -q 'wall_contacts' "$T/nowall/result.json" && fail "result.json of a case without wall lists wall contacts"
grep -q '^\[wall\]\|^\[gas\]' "$T/nowall/config.resolved.toml" && fail "resolved config of a case without wall/gas changed"

# The tetrahedron hitting a rigid wall at 30 degrees in air (drag and gravity) runs and touches the wall.
$A -q --no-plots collide "$SRC/cases/agglomerate_wall_gas.toml" --out "$T/aw" > /dev/null 2>&1 \
  || fail "agglomerate_wall_gas failed"
grep -q '"projectile_contact": true' "$T/aw/result.json" || fail "agglomerate_wall_gas: no wall contact"
grep -q '^drag = true' "$T/aw/config.resolved.toml" || fail "agglomerate_wall_gas: resolved [gas] lacks drag"
echo "ok"
