"""Draw the statement's picture (sample.png): the sample's points and its closest pairs.

Run from the checkout: .venv/bin/python assignments/closest-pair/statement/draw_sample.py
The minimum distance comes from reference_impl.closest_pair; every pair at that distance is drawn.

Example:
    python assignments/closest-pair/statement/draw_sample.py   # writes .../statement/sample.png
"""
from __future__ import annotations

from itertools import combinations
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from reference_impl import closest_pair  # noqa: E402

HERE = Path(__file__).resolve().parent


def main() -> Path:
    tok = (HERE.parent / "data" / "sample" / "1-tutorial.in").read_text().split()
    pts = [(float(tok[1 + 2 * i]), float(tok[2 + 2 * i])) for i in range(int(tok[0]))]

    def sq(i: int, j: int) -> float:
        return (pts[i][0] - pts[j][0]) ** 2 + (pts[i][1] - pts[j][1]) ** 2

    best = sq(*closest_pair(pts))
    fig, ax = plt.subplots(figsize=(3.6, 2.6), dpi=100)
    for i, j in combinations(range(len(pts)), 2):
        close = sq(i, j) == best  # small integers: exact in floats
        ax.plot([pts[i][0], pts[j][0]], [pts[i][1], pts[j][1]], color="tab:blue" if close else "0.85",
                lw=2 if close else 1, ls="-" if close else "--")
    ax.scatter(*zip(*pts), color="black", zorder=3)
    for k, (x, y) in enumerate(pts):
        ax.annotate(f"{k} ({x:g}, {y:g})", (x, y), xytext=(5, 4), textcoords="offset points", fontsize=8)
    ax.set_xlim(0, 6.5)
    ax.set_ylim(0, 5)
    ax.set_aspect("equal")
    ax.set_title("closest pairs (blue): distance √5", fontsize=9)
    out = HERE / "sample.png"
    fig.savefig(out, bbox_inches="tight")
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main())
