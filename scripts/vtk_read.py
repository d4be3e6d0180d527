#!/usr/bin/env python3
"""Independent reader of agglo's binary VTK XML files (docs/outputs.md): appended raw data, UInt64
block headers, little-endian. read(path) -> {"attrs": Piece attributes, "<Section>/<Name>": array
of shape (tuples, components)}; any inconsistency (bad header, offset or byte count outside the
block, a block that does not match its tuple count, trailing garbage, a truncated file) raises
ValueError. As a script: read every file given and print its arrays' shapes; exit 1 on a bad file."""
import re
import sys

import numpy as np

TYPES = {"Float64": "<f8", "Int64": "<i8", "Int32": "<i4", "UInt8": "u1"}
TAIL = b"\n  </AppendedData>\n</VTKFile>\n"


def read(path):
    raw = open(path, "rb").read()
    mark = raw.find(b'<AppendedData encoding="raw">')
    if mark < 0:
        raise ValueError(f"{path}: no raw AppendedData")
    start = raw.find(b"_", mark) + 1
    xml = raw[:mark].decode("ascii")
    head = re.search(r"<VTKFile ([^>]*)>", xml)
    if not head or 'byte_order="LittleEndian"' not in head.group(1) or 'header_type="UInt64"' not in head.group(1):
        raise ValueError(f"{path}: header {head.group(0) if head else None}")
    dataset = re.search(r'type="(\w+)"', head.group(1)).group(1)
    piece = dict(re.findall(r'(\w+)="(\d+)"', re.search(r"<Piece ([^>]*)>", xml).group(1)))
    if not raw.endswith(TAIL):
        raise ValueError(f"{path}: file does not end with the AppendedData closing tags (truncated?)")
    block = raw[start:len(raw) - len(TAIL)]
    out = {"attrs": {k: int(v) for k, v in piece.items()}, "dataset": dataset}
    end = 0
    for section, body in re.findall(r"<(\w+)[^>/]*>\n((?:\s*<DataArray [^>]*/>\n)*)\s*</\1>", xml):
        for attrs in re.findall(r"<DataArray ([^>]*)/>", body):
            a = dict(re.findall(r'(\w+)="([^"]*)"', attrs))
            if a["format"] != "appended":
                raise ValueError(f"{path}: {a['Name']} is {a['format']}")
            off, comps, dt = int(a["offset"]), int(a["NumberOfComponents"]), np.dtype(TYPES[a["type"]])
            if off != end or off + 8 > len(block):
                raise ValueError(f"{path}: {a['Name']} offset {off} (expected {end}, block {len(block)} bytes)")
            n = int(np.frombuffer(block, "<u8", 1, off)[0])
            if off + 8 + n > len(block) or n % (dt.itemsize * comps):
                raise ValueError(f"{path}: {a['Name']} has {n} bytes, {len(block) - off - 8} left")
            out[f"{section}/{a['Name']}"] = np.frombuffer(block, dt, n // dt.itemsize, off + 8).reshape(-1, comps)
            end = off + 8 + n
    if end != len(block):
        raise ValueError(f"{path}: {len(block) - end} bytes after the last array")
    return out


if __name__ == "__main__":
    bad = 0
    for p in sys.argv[1:]:
        try:
            d = read(p)
            print(p, {k: v.shape for k, v in d.items() if k not in ("attrs", "dataset")})
        except (ValueError, KeyError, AttributeError) as e:
            print(f"bad VTK file: {e}", file=sys.stderr)
            bad = 1
    sys.exit(bad)
