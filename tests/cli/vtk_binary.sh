#!/usr/bin/env bash
# Binary VTK (docs/outputs.md): aggregate.vtp, collide snapshots and surface.vtu (spectral, BEM and
# coulomb solvers) are read back by an independent parser (scripts/vtk_read.py) and every array is
# checked against what agglo wrote elsewhere (aggregate.csv at 17 digits) or the case, or against its
# definition (sigma = sigma_f + sigma_b, unit normals, cell offsets and types); a truncated file fails
# the parser; output.surface = false writes no surface.vtu, a non-boolean value is exit 2.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail
R="$SRC/scripts/vtk_read.py"

$A -q aggregate "$SRC/cases/aggregate_fractal.toml" --out "$T/agg" > /dev/null 2>&1 || fail "aggregate failed"
$A -q electrostatics "$SRC/cases/electrostatics_tetrahedron.toml" --out "$T/sp" > /dev/null 2>&1 || fail "spectral failed"
$A -q electrostatics "$SRC/cases/electrostatics_tetrahedron.toml" --set electrostatics.solver=bem \
  --set electrostatics.patches_per_sphere=200 --out "$T/bem" > /dev/null 2>&1 || fail "bem failed"
$A -q electrostatics "$SRC/cases/electrostatics_tetrahedron.toml" --set electrostatics.solver=coulomb \
  --out "$T/co" > /dev/null 2>&1 || fail "coulomb failed"
$A -q collide "$NT" --set time.after_contact=2e-4 --set output.snapshot_interval=5e-5 --set output.timeseries_interval=5e-5 \
  --out "$T/col" > /dev/null 2> "$T/col.err" || fail "collide failed: $(cat "$T/col.err")"

CASE="$SRC/cases/electrostatics_tetrahedron.toml" PYTHONPATH="$SRC/scripts" /usr/bin/python3 - "$T" <<'PY' || fail "VTK contents"
import csv, glob, sys
import numpy as np
from vtk_read import read
T = sys.argv[1]

# aggregate.vtp against aggregate.csv (17 significant digits: exact doubles)
v = read(f"{T}/agg/aggregate.vtp")
c = np.loadtxt(f"{T}/agg/aggregate.csv", delimiter=",", skiprows=1)
n = len(c)
assert v["dataset"] == "PolyData" and v["attrs"] == {"NumberOfPoints": n, "NumberOfVerts": n}, v["attrs"]
assert np.array_equal(v["Points/Points"], c[:, 0:3]), "aggregate positions"
assert np.array_equal(v["PointData/radius"][:, 0], c[:, 3]), "aggregate radii"
assert np.array_equal(v["PointData/coordination"][:, 0], c[:, 4]), "aggregate coordination"
assert np.array_equal(v["Verts/connectivity"][:, 0], np.arange(n)), "vertex connectivity"
assert np.array_equal(v["Verts/offsets"][:, 0], np.arange(1, n + 1)), "vertex offsets"

