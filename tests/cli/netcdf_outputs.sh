#!/usr/bin/env bash
# results.nc (issue 12 item 2, docs/outputs.md): written beside the CSV files by default; --format netcdf
# writes it and no CSV/JSON tables, --format csv no results.nc; xarray opens it with the `time`
# coordinate labelled, units on every variable and the same numbers as the CSV columns; provenance
# (version, git hash, command, seed, resolved config) in the global attributes. $1 = agglo executable,
# $2 = source dir.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, AC, NT
DEM="$SRC/cases/seed000_neutral_tetrahedron.toml"
SHORT=(--set time.after_contact=2e-5 --set output.snapshot_interval=1e-5)
ASHORT=(--set time.end=0.001 --set "output.psd_times=[0.0,0.001]" --set "output.snapshot_times=[0.0]")

# NetCDF is loaded on first use (io/netcdf_library.hpp): a process that writes no results.nc does not load
# it (the dynamic loader's own trace), one that writes results.nc does (negative control of the grep).
LD_DEBUG=libs $A --version > /dev/null 2> "$T/ld_version.txt" || fail "--version"
grep -q "libnetcdf" "$T/ld_version.txt" && fail "agglo --version loaded libnetcdf"
grep -q "libc.so" "$T/ld_version.txt" || fail "LD_DEBUG=libs printed no trace (check not effective)"
LD_DEBUG=libs $A -q --no-plots collide "$DEM" --out "$T/c" "${SHORT[@]}" > /dev/null 2> "$T/ld_collide.txt" || fail "collide"
grep -q "libnetcdf" "$T/ld_collide.txt" || fail "collide wrote results.nc without loading libnetcdf?"
$A -q --no-plots acoustic "$AC" --out "$T/a" "${ASHORT[@]}" > /dev/null 2>&1 || fail "acoustic"
for f in c/results.nc c/timeseries.csv c/result.json a/results.nc a/efficiency.csv a/psd.csv a/summary.json; do
  [ -s "$T/$f" ] || fail "default format: $f missing"
