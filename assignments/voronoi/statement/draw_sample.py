"""Draws statement/sample.png: sample 1 of `voronoi` with the cells from reference_impl.

Run from the checkout: .venv/bin/python assignments/voronoi/statement/draw_sample.py

Example (what it prints):
    sample.png: 4 cells
"""
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from reference_impl import Delaunay, voronoi  # noqa: E402

HERE = Path(__file__).resolve().parent
POINTS = [(1, 1), (3, 2), (5, 1), (4, 4)]
BOX = (0, 0, 6, 5)
COLOURS = ["#cfe2f3", "#d9ead3", "#fff2cc", "#f4cccc"]


def main() -> None:
    cells = voronoi(POINTS, BOX)
    fig, ax = plt.subplots(figsize=(4.2, 3.6), dpi=90)
    for cell, colour in zip(cells, COLOURS):
        ax.fill(cell[:, 0], cell[:, 1], color=colour, ec="tab:blue", lw=1)
    for a, b, c in Delaunay(POINTS).simplices.tolist():
        cyc = [POINTS[v] for v in (a, b, c, a)]
        ax.plot([p[0] for p in cyc], [p[1] for p in cyc], color="0.55", lw=0.7, ls="--")
    ax.scatter([p[0] for p in POINTS], [p[1] for p in POINTS], color="black", s=18, zorder=3)
    for i, (x, y) in enumerate(POINTS):
        ax.annotate(f"{i}: ({x},{y})", (x, y), fontsize=7, xytext=(4, 4), textcoords="offset points")
    ax.set_title("Voronoi cells clipped to [0,6] x [0,5]", fontsize=9)
    ax.set_aspect("equal")
    ax.set_xlim(-0.3, 6.3)
    ax.set_ylim(-0.3, 5.3)
    fig.tight_layout()
    fig.savefig(HERE / "sample.png")
    print(f"sample.png: {len(cells)} cells")


if __name__ == "__main__":
    main()
