#!/usr/bin/env bash
# Cross-check of agglo's adhesive DEM against LAMMPS (issue 2 acceptance; docs/benchmarks_dem.md).
#
#   bench/lammps_compare.sh [OUT_DIR]        (default OUT_DIR: results/lammps_compare)
#
# Same set-up in both codes: the tetrahedron + projectile of cases/seed000_neutral_tetrahedron_e0p9.toml
# (positions, radii, density 2500, E = 1e9, nu = 0.33, gamma = 0.01, e, mu = 0.3, the same time step),
# JKR with the pull-off break rule and Marshall/Mindlin sliding spring, no rolling/twisting:
#   agglo : --set contact.break_rule=lammps --set contact.tangential=marshall
#   LAMMPS: units si, atom_style sphere, pair_style granular <cutoff 2.4 r>,
#           pair_coeff * * jkr E e nu gamma tangential mindlin NULL 1.0 mu damping tsuji,
#           neighbor skin 0.1 r (>> delta_C = 3 nm), fix nve/sphere.
# v_crit is found in both by the same scan + bisection (vcrit.* of the case) and the same break-up
# rule (contact graph + escaping fragments, 2 ms after first contact). Exit 0 when they agree within
# 3 %, 1 otherwise. Environment: AGGLO (agglo executable), CASE, RESTITUTION (default: the case's
# material.restitution), STEPS_PER_PERIOD (dt = T0 / this, default 50), LMP (LAMMPS binary, default lmp;
# installed from Debian's `lammps` if missing; agglo is built in build-bench if AGGLO is missing).
#   SMOKE=1: the smoke test (ctest -L bench): the v_crit search of both codes cut to SMOKE_SETS below (a
#   scan of 3 speeds, 0.02, 0.31 and 0.6 m/s, no bisection round; projectile 0.02 r before contact; each run
#   SMOKE_AFTER s after contact, no extensions), the trajectory the same, CSV output and no plots; LAMMPS and
#   AGGLO must exist (no apt-get, no build), no LAMMPS version line and no JKR check (LAMMPS alone, two lmp
#   runs); the comparison and the verdict unchanged.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
OUT=${1:-$SRC/results/lammps_compare}
CASE=${CASE:-$SRC/cases/seed000_neutral_tetrahedron_e0p9.toml}
AGGLO=${AGGLO:-$SRC/build-bench/agglo}
PY=/usr/bin/python3
export LMP=${LMP:-lmp}
SMOKE_AFTER=1e-4
SMOKE_SETS=(vcrit.scan_points=3 vcrit.v_min=0.02 vcrit.v_max=0.6 vcrit.tolerance=0.3 projectile.gap_radii=0.02
            "time.after_contact=$SMOKE_AFTER" time.max_extensions=0)
AGGLO_SMOKE=() PNG=(--png "$OUT/ke_history.png")
if [ "${SMOKE:-0}" = 1 ]; then
  command -v "$LMP" >/dev/null || { echo "smoke: no LAMMPS binary '$LMP' (Debian package lammps)"; exit 2; }
  [ -x "$AGGLO" ] || { echo "smoke: no agglo executable '$AGGLO'"; exit 2; }
  AGGLO_SMOKE=(--format csv --no-plots) PNG=()
fi

# 1. LAMMPS (Debian package `lammps`, binary `lmp`).
if ! command -v "$LMP" >/dev/null 2>&1; then
  echo "== installing the Debian package lammps"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -q && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q lammps
fi
command -v "$LMP" >/dev/null || { echo "no LAMMPS binary '$LMP'"; exit 2; }
[ "${SMOKE:-0}" = 1 ] || echo "== LAMMPS: $("$LMP" -h | grep -m1 "^Large-scale")"

# 2. agglo (Release build in build-bench unless AGGLO points elsewhere).
if [ ! -x "$AGGLO" ]; then
  echo "== building agglo in $SRC/build-bench"
  cmake -S "$SRC" -B "$SRC/build-bench" -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=$PY -DAGGLO_BUILD_BENCH=ON >/dev/null
  cmake --build "$SRC/build-bench" -j2 --target agglo
  AGGLO=$SRC/build-bench/agglo
fi

# 3. Parameters, passed explicitly to both codes (the time step too). One Python process (each costs ~0.09 s
# of CPU) reads the case's restitution and projectile speed and computes the time step (which does not
# depend on the restitution, set after it).
SETS=(contact.break_rule=lammps contact.tangential=marshall contact.rolling=false contact.twisting=false
      material.density=2500.0 material.youngs_modulus=1.0e9 material.poisson_ratio=0.33
      material.surface_energy=0.01 material.friction=0.3 "time.steps_per_period=${STEPS_PER_PERIOD:-50}")
