#!/usr/bin/python3
"""Black-box fuzz harness of the agglo command line (stdlib only; docs/fuzzing.md).

Each execution takes one shipped case (cases/*.toml) and the command it is meant for, applies the
shortening overrides of the output regression runner (tests/regression/run_cases.sh), then mutates
the case file (numbers, types, keys, TOML syntax, control characters, truncation) and/or the command
line (--set, --param/--values of `agglo sweep`, --threads, --out, options) and runs
`agglo -q --no-plots COMMAND ...` in a temporary folder that is removed afterwards.

A finding is: a crash (killed by a signal, or an exit code other than 0, 2 and 3; exit 1 "internal
error" included), exit 0 with a non-finite number in an output CSV/JSON file, exit 2 or 3 with a
message on stderr that is not exactly one line (control characters and Unicode line separators
included), or a hang (no exit within --timeout seconds).

Deterministic: mutant I of seed S depends only on (S, I) and on the repository's cases and
docs/config.md, never on timing; `--only I` re-runs one mutant and prints its reproducer.

Usage: fuzz_cli.py AGGLO_EXECUTABLE SOURCE_DIR [--seed S] [--execs N] [--jobs J] [--timeout T]
       [--only I] [--keep DIR] [--min-engine FRACTION] [--verbose]
The execution count defaults to $AGGLO_FUZZ_EXECS, else 400. Exit status: 0 no finding, 1 findings
(or fewer mutants than --min-engine reached an engine: a hollow run), 2 bad usage.
"""
import argparse
import difflib
import json
import math
import os
import random
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

# ---------------------------------------------------------------------------------------------
# Base runs: the command each shipped case is meant for, shortened like run_cases.sh and further
# (charged runs, acoustic samples), so that one unmutated execution takes at most a few seconds.
# Every DEM run also relaxes a charged agglomerate for at most 1e-5 s and extends an undecided run once.
DEM_CHEAP = ["time.relax_time=1e-5", "time.max_extensions=1", "time.extension=2e-5"]
SHORT_DEM = ["time.after_contact=2e-4", "output.snapshot_interval=5e-5"] + DEM_CHEAP
SHORT_CHARGED = ["time.after_contact=1e-5", "output.snapshot_interval=1e-5", "projectile.gap_radii=0.1"] + DEM_CHEAP
VCRIT = ["vcrit.scan_points=4", "vcrit.v_min=0.05", "vcrit.v_max=0.8", "vcrit.tolerance=0.03"]
BREAKUP = ["breakup.speeds=[0.12,0.4]", "breakup.samples=2"]
SHORT_ACOUSTIC = ["time.end=0.005", "output.snapshot_times=[0.0]", "output.psd_times=[0.0,0.005]",
                  "population.0.samples=500", "population.1.samples=20"]

# Budgets of the pre-run checks (exceeded: exit 2 before any work): plain integers (bytes for memory
# and output); a value already in the environment wins.
# Steps are particle-steps (DEM), sample-steps (DSMC) or the solver's unit (electrostatics); the largest
# base run needs about 1.8e8 (electrostatics_tetrahedron).
BUDGET_ENV = {"AGGLO_MAX_STEPS": "300000000", "AGGLO_MAX_MEMORY": "1000000000", "AGGLO_MAX_OUTPUT": "200000000"}
CHILD_MEMORY_LIMIT = 2 << 30  # address-space limit of each agglo process (protects the machine)
CHILD_FILE_LIMIT = 2 << 30    # largest file an agglo process may write

NUMERIC_SPECIALS = [
    "0", "-0.0", "-1", "1e-300", "1e300", "-1e300", "nan", "-nan", "inf", "-inf", "+inf", "5e-324",
    "1.7976931348623157e308", "1e-17", "1e-6", "0.5", "2147483647", "2147483648", "-2147483649",
    "4294967296", "9223372036854775807", "9223372036854775808", "-9223372036854775809",
    "100000000000000000000000000000", "65536", "100000", "46341", "1e9", "3", "1_000", "0x7fffffff",
    "0o777", "0b101", "1e", ".5", "5.", "1e400", "0.1e-400",
]
HUGE_INTS = ["65536", "100000", "46341", "1000000", "2147483647", "2147483648", "4294967297",
             "9223372036854775807", "1e9"]
TYPE_SWAPS = [
    '"abc"', '""', '"1.0"', '"nan"', "true", "false", "[]", "[1, 2, 3]", '[1, "a"]', "[[1], [2]]",
    "{a = 1}", "{}", "1979-05-27T07:32:00Z", "07:32:00", "'literal'", '"\\u2028"', '"a\\nb"',
    '"\\u0000"', '"' + "x" * 5000 + '"', "[" + ",".join(["1e300"] * 3) + "]",
]
SCALE_FACTORS = [0.0, -1.0, 1e-300, 1e300, 1e-6, 1e6, 1e3, 1e-3, 0.5, 2.0, 10.0, 1.0000001]
BAD_KEYS = [
    " ", "\t", "  ", " \t ", "\n", ".", "..", "a..b", ".material.density", "material.density.",
    "material..density", "material. density", "material .density", "material.density ", " material.density",
    "material.\tdensity", "material.density.x", "name.x", "population.99.diameter", "population.-1.diameter",
    "population.x.diameter", "population.1e0.diameter", "population.18446744073709551616.diameter",
    "particles.0.radius.x", "time.end.end", "bogus", "bogus.key", "mat\nerial.density", "material.densit\u00e9",
    "material.density\u2028", "\u00a0", "\ufeffmaterial.density", "x" * 3000, "material." + "y" * 3000,
    "a.b.c.d.e.f.g.h", "domain.cells_x.0", "output.psd_times.0", "output.psd_times.9",
    "breakup.speeds.-1", "\"material\".\"density\"", "material.\"density\"",
]
WHITESPACE_KEYS = [" ", "\t", "  ", " \t ", "\u00a0", "\r", "\v"]
BAD_SET_FORMS = [
    "=5", "==", "=", "", " = ", "material.density", "material.density==1", "material.density=",
    "material.density= ", "material.density=2500\nbogus=1", "material.density=2500\n", "material.density=\"",
    "material.density=[1,", "material.density={", "material.density=2500 # c", "material.density=2500 extra",
    "material.density.=2500", "time.end=1\r", "name=\"a\u2028b\"", "name=\"\\u001b[31m\"",
    "output.psd_times=[0.0,]", "output.psd_times=[,]", "output.psd_times=[" + ",".join(["0.001"] * 50) + "]",
]
THREADS = ["0", "1", "2", "3", "4", "7", "16", "64", "-1", "-0", "+2", " 2", "2 ", "2.5", "1e3", "abc", "",
           "100001", "99999999999999999999", "0x10", "\u0662", "2\n", "１"]
