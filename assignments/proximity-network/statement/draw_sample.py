"""Draw the statement's picture (sample.png): the sample's Gabriel graph and the blocked pair 2-3.

Run from the checkout: .venv/bin/python assignments/proximity-network/statement/draw_sample.py
The edges come from reference_impl.gabriel_graph.

Example:
    python assignments/proximity-network/statement/draw_sample.py   # writes .../statement/sample.png
"""
from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from reference_impl import gabriel_graph  # noqa: E402

HERE = Path(__file__).resolve().parent


def main() -> Path:
    tok = (HERE.parent / "data" / "sample" / "1-tutorial.in").read_text().split()
    pts = [(float(tok[1 + 2 * i]), float(tok[2 + 2 * i])) for i in range(int(tok[0]))]
    fig, ax = plt.subplots(figsize=(3.6, 2.8), dpi=100)
    for i, j in gabriel_graph(pts).tolist():
        ax.plot([pts[i][0], pts[j][0]], [pts[i][1], pts[j][1]], color="tab:blue", lw=2)
    (x2, y2), (x3, y3) = pts[2], pts[3]
    centre, r = ((x2 + x3) / 2, (y2 + y3) / 2), ((x2 - x3) ** 2 + (y2 - y3) ** 2) ** 0.5 / 2
    ax.add_patch(plt.Circle(centre, r, fill=False, ls="--", color="tab:red"))
    ax.plot([x2, x3], [y2, y3], color="tab:red", ls=":", lw=1)
    ax.scatter(*zip(*pts), color="black", zorder=3)
    for k, (x, y) in enumerate(pts):
        ax.annotate(f"{k} ({x:g}, {y:g})", (x, y), xytext=(5, 4), textcoords="offset points", fontsize=8)
    ax.set_xlim(0, 6.8)
    ax.set_ylim(0, 4.8)
    ax.set_aspect("equal")
    ax.set_title("Gabriel edges (blue); 2-3 is blocked by point 1", fontsize=9)
    out = HERE / "sample.png"
    fig.savefig(out, bbox_inches="tight")
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main())