done
ls "$T"/c/*.tmp-* "$T"/a/*.tmp-* > /dev/null 2>&1 && fail "temporary files left behind"

$A -q --no-plots collide "$DEM" --out "$T/cn" --format netcdf "${SHORT[@]}" > /dev/null 2>&1 || fail "collide --format netcdf"
$A -q --no-plots acoustic "$AC" --out "$T/an" --format netcdf "${ASHORT[@]}" > /dev/null 2>&1 || fail "acoustic --format netcdf"
[ -s "$T/cn/results.nc" ] && [ -s "$T/an/results.nc" ] || fail "--format netcdf: results.nc missing"
for d in cn an; do
  found=$(cd "$T/$d" && ls *.csv *.vtp *.pvd result.json summary.json snapshots 2> /dev/null)
  [ -z "$found" ] || fail "--format netcdf wrote tables in $d: $found"
  [ -s "$T/$d/run.json" ] && [ -s "$T/$d/config.resolved.toml" ] || fail "--format netcdf: run files missing in $d"
done

$A -q --no-plots collide "$DEM" --out "$T/cc" --format csv "${SHORT[@]}" > /dev/null 2>&1 || fail "collide --format csv"
[ -e "$T/cc/results.nc" ] && fail "--format csv wrote results.nc"
[ -s "$T/cc/timeseries.csv" ] || fail "--format csv: timeseries.csv missing"
cmp -s "$T/c/timeseries.csv" "$T/cc/timeseries.csv" || fail "--format changed timeseries.csv"

# electrostatics (default formats) and a sweep with --format netcdf: its own results.nc over `case`, one per
# case folder, no sweep.csv
ES="$SRC/cases/electrostatics_two_spheres.toml"
$A -q --no-plots electrostatics "$ES" --out "$T/e" > /dev/null 2>&1 || fail "electrostatics"
$A -q --no-plots sweep "$DEM" --command collide --param projectile.speed --values 0.1,0.3 --format netcdf \
  --set time.after_contact=2e-5 --set output.snapshot_interval=0 --out "$T/s" > /dev/null 2>&1 || fail "sweep"
[ -e "$T/s/sweep.csv" ] && fail "sweep --format netcdf wrote sweep.csv"
for f in s/results.nc s/case_00_0.1/results.nc s/case_01_0.3/results.nc; do [ -s "$T/$f" ] || fail "$f missing"; done

/usr/bin/python3 - "$T" <<'PY' || fail "xarray check"
import sys
import numpy as np
import xarray as xr
T = sys.argv[1]

def check_units(ds):
    for name, v in ds.variables.items():
        assert "units" in v.attrs and "long_name" in v.attrs, f"{name} lacks units/long_name"

def same(a, b, what, rtol=1e-7):  # the CSV files round to 8-10 significant digits (psd.csv: 6)
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    assert a.shape == b.shape, f"{what}: shape {a.shape} vs {b.shape}"
    assert np.allclose(a, b, rtol=rtol, atol=0.0), f"{what}: values differ"

# collide: time coordinate and every timeseries.csv column
ds = xr.open_dataset(f"{T}/c/results.nc")
assert "time" in ds.coords and ds["time"].dims == ("time",), "time is not a coordinate"
assert ds["kinetic_energy"].dims == ("time",) and ds["kinetic_energy"].attrs["units"] == "J"
check_units(ds)
csv = np.genfromtxt(f"{T}/c/timeseries.csv", delimiter=",", names=True)
assert len(csv) > 2, "too few rows"
same(ds["time"], csv["t"], "time")
for col in csv.dtype.names[1:]:
    same(ds[col], csv[col], col)
assert ds["position"].dims == ("frame", "particle", "xyz") and ds.sizes["frame"] >= 2
assert ds.attrs["command"] == "collide" and ds.attrs["Conventions"] == "CF-1.8"
assert "[projectile]" in ds.attrs["config"] and ds.attrs["git_hash"]
cfg = open(f"{T}/c/config.resolved.toml").read()
assert ds.attrs["config"] == cfg, "config attribute differs from config.resolved.toml"
ds2 = xr.open_dataset(f"{T}/cn/results.nc")
same(ds2["kinetic_energy"], ds["kinetic_energy"], "collide --format netcdf")

# acoustic: time coordinate, efficiency.csv columns, psd over (psd_time, diameter)
ds = xr.open_dataset(f"{T}/a/results.nc")
check_units(ds)
assert "time" in ds.coords and ds["fine_efficiency"].dims == ("time",)
csv = np.genfromtxt(f"{T}/a/efficiency.csv", delimiter=",", names=True)
same(ds["time"], csv["t_s"], "acoustic time")
for col in csv.dtype.names[1:]:
    same(ds[col], csv[col], col)
assert ds["n_total_cm3"].attrs["units"] == "cm-3"
psd = np.genfromtxt(f"{T}/a/psd.csv", delimiter=",", names=True)
assert ds["total_dNdlogd_cm3"].dims == ("psd_time", "diameter")
assert "diameter" in ds.coords and ds["diameter"].attrs["units"] == "m"
same(ds["total_dNdlogd_cm3"].values.ravel(), psd["total_dNdlogd_cm3"], "psd", 1e-5)
same(np.tile(ds["diameter"].values, ds.sizes["psd_time"]), psd["d_mid_m"], "diameter", 1e-5)
assert ds.sizes["diameter_edge"] == ds.sizes["diameter"] + 1
import json
assert int(ds.attrs["seed"]) == json.load(open(f"{T}/a/run.json"))["seed"] and ds.attrs["command"] == "acoustic"

# electrostatics: force/torque (particle, xyz) equal forces.csv's columns, energy equals energy.json
ds = xr.open_dataset(f"{T}/e/results.nc")
check_units(ds)
f = np.genfromtxt(f"{T}/e/forces.csv", delimiter=",", names=True)
same(ds["particle"], f["id"], "particle")
for k, c in enumerate("xyz"):
    same(ds["force"][:, k], f["f" + c], "f" + c)
    same(ds["torque"][:, k], f["t" + c], "t" + c)
assert ds["force"].attrs["units"] == "N" and ds["force"].dims == ("particle", "xyz")
same(ds["energy"], json.load(open(f"{T}/e/energy.json"))["energy_J"], "energy", 1e-15)

# sweep: the swept key over `case` with its unit, a summary column per case
ds = xr.open_dataset(f"{T}/s/results.nc")
check_units(ds)
assert "case" in ds.coords and ds.sizes["case"] == 2
same(ds["projectile.speed"], [0.1, 0.3], "swept speeds")
assert ds["projectile.speed"].attrs["units"] == "m s-1"
for i in range(2):
    case = xr.open_dataset(f"{T}/s/case_0{i}_{[0.1, 0.3][i]}/results.nc")
    assert int(ds["broken"][i]) == int(case["broken"]), "sweep summary differs from the case's results.nc"
PY
echo "netcdf_outputs: ok"
