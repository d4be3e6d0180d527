"""Short cases and the CLI of the build under test, shared by the Python tests."""
import os
import pathlib
import subprocess

BUILD = pathlib.Path(os.environ.get("AGGLO_BUILD_DIR", pathlib.Path(__file__).resolve().parents[2] / "build"))
SOURCE = pathlib.Path(os.environ.get("AGGLO_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
CASES = SOURCE / "cases"
SQUARE = CASES / "seed000_neutral_square.toml"
SHORT_COLLIDE = {"time.after_contact": 2e-4, "output.snapshot_interval": 0}


def short(agglo, path=SQUARE, extra=None):
    """The case at `path` with the short collide settings and `extra` ({dotted key: value}) set."""
    case = agglo.Case.load(path)
    for key, value in {**SHORT_COLLIDE, **(extra or {})}.items():
        case.set(key, value)
    return case


def cli(*args, env=None):
    """Runs build/agglo -q --no-plots ARGS; returns the CompletedProcess (text)."""
    return subprocess.run([str(BUILD / "agglo"), "-q", "--no-plots", *map(str, args)], capture_output=True, text=True,
                          env=env, timeout=300)


def cli_error(proc):
    """The one-line message of a failed CLI run (stderr without the "agglo: error: " prefix)."""
    line = proc.stderr.strip().splitlines()[-1]
    for prefix in ("agglo: error: ", "agglo: numerical failure: "):
        if line.startswith(prefix):
            return line[len(prefix):]
    return line
