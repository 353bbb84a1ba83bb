"""Shared pieces of the Python tests: shapes, adversarial points, and the two references
(core's C++ locators through python_reference, and exact rational arithmetic)."""

import os
import subprocess
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import convexloc

# === Paths the CTest registration passes


def env_path(name):
    """The path in environment variable `name`, or skip when it is not set."""
    value = os.environ.get(name)
    if not value:
        pytest.skip(f"{name} is not set (run the tests through ctest)")
    return Path(value)


# === The documentation's code blocks


def doc_code_blocks():
    """Every ```python block of docs/python.md and of the README's "From Python" section, as
    (label, code) pairs; the label names the file and the block's first line."""
    root = env_path("CONVEXLOC_SOURCE_DIR")
    blocks = []
    for name in ("docs/python.md", "README.md"):
        text = (root / name).read_text()
        if name == "README.md":
            start = text.index("\n## From Python\n")
            end = text.find("\n## ", start + 1)
            text = text[start:end if end >= 0 else len(text)]
        lines = text.splitlines()
        k = 0
        while k < len(lines):
            if lines[k].strip() == "```python":
                first = k + 1
                k += 1
                while lines[k].strip() != "```":
                    k += 1
                blocks.append((f"{name}:{first + 1}", "\n".join(lines[first:k]) + "\n"))
            k += 1
    return blocks


# === Shapes


def regular_polygon(n, radius=1.0, centre=(0.0, 0.0)):
    """The n-gon's vertices, counter-clockwise (rounded to doubles, so edges are generic)."""
    t = 2 * np.pi * np.arange(n) / n
    return np.column_stack([centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)])


# an octagon with integer vertices: lattice points on its edges lie exactly on them
LATTICE_OCTAGON = np.array(
    [[0, 0], [8, 0], [12, 4], [12, 8], [8, 12], [0, 12], [-4, 8], [-4, 4]], dtype=float
)


def write_polygon(path, vertices):
    """A polygon file that reads back to exactly these doubles (repr is round-trip)."""
    path.write_text("".join(f"{x!r} {y!r}\n" for x, y in vertices))
    return path


def write_off(path, vertices, triangles):
    """An OFF file that reads back to exactly these doubles."""
    lines = ["OFF", f"{len(vertices)} {len(triangles)} 0"]
    lines += [" ".join(repr(float(c)) for c in v) for v in vertices]
    lines += ["3 " + " ".join(str(int(i)) for i in t) for t in triangles]
    path.write_text("\n".join(lines) + "\n")
    return path


# === Points


def ulp_ring(points, radius=1):
    """Each point and its neighbours up to `radius` ulps away in each coordinate."""
    out = [points]
    for axis in range(points.shape[1]):
        for k in range(1, radius + 1):
            for direction in (np.inf, -np.inf):
                moved = points.copy()
                for _ in range(k):
                    moved[:, axis] = np.nextafter(moved[:, axis], direction)
                out.append(moved)
    return np.concatenate(out)


def on_edges_lattice(vertices):
    """Integer points exactly on the edges of a polygon with integer vertices."""
    points = []
    n = len(vertices)
    for i in range(n):
        a, b = vertices[i], vertices[(i + 1) % n]
        d = (b - a).astype(int)
        g = np.gcd(abs(d[0]), abs(d[1]))
        for k in range(g + 1):
            points.append(a + d * k / g)
    return np.array(points)


def special_values(dims):
    """Points with infinite, NaN, huge, subnormal and signed-zero coordinates."""
    values = [0.0, -0.0, 5e-324, -5e-324, 1e-300, 1e300, -1e300, np.inf, -np.inf, np.nan,
              np.finfo(float).max, -np.finfo(float).max]
    rng = np.random.default_rng(7)
    return rng.choice(values, size=(400, dims))


def adversarial_points_2d(vertices, locator=None):
    """Vertices and their ulp neighbours, edge midpoints (near the edge) and their
    neighbours, the polar centre and rays through it, vertex heights, special values."""
    v = np.asarray(vertices, dtype=float)
    mid = (v + np.roll(v, -1, axis=0)) / 2
    parts = [ulp_ring(v, 2), ulp_ring(mid, 2), special_values(2)]
    if locator is not None and hasattr(locator, "centre"):
        c = np.array(locator.centre)
        rays = c + np.outer(np.linspace(-2, 2, 41), [1.0, 0.0])
        rays = np.concatenate([rays, c + np.outer(np.linspace(-2, 2, 41), [0.0, 1.0]),
                               c + np.outer(np.linspace(-2, 2, 41), [1.0, 1.0])])
        parts += [ulp_ring(c[None, :], 3), rays]
    heights = np.column_stack([np.linspace(v[:, 0].min(), v[:, 0].max(), len(v)), v[:, 1]])
    parts.append(ulp_ring(heights, 1))
    return np.concatenate(parts)


# === References


def reference_answers(shape_file, points, method, resolution=0, tmp_path=None):
    """The C++ locators' answers (Locator2D / Locator3D, one point at a time)."""
    program = env_path("CONVEXLOC_REFERENCE")
    points_file = tmp_path / "points.bin"
    answers_file = tmp_path / "answers.bin"
    np.ascontiguousarray(points, dtype=np.float64).tofile(points_file)
    subprocess.run([str(program), str(shape_file), str(points_file), method, str(resolution),
                    str(answers_file)], check=True)
    return np.fromfile(answers_file, dtype=np.int8)


def orient2d_exact(a, b, p):
    """The exact sign of the cross product (b - a) x (p - a) of doubles."""
    ax, ay = Fraction(a[0]), Fraction(a[1])
    det = (Fraction(b[0]) - ax) * (Fraction(p[1]) - ay) - (Fraction(b[1]) - ay) * (Fraction(p[0]) - ax)
    return (det > 0) - (det < 0)


def locate_exact_2d(vertices, points):
    """Eq. (1) in rational arithmetic: INSIDE, BOUNDARY or OUTSIDE for each point."""
    out = []
    n = len(vertices)
    for p in points:
        if not np.all(np.isfinite(p)):
            out.append(convexloc.OUTSIDE)
            continue
        signs = [orient2d_exact(vertices[i], vertices[(i + 1) % n], p) for i in range(n)]
        if min(signs) < 0:
            out.append(convexloc.OUTSIDE)
        else:
            out.append(convexloc.BOUNDARY if min(signs) == 0 else convexloc.INSIDE)
    return np.array(out, dtype=np.int8)


@pytest.fixture
def square():
    return convexloc.Polygon([[0, 0], [1, 0], [1, 1], [0, 1]])


@pytest.fixture
def cube():
    return convexloc.Polyhedron.hull(
        [[x, y, z] for x in (-1.0, 1.0) for y in (-1.0, 1.0) for z in (-1.0, 1.0)])