SWEEP_VALUES = [
    "10e-6,30e-6", "10e-6,", ",", "", " ", "10e-6,,30e-6", "nan", "inf", "1e300", "-1", "0", "a,b",
    "10e-6\n30e-6", "10e-6;30e-6", "[1,2]", "\"x\"", "1e-300,1e300", "true", "10e-6 ,30e-6", "\u2028",
    "20e-6,20e-6", "1,2,3,4",
]
CONTROL_INSERTS = [b"\x00", b"\x01", b"\x1b[31m", b"\x7f", b"\r", b"\t", b"\x0b", b"\x0c", b"\r\n",
                   "\u2028".encode(), "\u2029".encode(), "\u0085".encode(), "\ufeff".encode(),
                   "\u202e".encode(), "\U0001F600".encode(), b"\xff\xfe", b"\xed\xa0\x80", b"\xc3",
                   b"\xe2\x80", "é".encode(), b"\\", b"\\u0000", b"\"\"\"", b"'''"]
SYNTAX_INSERTS = ["[", "]", "[[", "]]", "=", "\"", "'", "{", "}", ",", ".", "#", "\n", " = ", "[x]\n",
                  "[material]\n", "[[population]]\n", "[[particles]]\n", "a = 1\n", "= 1\n", "0 = 0\n"]


class Case:
    def __init__(self, command, stem, sets, extra=()):
        self.command, self.stem, self.sets, self.extra = command, stem, list(sets), list(extra)


def base_runs():
    """Every (command, case, shortening) the regression runner uses, plus cross-command sweeps."""
    runs = []
    neutral_k1 = ["seed000_neutral_square", "seed000_neutral_tetrahedron", "seed000_charged_square_k1",
                  "seed000_charged_tetrahedron_k1"]
    charged = ["seed000_charged_square_k2p5", "seed000_charged_tetrahedron_k2p5",
               "seed000_charged_square_k15", "seed000_charged_tetrahedron_k15"]
    for s in neutral_k1:
        runs.append(Case("collide", s, SHORT_DEM))
    for s in charged:
        runs.append(Case("collide", s, SHORT_CHARGED))
    for s in ["seed000_neutral_tetrahedron", "seed000_charged_tetrahedron_k1"]:
        runs.append(Case("vcrit", s, SHORT_DEM + VCRIT))
    for s in ["seed000_neutral_square", "seed000_charged_square_k1"]:
        runs.append(Case("breakup", s, SHORT_DEM + BREAKUP))
    for s in ["electrostatics_two_spheres", "electrostatics_tetrahedron"]:
        runs.append(Case("electrostatics", s, []))
    for s in ["seed002_baseline", "seed002_droplet_concentration", "seed002_droplet_diameter",
              "seed002_integrator_check", "seed002_validation"]:
        runs.append(Case("acoustic", s, SHORT_ACOUSTIC))
    runs.append(Case("sweep", "seed002_baseline", SHORT_ACOUSTIC,
                     ["--param", "population.1.diameter", "--values", "10e-6,30e-6"]))
    runs.append(Case("sweep", "seed000_neutral_square", SHORT_DEM,
                     ["--command", "collide", "--param", "projectile.speed", "--values", "0.1,0.3"]))
    runs.append(Case("sweep", "electrostatics_two_spheres", [],
                     ["--command", "electrostatics", "--param", "electrostatics.min_gap", "--values", "0,0.01"]))
    return runs


COMMAND_FAMILY = {"collide": "impact", "vcrit": "impact", "breakup": "impact", "electrostatics": "impact",
                  "acoustic": "acoustic", "sweep": None}


def load_schema(source_dir):
    """Declared keys from docs/config.md: {command: [(dotted key, type, choices)]}."""
    schema = {}
    path = os.path.join(source_dir, "docs", "config.md")
    try:
        text = open(path, encoding="utf-8").read()
    except OSError:
        return schema
    readers = []
    for line in text.splitlines():
        m = re.search(r"Read by: (.*)\.$", line)
        if m:
            readers = [r.strip() for r in m.group(1).split(",")]
            continue
        m = re.match(r"\| `([^`]+)` \| ([^|]*) \|[^|]*\|[^|]*\| ([^|]*) \|", line)
        if m:
            key, typ, rng = m.group(1), m.group(2).strip(), m.group(3)
            choices = re.findall(r'"([^"]*)"', rng) if typ == "choice" else []
            for r in readers:
                schema.setdefault(r, []).append((key, typ, choices))
    return schema


# ---------------------------------------------------------------------------------------------
# Mutations. A mutant is (case bytes, --set list, other args, --out choice, threads).
class Mutant:
    def __init__(self, case, text):
        self.case = case
        self.command = case.command
        self.text = text                 # case-file bytes
        self.sets = list(case.sets)      # base shortening overrides, then mutated ones
        self.extra = list(case.extra)    # command-specific arguments (sweep --param/--values ...)
        self.threads = "2"
        self.out = "out"                 # relative to the execution folder, or a special path
        self.args_tail = []              # further options appended as is
        self.case_arg = None             # replaces the case path when set
        self.notes = []
        # Oracles of the targeted classes (ISSUE23_CLASSES), checked besides the general ones:
        self.expect_rc = None            # exit codes the mutant must end with (it is invalid by construction)
        self.must_name = None            # text an exit 2 or 3 message must hold (the cause of the failure)
        self.max_message = None          # longest message allowed [characters]
        self.checkpoint = None           # "fifo", "zero" or "big": checkpoint.bin of a --resume folder


