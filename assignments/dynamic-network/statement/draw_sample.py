"""Draw the statement's picture (sample.png): the sample's links before and after node 1 fails.

Run from the checkout: .venv/bin/python assignments/dynamic-network/statement/draw_sample.py
The links come from reference_impl.structures.dynamic.DynamicNetwork; the picture is committed (small PNG).

Example:
    python assignments/dynamic-network/statement/draw_sample.py    # writes .../statement/sample.png
"""
from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from reference_impl.structures.dynamic import DynamicNetwork  # noqa: E402

HERE = Path(__file__).resolve().parent


def main() -> Path:
    lines = (HERE.parent / "data" / "sample" / "1-tutorial.in").read_text().split("\n")[1:]
    pts = [(float(p[1]), float(p[2])) for p in (ln.split() for ln in lines) if p and p[0] == "join"]
    net = DynamicNetwork()
    for x, y in pts:
        net.join(x, y)
    fig, axes = plt.subplots(1, 2, figsize=(6.4, 2.6), dpi=100)
    for ax, title in zip(axes, ("before", "after fail 1")):
        title += f": {len(net.links())} links"
        for i, j in net.links():
            ax.plot([pts[i][0], pts[j][0]], [pts[i][1], pts[j][1]], color="tab:blue", lw=2)
        live = net.nodes()
        ax.scatter([pts[k][0] for k in live], [pts[k][1] for k in live], color="black", zorder=3)
        for k in live:
            ax.annotate(f"{k} ({pts[k][0]:g}, {pts[k][1]:g})", pts[k], xytext=(5, 4), textcoords="offset points",
                        fontsize=8)
        ax.set_xlim(0, 6.5)
        ax.set_ylim(0, 5)
        ax.set_aspect("equal")
        ax.set_title(title, fontsize=9)
        if title.startswith("before"):
            net.fail(1)
    out = HERE / "sample.png"
    fig.savefig(out, bbox_inches="tight")
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main())
