"""Exit 0 when two results.nc files hold the same content: dimensions, variables (values bit for bit,
NaN equal to NaN, dtype, dims, attributes) and global attributes; wall-clock timing variables
(wall_time_s, time_s, names starting with "wall_time_s_" or "time_s_" and names
containing "seconds") are left out. Used by the restart tests.

Usage: same_results_nc.py A.nc B.nc   (prints the first difference on stdout, exit 1)"""
import sys

import netCDF4
import numpy as np

TIMING = {"wall_time_s", "time_s"}


def timing(name):  # also the statistics of a seed ensemble, e.g. wall_time_s_mean
    return name in TIMING or "seconds" in name or any(name.startswith(t + "_") for t in TIMING)


def content(path):
    with netCDF4.Dataset(path) as d:
        dims = {n: len(v) for n, v in d.dimensions.items()}
        attrs = {k: d.getncattr(k) for k in d.ncattrs()}
        variables = {}
        for name, v in d.variables.items():
            if timing(name):
                continue
            v.set_auto_mask(False)
            variables[name] = (v.dimensions, v.dtype.str, {k: v.getncattr(k) for k in v.ncattrs()}, v[...].copy())
    return dims, attrs, variables


def same_value(x, y):
    x, y = np.asarray(x), np.asarray(y)
    if x.shape != y.shape or x.dtype != y.dtype:
        return False
    if x.dtype.kind == "f":
        return np.array_equal(x.view(np.uint64 if x.itemsize == 8 else np.uint32),
                              y.view(np.uint64 if y.itemsize == 8 else np.uint32))
    return np.array_equal(x, y)


def main(a, b):
    da, db = content(a), content(b)
    if da[0] != db[0]:
        return f"dimensions differ: {da[0]} vs {db[0]}"
    if da[1].keys() != db[1].keys() or any(not same_value(da[1][k], db[1][k]) for k in da[1]):
        return "global attributes differ"
    if da[2].keys() != db[2].keys():
        return f"variables differ: {sorted(set(da[2]) ^ set(db[2]))}"
    for name, (dims, dtype, attrs, values) in da[2].items():
        dims2, dtype2, attrs2, values2 = db[2][name]
        if dims != dims2 or dtype != dtype2 or attrs.keys() != attrs2.keys():
            return f"variable {name}: dims, dtype or attribute names differ"
        if any(not same_value(attrs[k], attrs2[k]) for k in attrs):
            return f"variable {name}: attributes differ"
        if not same_value(values, values2):
            return f"variable {name}: values differ"
    return None


if __name__ == "__main__":
    diff = main(sys.argv[1], sys.argv[2])
    if diff:
        print(f"{sys.argv[1]} vs {sys.argv[2]}: {diff}")
    sys.exit(1 if diff else 0)