def key_of_line(line):
    m = re.match(rb"\s*([A-Za-z0-9_\-\"'.]+)\s*=", line)
    return m.group(1).decode("latin-1").strip() if m else None


def section_lines(text):
    """[(line index, dotted key)] of `key = value` lines with their section prefix."""
    out, section = [], ""
    for i, line in enumerate(text.split(b"\n")):
        s = line.strip()
        if s.startswith(b"[["):
            section = s.strip(b"[] ").decode("latin-1")
        elif s.startswith(b"["):
            section = s.strip(b"[] ").decode("latin-1")
        else:
            k = key_of_line(line)
            if k:
                out.append((i, f"{section}.{k}" if section else k))
    return out


def numeric_value(rng, old=None):
    if old is not None and rng.random() < 0.3:
        try:
            v = float(old.replace("_", ""))
            return repr(v * rng.choice(SCALE_FACTORS))
        except ValueError:
            pass
    return rng.choice(NUMERIC_SPECIALS)


def nasty_value(rng, typ="real", choices=(), old=None):
    r = rng.random()
    if typ == "integer" and r < 0.45:
        return rng.choice(HUGE_INTS + ["0", "-1", "1.5", "nan"])
    if typ == "choice" and r < 0.3:
        return rng.choice(['"' + c.upper() + '"' for c in choices] + ['"' + c + ' "' for c in choices] + ['""'])
    if typ in ("real list", "vec3") and r < 0.4:
        n = rng.choice([0, 1, 2, 3, 4, 7])
        return "[" + ", ".join(numeric_value(rng) for _ in range(n)) + "]"
    if r < 0.75:
        return numeric_value(rng, old)
    return rng.choice(TYPE_SWAPS)


def drop_base_set(m, key):
    m.sets = [s for s in m.sets if s.split("=", 1)[0] != key]


def mut_file_value(rng, m, schema):
    lines = m.text.split(b"\n")
    cand = section_lines(m.text)
    if not cand:
        return mut_file_bytes(rng, m, schema)
    i, dotted = rng.choice(cand)
    line = lines[i]
    eq = line.index(b"=")
    old = line[eq + 1:].split(b"#")[0].strip().decode("latin-1")
    typ = next((t for k, t, _ in schema.get(m.command, []) if k == re.sub(r"\.\d+\.", ".", dotted)), "real")
    lines[i] = line[:eq + 1] + b" " + nasty_value(rng, typ, (), old).encode()
    m.text = b"\n".join(lines)
    drop_base_set(m, dotted)
    m.notes.append(f"file {dotted}")


def mut_file_lines(rng, m, schema):
    lines = m.text.split(b"\n")
    if not lines:
        return
    op = rng.choice(["delete", "duplicate", "swap", "dup_block", "unknown", "dup_header"])
    i = rng.randrange(len(lines))
    if op == "delete":
        del lines[i]
    elif op == "duplicate":
        lines.insert(i, lines[i])
    elif op == "swap":
        j = rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
    elif op == "dup_block":  # a [[particles]] or [[population]] block, or any section, copied once more
        heads = [k for k, l in enumerate(lines) if l.strip().startswith(b"[")]
        if heads:
            a = rng.choice(heads)
            b = next((k for k in heads if k > a), len(lines))
            lines += [b""] + lines[a:b]
    elif op == "unknown":
        lines.insert(i, rng.choice([b"bogus = 1", b"x.y = 2", b"\"quoted key\" = 3", b"dt = 1e-9"]))
    else:
        heads = [l for l in lines if l.strip().startswith(b"[")]
        if heads:
            lines.insert(i, rng.choice(heads))
    m.text = b"\n".join(lines)
    m.notes.append(f"file lines {op}")


def mut_file_bytes(rng, m, schema):
    t = m.text
    op = rng.choice(["control", "control", "syntax", "delete", "truncate", "empty", "repeat"])
    pos = rng.randrange(len(t) + 1)
    if op == "control":
        t = t[:pos] + rng.choice(CONTROL_INSERTS) + t[pos:]
    elif op == "syntax":
        t = t[:pos] + rng.choice(SYNTAX_INSERTS).encode() + t[pos:]
    elif op == "delete":
        t = t[:pos] + t[pos + rng.randint(1, 8):]
    elif op == "truncate":
        t = t[:pos]
    elif op == "empty":
        t = b"" if rng.random() < 0.7 else rng.choice([b"\n", b"# only a comment\n", b"\xef\xbb\xbf"])
    else:
        a = rng.randrange(len(t) + 1)
        t = t[:pos] + t[a:a + rng.randint(1, 200)] + t[pos:]
    m.text = t
    m.notes.append(f"file bytes {op}")


def schema_key(rng, m, schema):
    keys = schema.get(m.command, [])
    if m.command == "sweep":
        keys = schema.get("acoustic" if "population" in " ".join(m.extra) else "collide", [])
    if not keys:
        return "material.density", "real", []
    key, typ, choices = rng.choice(keys)
    for arr in ("population", "particles"):
        if key.startswith(arr + "."):
            idx = rng.choice(["0", "0", "1", "1", "2", "-1", "99"])
            key = f"{arr}.{idx}.{key[len(arr) + 1:]}"
    return key, typ, choices


def mut_set_schema(rng, m, schema):
    key, typ, choices = schema_key(rng, m, schema)
    drop_base_set(m, key)
    m.sets.append(f"{key}={nasty_value(rng, typ, choices)}")
    m.notes.append(f"--set {key}")


CELL_COUNTS = ["65536", "65536", "65536", "1048576", "16777216", "46341", "100000", "2147483647"]


def acoustic(m):
    return m.command == "acoustic" or (m.command == "sweep" and m.case.command == "sweep"
                                       and m.case.stem.startswith("seed002"))


