#!/usr/bin/env bash
# agglo aggregate: the shipped cases write aggregate.csv (x, y, z, radius in metres, coordination), the
# VTK, result.json and results.nc; the CSV read back as shape = "file" gives the same structure; bad
# input (overlapping or disconnected file, D_f outside the method, keys of another shape) -> exit 2, one
# line naming file and key, no folder. A 64-primary fractal target runs through `agglo collide`.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail

$A aggregate --help | grep -q -- "--out" || fail "aggregate --help"
for c in aggregate_fractal aggregate_bpca; do
  $A -q aggregate "$SRC/cases/$c.toml" --out "$T/$c" > /dev/null 2>&1 || fail "$c failed"
  for f in aggregate.csv aggregate.vtp result.json results.nc config.resolved.toml run.json; do
    [ -s "$T/$c/$f" ] || fail "$c: missing $f"
  done
  head -1 "$T/$c/aggregate.csv" | grep -q "^x,y,z,radius,coordination$" || fail "$c: header $(head -1 "$T/$c/aggregate.csv")"
  [ "$(($(wc -l < "$T/$c/aggregate.csv") - 1))" -eq 256 ] || fail "$c: not 256 rows"
done
/usr/bin/python3 - "$T/aggregate_fractal/result.json" "$T/aggregate_bpca/result.json" <<'PY' || fail "result.json"
import json, sys
f, b = (json.load(open(p)) for p in sys.argv[1:])
assert f["primaries"] == 256 and sum(f["coordination_counts"]) == 256, f
assert f["coordination_counts"][0] == 0, "a primary without contact"
assert f["max_contact_error"] <= 1e-6, f["max_contact_error"]
assert abs(f["fitted_fractal_dimension"] - 1.8) < 0.05 and f["target_fractal_dimension"] == 1.8, f
assert 0.95 < f["rg_spheres_m"] / f["rg_point_mass_m"] < 1.05, f   # lognormal: mass weights differ a little
assert b["target_fractal_dimension"] is None and b["fitted_fractal_dimension"] > 2.2, b
PY

# The written CSV read back: the same R_g (17 significant digits keep the contacts exact).
printf 'name = "back"\n[agglomerate]\nshape = "file"\nfile = "%s"\n' "$T/aggregate_fractal/aggregate.csv" > "$T/back.toml"
$A -q aggregate "$T/back.toml" --out "$T/back" > /dev/null 2>&1 || fail "reading aggregate.csv back"
/usr/bin/python3 -c "
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
assert abs(a['rg_point_mass_m'] / b['rg_point_mass_m'] - 1) < 1e-12 and a['contacts'] == b['contacts'], (a, b)
" "$T/aggregate_fractal/result.json" "$T/back/result.json" || fail "file round trip"

# Materials (issue 24 follow-up): agglo aggregate reads [material], [[materials]] and agglomerate.material
# and writes each primary's material and density; read back with another density for "ash", the file's
# column keeps the names and the case gives the density. (Before, [material] was an unknown key.)
printf 'name = "mat"\n[material]\ndensity = 2500.0\n[[materials]]\nname = "ash"\ndensity = 2000.0\n[agglomerate]\nshape = "bpca"\nprimaries = 16\nradius = 10e-6\nmaterial = "ash"\n' > "$T/mat.toml"
$A -q aggregate "$T/mat.toml" --out "$T/mat" > /dev/null 2>&1 || fail "aggregate with materials: $($A -q aggregate "$T/mat.toml" --out "$T/mat2" 2>&1)"
head -1 "$T/mat/aggregate.csv" | grep -q "^x,y,z,radius,coordination,material,density$" || fail "materials header: $(head -1 "$T/mat/aggregate.csv")"
[ "$(tail -n +2 "$T/mat/aggregate.csv" | cut -d, -f6,7 | sort | uniq -c | awk '{print $1, $2}')" = "16 ash,2000" ] || fail "material, density columns"
printf 'name = "back"\n[[materials]]\nname = "ash"\ndensity = 1800.0\n[agglomerate]\nshape = "file"\nfile = "%s"\n' "$T/mat/aggregate.csv" > "$T/matback.toml"
$A -q aggregate "$T/matback.toml" --out "$T/matback" > /dev/null 2>&1 || fail "reading the material column back"
[ "$(tail -n +2 "$T/matback/aggregate.csv" | cut -d, -f6,7 | sort -u)" = "ash,1800" ] || fail "material column read back"
head -1 "$T/aggregate_fractal/aggregate.csv" | grep -q "^x,y,z,radius,coordination$" || fail "no material columns without materials"

bad() {  # bad <expected fragment> <toml text>
  printf '%s\n' "$2" > "$T/bad.toml"
  refused aggregate "$1" "$2"
}
printf 'x,y,z,radius\n0,0,0,1e-6\n1.9e-6,0,0,1e-6\n' > "$T/overlap.csv"
printf 'x,y,z,radius\n0,0,0,1e-6\n2e-6,0,0,1e-6\n1e-5,0,0,1e-6\n' > "$T/apart.csv"
bad "agglomerate.file' = \"$T/overlap.csv\": primaries 0 and 1 overlap" $'[agglomerate]\nshape = "file"\nfile = "'"$T"'/overlap.csv"'
bad "disconnected groups" $'[agglomerate]\nshape = "file"\nfile = "'"$T"'/apart.csv"'
bad "agglomerate.file" $'[agglomerate]\nshape = "file"\nfile = "'"$T"'/missing.csv"'
bad "agglomerate.fractal_dimension' = 1.2" $'[agglomerate]\nshape = "fractal"\nfractal_dimension = 1.2'
bad "agglomerate.fractal_dimension' = 1.6" $'[agglomerate]\nshape = "fractal"\nfractal_dimension = 1.6'
bad "agglomerate.fractal_dimension' = 2" $'[agglomerate]\nshape = "bpca"\nfractal_dimension = 2.0'
bad "agglomerate.primaries' = 1" $'[agglomerate]\nshape = "fractal"\nprimaries = 1'
bad "agglomerate.shape' = \"tetrahedron\"" $'[agglomerate]\nshape = "tetrahedron"'
bad "agglomerate.primaries" $'[agglomerate]\nshape = "square"\nprimaries = 10'
bad "agglomerate.material' = \"ash\": unknown material" $'[agglomerate]\nshape = "bpca"\nmaterial = "ash"'

# A 64-primary fractal target through the DEM (electrostatics off): one run, a decided outcome.
printf 'name = "fractal64"\n[agglomerate]\nseed = 2\nshape = "fractal"\nprimaries = 64\nradius = 10e-6\n[projectile]\nspeed = 0.5\n' > "$T/f64.toml"
$A -q collide "$T/f64.toml" --out "$T/f64" --set time.after_contact=2e-4 --set output.snapshot_interval=0 \
  > /dev/null 2>&1 || fail "collide of a 64-primary fractal target"
/usr/bin/python3 -c "
import json, sys
r = json.load(open(sys.argv[1]))
assert 'broken' in r, r
" "$T/f64/result.json" || fail "collide result.json"
echo "aggregate_cli: ok"
