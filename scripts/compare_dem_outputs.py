#!/usr/bin/env python3
"""Compare two output trees of tests/regression/run_cases.sh against the DEM output tolerance
(docs/benchmarks_dem.md §8): for every file present in both trees, the largest relative difference of each
numeric quantity (NetCDF variables, CSV columns, JSON numbers), relative to the largest magnitude of that
quantity in the older tree, and whether every discrete output (integers, booleans, strings: contact counts,
outcomes, classifications) is equal. VTK snapshots are skipped (their fields are in results.nc).

Usage: compare_dem_outputs.py OLD_DIR NEW_DIR [--bound 1e-10] [--diagnostic-bound 1e-7]
Prints one line per file that differs and exits 1 when a relative difference exceeds the bound (for the
electrostatics' error-control diagnostics, names containing "hold_error": the diagnostic bound) or a discrete
output differs. Chaotic runs exceed it in the reference itself (docs/benchmarks_dem.md §8): compare them with
the reference run at a speed changed by 1e-12 relative.
"""
import argparse
import csv
import json
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests" / "regression"))
from checksums import dropped  # noqa: E402  (the timing and provenance fields the output regression ignores)


def rel_diff(a, b):
    """max |a - b| / max |a| over two equal-length lists of floats (0 when equal, inf on a NaN mismatch)."""
    scale = max((abs(x) for x in a if math.isfinite(x)), default=0.0)
    worst = 0.0
    for x, y in zip(a, b):
        if x == y or (math.isnan(x) and math.isnan(y)):
            continue
        if not (math.isfinite(x) and math.isfinite(y)):
            return math.inf
        worst = max(worst, abs(x - y) / scale if scale > 0 else math.inf)
    return worst


def number(s):
    try:
        return float(s)
    except ValueError:
        return None


def compare_csv(old, new):
    ro = list(csv.reader(old.open()))
    rn = list(csv.reader(new.open()))
    if len(ro) != len(rn) or (ro and ro[0] != rn[0]):
        return {}, ["rows or header"]
    out, discrete = {}, []
    for c, name in enumerate(ro[0] if ro else []):
        if dropped(name.strip()):
            continue
        a = [r[c] if c < len(r) else "" for r in ro[1:]]
        b = [r[c] if c < len(r) else "" for r in rn[1:]]
        fa, fb = [number(x) for x in a], [number(x) for x in b]
        integral = all(x is not None and "." not in s and "e" not in s.lower() for x, s in zip(fa, a))
        if any(x is None for x in fa + fb) or integral:
            if a != b:
                discrete.append(name)
        else:
            out[name] = rel_diff(fa, fb)
    return out, discrete


def walk_json(x, path, nums, other):
    if isinstance(x, bool) or x is None or isinstance(x, str) or isinstance(x, int):
        other[path] = x
    elif isinstance(x, float):
        nums.setdefault(path, []).append(x)
    elif isinstance(x, dict):
        for k, v in x.items():
            walk_json(v, f"{path}.{k}", nums, other)
    else:
        for i, v in enumerate(x):
            walk_json(v, f"{path}[{i}]", nums, other)


def compare_json(old, new):
    no, oo, nn, on = {}, {}, {}, {}
    walk_json(json.loads(old.read_text()), "", no, oo)
    walk_json(json.loads(new.read_text()), "", nn, on)
    discrete = [k for k in set(oo) | set(on) if oo.get(k) != on.get(k) and not dropped(k.rsplit(".", 1)[-1])]
    out = {}
    for k in set(no) | set(nn):
        if dropped(k.rsplit(".", 1)[-1]):
            continue
        if k not in no or k not in nn or len(no[k]) != len(nn[k]):
            discrete.append(k)
        else:
            out[k] = rel_diff(no[k], nn[k])
    return out, discrete


def compare_nc(old, new):
    import netCDF4
    import numpy as np
    out, discrete = {}, []
    with netCDF4.Dataset(old) as a, netCDF4.Dataset(new) as b:
        for name, va in a.variables.items():
            if dropped(name):
                continue
            if name not in b.variables:
                discrete.append(name)
                continue
            x = np.asarray(va[:]).ravel()
            y = np.asarray(b.variables[name][:]).ravel()
            if x.shape != y.shape:
                discrete.append(name)
            elif x.dtype.kind in "iub" or y.dtype.kind in "iub" or x.dtype.kind in "SUO":
                if not np.array_equal(x, y):
                    discrete.append(name)
            else:
                out[name] = rel_diff(x.astype(float).tolist(), y.astype(float).tolist())
    return out, discrete


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--bound", type=float, default=1e-10)
    ap.add_argument("--diagnostic-bound", type=float, default=1e-7)
    args = ap.parse_args()
    old, new = Path(args.old), Path(args.new)
    compare = {".csv": compare_csv, ".json": compare_json, ".nc": compare_nc}
    bad = 0
    overall = 0.0
    for f in sorted(old.rglob("*")):
        g = new / f.relative_to(old)
        if f.suffix not in compare or not g.exists() or f.read_bytes() == g.read_bytes():
            continue
        nums, discrete = compare[f.suffix](f, g)
        worst = max(nums.items(), key=lambda kv: kv[1], default=("-", 0.0))
        overall = max(overall, worst[1])
        beyond = [k for k, v in nums.items() if v > (args.diagnostic_bound if "hold_error" in k else args.bound)]
        fail = bool(beyond) or bool(discrete)
        bad += fail
        print(f"{'FAIL' if fail else 'ok  '} {f.relative_to(old)}: largest relative difference {worst[1]:.2e} "
              f"({worst[0]}){'; discrete outputs differ: ' + ', '.join(sorted(discrete)[:6]) if discrete else ''}")
    print(f"largest relative difference {overall:.2e}; {bad} file(s) beyond the bound {args.bound:g} or with a "
          f"discrete difference")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
