#!/usr/bin/env python3
"""Content keys for the function-size lint's cache (scripts/check_function_size.sh).

For each src/**/*.cpp given, prints "KEY PATH": KEY is the SHA-256 of the file, of every project
header it includes directly or indirectly (#include "agglo/..." resolved under src/), of the
clang-tidy version and of the check's configuration. A file whose key is in the cache was checked,
in exactly this content, by this clang-tidy, and had no function over the limit; any change to it
or to a header it sees gives a new key, so it is checked again.
Usage: function_size_keys.py ROOT CONFIG FILE.cpp ...
"""
import hashlib
import re
import subprocess
import sys
from pathlib import Path

INCLUDE = re.compile(r'^\s*#\s*include\s+"(agglo/[^"]+)"', re.M)


def headers(root, path, seen):
    """The project headers path includes, transitively (those under src/; generated ones skipped)."""
    for name in INCLUDE.findall(path.read_text(errors="replace")):
        h = root / "src" / name
        if h not in seen and h.is_file():
            seen.add(h)
            headers(root, h, seen)
    return seen


def main():
    root, config, files = Path(sys.argv[1]), sys.argv[2], sys.argv[3:]
    tool = subprocess.run(["clang-tidy", "--version"], capture_output=True, text=True).stdout
    for f in files:
        p = root / f
        h = hashlib.sha256((tool + config).encode())
        for dep in [p] + sorted(headers(root, p, set())):
            h.update(str(dep.relative_to(root)).encode() + b"\0" + dep.read_bytes())
        print(h.hexdigest(), f)


if __name__ == "__main__":
    main()
