"""Drawing for the lesson widgets: one persistent Agg figure rendered to PNG bytes, and helpers.

Run the examples:  python -m pytest reference_impl/kit/render.py

Every kit widget draws with matplotlib's Agg renderer into a ``Canvas`` that it
keeps for its whole life (no pyplot, no new figure per frame) and shows the PNG
bytes in an ``ipywidgets.Image``.  The same bytes are the static picture a
headless notebook keeps.  The PNG is exactly ``width x height`` pixels and the
axes never move, so a click at image pixel (px, py) maps back to data
coordinates with ``Canvas.to_data``.

>>> c = Canvas(width=200, height=160)
>>> ax = c.clear(bounds=(0, 0, 4, 3))
>>> pts = [(0, 0), (4, 0), (2, 3)]
>>> draw_triangles(ax, pts, [(0, 1, 2)]); draw_points(ax, pts, labels=True)
>>> png = c.png()
>>> png[:4] == b"\\x89PNG", png_size(png)
(True, (200, 160))
>>> x, y = c.to_data(*c.to_pixel(2, 1.5)); round(x, 6), round(y, 6)
(2.0, 1.5)
"""
from __future__ import annotations

import io
import math
import struct
from typing import Callable, Iterable, Sequence

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.figure import Figure
from matplotlib.patches import Circle

__all__ = ["Canvas", "show_figure", "draw_points", "draw_triangles", "fill_triangles", "draw_edges",
           "draw_circumcircle", "circumcircle", "filmstrip", "png_size", "fit_bounds",
           "COLORS"]

COLORS = {
    "edge": "#555555", "point": "#1f4e9c", "future": "#b8b8b8", "new_point": "#d62728",
    "bad": "#f4a6a6", "boundary": "#d62728", "new": "#a6dba0", "located": "#ffd27f",
    "circle": "#d62728", "hull": "#2a7f2a", "voronoi": "#7b3fa0", "flip": "#ff7f0e",
}
"""One palette for every lesson, so "bad" and "new" look the same everywhere."""

Bounds = tuple[float, float, float, float]


def _forget_drawing(ax) -> bool:
    """Take every artist a drawing added off ``ax`` and undo the settings the kit's drawings change;
    ``False`` when the axes holds more than that (log scales, a hidden frame, ticks), and only
    ``cla`` can be trusted.

    ``cla`` rebuilds both axes' ticks and spines: that was more than half of the kernel's answer to
    a dragged point of 100 (a median of 72 ms, 25 ms without it, on a loaded 2-core machine).  The
    kit hides the ticks anyway, so a drawing that stayed on linear axes is cleared by removing what
    it added.

    >>> c = Canvas(100, 80); ax = c.clear(bounds=(0, 0, 1, 1))
    >>> _ = ax.plot([0, 1], [0, 1]); _ = ax.text(0.5, 0.5, "x"); _ = ax.legend(["a"])
    >>> _forget_drawing(ax), len(ax.get_lines()), len(ax.texts), ax.get_legend()
    (True, 0, 0, None)
    >>> ax.set_xscale("log"); _forget_drawing(ax)
    False
    """
    if ((ax.get_xscale(), ax.get_yscale()) != ("linear", "linear") or not ax.axison
            or len(ax.get_xticks()) or len(ax.get_yticks())):
        return False
    for group in (ax.lines, ax.collections, ax.patches, ax.texts, ax.images, ax.artists, ax.tables):
        for artist in list(group):
            artist.remove()
    if ax.get_legend() is not None:
        ax.get_legend().remove()
    ax.relim()                           # the data limits forget the removed artists, as after cla
    for loc in ("left", "right"):
        if ax.get_title(loc):
            ax.set_title("", loc=loc)
    if ax.get_xlabel() or ax.get_ylabel():
        ax.set_xlabel("")
        ax.set_ylabel("")
    return True