def mut_set_cells(rng, m, schema):
    """Integer sizes set huge; for `acoustic`, cell counts on one to three axes (products beyond
    2^31) with the box enlarged so that the cells stay larger than the particles."""
    if not acoustic(m) or rng.random() < 0.2:
        keys = [k for k, t, _ in schema.get(m.command, []) if t == "integer"] or ["seed"]
        key = rng.choice(keys)
        drop_base_set(m, key)
        m.sets.append(f"{key}={rng.choice(HUGE_INTS)}")
        m.notes.append(f"--set {key} huge")
        return
    axes = rng.choice([["y", "z"], ["y", "z"], ["y", "z"], ["x", "y", "z"], ["y"], ["z"], ["x"]])
    for a in axes:
        m.sets.append(f"domain.cells_{a}={rng.choice(CELL_COUNTS)}")
    if rng.random() < 0.85:
        size = rng.choice(["1e3", "1e4", "1e6", "1e6", "1e300"])
        m.sets += [f"domain.length_y={size}", f"domain.length_z={size}"]
    m.notes.append("--set huge cell counts")


def mut_file_scale(rng, m, schema):
    """A number of the case file scaled by a modest factor: mostly valid, so the engines run."""
    lines = m.text.split(b"\n")
    cand = [(i, d) for i, d in section_lines(m.text)
            if re.match(rb"\s*[A-Za-z_]+\s*=\s*[-+0-9.]", lines[i])]
    if not cand:
        return mut_file_value(rng, m, schema)
    i, dotted = rng.choice(cand)
    eq = lines[i].index(b"=")
    old = lines[i][eq + 1:].split(b"#")[0].strip()
    try:
        v = float(old.replace(b"_", b""))
    except ValueError:
        return mut_file_value(rng, m, schema)
    f = rng.choice([0.1, 0.5, 0.8, 0.9, 1.1, 1.25, 2.0, 3.0, 10.0, -1.0])
    new = str(int(v * f)) if re.fullmatch(rb"[-+]?\d+", old) else repr(v * f)
    base = [k for k, s in enumerate(m.sets) if s.split("=", 1)[0] == dotted]
    if base:  # a shortened key: scale the shortened value, so that the run stays short
        k = base[0]
        try:
            m.sets[k] = f"{dotted}={float(m.sets[k].split('=', 1)[1]) * f!r}"
        except ValueError:
            pass
    else:
        lines[i] = lines[i][:eq + 1] + b" " + new.encode()
        m.text = b"\n".join(lines)
    m.notes.append(f"file {dotted} x{f:g}")


def mut_set_badkey(rng, m, schema):
    r = rng.random()
    if r < 0.35:
        key = rng.choice(WHITESPACE_KEYS)
        m.sets.append(f"{key}={rng.choice(['5', '1', 'x', ''])}")
    elif r < 0.75:
        m.sets.append(rng.choice(BAD_KEYS) + "=" + rng.choice(["5", "2500", "[1]", "true", '"x"']))
    else:
        m.sets.append(rng.choice(BAD_SET_FORMS))
    m.notes.append("--set bad form")


def mut_threads(rng, m, schema):
    m.threads = rng.choice(THREADS)
    m.notes.append("--threads")


def mut_out(rng, m, schema):
    m.out = rng.choice(["/proc/agglo_fuzz", "/proc/self/agglo_fuzz/x", "/sys/agglo_fuzz", "@file/x", "@file",
                        "/dev/null", "/dev/null/x", "", "@long", "@newline", "@nonempty", "@ro", "-", ".",
                        "@dots", "@unicode"])
    m.notes.append("--out")


def mut_options(rng, m, schema):
    op = rng.choice(["unknown", "dup_out", "positional", "no_case", "case_dir", "case_missing", "case_dev",
                     "help_mix", "no_set_value", "speed", "resume", "empty_set", "format", "checkpoint"])
    if op == "unknown":
        m.args_tail += [rng.choice(["--bogus", "-x", "--set-", "--threads=", "---", "--out=", "-j"])]
    elif op == "dup_out":
        m.args_tail += ["--out", "out2"]
    elif op == "positional":
        m.args_tail += [rng.choice(["extra.toml", "", "-", "\u2028"])]
    elif op == "no_case":
        m.case_arg = ""
    elif op == "case_dir":
        m.case_arg = "."
    elif op == "case_missing":
        m.case_arg = "missing.toml"
    elif op == "case_dev":
        m.case_arg = rng.choice(["/dev/null", "/dev/zero", "/proc/self/status"])
    elif op == "help_mix":
        m.args_tail += [rng.choice(["--help", "-h", "--version"])]
    elif op == "no_set_value":
        m.args_tail += ["--set"]
    elif op == "speed":
        m.args_tail += ["--speed", nasty_value(rng).strip('"')]
    elif op == "resume":
        m.args_tail += ["--resume"]
    elif op == "format":
        m.args_tail += ["--format", rng.choice(["csv", "netcdf", "csv,netcdf", "netcdf,csv", "", ",", "csv,",
                                                "xml", "CSV", "csv,csv"])]
    elif op == "checkpoint":  # an option of collide, acoustic and sectional only; refused elsewhere
        m.args_tail += ["--checkpoint", rng.choice(["0", "-1", "nan", "inf", "0.5", "x", "", "1e300"])]
    else:
        m.sets.append("")
    m.notes.append(f"option {op}")


def mut_sweep(rng, m, schema):
    if m.command != "sweep":
        return mut_set_schema(rng, m, schema)
    op = rng.choice(["param_ws", "param_key", "values", "values", "count", "command", "param_dup"])
    ex = m.extra
    if op == "param_ws":
        ex[ex.index("--param") + 1] = rng.choice(WHITESPACE_KEYS + ["", "."])
    elif op == "param_key":
        ex[ex.index("--param") + 1] = rng.choice([schema_key(rng, m, schema)[0], rng.choice(BAD_KEYS)])
    elif op == "values":
        ex[ex.index("--values") + 1] = rng.choice(SWEEP_VALUES)
    elif op == "count":
        ex += rng.choice([["--param", "seed"], ["--values", "1,2"], ["--param", "time.end", "--values", "1e300"]])
    elif op == "command":
        if "--command" in ex:
            ex[ex.index("--command") + 1] = rng.choice(["acoustic", "collide", "vcrit", "breakup",
                                                        "electrostatics", "sweep", "bogus", "", "config"])
        else:
            ex += ["--command", rng.choice(["collide", "electrostatics", "sweep", "bogus", ""])]
    else:
        p = ex[ex.index("--param") + 1]
        ex += ["--param", p, "--values", ex[ex.index("--values") + 1]]
    m.notes.append(f"sweep {op}")


