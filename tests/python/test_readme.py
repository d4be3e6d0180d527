"""The "From Python" example of README.md runs as written (from the repository root)."""
import os
import re
import subprocess
import sys


def test_readme_example(agglo_module, source_dir, tmp_path):
    text = (source_dir / "README.md").read_text()
    section = text.split("## From Python", 1)[1].split("\n## ", 1)[0]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    assert len(code.strip().splitlines()) <= 10
    (tmp_path / "cases").symlink_to(source_dir / "cases")  # run where the example expects cases/
    proc = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True, timeout=300,
                          env={**os.environ, "PYTHONPATH": os.path.dirname(os.path.dirname(agglo_module.__file__))})
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    assert lines[0].startswith("0.1 m/s:") and lines[1].startswith("0.5 m/s:") and lines[2].endswith(" m/s")
    assert os.listdir(tmp_path) == ["cases"]  # the example writes nothing