class Canvas:
    """One Agg figure with one equal-aspect axes that fills it; ``png()`` renders it.

    >>> c = Canvas(width=120, height=100)
    >>> _ = c.clear(bounds=(0, 0, 1, 1), title="empty")
    >>> png_size(c.png())
    (120, 100)
    """

    def __init__(self, width: int = 480, height: int = 400, dpi: int = 100) -> None:
        self.width, self.height, self.dpi = int(width), int(height), int(dpi)
        self.figure = Figure(figsize=(self.width / dpi, self.height / dpi), dpi=dpi)
        FigureCanvasAgg(self.figure)
        self.ax = self.figure.add_axes((0.02, 0.02, 0.96, 0.90))
        self.bounds: Bounds = (0.0, 0.0, 1.0, 1.0)

    def clear(self, bounds: Bounds | None = None, title: str = "") -> "Axes":  # noqa: F821
        """Empty the axes, fix the view to ``bounds`` (equal aspect, no ticks); return the axes."""
        ax = self.ax
        if not _forget_drawing(ax):
            ax.cla()
        if bounds is not None:
            self.bounds = tuple(float(v) for v in bounds)  # type: ignore[assignment]
        x0, y0, x1, y1 = self.bounds
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
        ax.set_aspect("equal", adjustable="box")
        if len(ax.get_xticks()) or len(ax.get_yticks()):
            ax.set_xticks([])
            ax.set_yticks([])
        ax.set_title(title, fontsize=10)
        return ax

    def png(self) -> bytes:
        """The figure as PNG bytes (fast zlib level: frames are shown, not archived)."""
        buf = io.BytesIO()
        self.figure.savefig(buf, format="png", dpi=self.dpi, pil_kwargs={"compress_level": 1})
        return buf.getvalue()

    def to_pixel(self, x: float, y: float) -> tuple[float, float]:
        """Data coordinates -> image pixels (origin top-left, as a browser reports clicks)."""
        px, py = self.to_pixels([(x, y)])[0]
        return float(px), float(py)

    def to_pixels(self, points) -> np.ndarray:
        """``to_pixel`` of every point at once: an (n, 2) array (no drawing needed: the axes
        box is fixed, and ``apply_aspect`` places it as a draw would)."""
        P = np.asarray(points, dtype=float).reshape(-1, 2)
        self.ax.apply_aspect()
        if len(P) == 0:
            return np.zeros((0, 2))
        Q = self.ax.transData.transform(P)
        Q[:, 1] = self.height - Q[:, 1]
        return Q

    def to_data(self, px: float, py: float) -> tuple[float, float]:
        """Image pixels (origin top-left) -> data coordinates."""
        self.ax.apply_aspect()
        x, y = self.ax.transData.inverted().transform((px, self.height - py))
        return float(x), float(y)


