"""Draws statement/sample.png: sample 1 of `largest-empty-circle` with the answer from reference_impl.

Run from the checkout: .venv/bin/python assignments/largest-empty-circle/statement/draw_sample.py

Example (what it prints):
    sample.png: (4.5, 2.5, 1.5811388300841898)
"""
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402

from reference_impl import convex_hull, largest_empty_circle  # noqa: E402

HERE = Path(__file__).resolve().parent
POINTS = [(1, 1), (3, 2), (5, 1), (4, 4)]


def main() -> None:
    x, y, r = largest_empty_circle(POINTS)
    fig, ax = plt.subplots(figsize=(4.0, 3.6), dpi=90)
    hull = convex_hull(POINTS).tolist()
    cyc = [POINTS[i] for i in hull + hull[:1]]
    ax.fill([p[0] for p in cyc], [p[1] for p in cyc], color="0.92", zorder=0)
    ax.plot([p[0] for p in cyc], [p[1] for p in cyc], color="0.6", lw=0.8)
    ax.scatter([p[0] for p in POINTS], [p[1] for p in POINTS], color="black", s=18, zorder=3)
    for px, py in POINTS:
        ax.annotate(f"({px},{py})", (px, py), fontsize=7, xytext=(4, -9), textcoords="offset points")
    ax.add_patch(Circle((x, y), r, fill=False, color="tab:blue", lw=1.2))
    ax.plot([x], [y], marker="+", color="tab:blue", ms=9)
    ax.add_patch(Circle((3, -1.5), 2.5, fill=False, color="tab:red", lw=0.8, ls="--"))
    ax.annotate("empty, but centred outside the hull", (3, -1.5), fontsize=7, color="tab:red", ha="center")
    ax.set_title(f"centre ({x:g}, {y:g}), r = {r:.4f}", fontsize=9)
    ax.set_aspect("equal")
    ax.set_xlim(-0.2, 6.6)
    ax.set_ylim(-4.2, 4.6)
    fig.tight_layout()
    fig.savefig(HERE / "sample.png")
    print(f"sample.png: {(x, y, r)!r}")


if __name__ == "__main__":
    main()
