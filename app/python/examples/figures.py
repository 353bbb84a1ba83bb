#!/usr/bin/python3
"""The paper's seven figures, drawn from the locators' cells() and trace() by convexloc's own
picture code (convexloc.figure for matplotlib, convexloc.figure_svg for SVG without it):

    python3 app/python/examples/figures.py [--svg] [OUTPUT_DIR]

writes fig1.png ... fig7.png with matplotlib, or fig1.svg ... fig7.svg with --svg or where
matplotlib is not installed. In a notebook, convexloc.figure(6) draws Fig. 6 inline.
"""

import sys
from pathlib import Path

import convexloc


def write_figures(out: Path, use_matplotlib: bool) -> list[Path]:
    """Every figure into `out`: PNG through matplotlib when asked and installed, else SVG."""
    written = []
    if use_matplotlib:
        try:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError:
            use_matplotlib = False
    for number in range(1, 8):
        if use_matplotlib:
            path = out / f"fig{number}.png"
            ax = convexloc.figure(number)
            ax.figure.savefig(path, dpi=150)
            plt.close(ax.figure)
        else:
            path = out / f"fig{number}.svg"
            path.write_text(convexloc.figure_svg(number))
        written.append(path)
    return written


def main(argv: list[str]) -> None:
    flags = [a for a in argv[1:] if a.startswith("--")]
    places = [a for a in argv[1:] if not a.startswith("--")]
    out = Path(places[0]) if places else Path(".")
    out.mkdir(parents=True, exist_ok=True)
    for path in write_figures(out, "--svg" not in flags):
        print(path)


if __name__ == "__main__":
    main(sys.argv)
