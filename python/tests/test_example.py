# SPDX-License-Identifier: Apache-2.0
"""The example runs and writes its figure (matplotlib) or its CSV (without)."""
import os
import subprocess
import sys


def test_example_runs(tmp_path):
    here = os.path.dirname(os.path.abspath(__file__))
    script = os.path.join(here, "..", "examples", "cleat_curves.py")
    r = subprocess.run([sys.executable, script, str(tmp_path)], capture_output=True,
                       text=True)
    assert r.returncode == 0, r.stderr
    assert "springs  peak h" in r.stdout
    written = sorted(os.listdir(tmp_path))
    assert written in (["cleat_curves.png"], ["cleat_curves.csv"]), written
    if written == ["cleat_curves.csv"]:
        lines = (tmp_path / "cleat_curves.csv").read_text().splitlines()
        assert lines[0] == "x_m,h_rigid_m,h_springs_m,h_cam_m,h_ring_m" and len(lines) == 802


def test_readme_example_prints_what_the_readme_says(source_dir, tmp_path):
    """The README's "Using tirenv from Python" block, run, prints the lines shown under it."""
    lines = open(os.path.join(source_dir, "README.md")).read().splitlines()
    start = next(i for i, line in enumerate(lines)
                 if line.startswith("$ PYTHONPATH=build/python /usr/bin/python3 - <<'END'"))
    end = lines.index("END", start)
    shown = lines[end + 1:lines.index("```", end)]
    r = subprocess.run([sys.executable, "-"], input="\n".join(lines[start + 1:end]),
                       capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines() == shown and len(shown) == 2