def surface(path, spheres, triangles):
    s = read(path)
    x, n = s["Points/Points"], s["PointData/normal"]
    m = s["attrs"]["NumberOfPoints"]
    assert s["dataset"] == "UnstructuredGrid" and len(x) == m > 0, s["attrs"]
    for k in ("sigma_f", "sigma_b", "sigma", "area", "body"):
        assert s[f"PointData/{k}"].shape == (m, 1), k
    assert np.array_equal(s["PointData/sigma"], s["PointData/sigma_f"] + s["PointData/sigma_b"]), "sigma"
    assert np.all(s["PointData/area"] > 0) and s["PointData/body"].dtype == np.int32
    body = s["PointData/body"][:, 0]
    assert set(body) == set(range(len(spheres))), set(body)
    assert np.allclose(np.linalg.norm(n, axis=1), 1, atol=1e-12), "unit normals"
    # each sample lies on its body's sphere (centre and electrostatic radius of the case), normal outward
    r = x - spheres[body, 0:3]
    d = np.linalg.norm(r, axis=1)
    assert np.allclose(d, spheres[body, 3], rtol=1e-3), "samples on their sphere"
    assert np.all(np.einsum("ij,ij->i", r / d[:, None], n) > 0.9), "outward normals"
    # the values against the case: uniform free charge q / (4 pi r_E^2), the samples' areas tile each
    # sphere, and the total charge sigma * area is the free charge (bound charge sums to zero; the
    # spectral solver's quadrature of sigma_b to 2 %)
    q, rE, a = spheres[:, 4], spheres[:, 3], s["PointData/area"][:, 0]
    assert np.allclose(s["PointData/sigma_f"][:, 0], q[body] / (4 * np.pi * rE[body] ** 2), rtol=1e-12, atol=0), "sigma_f"
    assert np.allclose(np.bincount(body, a), 4 * np.pi * rE ** 2, rtol=1e-10, atol=0), "areas"
    total = np.bincount(body, a * s["PointData/sigma"][:, 0])
    assert np.allclose(total, q, rtol=0, atol=2e-2 * abs(q).max()), (total, q)
    cells, conn, off, typ = s["attrs"]["NumberOfCells"], s["Cells/connectivity"][:, 0], s["Cells/offsets"][:, 0], s["Cells/types"][:, 0]
    k = 3 if triangles else 1
    assert len(off) == len(typ) == cells and np.array_equal(off, k * np.arange(1, cells + 1)), "offsets"
    assert len(conn) == k * cells and conn.min() >= 0 and conn.max() < m, "connectivity"
    assert np.all(typ == (5 if triangles else 1)) and typ.dtype == np.uint8, "types"
    if not triangles:
        assert np.array_equal(conn, np.arange(m)), "vertex cells"

# the sphere centres, electrostatic radii r / (1 + g_min / 2) and charges from the case file
import tomllib
import os
case = tomllib.load(open(os.environ["CASE"], "rb"))
g = case.get("electrostatics", {}).get("min_gap", 0.01)
sp = np.array([[*p["position"], p["radius"] / (1 + g / 2), p["charge"]] for p in case["particles"]])
for solver in ("sp", "bem", "co"):
    surface(f"{T}/{solver}/surface.vtu", sp, True)  # every solver provides a triangulation

# collide snapshots: PolyData with radius, velocity, angular_velocity, charge, contacts
snaps = sorted(glob.glob(f"{T}/col/snapshots/particles_*.vtp"))
assert len(snaps) >= 3, snaps
for p in snaps:
    s = read(p)
    m = s["attrs"]["NumberOfPoints"]
    assert [k for k in s if k.startswith("PointData/")] == [
        "PointData/radius", "PointData/velocity", "PointData/angular_velocity", "PointData/charge", "PointData/contacts"]
    assert s["PointData/velocity"].shape == (m, 3) and s["PointData/contacts"].dtype == np.int32
    assert np.all(s["PointData/radius"] > 0) and np.all(np.isfinite(s["Points/Points"]))
print("ok")
PY

# negative controls: a truncated file, one byte changed in a block length
head -c -100 "$T/bem/surface.vtu" > "$T/trunc.vtu"
/usr/bin/python3 "$R" "$T/trunc.vtu" > /dev/null 2>&1 && fail "the parser accepted a truncated surface.vtu"
head -c -40 "$T/agg/aggregate.vtp" > "$T/trunc.vtp"
/usr/bin/python3 "$R" "$T/trunc.vtp" > /dev/null 2>&1 && fail "the parser accepted a truncated aggregate.vtp"
/usr/bin/python3 "$R" "$T/agg/aggregate.vtp" "$T/bem/surface.vtu" > /dev/null || fail "the parser refused good files"

# output.surface
$A -q electrostatics "$SRC/cases/electrostatics_two_spheres.toml" --set output.surface=false --out "$T/nosurf" \
  > /dev/null 2>&1 || fail "output.surface = false failed"
[ -s "$T/nosurf/forces.csv" ] || fail "output.surface = false: no forces.csv"
[ ! -e "$T/nosurf/surface.vtu" ] || fail "output.surface = false wrote surface.vtu"
$A -q electrostatics "$SRC/cases/electrostatics_two_spheres.toml" --set output.surface=3 --out "$T/badsurf" \
  > /dev/null 2> "$T/bad.err"
rc=$?
[ "$rc" -eq 2 ] && [ "$(wc -l < "$T/bad.err")" -eq 1 ] && grep -q "output.surface" "$T/bad.err" \
  || fail "output.surface = 3: exit $rc, $(cat "$T/bad.err")"
echo "binary VTK: all checks passed"
