"""The example script writes the paper's seven figures, as SVG without matplotlib and as PNG
with it, from convexloc's own picture code."""

import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

import convexloc
from conftest import env_path


def run_script(*args):
    script = env_path("CONVEXLOC_EXAMPLES") / "figures.py"
    run = subprocess.run([sys.executable, str(script), *map(str, args)], capture_output=True,
                         text=True, env=dict(os.environ), check=True)
    return [os.path.basename(p) for p in run.stdout.split()]


def test_figures_script_writes_svg(tmp_path):
    assert run_script("--svg", tmp_path) == [f"fig{n}.svg" for n in range(1, 8)]
    fig6 = (tmp_path / "fig6.svg").read_text()
    assert fig6 == convexloc.figure_svg(6)  # the script draws what the package draws
    polygons = [e for e in ET.fromstring(fig6).iter() if e.tag.endswith("polygon")]
    # Fig. 6: the polar cells, the query's cell again (highlighted), the box and the polygon
    polar = convexloc.PolarLocator(convexloc.drawing._figure_polygon(), 4)
    assert len(polygons) == len(polar.cells()) + 3
    fig7 = ET.fromstring((tmp_path / "fig7.svg").read_text())
    assert sum(e.tag.endswith("polygon") for e in fig7.iter()) > 6 * 4 * 4


def test_figures_script_writes_png(tmp_path):
    pytest.importorskip("matplotlib")
    assert run_script(tmp_path) == [f"fig{n}.png" for n in range(1, 8)]
    assert all((tmp_path / f"fig{n}.png").read_bytes()[:4] == b"\x89PNG" for n in range(1, 8))
