"""Draw the statement's picture of sample 2 (five points, three tetrahedra) into sample.png.

Run from the repository root:  .venv/bin/python assignments/delaunay-3d/statement/draw_sample.py
The tetrahedra come from ``reference_impl.delaunay_3d``; matplotlib renders off-screen (Agg).
"""
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from reference_impl import delaunay_3d  # noqa: E402

HERE = Path(__file__).resolve().parent


def main() -> Path:
    text = (HERE.parent / "data" / "sample" / "2-five-points.in").read_text().split()
    pts = np.array(text[1:], dtype=float).reshape(-1, 3)
    tets = delaunay_3d(pts)
    fig = plt.figure(figsize=(4.2, 3.6), dpi=100)
    ax = fig.add_subplot(projection="3d")
    edges = {tuple(sorted((t[i], t[j]))) for t in tets.tolist() for i in range(4) for j in range(i + 1, 4)}
    for a, b in sorted(edges):
        colour, width = ("tab:red", 2.0) if (a, b) == (0, 4) else ("tab:blue", 1.0)
        ax.plot(*pts[[a, b]].T, color=colour, lw=width)
    ax.scatter(*pts.T, color="black", s=18, depthshade=False)
    for i, p in enumerate(pts):
        ax.text(*(p + 0.04), str(i), fontsize=10)
    ax.set_title("sample 2: three tetrahedra around edge 0-4", fontsize=9)
    ax.view_init(elev=18, azim=-62)
    ax.set_xticks([0, 1])
    ax.set_yticks([0, 1])
    ax.set_zticks([0, 1])
    out = HERE / "sample.png"
    fig.savefig(out, bbox_inches="tight")
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main())
