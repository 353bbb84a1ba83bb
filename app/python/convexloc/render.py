"""A Scene (drawing.py) drawn by matplotlib, or written as SVG; and the public entry points
convexloc.plot, convexloc.figure and convexloc.svg. matplotlib is optional: it is imported
when plot or figure is called, never by `import convexloc`."""

from __future__ import annotations

from html import escape
from typing import Any

import numpy as np

from .drawing import Scene, paper_figure, scene

__all__ = ["plot", "figure", "svg", "figure_svg", "draw", "to_svg"]


def draw(made: Scene, ax: Any = None) -> Any:
    """The Scene on matplotlib Axes `ax` (a new figure's when None); returns the Axes."""
    # matplotlib: optional, and Debian's ships no type information
    import matplotlib.pyplot as plt  # type: ignore[import]
    from matplotlib.collections import PolyCollection  # type: ignore[import]

    fresh = ax is None
    if ax is None:
        _, ax = plt.subplots(figsize=(7.2, 5.2))
    for item in made.items:
        if item.kind == "polygons":
            ax.add_collection(PolyCollection(item.points, facecolors=item.fills,
                                             edgecolors=item.stroke, linewidths=item.width))
        elif item.kind == "line":
            p = item.points[0]
            ax.plot(p[:, 0], p[:, 1], color=item.stroke, linewidth=item.width,
                    linestyle="--" if item.dashed else "-")
        elif item.kind == "dots":
            p = item.points[0]
            ax.scatter(p[:, 0], p[:, 1], s=item.size ** 2, color=item.stroke, zorder=3,
                       label=item.label or None)
        else:
            x, y = item.points[0][0]
            ax.text(x, y, item.text, fontsize=item.size, color=item.stroke, ha="center",
                    va="center")
    x0, y0, x1, y1 = made.bounds()
    pad = 0.04 * max(x1 - x0, y1 - y0, 1e-300)
    ax.set_xlim(x0 - pad, x1 + pad)
    ax.set_ylim(y0 - pad, y1 + pad)
    ax.set_aspect("equal")
    ax.set_title(made.title, fontsize=9, wrap=True)
    from matplotlib.patches import Patch  # type: ignore[import]

    handles = [Patch(facecolor=c, edgecolor="#8c8c8c", label=t) for c, t in made.legend]
    dots, labels = ax.get_legend_handles_labels()
    if handles or dots:
        ax.legend(handles=handles + dots, labels=[t for _, t in made.legend] + labels,
                  fontsize=7, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    if fresh:
        ax.figure.tight_layout()  # the legend beside the axes stays inside the figure
    return ax


def to_svg(made: Scene, width: int = 480) -> str:
    """The Scene as an SVG document `width` pixels wide (y up, scaled to fit)."""
    x0, y0, x1, y1 = made.bounds()
    margin, title = 12.0, 18.0 if made.title else 0.0
    span = max(x1 - x0, y1 - y0, 1e-300)
    scale = (width - 2 * margin) / span
    height = (y1 - y0) * scale + 2 * margin + title + 14.0 * len(made.legend)

    def xy(p: Any) -> str:
        return " ".join(f"{margin + (x - x0) * scale:.2f},{title + margin + (y1 - y) * scale:.2f}"
                        for x, y in np.asarray(p))

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height:.0f}" '
           f'viewBox="0 0 {width} {height:.0f}">',
           f"<title>{escape(made.title)}</title>",
           '<rect width="100%" height="100%" fill="white"/>']
    if made.title:
        # a sans-serif letter is about 0.55 of the font size wide: the title fits the width
        size = min(11.0, (width - 2 * margin) / (0.55 * len(made.title)))
        out.append(f'<text x="{margin}" y="13" font-size="{size:.1f}" '
                   f'font-family="sans-serif">{escape(made.title)}</text>')
    for item in made.items:
        out += _svg_item(item, xy)
    for k, (colour, words) in enumerate(made.legend):
        y = height - 14.0 * (len(made.legend) - k) + 2
        out.append(f'<rect x="{margin}" y="{y:.1f}" width="10" height="10" fill="{colour}" '
                   'stroke="#8c8c8c"/>')
        out.append(f'<text x="{margin + 14}" y="{y + 9:.1f}" font-size="10" '
                   f'font-family="sans-serif">{escape(words)}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def _svg_item(item: Any, xy: Any) -> list[str]:
    if item.kind == "polygons":
        return [f'<polygon points="{xy(p)}" fill="{fill}" stroke="{item.stroke}" '
                f'stroke-width="{item.width}"/>' for p, fill in zip(item.points, item.fills)]
    if item.kind == "line":
        dash = ' stroke-dasharray="4 3"' if item.dashed else ""
        return [f'<polyline points="{xy(item.points[0])}" fill="none" stroke="{item.stroke}" '
                f'stroke-width="{item.width}"{dash}/>']
    if item.kind == "dots":
        r = item.size / 2
        return [f'<circle cx="{c.split(",")[0]}" cy="{c.split(",")[1]}" r="{r}" '
                f'fill="{item.stroke}"/>' for c in xy(item.points[0]).split()]
    x, y = xy(item.points[0]).split(",")
    return [f'<text x="{x}" y="{y}" font-size="{item.size}" fill="{item.stroke}" '
            f'text-anchor="middle" dominant-baseline="middle" font-family="sans-serif">'
            f"{escape(item.text)}</text>"]


# === The public entry points


def plot(locator_or_shape: Any, points: Any = None, trace: Any = None, ax: Any = None) -> Any:
    """Draws a shape or a locator with matplotlib (an optional dependency): the shape, its
    subdivision (polar slabs and other cells filled by the edges each lists, with the count
    written in small subdivisions; the cube map's cells as a net of the cube around its
    centre), `points` classified by the locator (a shape's: polar, cubemap) and coloured by
    Location, and the query of the point `trace` step by step (its cell, each ray and edge
    tested coloured by sign, the answer). Returns the matplotlib Axes."""
    return draw(scene(locator_or_shape, points, trace), ax)


def figure(number: int, ax: Any = None) -> Any:
    """The paper's figure `number` (1 to 7) with matplotlib, drawn by plot's own code."""
    return draw(paper_figure(number), ax)


def svg(locator_or_shape: Any, points: Any = None, trace: Any = None) -> str:
    """What plot draws, as SVG text, without matplotlib (what notebooks show for shapes and
    locators through _repr_svg_)."""
    return to_svg(scene(locator_or_shape, points, trace))


def figure_svg(number: int) -> str:
    """The paper's figure `number` as SVG text, without matplotlib."""
    return to_svg(paper_figure(number))
