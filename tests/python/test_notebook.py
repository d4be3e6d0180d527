"""examples/aggregate_wall.ipynb runs from its first to its last cell with Debian's jupyter-nbconvert
(package jupyter-nbconvert, kernel python3-ipykernel; scripts/packages.sh TEST_PKGS) against the build under
test: a failing cell (its own assertions included) fails the test, and the executed notebook holds the
three impacts' lines and the figure. About 8 s."""
import json
import os
import pathlib
import shutil
import subprocess

import pytest


def test_aggregate_wall_notebook(agglo_module, source_dir, tmp_path):
    exe = shutil.which("jupyter-nbconvert")
    if exe is None:
        pytest.skip("jupyter-nbconvert is not installed (Debian: jupyter-nbconvert python3-ipykernel)")
    env = dict(os.environ)
    module_dir = str(pathlib.Path(agglo_module.__file__).resolve().parents[1])
    env["PYTHONPATH"] = os.pathsep.join([module_dir, env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    env["MPLBACKEND"] = "module://matplotlib_inline.backend_inline"
    shutil.copy(source_dir / "examples" / "aggregate_wall.ipynb", tmp_path)
    run = subprocess.run([exe, "--to", "notebook", "--execute", "--ExecutePreprocessor.timeout=300",
                          "--output", "executed.ipynb", "aggregate_wall.ipynb"],
                         cwd=tmp_path, env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr[-3000:]
    cells = json.loads((tmp_path / "executed.ipynb").read_text())["cells"]
    outputs = [o for c in cells if c["cell_type"] == "code" for o in c["outputs"]]
    assert not [o for o in outputs if o["output_type"] == "error"]
    text = "".join("".join(o.get("text", "")) for o in outputs)
    assert str(pathlib.Path(agglo_module.__file__).resolve()) in text or agglo_module.__file__ in text  # the build under test
    assert text.count(" m/s: ") == 3, text
    assert any("image/png" in o.get("data", {}) for o in outputs)
