"""The notebooks of examples/ run from their first to their last cell with Debian's jupyter-nbconvert
(package jupyter-nbconvert, kernel python3-ipykernel; scripts/packages.sh TEST_PKGS) against the build under
test: a failing cell (its own assertions included) fails the test, and the executed notebook holds the lines
and the figure it is about. aggregate_wall.ipynb: the three impacts' lines, about 8 s.
outcome_table_dsmc.ipynb: a 60-impact sphere table and two 0.4 s DSMC runs with and without it, about 10 s
of CPU (user + sys) of which the table and the runs take 2.5 s, the rest is Jupyter and its kernel."""
import json
import os
import pathlib
import shutil
import subprocess

import pytest


def execute_notebook(name, agglo_module, source_dir, tmp_path):
    """Runs examples/<name> with nbconvert; returns the text of its outputs and its outputs."""
    exe = shutil.which("jupyter-nbconvert")
    if exe is None:
        pytest.skip("jupyter-nbconvert is not installed (Debian: jupyter-nbconvert python3-ipykernel)")
    env = dict(os.environ)
    module_dir = str(pathlib.Path(agglo_module.__file__).resolve().parents[1])
    env["PYTHONPATH"] = os.pathsep.join([module_dir, env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    env["MPLBACKEND"] = "module://matplotlib_inline.backend_inline"
    shutil.copy(source_dir / "examples" / name, tmp_path)
    run = subprocess.run([exe, "--to", "notebook", "--execute", "--ExecutePreprocessor.timeout=300",
                          "--output", "executed.ipynb", name],
                         cwd=tmp_path, env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr[-3000:]
    cells = json.loads((tmp_path / "executed.ipynb").read_text())["cells"]
    outputs = [o for c in cells if c["cell_type"] == "code" for o in c["outputs"]]
    assert not [o for o in outputs if o["output_type"] == "error"]
    text = "".join("".join(o.get("text", "")) for o in outputs)
    assert str(pathlib.Path(agglo_module.__file__).resolve()) in text or agglo_module.__file__ in text  # the build under test
    assert any("image/png" in o.get("data", {}) for o in outputs)
    return text, outputs


def test_aggregate_wall_notebook(agglo_module, source_dir, tmp_path):
    text, _ = execute_notebook("aggregate_wall.ipynb", agglo_module, source_dir, tmp_path)
    assert text.count(" m/s: ") == 3, text


def test_outcome_table_dsmc_notebook(agglo_module, source_dir, tmp_path):
    text, outputs = execute_notebook("outcome_table_dsmc.ipynb", agglo_module, source_dir, tmp_path)
    assert "60 impacts over 5 speeds x 2 x 2 diameters" in text, text
    assert text.count(": N drops by ") == 2, text
    # Nothing on stderr: a NetCDF read on a run's worker thread once printed HDF5-DIAG lines there.
    assert not [o for o in outputs if o.get("name") == "stderr"], text