# Weights: file mutations and command-line mutations about evenly; a few cheap, targeted operators
# (whitespace keys, huge integers) are frequent enough that a CI-sized run meets each of them.
OPERATORS = [(mut_file_value, 12), (mut_file_scale, 12), (mut_file_lines, 6), (mut_file_bytes, 8),
             (mut_set_schema, 20), (mut_set_cells, 6), (mut_set_badkey, 8), (mut_threads, 4), (mut_out, 5),
             (mut_options, 4), (mut_sweep, 8)]


# ---------------------------------------------------------------------------------------------
# Targeted classes (issue 23): the inputs behind its items, each with an oracle of its own, since the
# defects they found were slow refusals, silent acceptance or misleading words rather than crashes.
# A fraction ISSUE23_SHARE of the mutants (drawn from a stream of their own, so that every other mutant
# stays what it was) is one of these classes alone, in place of the ordinary mutant of that index.
ISSUE23_SHARE = 0.06
SLOW_REFUSAL_S = 20.0  # an exit 2 after this long did work before its checks (45 s for --seeds 100000)
CALIBRATION = "calibrate_seed000_tetrahedron"
HUGE_SEEDS = ["100000", "1000000000", "18446744073709551616", "1e9", "99999999999", "-1", "0", "2.5", ""]
ARRAY_VALUES = ["[{}]", "[[{}]]", "[]", "[{}, {}]", "[{}, 0.0, 0.0]"]
LIST_TARGET = ("\n[[particles]]\nposition = [0.0, 0.0, 0.0]\nradius = 10e-6\n"
               "\n[[particles]]\nposition = [0.0, 0.0, 1.9999e-5]\nradius = 10e-6\n"
               "\n[[particles]]\nposition = [0.0, 1.9999e-5, 0.0]\nradius = 10e-6\n"
               "\n[[particles]]\nposition = [0.0, 0.0, {}]\nradius = 10e-6\n")  # the last one alone


def issue23_seeds(rng, m, source_dir):
    """Huge or malformed --seeds (acoustic --seeds 1e9 planned every member before the budget check)."""
    m.args_tail += ["--seeds", rng.choice(HUGE_SEEDS)]
    m.notes.append("issue23 --seeds")


def issue23_array(rng, m, source_dir, schema):
    """A NumPy-like array for a scalar key (np.array([1.5]) became 1 through Case.set): refused."""
    keys = [(k, t) for k, t, _ in schema.get(m.command, []) if t in ("real", "integer", "boolean")]
    key, typ = rng.choice(keys) if keys else ("material.density", "real")
    v = rng.choice(["1.5", "3.7", "1", "0.5", "2500"])
    m.sets.append(f"{key}={rng.choice(ARRAY_VALUES).format(v, v)}")
    m.expect_rc = {2}
    m.notes.append(f"issue23 array --set {key}")


def issue23_long_key(rng, m, source_dir):
    """An over-long unknown key in the case file (a 1 MB key was echoed whole in the error line)."""
    n = rng.choice([1000, 100000, 1000000])
    m.text = m.text + b"\n" + (b"k" * n) + b" = 1\n"
    m.expect_rc, m.max_message = {2}, 2000
    m.notes.append(f"issue23 key of {n} bytes")


def issue23_checkpoint(rng, m, source_dir):
    """--resume into a folder whose checkpoint.bin is a FIFO, /dev/zero or larger than the memory budget
    (the FIFO blocked for ever, /dev/zero grew to 1.4 GB): refused in one line."""
    if m.command not in ("collide", "acoustic"):
        return issue23_seeds(rng, m, source_dir)
    m.checkpoint = rng.choice(["fifo", "zero", "big"])
    m.out = "@checkpoint"
    m.args_tail += ["--resume"]
    m.expect_rc = {2}
    m.notes.append(f"issue23 checkpoint {m.checkpoint}")


def issue23_calibrate(rng, m, source_dir):
    """agglo calibrate --dry-run with the same [[parameter]] key twice, an integer key, or a grid beyond
    the step budget (all three were accepted: two best values for one key, a best scan_points of 5.4,
    and "0 steps"). Its target cases are named by absolute path (the case is copied elsewhere)."""
    with open(os.path.join(source_dir, "cases", CALIBRATION + ".toml"), "rb") as f:
        text = f.read()
    cases = os.path.join(source_dir, "cases").encode()
    text = re.sub(rb'(?m)^case = "', b'case = "' + cases + b"/", text)
    m.case, m.command, m.extra, m.sets = Case("calibrate", CALIBRATION, []), "calibrate", [], []
    op = rng.choice(["duplicate", "integer", "grid"])
    if op == "duplicate":  # the second parameter (material.restitution) fits the first one's key again
        m.sets = ['parameter.1.key="material.youngs_modulus"', "parameter.1.lower=1e9", "parameter.1.upper=1e10"]
        m.must_name = "is also the key of [[parameter]] 0"
    elif op == "integer":
        key = rng.choice(["vcrit.scan_points", "time.max_extensions", "breakup.samples", "vcrit.points_per_round"])
        m.sets = [f"parameter.1.key={json.dumps(key)}", "parameter.1.lower=4", "parameter.1.upper=12"]
        m.must_name = "is a key of type integer"
    else:
        m.sets = ["calibrate.grid_points=101", "calibrate.refine_points=101",
                  f"calibrate.refine_rounds={rng.choice([3, 10])}"]
        m.must_name = "step budget"
    m.text = text
    m.args_tail += ["--dry-run"]
    m.expect_rc = {2}
    m.notes.append(f"issue23 calibrate {op}")


