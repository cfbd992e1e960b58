"""Draw the statement's picture (sample.png): the sample room and its shortest path.

Run from the checkout: .venv/bin/python assignments/navmesh/statement/draw_sample.py
The path comes from reference_impl.NavMesh.shortest_path; the picture is committed (small PNG).

Example:
    python assignments/navmesh/statement/draw_sample.py    # writes assignments/navmesh/statement/sample.png
"""
from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from reference_impl import NavMesh  # noqa: E402

HERE = Path(__file__).resolve().parent


def main() -> Path:
    tok = (HERE.parent / "data" / "sample" / "1-pillar.in").read_text().split()
    vals = iter(tok)

    def ring():
        n = int(next(vals))
        return [(float(next(vals)), float(next(vals))) for _ in range(n)]

    boundary = ring()
    holes = [ring() for _ in range(int(next(vals)))]
    start, goal = (float(next(vals)), float(next(vals))), (float(next(vals)), float(next(vals)))
    path = NavMesh(boundary, holes).shortest_path(start, goal)
    fig, ax = plt.subplots(figsize=(3.2, 3.2), dpi=100)
    ax.plot(*zip(*(boundary + boundary[:1])), color="black", lw=1.5)
    for h in holes:
        ax.fill(*zip(*h), color="grey", alpha=0.6)
    ax.plot(*zip(*path), color="tab:red", lw=2, marker="o", ms=4)
    for name, (x, y) in (("start", start), ("goal", goal)):
        ax.annotate(f"{name} ({x:g}, {y:g})", (x, y), xytext=(4, 5), textcoords="offset points", fontsize=8)
    ax.set_aspect("equal")
    ax.set_title(f"shortest path, length {sum(((a[0]-b[0])**2+(a[1]-b[1])**2)**0.5 for a, b in zip(path, path[1:])):.3f}", fontsize=9)
    out = HERE / "sample.png"
    fig.savefig(out, bbox_inches="tight")
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main())
