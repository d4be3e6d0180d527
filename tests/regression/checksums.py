#!/usr/bin/env python3
"""Checksums of a tree of run outputs with timing and provenance stripped.

Usage: checksums.py OUTROOT            -> prints "<sha256>  <relative path>" for every file
       checksums.py OUTROOT --compare FILE -> compares with a stored list; exit 1 on any difference

Stripped before hashing (they change from run to run or machine to machine, never with the physics):
  JSON keys  wall_time_s, time_s, finished_utc, git_hash, version, threads, cpu_level, and any key containing 'seconds'
             (run.json, summary.json, result.json, stats.json, vcrit.json, breakup.json);
  run.log    'wall_time=<x> s';
  CSV        columns whose header is one of those keys or contains 'seconds' (sweep.csv), and rows naming one
             in a table of one row per quantity (ensemble_summary.csv; also wall_time_s_mean/_stderr);
  results.nc compared by content, not bytes (HDF5 files are not byte-stable): dimensions, variables (name,
             dimensions, type, attributes, values), global attributes (attributes in name order); the variables named like the
             stripped JSON keys and the provenance attributes agglo_version and git_hash are left out.
PNG files are skipped (matplotlib versions differ), and so are the ensemble journals journal.jsonl (a
work log: its lines are in the order the jobs finished, which depends on scheduling; the results it
holds are checked through vcrit.json, breakup.json and sweep.csv).
"""
import csv
import hashlib
import io
import json
import re
import sys
from pathlib import Path

DROP = {"wall_time_s", "time_s", "finished_utc", "git_hash", "version", "threads", "cpu_level"}


def dropped(key: str) -> bool:
    return (key in DROP or "seconds" in key or key.endswith(".wall_time_s")
            or key.startswith(("wall_time_s_", "time_s_")))  # an ensemble's wall_time_s_mean, _stderr


def strip_json(x):
    if isinstance(x, dict):
        return {k: strip_json(v) for k, v in x.items() if not dropped(k)}
    if isinstance(x, list):
        return [strip_json(v) for v in x]
    return x


NC_PROVENANCE = {"agglo_version", "git_hash"}


def normalised_netcdf(path: Path) -> bytes:
    import netCDF4  # Debian python3-netcdf4
    import numpy
    lines = []
    with netCDF4.Dataset(str(path)) as ds:
        ds.set_auto_mask(False)
        for name, dim in ds.dimensions.items():
            lines.append(f"dim {name} {len(dim)}")
        for key in sorted(ds.ncattrs()):
            if key not in NC_PROVENANCE:
                lines.append(f"attr {key} {ds.getncattr(key)!r}")
        for name, var in ds.variables.items():
            if dropped(name):
                continue
            attrs = {k: repr(var.getncattr(k)) for k in sorted(var.ncattrs())}
            values = numpy.ascontiguousarray(var[...]).tobytes()
            lines.append(f"var {name} {var.dimensions} {var.dtype} {attrs} {hashlib.sha256(values).hexdigest()}")
    return "\n".join(lines).encode()


def normalised(path: Path) -> bytes:
    if path.suffix == ".nc":
        return normalised_netcdf(path)
    data = path.read_bytes()
    if path.suffix == ".json":
        return json.dumps(strip_json(json.loads(data)), indent=1, sort_keys=True).encode()
    if path.name == "run.log":
        return re.sub(rb"wall_time=[0-9.eE+-]+ s", b"wall_time=<stripped>", data)
    if path.suffix == ".csv":
        rows = list(csv.reader(io.StringIO(data.decode())))
        if rows and rows[0] and rows[0][0] == "quantity":  # one row per quantity (ensemble_summary.csv)
            rows = [r for r in rows if not (r and dropped(r[0].strip()))]
            out = io.StringIO()
            csv.writer(out, lineterminator="\n").writerows(rows)
            return out.getvalue().encode()
        if rows:
            keep = [i for i, h in enumerate(rows[0]) if not dropped(h.strip())]
            if len(keep) != len(rows[0]):
                out = io.StringIO()
                csv.writer(out, lineterminator="\n").writerows([[r[i] for i in keep if i < len(r)] for r in rows])
                return out.getvalue().encode()
    return data


def checksums(root: Path) -> dict:
    out = {}
    for p in sorted(root.rglob("*")):
        if p.is_file() and p.suffix != ".png" and p.name != "journal.jsonl":
            out[str(p.relative_to(root))] = hashlib.sha256(normalised(p)).hexdigest()
    return out


def main() -> int:
    root = Path(sys.argv[1])
    sums = checksums(root)
    if len(sys.argv) == 2:
        for k, v in sums.items():
            print(f"{v}  {k}")
        return 0
    stored = {}
    for line in Path(sys.argv[3]).read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            h, name = line.split(None, 1)
            stored[name.strip()] = h
    bad = 0
    for name in sorted(set(stored) | set(sums)):
        if name not in sums:
            print(f"missing: {name}"); bad += 1
        elif name not in stored:
            print(f"new file: {name}"); bad += 1
        elif sums[name] != stored[name]:
            print(f"differs: {name}"); bad += 1
    print(f"{len(sums)} files checked, {bad} differences")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