def issue23_isolated(rng, m, source_dir):
    """A list agglomerate with a primary that touches nothing: an error (exit 3, naming it), never an
    outcome (it ended "undecided", exit 0)."""
    stem = rng.choice(["seed000_neutral_tetrahedron", "seed000_neutral_square"])
    with open(os.path.join(source_dir, "cases", stem + ".toml"), "rb") as f:
        text = f.read()
    text = re.sub(rb'(?m)^shape = "\w+"', b'shape = "list"', text)
    text = re.sub(rb"(?m)^orientation = .*$", b"", text)
    far = rng.choice(["1e-3", "5e-5", "-2e-4"])
    m.case = Case(rng.choice(["collide", "vcrit", "breakup"]), stem, SHORT_DEM)
    m.command = m.case.command
    m.sets = SHORT_DEM + {"vcrit": VCRIT, "breakup": BREAKUP}.get(m.command, [])
    m.extra = []
    m.text = text + LIST_TARGET.format(far).encode()
    m.expect_rc, m.must_name = {2, 3}, "not one agglomerate"
    m.notes.append(f"issue23 isolated primary {m.command}")


def issue23_field(rng, m, source_dir):
    """A charged run in a field of 1e9 V/m fails; the message must name the field (it advised to raise
    electrostatics.min_gap or lower the impact speed)."""
    stem = rng.choice(["seed000_charged_tetrahedron_k1", "seed000_charged_square_k1"])
    with open(os.path.join(source_dir, "cases", stem + ".toml"), "rb") as f:
        m.text = f.read()
    m.case = Case("collide", stem, SHORT_CHARGED)
    m.command, m.extra = "collide", []
    e = rng.choice(["1e9", "-1e9", "5e8"])
    m.sets = SHORT_CHARGED + [f"electrostatics.external_field={rng.choice(['[{}, 0.0, 0.0]', '[0.0, {}, 0.0]']).format(e)}"]
    m.must_name = "electrostatics.external_field"
    m.notes.append("issue23 field")


ISSUE23_CLASSES = ["seeds", "array", "long_key", "checkpoint", "calibrate", "isolated", "field"]


def issue23_mutant(seed, index, runs, source_dir, schema):
    """Mutant `index` as one targeted class, or None (the ordinary mutant of that index)."""
    rng = random.Random(f"agglo-fuzz-issue23/{seed}/{index}")
    if rng.random() >= ISSUE23_SHARE:
        return None
    case = rng.choice([r for r in runs if r.command != "sweep"] + [r for r in runs if r.command == "sweep"][:1])
    with open(os.path.join(source_dir, "cases", case.stem + ".toml"), "rb") as f:
        m = Mutant(case, f.read())
    kind = rng.choice(ISSUE23_CLASSES)
    if kind == "array":
        issue23_array(rng, m, source_dir, schema)
    else:
        globals()["issue23_" + kind](rng, m, source_dir)
    return m


def make_mutant(seed, index, runs, source_dir, schema):
    targeted = issue23_mutant(seed, index, runs, source_dir, schema)
    if targeted is not None:
        return targeted
    rng = random.Random(f"agglo-fuzz/{seed}/{index}")
    command = rng.choice(["collide", "vcrit", "breakup", "electrostatics", "acoustic", "sweep"])
    case = rng.choice([r for r in runs if r.command == command])
    with open(os.path.join(source_dir, "cases", case.stem + ".toml"), "rb") as f:
        m = Mutant(case, f.read())
    if rng.random() < 0.03:  # a case given to a command it is not meant for
        m.command = rng.choice(["collide", "vcrit", "breakup", "electrostatics", "acoustic"])
        m.extra = []
        m.sets += {"vcrit": VCRIT, "breakup": BREAKUP}.get(m.command, [])  # that command's shortening
        m.notes.append(f"cross {case.command}->{m.command}")
    ops, weights = zip(*OPERATORS)
    if acoustic(m):  # the acoustic cell grid is the largest allocation a case controls
        weights = [30 if op is mut_set_cells else w for op, w in OPERATORS]
    for _ in range(rng.choice([1, 1, 1, 1, 1, 2, 2, 3])):
        rng.choices(ops, weights)[0](rng, m, schema)
    return m


# ---------------------------------------------------------------------------------------------
# Execution and checks.
def resolve_out(m, work):
    o = m.out
    if o == "@file":
        open(os.path.join(work, "afile"), "w").close()
        return os.path.join(work, "afile")
    if o == "@file/x":
        open(os.path.join(work, "afile"), "w").close()
        return os.path.join(work, "afile", "x")
    if o == "@long":
        return os.path.join(work, "d" * 300, "e" * 300)
    if o == "@newline":
        return os.path.join(work, "out\nline")
    if o == "@nonempty":
        d = os.path.join(work, "full")
        os.makedirs(d)
        with open(os.path.join(d, "other.txt"), "w") as f:
            f.write("someone else's file\n")
        with open(os.path.join(d, "timeseries.csv.tmp-1"), "w") as f:
            f.write("t,x\n0,")
        return d
    if o == "@ro":  # read-only for a non-root user; root writes anyway
        d = os.path.join(work, "ro")
        os.makedirs(d)
        os.chmod(d, 0o555)
        return os.path.join(d, "out")
    if o == "@checkpoint":  # the folder of an interrupted run whose checkpoint.bin is not one
        d = os.path.join(work, "resumed")
        os.makedirs(d)
        with open(os.path.join(d, "run.json"), "w") as f:
            json.dump({"program": "agglo", "command": m.command, "status": "incomplete"}, f)
        ck = os.path.join(d, "checkpoint.bin")
        if m.checkpoint == "fifo":
            os.mkfifo(ck)
        elif m.checkpoint == "zero":
            os.symlink("/dev/zero", ck)
        else:  # sparse: 4 GiB on no disk blocks, above the memory budget of BUDGET_ENV
            with open(ck, "wb") as f:
                f.truncate(4 << 30)
        return d
    if o == "@dots":
        return os.path.join(work, "a", "..", "..", os.path.basename(work), "dots")
    if o == "@unicode":
        return os.path.join(work, "\u00e9\u2028\U0001F600")
    if o in ("", "-", "."):
        return o
    return o if o.startswith("/") else os.path.join(work, o)


