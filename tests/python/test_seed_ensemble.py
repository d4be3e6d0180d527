"""agglo.acoustic(case, seeds=N): the seed ensemble of `agglo acoustic --seeds N` from Python: same
files and numbers as the CLI, the summary's mean/stderr/n of every scalar, arrays of the mean and
stderr; seeds=1 is the single run; bad seeds raise ConfigError."""
import json

import numpy as np
import pytest

from agglo_cases import CASES, cli


def _case(agglo):
    return (agglo.Case.load(CASES / "seed002_integrator_check.toml").set("time.end", 0.005)
            .set("output.psd_times", [0.0, 0.005]).set("population.0.samples", 200).set("population.1.samples", 50))


def test_seed_ensemble_equals_cli(agglo_module, tmp_path):
    agglo = agglo_module
    path = tmp_path / "case.toml"
    path.write_text(_case(agglo).to_toml())
    res = agglo.acoustic(agglo.Case.load(path), seeds=3, out=tmp_path / "py", threads=2)
    proc = cli("acoustic", path, "--seeds", "3", "--threads", "2", "--out", tmp_path / "cli")
    assert proc.returncode == 0, proc.stderr
    assert res.summary["members"] == 3 and res.summary["seeds"][0] == res.seed == 1
    assert len(set(res.summary["seeds"])) == 3
    eff = res.summary["ensemble"]["fine_efficiency"]
    assert eff["n"] == 3
    rows = {line.split(",")[0]: line.split(",") for line in (tmp_path / "cli" / "ensemble_summary.csv").read_text()
            .splitlines()[1:]}
    assert float(rows["fine_efficiency"][2]) == pytest.approx(eff["mean"], rel=1e-9)
    assert float(rows["fine_efficiency"][3]) == pytest.approx(eff["stderr"], rel=1e-9)
    # the members' own final efficiencies give the mean and stderr
    own = [json.loads(next((tmp_path / "py").glob(f"case_*_{s}")).joinpath("summary.json").read_text())
           ["fine_efficiency"] for s in res.summary["seeds"]]
    assert eff["mean"] == pytest.approx(np.mean(own), rel=1e-12)
    assert eff["stderr"] == pytest.approx(np.std(own, ddof=1) / np.sqrt(3), rel=1e-9)
    assert res["fine_efficiency_mean"][-1] == pytest.approx(eff["mean"], rel=1e-12)
    assert (tmp_path / "py" / "ensemble_timeseries.csv").read_text() == \
        (tmp_path / "cli" / "ensemble_timeseries.csv").read_text()
    # one request for both front ends: the same run.json command and details
    py_run, cli_run = (json.loads((tmp_path / d / "run.json").read_text()) for d in ("py", "cli"))
    assert py_run["command"] == cli_run["command"] == "acoustic"
    assert py_run["details"] == cli_run["details"]
    assert py_run["details"]["seeds"] == res.summary["seeds"] and py_run["details"]["members"] == 3


def test_seeds_one_is_the_single_run_and_bad_seeds_raise(agglo_module):
    agglo = agglo_module
    one = agglo.acoustic(_case(agglo), seeds=1, threads=1)
    plain = agglo.acoustic(_case(agglo), threads=1)
    assert {k: v for k, v in one.summary.items() if k != "wall_time_s"} == \
        {k: v for k, v in plain.summary.items() if k != "wall_time_s"}
    for bad in (0, -2):
        with pytest.raises(agglo.ConfigError, match=f"agglo.acoustic: seeds = {bad}: give an integer >= 1"):
            agglo.acoustic(_case(agglo), seeds=bad)


def test_sweep_with_seeds_equals_cli(agglo_module, tmp_path):
    """agglo.sweep(..., seeds=N) as `agglo sweep --seeds N`: the points' statistics in the summary and in
    sweep_ensemble.csv, each from the point's own members."""
    agglo = agglo_module
    path = tmp_path / "case.toml"
    path.write_text(_case(agglo).to_toml())
    res = agglo.sweep(agglo.Case.load(path), {"population.1.diameter": [20e-6, 40e-6]}, seeds=2,
                      out=tmp_path / "py", threads=2)
    proc = cli("sweep", path, "--param", "population.1.diameter", "--values", "2e-05,4e-05", "--seeds", "2",
               "--threads", "2", "--out", tmp_path / "cli")
    assert proc.returncode == 0, proc.stderr
    points, cases = res.summary["points"], res.summary["cases"]
    assert len(points) == 2 and len(cases) == 4
    assert [p["values"]["population.1.diameter"] for p in points] == [20e-6, 40e-6]
    rows = (tmp_path / "cli" / "sweep_ensemble.csv").read_text().splitlines()
    header = rows[0].split(",")
    for i, p in enumerate(points):
        assert p["members"] == 2 and p["folder"] == cases[2 * i]["folder"]
        own = [c["summary"]["fine_efficiency"] for c in cases[2 * i:2 * i + 2]]
        eff = p["stats"]["fine_efficiency"]
        assert own[0] != own[1]
        assert eff["mean"] == pytest.approx(np.mean(own), rel=1e-12)
        assert eff["stderr"] == pytest.approx(np.std(own, ddof=1) / np.sqrt(2), rel=1e-9)
        row = rows[1 + i].split(",")
        assert float(row[header.index("fine_efficiency_mean")]) == pytest.approx(eff["mean"], rel=1e-9)
        # the point's whole statistics (time series), as the CLI's point folder
        assert p["statistics"].startswith(f"point_{i:02d}_")
        series = (tmp_path / "py" / p["statistics"] / "ensemble_timeseries.csv").read_text()
        assert "fine_efficiency_mean,fine_efficiency_stderr" in series.splitlines()[0]
        (cli_point,) = (tmp_path / "cli").glob(f"point_{i:02d}_*")
        assert series == (cli_point / "ensemble_timeseries.csv").read_text()
        last = series.splitlines()[-1].split(",")
        head = series.splitlines()[0].split(",")
        assert float(last[head.index("fine_efficiency_mean")]) == pytest.approx(eff["mean"], rel=1e-9)
    with pytest.raises(agglo.ConfigError, match="agglo.sweep: seeds = 0: give an integer >= 1"):
        agglo.sweep(agglo.Case.load(path), {"population.1.diameter": [20e-6]}, seeds=0, out=tmp_path / "bad")
    assert not (tmp_path / "bad").exists()
