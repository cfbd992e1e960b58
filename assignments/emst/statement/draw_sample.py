"""Draw the statement's picture (sample.png): the sample's points and its minimum spanning tree.

Run from the checkout: .venv/bin/python assignments/emst/statement/draw_sample.py
The tree comes from reference_impl.euclidean_mst; the picture is committed (small PNG).

Example:
    python assignments/emst/statement/draw_sample.py    # writes assignments/emst/statement/sample.png
"""
from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from reference_impl import euclidean_mst  # noqa: E402

HERE = Path(__file__).resolve().parent


def main() -> Path:
    tok = (HERE.parent / "data" / "sample" / "1-tutorial.in").read_text().split()
    pts = [(float(tok[1 + 2 * i]), float(tok[2 + 2 * i])) for i in range(int(tok[0]))]
    fig, ax = plt.subplots(figsize=(3.6, 2.6), dpi=100)
    for i, j in euclidean_mst(pts).tolist():
        ax.plot([pts[i][0], pts[j][0]], [pts[i][1], pts[j][1]], color="tab:blue", lw=2)
    ax.scatter(*zip(*pts), color="black", zorder=3)
    for k, (x, y) in enumerate(pts):
        ax.annotate(f"{k} ({x:g}, {y:g})", (x, y), xytext=(5, 4), textcoords="offset points", fontsize=8)
    ax.set_xlim(0, 6.5)
    ax.set_ylim(0, 5)
    ax.set_aspect("equal")
    ax.set_title("minimum spanning tree: 3 edges of length √5", fontsize=9)
    out = HERE / "sample.png"
    fig.savefig(out, bbox_inches="tight")
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main())