def command_line(agglo, m, case_path, out):
    cmd = [agglo, "-q", "--no-plots", m.command, case_path if m.case_arg is None else m.case_arg]
    if out is not None:
        cmd += ["--out", out]
    if m.threads is not None:
        cmd += ["--threads", m.threads]
    for s in m.sets:
        cmd += ["--set", s]
    return cmd + m.extra + m.args_tail


def limited(cmd):
    """cmd under a shell that sets the child's limits (no core files; address space; file size) and execs it."""
    lim = "ulimit -c 0; ulimit -f %d; " % (CHILD_FILE_LIMIT // 512)
    if CHILD_MEMORY_LIMIT:
        lim += "ulimit -v %d; " % (CHILD_MEMORY_LIMIT // 1024)
    return ["/bin/sh", "-c", lim + 'exec "$@"', "sh"] + cmd


def nonfinite_in(path):
    """First non-finite number in a CSV/JSON(L) output file, or None."""
    try:
        with open(path, "rb") as f:
            data = f.read(64 << 20).decode("utf-8", "replace")
    except OSError:
        return None
    if path.endswith((".json", ".jsonl")):
        bad = []

        def walk(v, where):
            if isinstance(v, float) and not math.isfinite(v):
                bad.append(where)
            elif isinstance(v, dict):
                for k, x in v.items():
                    walk(x, f"{where}.{k}")
            elif isinstance(v, list):
                for k, x in enumerate(v):
                    walk(x, f"{where}[{k}]")
        docs = data.splitlines() if path.endswith(".jsonl") else [data]
        for d in docs:
            try:
                walk(json.loads(d), "")
            except ValueError:
                if re.search(r"\b(NaN|-?Infinity)\b", d):
                    return "NaN/Infinity in unparsable JSON"
        return f"{bad[0]} is not finite" if bad else None
    lines = data.splitlines()
    header = lines[0].split(",") if lines else []
    for n, line in enumerate(lines[1:], start=2):
        for c, field in enumerate(line.split(",")):
            f = field.strip().strip('"')
            if re.fullmatch(r"[+-]?(nan|inf|infinity)", f, re.IGNORECASE):
                col = header[c] if c < len(header) else str(c)
                # U_over_U0 is NaN by definition for a list agglomerate (docs/outputs.md)
                if not re.search(r"name|folder|phase|population|U_over_U0", col):
                    return f"line {n} column {col!r} = {f}"
    return None


def check_outputs(work):
    for root, _, files in os.walk(work):
        for fn in files:
            if fn.endswith((".csv", ".json", ".jsonl")):
                p = os.path.join(root, fn)
                bad = nonfinite_in(p)
                if bad:
                    return f"{os.path.relpath(p, work)}: {bad}"
    return None


LINE_BREAKS = re.compile("[\x00-\x08\x0a-\x1f\x7f\u0085\u2028\u2029]")


def started_engine(work):
    """True if the run got as far as writing results (files in an output folder)."""
    for root, _, files in os.walk(work):
        rel = os.path.relpath(root, work)
        for fn in files:
            if fn.endswith((".csv", ".json", ".jsonl", ".vtp", ".pvd")) and rel != "." and "full" not in rel:
                return True
    return False


RUNNING = set()  # process groups of the executions in flight, killed when the harness is stopped
STOPPED = []


def stop_children(signum, _frame):
    STOPPED.append(signum)
    for pgid in list(RUNNING):
        try:
            os.killpg(pgid, signal.SIGKILL)
        except OSError:
            pass
    sys.exit(128 + signum)


def run_one(args, runs, schema, index, keep=None):
    if STOPPED:
        return None
    m = make_mutant(args.seed, index, runs, args.source, schema)
    work = tempfile.mkdtemp(prefix=f"agglo-fuzz-{index}-")
    try:
        case_path = os.path.join(work, m.case.stem + ".toml")
        with open(case_path, "wb") as f:
            f.write(m.text)
        out = resolve_out(m, work)
        cmd = command_line(args.agglo, m, case_path, out)
        env = dict(os.environ)
        for k, v in BUDGET_ENV.items():
            env.setdefault(k, v)
        t0 = time.monotonic()
        proc = subprocess.Popen(limited(cmd), cwd=work, env=env, stdout=subprocess.DEVNULL,
                                stderr=subprocess.PIPE, start_new_session=True)
        RUNNING.add(proc.pid)
        try:
            _, err = proc.communicate(timeout=args.timeout)
            rc = proc.returncode
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            _, err = proc.communicate()
            rc = None
        finally:
            RUNNING.discard(proc.pid)
        wall = time.monotonic() - t0
        msg = err.decode("utf-8", "replace")
        finding = None
        if rc is None:
            finding = f"hang: no exit within {args.timeout:g} s"
        elif rc < 0:
            finding = f"crash: killed by signal {signal.Signals(-rc).name}"
        elif rc not in (0, 2, 3):
            finding = f"crash: exit {rc}: {first_line(msg)}"
        elif rc == 0:
            bad = check_outputs(work)
            if bad:
                finding = f"exit 0 with a non-finite output: {bad}"
        elif not (msg.endswith("\n") and not LINE_BREAKS.search(msg[:-1])):
            finding = f"exit {rc} with a message of {len(msg.splitlines())} lines/control characters: {msg[:200]!r}"
        finding = finding or targeted_finding(m, rc, wall, msg)
        engine = rc in (0, 3) or rc is None or started_engine(work)
        if keep:
            os.makedirs(keep, exist_ok=True)
            shutil.copy(case_path, os.path.join(keep, os.path.basename(case_path)))
        return dict(index=index, rc=rc, wall=wall, engine=engine, finding=finding, notes=m.notes,
                    cmd=reproducer(cmd, work, env, keep), diff=case_diff(args.source, m))
    finally:
        for root, dirs, _ in os.walk(work):
            for d in dirs:
                try:
                    os.chmod(os.path.join(root, d), 0o755)
                except OSError:
                    pass
        shutil.rmtree(work, ignore_errors=True)


def targeted_finding(m, rc, wall, msg):
    """The oracles of the targeted classes (and a slow refusal, for every mutant), or None."""
    if m.expect_rc and rc not in m.expect_rc:
        return f"exit {rc} where the mutation must be refused (exit {'/'.join(map(str, sorted(m.expect_rc)))}): " \
               f"{first_line(msg)}"
    if m.must_name and rc in (2, 3) and m.must_name not in msg:
        return f"exit {rc} without naming {m.must_name}: {first_line(msg)}"
    if m.max_message and len(msg) > m.max_message:
        return f"a message of {len(msg)} characters: {msg[:200]!r}"
    if rc == 2 and wall > SLOW_REFUSAL_S:
        return f"slow refusal: exit 2 after {wall:.0f} s: {first_line(msg)}"
    return None


def signature(r):
    """Findings of one kind (crash by signal, exit code, non-finite column, long message, hang) from
    the same kinds of mutation are reported together."""
    f = r["finding"]
    m = re.match(r"crash: killed by signal \w+|crash: exit \d+|hang|exit \d+ with a message|exit \d+ where the "
                 r"mutation must be refused|exit \d+ without naming \S+|a message of|slow refusal", f)
    if m:
        kind = m.group(0)
    else:  # exit 0 with a non-finite output: FOLDER/FILE: line N column 'C' = V
        m = re.match(r"exit 0 with a non-finite output: (?:.*/)?([^/:]+):(?:.*(column '[^']*'))?", f)
        kind = f"exit 0 non-finite {m.group(1)} {m.group(2) or ''}".strip() if m else f
    return kind + " | " + ", ".join(sorted({n.split()[0] for n in r["notes"]}))


def first_line(msg):
    return msg.splitlines()[0][:200] if msg else "(no message)"


def reproducer(cmd, work, env, keep):
    shown = [c.replace(work, keep if keep else "$DIR") for c in cmd]
    budgets = " ".join(f"{k}={env[k]}" for k in BUDGET_ENV)
    return budgets + " " + " ".join(shlex.quote(c) if "$DIR" not in c else '"' + c + '"' for c in shown)


def case_diff(source, m):
    with open(os.path.join(source, "cases", m.case.stem + ".toml"), "rb") as f:
        orig = f.read()
    if orig == m.text:
        return ""
    a = [ascii(l)[:300] for l in orig.split(b"\n")]
    b = [ascii(l)[:300] for l in m.text.split(b"\n")]
    d = list(difflib.unified_diff(a, b, "case", "mutant", n=0, lineterm=""))[2:]
    return "\n".join(d[:12]) + ("\n..." if len(d) > 12 else "")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("agglo")
    p.add_argument("source")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--execs", type=int, default=int(os.environ.get("AGGLO_FUZZ_EXECS", "400")))
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--timeout", type=float, default=60.0)
    p.add_argument("--only", type=int, help="run mutant I only and print its reproducer")
    p.add_argument("--keep", help="copy mutated case files here (for reproducing)")
    p.add_argument("--min-engine", type=float, default=0.0,
                   help="fail when fewer than this fraction of executions reached an engine")
    p.add_argument("--verbose", action="store_true")
    args = p.parse_args()
    args.agglo = os.path.abspath(args.agglo)
    args.source = os.path.abspath(args.source)
    if not os.access(args.agglo, os.X_OK):
        print(f"fuzz_cli: {args.agglo} is not an executable", file=sys.stderr)
        return 2
    signal.signal(signal.SIGTERM, stop_children)
    signal.signal(signal.SIGINT, stop_children)
    runs, schema = base_runs(), load_schema(args.source)
    indices = [args.only] if args.only is not None else range(args.execs)
    t0 = time.monotonic()
    results, findings = [], {}
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        for r in pool.map(lambda i: run_one(args, runs, schema, i, args.keep), indices):
            results.append(r)
            if args.verbose or args.only is not None:
                print(f"[{r['index']}] rc={r['rc']} {r['wall']:.2f}s engine={r['engine']} {'; '.join(r['notes'])}"
                      f"{'  FINDING ' + r['finding'] if r['finding'] else ''}\n    {r['cmd']}", flush=True)
                if r["diff"]:
                    print("    " + r["diff"].replace("\n", "\n    "), flush=True)
            if r["finding"]:
                findings.setdefault(signature(r), []).append(r)
    n = len(results)
    engine = sum(r["engine"] for r in results)
    codes = {}
    for r in results:
        codes[r["rc"]] = codes.get(r["rc"], 0) + 1
    print(f"fuzz_cli: seed {args.seed}, {n} executions in {time.monotonic() - t0:.0f} s, {engine} reached an engine "
          f"(exit 0/3, hang, or results written); exit codes "
          + ", ".join(f"{k if k is not None else 'timeout'}: {v}" for k, v in sorted(codes.items(), key=str)))
    nf = sum(len(v) for v in findings.values())
    print(f"fuzz_cli: {nf} findings ({len(findings)} distinct)")
    for sig, rs in findings.items():
        r = rs[0]
        print(f"\n== {sig}\n   {r['finding'][:300]}\n   {len(rs)} mutant(s): {' '.join(str(x['index']) for x in rs[:20])}"
              f"{' ...' if len(rs) > 20 else ''}\n   mutations: {'; '.join(r['notes'])}\n   reproduce: "
              f"{sys.argv[0]} AGGLO SOURCE --seed {args.seed} --only {r['index']} --keep DIR\n   command: {r['cmd']}")
        if r["diff"]:
            print("   case diff:\n     " + r["diff"].replace("\n", "\n     "))
    if n and engine < args.min_engine * n:
        print(f"fuzz_cli: only {engine} of {n} executions reached an engine (< {args.min_engine:g}): hollow run",
              file=sys.stderr)
        return 1
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
