"""Draws statement/sample.png: sample 1 of `obstacle-clearance` with the answer from reference_impl.

Run from the checkout: .venv/bin/python assignments/obstacle-clearance/statement/draw_sample.py

Example (what it prints):
    sample.png: r = 1.019803902718557
"""
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402

from reference_impl import Delaunay, max_clearance  # noqa: E402

HERE = Path(__file__).resolve().parent
POINTS = [(1, 1), (3, 2), (5, 1), (4, 4)]
START, GOAL = (4, 2.2), (4, 8)


def main() -> None:
    r = max_clearance(POINTS, START, GOAL)
    fig, ax = plt.subplots(figsize=(3.6, 4.2), dpi=90)
    for a, b, c in Delaunay(POINTS).simplices.tolist():
        cyc = [POINTS[v] for v in (a, b, c, a)]
        ax.plot([p[0] for p in cyc], [p[1] for p in cyc], color="0.75", lw=0.8, zorder=1)
    ax.scatter([p[0] for p in POINTS], [p[1] for p in POINTS], color="black", s=18, zorder=3)
    for x, y in POINTS:
        ax.annotate(f"({x},{y})", (x, y), fontsize=7, xytext=(4, -9), textcoords="offset points")
    ax.add_patch(Circle(START, r, fill=False, color="tab:blue", lw=1.2))
    ax.plot([START[0], 6.2, 6.2, GOAL[0]], [START[1], 3.0, 6.0, GOAL[1]], ls="--", color="tab:blue", lw=0.8)
    for (x, y), label in ((START, "start"), (GOAL, "goal")):
        ax.plot([x], [y], marker="*", color="tab:red", ms=9, zorder=4)
        ax.annotate(label, (x, y), fontsize=8, xytext=(5, 3), textcoords="offset points")
    ax.set_title(f"r = {r:.4f}", fontsize=9)
    ax.set_aspect("equal")
    ax.set_xlim(0, 7.5)
    ax.set_ylim(-0.3, 8.6)
    fig.tight_layout()
    fig.savefig(HERE / "sample.png")
    print(f"sample.png: r = {r!r}")


if __name__ == "__main__":
    main()
