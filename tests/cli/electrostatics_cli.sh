#!/usr/bin/env bash
# CLI checks of `agglo electrostatics`: bad input -> exit code 2 and a one-line message;
# a good case writes forces.csv with the documented header and the other outputs.
. "$(dirname "$0")/lib.sh"  # A, SRC, T (removed on exit), fail
AGGLO=$A TMP=$T

good() {
  cat <<'TOML'
[electrostatics]
solver = "spectral"
min_gap = 0.0
[[particles]]
position = [0.0, 0.0, 0.0]
radius = 10e-6
charge = 1e-14
permittivity = 10.0
[[particles]]
position = [0.0, 0.0, 21e-6]
radius = 10e-6
charge = -1e-14
permittivity = 10.0
TOML
}

expect_bad() {  # name, sed expression applied to the good case, grep pattern for the message
  local name="$1" expr="$2" pat="$3"
  good | sed "$expr" > "$TMP/$name.toml"
  "$AGGLO" -q electrostatics "$TMP/$name.toml" --out "$TMP/out_$name" > "$TMP/$name.out" 2> "$TMP/$name.err"
  local rc=$?
  [ "$rc" -eq 2 ] || fail "$name: exit code $rc (expected 2); stderr: $(cat "$TMP/$name.err")"
  [ "$(wc -l < "$TMP/$name.err")" -eq 1 ] || fail "$name: message is not one line: $(cat "$TMP/$name.err")"
  grep -qi -- "$pat" "$TMP/$name.err" || fail "$name: message lacks '$pat': $(cat "$TMP/$name.err")"
  [ ! -e "$TMP/out_$name/forces.csv" ] || fail "$name: forces.csv written despite the error"
}

expect_bad kappa_zero   '0,/permittivity = 10.0/s//permittivity = 0.0/' "permittivity"
expect_bad kappa_neg    '0,/permittivity = 10.0/s//permittivity = -2.0/' "permittivity"
expect_bad zero_radius  '0,/radius = 10e-6/s//radius = 0.0/' "radius"
expect_bad overlap      's/21e-6/15e-6/' "overlap"
expect_bad unknown_key  's/^min_gap = 0.0/min_gap = 0.0\nmin_gapp = 0.1/' "min_gapp"
expect_bad medium       's/^min_gap = 0.0/min_gap = 0.0\nmedium_permittivity = 0.0/' "medium_permittivity"
expect_bad solver_name  's/solver = "spectral"/solver = "magic"/' "solver"
expect_bad precond_name 's/solver = "spectral"/solver = "spectral"\npreconditioner = "ilu"/' "preconditioner"
expect_bad precond_steps 's/solver = "spectral"/solver = "spectral"\npreconditioner_steps = 0/' "preconditioner_steps"

# electrostatics.preconditioner reaches the solver: the seed's tetrahedron (kappa_p = 15, touching
# spheres) takes fewer GMRES iterations with contact_low (16 and 12 measured), the same energy to the
# GMRES tolerance; a case that does not name the key resolves without it.
iterations() { sed -n 's/^  "iterations": \([0-9]*\),$/\1/p' "$1/stats.json"; }
for pc in none contact_low; do
  "$AGGLO" -q electrostatics "$SRC/cases/electrostatics_tetrahedron.toml" --out "$TMP/pc_$pc" \
    --set electrostatics.preconditioner=$pc > /dev/null 2> "$TMP/pc_$pc.err" || fail "preconditioner $pc: $(cat "$TMP/pc_$pc.err")"
done
it_none=$(iterations "$TMP/pc_none"); it_low=$(iterations "$TMP/pc_contact_low")
[ -n "$it_none" ] && [ -n "$it_low" ] || fail "no iteration count in stats.json"
[ "$it_low" -le $((it_none - 2)) ] || fail "contact_low: $it_low GMRES iterations, none: $it_none (expected at least 2 fewer)"
energy() { sed -n 's/^  "energy_J": \(.*\)$/\1/p' "$1/energy.json"; }
awk -v a="$(energy "$TMP/pc_none")" -v b="$(energy "$TMP/pc_contact_low")" \
  'BEGIN { d = (a - b) / a; if (d < 0) d = -d; exit !(d < 1e-5) }' || fail "contact_low changed the energy beyond 1e-5"
grep -q "preconditioner = 'contact_low'" "$TMP/pc_contact_low/config.resolved.toml" || fail "resolved config lacks the key"
# electrostatics.preconditioner_steps reaches it too: another iterate (iterations or energy differ from two steps)
"$AGGLO" -q electrostatics "$SRC/cases/electrostatics_tetrahedron.toml" --out "$TMP/pc_steps4" \
  --set electrostatics.preconditioner=contact_low --set electrostatics.preconditioner_steps=4 > /dev/null 2>&1 ||
  fail "preconditioner_steps = 4 failed"
[ "$(iterations "$TMP/pc_steps4") $(energy "$TMP/pc_steps4")" != "$it_low $(energy "$TMP/pc_contact_low")" ] ||
  fail "preconditioner_steps = 4 gave the iterations and energy of two steps"
grep -q "preconditioner_steps = 4" "$TMP/pc_steps4/config.resolved.toml" || fail "resolved config lacks preconditioner_steps"

# overlap only after shrinking is fine with min_gap = 0.01 when centres are 2.0 r apart? No:
# touching spheres (distance 2r) are separated by the regularisation and must be accepted.
good | sed 's/21e-6/20e-6/; s/^min_gap = 0.0/min_gap = 0.01/' > "$TMP/touch.toml"
"$AGGLO" -q electrostatics "$TMP/touch.toml" --out "$TMP/touch" > /dev/null 2> "$TMP/touch.err" \
  || fail "touching spheres with min_gap 0.01 rejected: $(cat "$TMP/touch.err")"

good > "$TMP/good.toml"
"$AGGLO" -q electrostatics "$TMP/good.toml" --out "$TMP/good" > "$TMP/good.out" 2> "$TMP/good.err" \
  || fail "good case failed: $(cat "$TMP/good.err")"
for f in forces.csv energy.json stats.json surface.vtu config.resolved.toml run.json; do
  [ -s "$TMP/good/$f" ] || fail "good case: $f missing"
done
[ "$(head -1 "$TMP/good/forces.csv")" = "id,fx,fy,fz,tx,ty,tz" ] || fail "forces.csv header: $(head -1 "$TMP/good/forces.csv")"
[ "$(wc -l < "$TMP/good/forces.csv")" -eq 3 ] || fail "forces.csv should have 2 rows"
grep -q '"energy_J"' "$TMP/good/energy.json" || fail "energy.json lacks energy_J"
grep -q '<VTKFile type="UnstructuredGrid"' "$TMP/good/surface.vtu" || fail "surface.vtu is not a VTU file"
grep -q 'Name="sigma_b"' "$TMP/good/surface.vtu" || fail "surface.vtu lacks sigma_b"
# physics sanity: opposite charges attract -> fz of particle 1 (at +z) is negative
awk -F, 'NR==3 { if ($4 >= 0) exit 1 }' "$TMP/good/forces.csv" || fail "particle 1 should be attracted (fz < 0)"
# the shipped case runs
"$AGGLO" -q electrostatics "$SRC/cases/electrostatics_two_spheres.toml" --out "$TMP/case" > /dev/null 2>&1 \
  || fail "cases/electrostatics_two_spheres.toml failed"
! grep -q preconditioner "$TMP/case/config.resolved.toml" || fail "the key was written into a case that does not set it"
echo "electrostatics CLI: all checks passed"