def png_size(png: bytes) -> tuple[int, int]:
    """(width, height) read from a PNG header.

    >>> png_size(Canvas(width=64, height=48).png())
    (64, 48)
    """
    if png[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not PNG data")
    return struct.unpack(">II", png[16:24])


def fit_bounds(points, margin: float = 0.12, square_min: float = 1e-9) -> Bounds:
    """A view box around ``points`` with a relative margin (a unit box when there are none).

    >>> fit_bounds([(1, 1), (5, 4)])
    (0.52, 0.52, 5.48, 4.48)
    """
    P = np.asarray(points, dtype=float).reshape(-1, 2)
    if len(P) == 0:
        return (0.0, 0.0, 1.0, 1.0)
    lo, hi = P.min(axis=0), P.max(axis=0)
    span = max(float((hi - lo).max()), square_min)
    pad = margin * span
    return tuple(round(float(v), 12) for v in (lo[0] - pad, lo[1] - pad, hi[0] + pad, hi[1] + pad))


def draw_points(ax, points, *, labels: bool | Sequence[str] = False, color: str = COLORS["point"],
                size: float = 28, zorder: int = 5, fontsize: int = 9) -> None:
    """Scatter the points; ``labels=True`` writes each index next to its point."""
    P = np.asarray(points, dtype=float).reshape(-1, 2)
    if len(P) == 0:
        return
    ax.scatter(P[:, 0], P[:, 1], s=size, color=color, zorder=zorder, edgecolors="white", linewidths=0.6)
    if labels is not False:
        names = [str(i) for i in range(len(P))] if labels is True else list(labels)
        for (x, y), name in zip(P, names):
            ax.annotate(name, (x, y), xytext=(4, 4), textcoords="offset points", fontsize=fontsize,
                        zorder=zorder + 1)


def _polygons(points, triangles) -> np.ndarray:
    P = np.asarray(points, dtype=float).reshape(-1, 2)
    T = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    return P[T]


def draw_triangles(ax, points, triangles, *, color: str = COLORS["edge"], linewidth: float = 1.0,
                   zorder: int = 2) -> None:
    """Outline every triangle (point-index rows)."""
    polys = _polygons(points, triangles)
    if len(polys):
        ax.add_collection(PolyCollection(polys, facecolors="none", edgecolors=color,
                                         linewidths=linewidth, zorder=zorder))


def fill_triangles(ax, points, triangles, *, color: str, alpha: float = 0.8, zorder: int = 1) -> None:
    """Fill the given triangles (e.g. the bad ones in red, the new ones in green)."""
    polys = _polygons(points, triangles)
    if len(polys):
        ax.add_collection(PolyCollection(polys, facecolors=color, edgecolors="none", alpha=alpha,
                                         zorder=zorder))


def draw_edges(ax, points, edges, *, color: str = COLORS["boundary"], linewidth: float = 2.5,
               linestyle: str = "-", zorder: int = 3) -> None:
    """Draw edges given as pairs of point indices."""
    P = np.asarray(points, dtype=float).reshape(-1, 2)
    E = np.asarray(list(edges), dtype=np.int64).reshape(-1, 2)
    if len(E):
        ax.add_collection(LineCollection(P[E], colors=color, linewidths=linewidth,
                                         linestyles=linestyle, zorder=zorder))


def circumcircle(a, b, c) -> tuple[float, float, float]:
    """(cx, cy, r) of the circle through three points, in floating point (for drawing only).

    Collinear points have no circle: the radius is ``inf``.

    >>> circumcircle((0, 0), (2, 0), (0, 2))
    (1.0, 1.0, 1.4142135623730951)
    """
    ax_, ay = float(a[0]), float(a[1])
    bx, by = float(b[0]) - ax_, float(b[1]) - ay
    cx, cy = float(c[0]) - ax_, float(c[1]) - ay
    d = 2.0 * (bx * cy - by * cx)
    if d == 0.0:
        return (math.nan, math.nan, math.inf)
    b2, c2 = bx * bx + by * by, cx * cx + cy * cy
    ux = (cy * b2 - by * c2) / d
    uy = (bx * c2 - cx * b2) / d
    return (ax_ + ux, ay + uy, math.hypot(ux, uy))


def draw_circumcircle(ax, a, b, c, *, color: str = COLORS["circle"], linewidth: float = 1.2,
                      linestyle: str = "--", zorder: int = 4) -> None:
    """Draw the circumcircle of triangle abc (nothing when the points are collinear)."""
    cx, cy, r = circumcircle(a, b, c)
    if math.isfinite(r):
        ax.add_patch(Circle((cx, cy), r, fill=False, edgecolor=color, linewidth=linewidth,
                            linestyle=linestyle, zorder=zorder))


def filmstrip(draw: Callable[..., None], items: Iterable, *, columns: int = 4,
              frame: tuple[int, int] = (220, 190), titles: Sequence[str] | None = None) -> bytes:
    """One PNG with a small picture per item: ``draw(ax, item, k)`` draws frame k.

    This is the static stand-in for a step player: the steps side by side.

    >>> png = filmstrip(lambda ax, item, k: ax.plot([0, item], [0, 1]), [1, 2, 3], columns=2)
    >>> png_size(png)
    (440, 380)
    """
    items = list(items)
    columns = max(1, min(columns, len(items) or 1))
    rows = max(1, math.ceil(len(items) / columns))
    w, h = frame
    fig = Figure(figsize=(columns * w / 100, rows * h / 100), dpi=100)
    FigureCanvasAgg(fig)
    for k, item in enumerate(items):
        ax = fig.add_subplot(rows, columns, k + 1)
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_aspect("equal", adjustable="box")
        draw(ax, item, k)
        if titles is not None:
            ax.set_title(titles[k], fontsize=8)
    # fixed margins in pixels (room for a title above each row), not tight_layout: that draws the
    # whole figure once more to measure it, which doubled the cost of every player's static picture
    W, H = columns * w, rows * h
    fig.subplots_adjust(left=4 / W, right=1 - 4 / W, bottom=4 / H, top=1 - (18 if titles is not None else 4) / H,
                        wspace=0.05, hspace=0.1 if titles is not None else 0.03)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100, pil_kwargs={"compress_level": 6})
    return buf.getvalue()


def show_figure(fig, dpi: int = 90) -> None:
    """Display a matplotlib figure as a PNG and close it.

    Works whatever the matplotlib backend (``plt.show()`` under ``Agg``, as in
    headless runs, displays nothing), so an exported notebook keeps the picture.

    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots(); _ = ax.plot([0, 1]); show_figure(fig)   # doctest: +ELLIPSIS
    <IPython.core.display.Image object>
    """
    import matplotlib.pyplot as plt
    from IPython.display import Image, display

    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi, bbox_inches="tight")
    plt.close(fig)
    display(Image(buf.getvalue()))