if [ "${SMOKE:-0}" = 1 ]; then SETS+=("${SMOKE_SETS[@]}"); fi
cv=$($PY -c "
import sys; sys.path.insert(0, '$SRC/bench/lammps'); import lmp_case
c = lmp_case.load_case(sys.argv[1])
print(c.get('material', {}).get('restitution', 0.7), c.get('projectile', {}).get('speed', 0.18),
      repr(lmp_case.Setup(lmp_case.load_case(sys.argv[1], sys.argv[2:])).dt))" "$CASE" "${SETS[@]}")
read -r E_CASE V DT <<< "$cv"
E_REST=${RESTITUTION:-$E_CASE}
SETS+=("material.restitution=$E_REST" "time.dt=$DT")
SETARGS=(); for s in "${SETS[@]}"; do SETARGS+=(--set "$s"); done
echo "== set-up: e = $E_REST, dt = $DT s; overrides: ${SETS[*]}"
rm -rf "$OUT"; mkdir -p "$OUT"

# 4. What LAMMPS' jkr coefficients mean: equilibrium, pull-off force and break point, snap-in.
if [ "${SMOKE:-0}" = 1 ]; then
  echo "smoke: LAMMPS JKR check skipped (LAMMPS alone, no agglo)"
else
  echo "== LAMMPS JKR check (two spheres, no damping; units of docs/model.md §A.2)"
  $PY "$SRC/bench/lammps/check_jkr_lammps.py" "$OUT/lammps_jkr_check" | tee "$OUT/lammps_jkr_check.txt"
fi

# 5. v_crit in both codes.
echo "== agglo vcrit"
t0=$(date +%s.%N)
"$AGGLO" -q vcrit "$CASE" "${SETARGS[@]}" "${AGGLO_SMOKE[@]}" --overwrite --out "$OUT/agglo_vcrit" -j 2 2>/dev/null | tail -3
t1=$(date +%s.%N)
echo "== LAMMPS vcrit (same scan + bisection, 2 lmp processes at a time)"
$PY "$SRC/bench/lammps/vcrit_lammps.py" "$CASE" "${SETARGS[@]}" --workdir "$OUT/lammps_vcrit" \
    --json "$OUT/lammps_vcrit.json" | tail -4
t2=$(date +%s.%N)

# 6. One trajectory in both (v = projectile.speed of the case): kinetic energy history.
"$AGGLO" collide "$CASE" "${SETARGS[@]}" "${AGGLO_SMOKE[@]}" --speed "$V" --overwrite --out "$OUT/agglo_collide" -j 1 >/dev/null 2>&1
mkdir -p "$OUT/lammps_collide"
$PY "$SRC/bench/lammps/lmp_case.py" "$CASE" "${SETARGS[@]}" --speed "$V" --workdir "$OUT/lammps_collide" \
    --thermo-every 1 > "$OUT/lammps_collide/result.json"
echo "== kinetic energy history at v = $V m/s (agglo vs LAMMPS)"
$PY "$SRC/bench/lammps/compare_trajectory.py" "$OUT/agglo_collide" "$OUT/lammps_collide" "${PNG[@]}"

# 7. Verdict.
$PY - "$OUT" "$t0" "$t1" "$t2" <<'EOF'
import json, sys
out, t0, t1, t2 = sys.argv[1], *map(float, sys.argv[2:5])
a = json.load(open(f"{out}/agglo_vcrit/vcrit.json"))
l = json.load(open(f"{out}/lammps_vcrit.json"))
ratio = a["v_crit"] / l["v_crit"]
ao = {round(r["v"], 12): r["broken"] for r in a["runs"]}
differ = [r["v"] for r in l["runs"] if round(r["v"], 12) in ao and ao[round(r["v"], 12)] != r["broken"]]
s = {"agglo_v_crit": a["v_crit"], "agglo_bracket": a["bracket"], "lammps_v_crit": l["v_crit"],
     "lammps_bracket": l["bracket"], "ratio_agglo_over_lammps": ratio, "within_3_percent": abs(ratio - 1) <= 0.03,
     "speeds_with_different_outcome": differ, "agglo_warnings": a.get("warnings", []),
     "lammps_warnings": l["warnings"], "agglo_vcrit_wall_s": t1 - t0, "lammps_vcrit_wall_s": t2 - t1}
json.dump(s, open(f"{out}/summary.json", "w"), indent=1)
print(f"agglo  v_crit = {a['v_crit']:.6f} m/s  bracket [{a['bracket'][0]:.6f}, {a['bracket'][1]:.6f}]  ({t1 - t0:.1f} s)")
print(f"LAMMPS v_crit = {l['v_crit']:.6f} m/s  bracket [{l['bracket'][0]:.6f}, {l['bracket'][1]:.6f}]  ({t2 - t1:.1f} s)")
print(f"ratio agglo / LAMMPS = {ratio:.5f}  ->  {'AGREE' if s['within_3_percent'] else 'DISAGREE'} (3 % criterion)")
if differ:
    print("speeds tested by both with different outcomes:", ", ".join(f"{v:.6f}" for v in differ))
for w in s["agglo_warnings"]:
    print("agglo warning:", w)
for w in s["lammps_warnings"]:
    print("LAMMPS warning:", w)
print(f"summary: {out}/summary.json")
sys.exit(0 if s["within_3_percent"] else 1)
EOF
