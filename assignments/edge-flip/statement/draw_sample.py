"""Draw the statement's picture of sample 3 (a fan of a hexagon, three flips) into sample.png.

Run from the repository root:  .venv/bin/python assignments/edge-flip/statement/draw_sample.py
The flips and the final triangles come from ``reference_impl.lawson_flip``; matplotlib renders
off-screen (Agg).
"""
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from reference_impl import lawson_flip  # noqa: E402

HERE = Path(__file__).resolve().parent


def main() -> Path:
    tok = (HERE.parent / "data" / "sample" / "3-fan.in").read_text().split()
    n, m = int(tok[0]), int(tok[1])
    pts = [(float(tok[2 + 2 * i]), float(tok[3 + 2 * i])) for i in range(n)]
    tris = [[int(v) for v in tok[2 + 2 * n + 3 * k: 5 + 2 * n + 3 * k]] for k in range(m)]
    final, flips = lawson_flip(pts, tris)
    fig, axes = plt.subplots(1, 2, figsize=(7.0, 2.2), dpi=100)
    for ax, T, title in ((axes[0], tris, "start: the fan from point 0"),
                         (axes[1], final.tolist(), f"after the flips {', '.join(f'{a}-{b}' for a, b in flips)}")):
        for t in T:
            cyc = list(t) + [t[0]]
            ax.plot([pts[v][0] for v in cyc], [pts[v][1] for v in cyc], color="tab:blue", lw=1.0)
        if T is tris:
            for a, b in flips:
                ax.plot([pts[a][0], pts[b][0]], [pts[a][1], pts[b][1]], color="tab:red", lw=2.0)
        ax.scatter([p[0] for p in pts], [p[1] for p in pts], color="black", s=14, zorder=3)
        for i, (x, y) in enumerate(pts):
            ax.annotate(str(i), (x, y), fontsize=9, xytext=(3, 3), textcoords="offset points")
        ax.set_title(title, fontsize=9)
        ax.set_aspect("equal")
        ax.axis("off")
    out = HERE / "sample.png"
    fig.savefig(out, bbox_inches="tight")
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main())
