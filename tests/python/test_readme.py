"""The README's Python example runs as printed (from the repository's root, as a script: its
sweep starts worker processes that import it)."""
import os
import re
import subprocess
import sys

from conftest import ROOT


def test_the_readmes_python_example_runs(tmp_path):
    readme = (ROOT / "README.md").read_text()
    section = readme.split("## Python", 1)[1]
    example = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    script = tmp_path / "example.py"
    script.write_text(example)
    env = dict(os.environ, DASK_TEMPORARY_DIRECTORY=str(tmp_path))
    r = subprocess.run([sys.executable, str(script)], cwd=ROOT, capture_output=True, text=True,
                       timeout=300, env=env)
    assert r.returncode == 0, r.stderr
    # the sweep's table: its header and six rows, none with an error
    assert "springs.stiffness" in r.stdout, r.stdout
    assert all(re.search(rf"^{row}\s", r.stdout, re.M) for row in range(6)), r.stdout
    assert "Error" not in r.stdout, r.stdout
