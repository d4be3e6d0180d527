#!/usr/bin/env bash
# CLI contract of materials per particle (docs/dem.md "Materials", docs/model.md §A.8): unknown or
# ill-declared material names -> one line naming file, key, value and the allowed names, exit 2, no
# output folder; the mixed-material case runs; a named copy of the default material changes nothing.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail

bad() {  # bad <expected fragment> <case file> <sed expression>
  sed "$3" "$2" > "$T/bad.toml"
  refused collide "$1" "$3"
}
M="$SRC/cases/materials_ash_on_silica.toml"
bad "projectile.material' = \"glass\": unknown material; allowed: \"default\", \"ash\"" "$M" 's/^material = "ash"/material = "glass"/'
bad "materials.0.name' = \"default\": is reserved" "$M" 's/^name = "ash"/name = "default"/'
bad "agglomerate.material' = \"soot\"" "$M" 's/^shape = "tetrahedron"/shape = "tetrahedron"\nmaterial = "soot"/'
bad "materials.0.youngs_modulus' = -1" "$M" 's/^youngs_modulus = 1.5e8/youngs_modulus = -1.0/'
bad "is declared twice" "$M" 's/^\[contact\]/[[materials]]\nname = "ash"\n\n[contact]/'
bad "wall.material' = \"steel\": unknown material; allowed: \"same\", \"rigid\", \"default\"" "$SRC/cases/sphere_wall.toml" 's/^material = "same"/material = "steel"/'
bad "particles.0.material' = \"ash\"" "$SRC/cases/sphere_wall.toml" 's/^radius = 10e-6/radius = 10e-6\nmaterial = "ash"/'
# A structure file naming an undeclared material in its material column.
printf 'x,y,z,radius,material\n0,0,0,1e-5,default\n2e-5,0,0,1e-5,ash\n' > "$T/two.csv"
cat > "$T/filecase.toml" <<TOML
[agglomerate]
shape = "file"
file = "two.csv"
TOML
rm -rf "$T/out"
$A collide "$T/filecase.toml" --out "$T/out" > /dev/null 2> "$T/stderr"
[ $? -eq 2 ] || fail "file with an unknown material: expected exit 2"
[ "$(wc -l < "$T/stderr")" -eq 1 ] || fail "error must be one line: $(cat "$T/stderr")"
grep -qF "unknown material \"ash\" in the material column; allowed: \"default\"" "$T/stderr" \
  || fail "file material message: $(cat "$T/stderr")"
grep -qF "agglomerate.file" "$T/stderr" || fail "file material message lacks the key: $(cat "$T/stderr")"
[ ! -e "$T/out" ] || fail "output folder created despite the error"
# Declared, the same file runs, and the resolved config keeps the materials.
printf '\n[[materials]]\nname = "ash"\nsurface_energy = 0.02\n\n[projectile]\nspeed = 0.05\n[time]\nafter_contact = 1e-4\n' \
  >> "$T/filecase.toml"
$A -q --no-plots collide "$T/filecase.toml" --out "$T/fileok" > /dev/null 2>&1 || fail "file with materials failed"
grep -q "^name = 'ash'" "$T/fileok/config.resolved.toml" || fail "resolved config lacks [[materials]]"

# The mixed-material case runs.
$A -q --no-plots collide "$M" --out "$T/mixed" --set time.after_contact=2e-4 > /dev/null 2>&1 || fail "mixed case failed"
grep -q '"projectile_contact": true' "$T/mixed/result.json" || fail "mixed case: no contact"
# A projectile of a named copy of the default material: result.json identical to the single material.
S="$SRC/cases/seed000_neutral_tetrahedron.toml"
$A -q --no-plots collide "$S" --out "$T/one" --set time.after_contact=2e-4 > /dev/null 2>&1 || fail "seed case failed"
{ cat "$S"; printf '\n[[materials]]\nname = "copy"\n'; } | sed 's/^offset_radii = 0.05/offset_radii = 0.05\nmaterial = "copy"/' > "$T/copy.toml"
$A -q --no-plots collide "$T/copy.toml" --out "$T/copy" --set time.after_contact=2e-4 > /dev/null 2>&1 || fail "copy case failed"
grep -q '^material = "copy"' "$T/copy.toml" || fail "test setup: projectile material not set"
diff <(grep -v '"version\|seconds\|wall_time' "$T/one/result.json") <(grep -v '"version\|seconds\|wall_time' "$T/copy/result.json") \
  || fail "a named copy of the default material changed result.json"
echo "ok"
