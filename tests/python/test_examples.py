"""The example script draws Fig. 6 and Fig. 7 from cells() (as SVG without matplotlib)."""

import os
import subprocess
import sys

import convexloc
from conftest import env_path


def test_figures_script_writes_svg(tmp_path):
    script = env_path("CONVEXLOC_EXAMPLES") / "figures.py"
    run = subprocess.run([sys.executable, str(script), "--svg", str(tmp_path)],
                         capture_output=True, text=True, env=dict(os.environ), check=True)
    written = run.stdout.split()
    assert [os.path.basename(p) for p in written] == ["fig6_polar.svg", "fig7_cubemap.svg"]
    fig6 = (tmp_path / "fig6_polar.svg").read_text()
    fig7 = (tmp_path / "fig7_cubemap.svg").read_text()
    assert fig6.startswith("<svg") and fig6.rstrip().endswith("</svg>")
    # Fig. 6: one polygon per polar cell, then the box and the polygon itself
    assert fig6.count("<polygon") == 8 * 4 + 2
    assert fig7.count("<polygon") > 6 * 4 * 4
    assert convexloc.__file__  # the module the script used is the one under test
