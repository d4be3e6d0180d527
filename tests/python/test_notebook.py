"""The notebooks of examples/ run from their first to their last cell with Debian's jupyter-nbconvert
(package jupyter-nbconvert, kernel python3-ipykernel; scripts/packages.sh TEST_PKGS) against the build under
test: a cell that raises (its own assertions included) fails the notebook's test, and the executed notebook
holds the lines and the figure it is about. Both notebooks run in one nbconvert process (each in its own
kernel; --allow-errors, so that one notebook's error does not stop the other and is reported by its own
test), which saves the ~2 s of CPU a second nbconvert start costs. aggregate_wall.ipynb: the three
impacts' lines; outcome_table_dsmc.ipynb: a 60-impact sphere table and two 0.4 s DSMC runs with and
without it (2.5 s of CPU). Both tests together: about 13 s of CPU (user + sys), most of it Jupyter."""
import json
import os
import pathlib
import shutil
import subprocess

import pytest

NOTEBOOKS = ["aggregate_wall.ipynb", "outcome_table_dsmc.ipynb"]


@pytest.fixture(scope="module")
def executed(agglo_module, source_dir, tmp_path_factory):
    """{notebook: (text of its outputs, its outputs)} after one nbconvert run of every notebook."""
    exe = shutil.which("jupyter-nbconvert")
    if exe is None:
        pytest.skip("jupyter-nbconvert is not installed (Debian: jupyter-nbconvert python3-ipykernel)")
    work = tmp_path_factory.mktemp("notebooks")
    env = dict(os.environ)
    module_dir = str(pathlib.Path(agglo_module.__file__).resolve().parents[1])
    env["PYTHONPATH"] = os.pathsep.join([module_dir, env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    env["MPLBACKEND"] = "module://matplotlib_inline.backend_inline"
    for name in NOTEBOOKS:
        shutil.copy(source_dir / "examples" / name, work)
    run = subprocess.run([exe, "--to", "notebook", "--execute", "--allow-errors",
                          "--ExecutePreprocessor.timeout=300", "--output-dir", "executed"] + NOTEBOOKS,
                         cwd=work, env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr[-3000:]
    result = {}
    for name in NOTEBOOKS:
        cells = json.loads((work / "executed" / name).read_text())["cells"]
        outputs = [o for c in cells if c["cell_type"] == "code" for o in c["outputs"]]
        result[name] = ("".join("".join(o.get("text", "")) for o in outputs), outputs)
    return result


def check_common(text, outputs, agglo_module):
    errors = [o for o in outputs if o["output_type"] == "error"]
    assert not errors, "\n".join(f"{o['ename']}: {o['evalue']}" for o in errors)
    assert str(pathlib.Path(agglo_module.__file__).resolve()) in text or agglo_module.__file__ in text  # the build under test
    assert any("image/png" in o.get("data", {}) for o in outputs)


def test_aggregate_wall_notebook(executed, agglo_module):
    text, outputs = executed["aggregate_wall.ipynb"]
    check_common(text, outputs, agglo_module)
    assert text.count(" m/s: ") == 3, text


def test_outcome_table_dsmc_notebook(executed, agglo_module):
    text, outputs = executed["outcome_table_dsmc.ipynb"]
    check_common(text, outputs, agglo_module)
    assert "60 impacts over 5 speeds x 2 x 2 diameters" in text, text
    assert text.count(": N drops by ") == 2, text
    # Nothing on stderr: a NetCDF read on a run's worker thread once printed HDF5-DIAG lines there.
    assert not [o for o in outputs if o.get("name") == "stderr"], text
