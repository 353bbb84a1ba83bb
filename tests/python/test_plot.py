"""convexloc.plot draws every locator kind, classified points and a query's steps to PNG with
matplotlib's Agg backend (no display); svg and _repr_svg_ give SVG without matplotlib; the
paper's figures come from the same code. CONVEXLOC_PLOT_DIR keeps the PNGs to look at."""

import os
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import convexloc
from conftest import regular_polygon

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

POLYGON = convexloc.Polygon(regular_polygon(9) * [1.5, 1.0])
POLYHEDRON = convexloc.Polyhedron.hull(np.random.default_rng(3).normal(size=(60, 3)))
POINTS_2D = np.random.default_rng(1).uniform(-1.6, 1.6, size=(300, 2))
POINTS_3D = np.random.default_rng(2).uniform(-2, 2, size=(300, 3))


def drawn(ax, tmp_path, name):
    """The PNG of `ax`'s figure as an RGB array (kept under CONVEXLOC_PLOT_DIR when set)."""
    folder = os.environ.get("CONVEXLOC_PLOT_DIR") or tmp_path
    path = os.path.join(folder, name + ".png")
    ax.figure.savefig(path, dpi=60)
    plt.close(ax.figure)
    return plt.imread(path)[..., :3]


def colour_pixels(image, hex_colour):
    rgb = np.array([int(hex_colour[k:k + 2], 16) / 255 for k in (1, 3, 5)])
    return int((np.abs(image - rgb).max(axis=2) < 0.02).sum())


@pytest.mark.parametrize("method", list(convexloc.LOCATORS_2D))
def test_each_2d_locator_with_points_and_a_trace(method, tmp_path):
    locator = convexloc.LOCATORS_2D[method](POLYGON)
    ax = convexloc.plot(locator, points=POINTS_2D, trace=[0.3, 0.2])
    codes = locator.locate(POINTS_2D)
    labels = ax.get_legend_handles_labels()[1]
    for code in convexloc.Location:  # one legend entry per class present, with its count
        count = int((codes == code).sum())
        assert (f"{code.name.lower()} ({count})" in labels) == (count > 0)
    assert "query: INSIDE" in labels and "inside" in ax.get_title()
    # the subdivision: one filled outline per cell
    polygons = sum(len(c.get_paths()) for c in ax.collections
                   if type(c).__name__ == "PolyCollection")
    assert polygons >= len(locator.cells())
    image = drawn(ax, tmp_path, f"plot_{method}")
    assert colour_pixels(image, convexloc.drawing.LOCATION_COLOURS[convexloc.INSIDE]) > 20
    assert colour_pixels(image, convexloc.drawing.LOCATION_COLOURS[convexloc.OUTSIDE]) > 20


@pytest.mark.parametrize("method", list(convexloc.LOCATORS_3D))
def test_each_3d_locator_with_points_and_a_trace(method, tmp_path):
    locator = convexloc.LOCATORS_3D[method](POLYHEDRON)
    ax = convexloc.plot(locator, points=POINTS_3D, trace=[0.1, 0.2, 0.1])
    assert "query: INSIDE" in ax.get_legend_handles_labels()[1]
    image = drawn(ax, tmp_path, f"plot_{method}")
    if method == "cubemap":
        # the net: six cube faces of G x G cells (or finer) filled by their face counts
        cells = locator.cells()
        assert len(ax.collections[0].get_paths()) == len(cells) >= 6 * locator.resolution ** 2
        assert colour_pixels(image, convexloc.drawing.count_fill(1)) > 50
    else:
        assert colour_pixels(image, "#f4b183") > 200  # the solid's faces seen from outside


def test_shapes_and_shapely_polygons_plot(tmp_path):
    shapely = pytest.importorskip("shapely.geometry")
    ax = convexloc.plot(shapely.Polygon([(0, 0), (2, 0), (2, 1), (0, 1)]), points=[[1, 0.5]])
    assert ax.get_title() == "polar over a 4-gon"
    drawn(ax, tmp_path, "plot_shapely")
    ax = convexloc.plot(POLYHEDRON)  # a polyhedron: its cube map's net
    drawn(ax, tmp_path, "plot_polyhedron")


def test_the_paper_figures(tmp_path):
    for number in range(1, 8):
        ax = convexloc.figure(number)
        assert ax.get_title().startswith(f"Fig. {number}:")
        drawn(ax, tmp_path, f"figure_{number}")
    with pytest.raises(ValueError, match="figures 1 to 7, got 8"):
        convexloc.figure(8)


def test_svg_for_notebooks():
    for thing in (POLYGON, POLYHEDRON, convexloc.PolarLocator(POLYGON),
                  convexloc.CubemapLocator(POLYHEDRON), convexloc.WalkLocator(POLYHEDRON)):
        text = thing._repr_svg_()
        root = ET.fromstring(text)  # well-formed XML
        assert root.tag.endswith("svg") and text == convexloc.svg(thing)
    cells = len(convexloc.PolarLocator(POLYGON).cells())
    root = ET.fromstring(convexloc.PolarLocator(POLYGON)._repr_svg_())
    polygons = [e for e in root.iter() if e.tag.endswith("polygon")]
    assert len(polygons) == cells + 2  # the cells, the box, the polygon
    assert ET.fromstring(convexloc.figure_svg(6)).tag.endswith("svg")


def test_a_large_shape_shows_its_repr_in_a_notebook():
    big = convexloc.Polygon(regular_polygon(convexloc.SVG_LIMIT + 1))
    assert big._repr_svg_() is None and convexloc.PolarLocator(big)._repr_svg_() is None
    assert convexloc.Polygon(regular_polygon(100))._repr_svg_().startswith("<svg")
