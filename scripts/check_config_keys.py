#!/usr/bin/env python3
"""Check that every case-file key is declared once, in the settings tables.

Usage: check_config_keys.py AGGLO_EXECUTABLE SOURCE_DIR

1. Every key printed by `agglo config --list` must appear as a C++ string literal exactly once in
   src/ (its declaration in src/agglo/core/settings_*.hpp, or in the tables the engines declare beside
   the models they name: src/agglo/dem/contact/settings.*, src/agglo/acoustics/kernels/keys.*,
   src/agglo/electrostatics/keys.*). A key
   whose name is also a quoted value in the listing (the top-level key "seed" and the deprecated contact
   model name "seed") cannot be told apart from that value: it must appear at least once. The keys of
   the structure builder are declared once for several tables (settings::BuilderKeys): "<table>.<leaf>"
   for each table constructing one in settings_impact.hpp (`BuilderKeys builder{t, "<table>", ...}`) and
   each leaf of builder_text() in settings_catalogue.cpp (`key("<leaf>")`); they appear as no literal.
2. No string literal in src/ or apps/ outside the settings tables may contain a dotted key
   ("time.motion_dt" in a message, "projectile.speed=..." in an override): messages name keys
   through the setting objects (Setting::dotted()).
3. No call of the config reader (ConfigSection::number, integer, ..., section, tables, has) in
   src/ or apps/ may pass a literal key: values are read through the setting objects.

src/agglo/io/ and src/agglo/writers/ are excluded: they hold output column names, which may coincide with key
names.
Every offender is printed as file:line; the exit status is 1 if there is any.
"""
import pathlib
import re
import subprocess
import sys

LITERAL = re.compile(r'"((?:[^"\\\n]|\\.)*)"')
READER_CALL = re.compile(r'\.(number|integer|boolean|string|choice|numbers|vec3|section|tables|has)\(\s*"')
TABLES = re.compile(r"src/agglo/(core/settings_[a-z]+\.hpp|dem/contact/settings\.[ch]pp|acoustics/kernels/keys\.[ch]pp|electrostatics/keys\.[ch]pp)$")


def listed_keys(agglo):
    out = subprocess.run([agglo, "config", "--list"], check=True, capture_output=True, text=True).stdout
    keys = []
    for line in out.splitlines():
        if line.startswith("  ") and line.split()[0] != "key":
            keys.append(line.split()[0])
    values = set(re.findall(r'"([^"]*)"', out))  # choice values and string defaults
    return keys, values


def code_lines(path):
    """(line number, code without // comments) of a C++ file."""
    for n, line in enumerate(path.read_text().splitlines(), 1):
        code, in_str, k = [], False, 0
        while k < len(line):
            c = line[k]
            if in_str and c == "\\":
                code.append(line[k:k + 2])
                k += 2
                continue
            if c == '"':
                in_str = not in_str
            elif not in_str and line.startswith("//", k):
                break
            code.append(c)
            k += 1
        yield n, "".join(code)


def builder_keys(root):
    """The keys settings::BuilderKeys declares: every table that builds one times every leaf."""
    tables = re.findall(r'BuilderKeys builder\{t, "([a-z_]+)"', (root / "src/agglo/core/settings_impact.hpp").read_text())
    leaves = re.findall(r'key\("([a-z_]+)"\)', (root / "src/agglo/core/settings_catalogue.cpp").read_text())
    return {f"{t}.{leaf}" for t in tables for leaf in leaves}


def sources(root, folder):
    for p in sorted((root / folder).rglob("*")):
        rel = p.relative_to(root).as_posix()
        if p.suffix in (".cpp", ".hpp") and not rel.startswith(("src/agglo/io/", "src/agglo/writers/")):
            yield p, rel


def main():
    agglo, root = sys.argv[1], pathlib.Path(sys.argv[2])
    keys, values = listed_keys(agglo)
    dotted = sorted((k for k in keys if "." in k), key=len, reverse=True)
    dotted_re = re.compile(r"(?<![\w.])(" + "|".join(re.escape(k) for k in dotted) + r")(?![\w])")
    where = {k: [] for k in keys}
    offenders = []
    for folder in ("src", "apps"):
        for path, rel in sources(root, folder):
            in_tables = bool(TABLES.search(rel))
            for n, code in code_lines(path):
                for m in LITERAL.finditer(code):
                    text = m.group(1)
                    if folder == "src" and text in where:
                        where[text].append(f"{rel}:{n}")
                    hit = dotted_re.search(text)
                    if hit and not in_tables:
                        offenders.append(f"{rel}:{n}: literal names the key '{hit.group(1)}': \"{text}\"")
                if READER_CALL.search(code):
                    offenders.append(f"{rel}:{n}: config read with a literal key: {code.strip()}")
    generated = builder_keys(root)
    for key in keys:
        n = len(where[key])
        if key in generated:
            if n:
                offenders.append(f"key '{key}' (declared by BuilderKeys) also appears as a literal: {', '.join(where[key])}")
            continue
        if n == 0 or (n > 1 and key not in values):
            places = ", ".join(where[key]) or "nowhere"
            offenders.append(f"key '{key}' appears {n} times as a literal in src/ (expected once): {places}")
    for o in offenders:
        print(o)
    print(f"check_config_keys: {len(keys)} keys, {len(offenders)} offenders")
    return 1 if offenders else 0


if __name__ == "__main__":
    sys.exit(main())
