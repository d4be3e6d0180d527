"""One function per command: each runs on a short case; results and files equal the CLI's; error classes."""
import filecmp
import json
import os

import pytest

from agglo_cases import CASES, SQUARE, cli, cli_error, short

SHORT_VCRIT = {"vcrit.scan_points": 4, "vcrit.v_min": 0.05, "vcrit.v_max": 0.8, "vcrit.tolerance": 0.05}


def _acoustic(agglo):
    return (agglo.Case.load(CASES / "seed002_integrator_check.toml").set("time.end", 0.005)
            .set("output.psd_times", [0.0]).set("population.0.samples", 200).set("population.1.samples", 50))


def test_command_names(agglo_module):
    names = agglo_module.command_names()
    assert {"collide", "vcrit", "breakup", "electrostatics", "acoustic", "sectional", "calibrate"} <= set(names)
    for name in names:
        assert callable(getattr(agglo_module, name))


def test_collide_runs_without_output(agglo_module):
    agglo = agglo_module
    res = agglo.collide(short(agglo), speed=0.3, threads=1)
    assert res.command == "collide" and res.out is None
    assert res.summary["speed_m_per_s"] == pytest.approx(0.3) and isinstance(res.summary["broken"], bool)


def test_no_temporary_left(agglo_module, tmp_path, monkeypatch):
    agglo = agglo_module
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    agglo.collide(short(agglo), threads=1)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("name, make", [
    ("vcrit", lambda agglo: short(agglo, extra=SHORT_VCRIT)),
    ("breakup", lambda agglo: short(agglo, extra={"breakup.speeds": [0.1, 0.4], "breakup.samples": 2})),
    ("electrostatics", lambda agglo: agglo.Case.load(CASES / "electrostatics_two_spheres.toml")),
    ("outcomes", lambda agglo: agglo.Case.load(CASES / "outcomes_sphere_sphere.toml").set("outcome_grid.impacts", 1)),
    ("acoustic", _acoustic),
    ("sectional", lambda agglo: agglo.Case.load(CASES / "partmc_constant.toml").set("time.end", 1.8)
     .set("output.psd_times", [0.0, 1.8])),
])
def test_every_command_runs(agglo_module, name, make):
    res = getattr(agglo_module, name)(make(agglo_module), threads=2)
    assert res.command == name and isinstance(res.summary, dict) and res.summary


def test_calibrate_runs(agglo_module, tmp_path):
    agglo = agglo_module
    case = agglo.Case({
        "calibrate": {"grid_points": 3, "refine_rounds": 0,
                      "case_overrides": "time.after_contact=2e-4; output.snapshot_interval=0; vcrit.scan_points=4; "
                                        "vcrit.v_min=0.05; vcrit.v_max=0.8; vcrit.tolerance=0.05"},
        "parameter": [{"key": "material.restitution", "lower": 0.8, "upper": 0.98}],
        "target": [{"case": str(SQUARE), "value": 0.2, "tolerance": 0.05}],
    })
    res = agglo.calibrate(case, threads=2, out=tmp_path / "cal")
    assert res.out == str(tmp_path / "cal") and (tmp_path / "cal" / "calibration.json").exists()
    assert res.summary


def test_sweep(agglo_module, tmp_path):
    agglo = agglo_module
    res = agglo.sweep(short(agglo), {"projectile.speed": [0.1, 0.5]}, command="collide", out=tmp_path / "s")
    cases = res.summary["cases"]
    assert [c["values"]["projectile.speed"] for c in cases] == [0.1, 0.5]
    assert [c["summary"]["speed_m_per_s"] for c in cases] == pytest.approx([0.1, 0.5])
    cli_run = cli("sweep", SQUARE, "--set", "time.after_contact=2e-4", "--set", "output.snapshot_interval=0",
                  "--command", "collide", "--param", "projectile.speed", "--values", "0.1,0.5", "--out", tmp_path / "c")
    assert cli_run.returncode == 0, cli_run.stderr
    assert (tmp_path / "s" / "sweep.csv").read_bytes() == (tmp_path / "c" / "sweep.csv").read_bytes()
    py_json = json.loads((tmp_path / "s" / "run.json").read_text())
    cli_json = json.loads((tmp_path / "c" / "run.json").read_text())
    assert py_json["details"] == cli_json["details"]


def _without_wall_time(path):
    """A text file's lines, or a NetCDF file's dataset, without what holds a wall time."""
    if path.suffix == ".nc":
        import xarray
        with xarray.open_dataset(path) as ds:
            return ds.drop_vars([v for v in ds.variables if "wall_time" in v]).load()
    return [line for line in path.read_text().splitlines() if "wall_time" not in line]


def _same_files(a, b, timed=()):
    """Every file of folder a equals b's byte for byte, both ways; run.json (pid, wall time) aside, and the
    files in `timed` compared without their lines that hold a wall time."""
    names = sorted(str(p.relative_to(a)) for p in a.rglob("*") if p.is_file() and p.name != "run.json")
    assert names == sorted(str(p.relative_to(b)) for p in b.rglob("*") if p.is_file() and p.name != "run.json")
    exact = [n for n in names if n not in timed]
    _, mismatch, errors = filecmp.cmpfiles(a, b, exact, shallow=False)
    assert not mismatch and not errors, (mismatch, errors)
    for n in set(timed) & set(names):
        x, y = _without_wall_time(a / n), _without_wall_time(b / n)
        assert x.identical(y) if n.endswith(".nc") else x == y, n
    return names


def test_collide_identical_to_cli(agglo_module, tmp_path):
    agglo = agglo_module
    res = agglo.collide(short(agglo), speed=0.3, out=tmp_path / "py", threads=2)
    proc = cli("collide", SQUARE, "--speed", "0.3", "--set", "time.after_contact=2e-4", "--set",
               "output.snapshot_interval=0", "--threads", "2", "--out", tmp_path / "cli")
    assert proc.returncode == 0, proc.stderr
    names = _same_files(tmp_path / "py", tmp_path / "cli")
    assert "result.json" in names and "config.resolved.toml" in names
    assert res.summary == json.loads((tmp_path / "cli" / "result.json").read_text())
    assert res.out == str(tmp_path / "py")


def test_acoustic_identical_to_cli(agglo_module, tmp_path):
    agglo = agglo_module
    path = tmp_path / "case.toml"
    path.write_text(_acoustic(agglo).to_toml())
    res = agglo.acoustic(agglo.Case.load(path), out=tmp_path / "py", threads=2)
    proc = cli("acoustic", path, "--threads", "2", "--out", tmp_path / "cli")
    assert proc.returncode == 0, proc.stderr
    _same_files(tmp_path / "py", tmp_path / "cli", timed=("summary.json", "run.log", "results.nc"))
    cli_summary = json.loads((tmp_path / "cli" / "summary.json").read_text())
    assert {k: v for k, v in res.summary.items() if k != "wall_time_s"} == \
        {k: v for k, v in cli_summary.items() if k != "wall_time_s"}
    assert res.seed == json.loads((tmp_path / "cli" / "run.json").read_text())["seed"] == 1


def test_limit_error(agglo_module, tmp_path, monkeypatch):
    agglo = agglo_module
    monkeypatch.setenv("AGGLO_MAX_STEPS", "1000")
    with pytest.raises(agglo.LimitError) as err:
        agglo.collide(short(agglo))
    assert not isinstance(err.value, agglo.ConfigError) and isinstance(err.value, agglo.Error)
    proc = cli("collide", SQUARE, "--set", "time.after_contact=2e-4", "--set", "output.snapshot_interval=0",
               "--out", tmp_path / "cli", env={**os.environ, "AGGLO_MAX_STEPS": "1000"})
    # the same line, in Python's words: the budget is raised with the keyword max_steps=, not --max-steps
    assert proc.returncode == 2 and str(err.value) == cli_error(proc).replace("--max-steps", "max_steps=")
    assert "max_steps=" in str(err.value)
    assert not (tmp_path / "cli").exists()


def test_numerical_error(agglo_module, tmp_path):
    agglo = agglo_module
    tet = CASES / "seed000_neutral_tetrahedron.toml"
    with pytest.raises(agglo.NumericalError) as err:
        agglo.collide(agglo.Case.load(tet), speed=1000)
    assert isinstance(err.value, ArithmeticError)
    proc = cli("collide", tet, "--speed", "1000", "--out", tmp_path / "cli")
    assert proc.returncode == 3 and str(err.value) == cli_error(proc)


def test_option_errors(agglo_module):
    agglo = agglo_module
    case = short(agglo)
    for kwargs in ({"threads": -1}, {"format": "xml", "out": "x"}, {"checkpoint": 1e-4}, {"resume": True}):
        with pytest.raises(agglo.ConfigError):
            agglo.collide(case, **kwargs)
    with pytest.raises(agglo.ConfigError) as err:
        agglo.sweep(case, {"projectile.speed": [0.1]}, command="nothing")
    assert "available" in str(err.value)


def test_help_documents_parameters_and_units(agglo_module):
    agglo = agglo_module
    for name in agglo.command_names() + ["sweep"]:
        doc = getattr(agglo, name).__doc__
        for word in ("case", "out", "threads", "progress", "format", "resume", "overwrite"):
            assert word in doc, (name, word)
    assert "m/s" in agglo.collide.__doc__ and "[s]" in agglo.collide.__doc__
    for cls in (agglo.Case, agglo.Result, agglo.Error, agglo.ConfigError, agglo.LimitError, agglo.NumericalError,
                agglo.InterruptedError):
        assert cls.__doc__


def test_warnings_go_to_python(agglo_module, tmp_path):
    """A run's warnings become warnings.warn(RuntimeWarning) with the CLI's text, attributed to the caller."""
    agglo = agglo_module
    odd = {"time.motion_dt": 1 / 30000, "time.collision_dt": 1 / 30000}  # 15 steps per acoustic period: a warning
    case = _acoustic(agglo)
    for key, value in odd.items():
        case.set(key, value)
    with pytest.warns(RuntimeWarning) as record:
        agglo.acoustic(case, threads=1)
    assert len(record) == 1 and record[0].filename == __file__
    path = tmp_path / "case.toml"
    path.write_text(case.to_toml())
    proc = cli("acoustic", path, "--threads", "1", "--out", tmp_path / "cli")
    assert proc.returncode == 0 and f"agglo: warning: {record[0].message}" in proc.stderr.splitlines()
