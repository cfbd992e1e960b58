"""A matplotlib axes turned into a scene the browser draws: paths, circles, dots and text in pixels.

Run the examples:  python -m pytest reference_impl/kit/scene.py

The lessons draw their pickers' pictures with ordinary matplotlib calls
(``draw(ax, points)``: triangles, circumcircles, fills, plots, annotations).
``axes_scene`` reads back what such a call left on the axes and writes it as
plain JSON in image pixels (origin top-left, exactly where the Agg PNG would put
it), so that ``canvas.js`` can draw it as SVG.  Every vertex that lies on one of
the picker's points is written as that point's index, not only its position: while
the student drags point ``i`` the browser moves every vertex, dot, label and
circle that refers to ``i`` in the same frame, before the kernel has answered.

What a scene holds (every colour a ``#rrggbb`` string, every size in pixels)::

    {"w": 440, "h": 400, "clip": [x, y, w, h],      # the axes' box: items with "clip" stay inside
     "items": [{"t": "path",   "xy": [x0, y0, x1, y1, ...], "ref": [i or -1 per vertex],
                "n": [vertices per part], "closed": bool, "fill": [..], "fo": [..],
                "stroke": [..], "so": [..], "lw": [..], "dash": "4 2" or "", "z": zorder},
               {"t": "circle", "c": [x, y], "r": r, "through": [i, j, k] or [], ... style},
               {"t": "dots",   "xy": [...], "ref": [...], "r": [..], "fill": [..], "fo": [..],
                "stroke": [..], "lw": [..], "z": zorder},
               {"t": "text",   "xy": [x, y], "ref": i or -1, "dx": px, "dy": px, "s": "...",
                "size": px, "color": "#rrggbb", "ha": "left|center|right",
                "va": "top|center|baseline|bottom", "rot": degrees, "z": zorder}],
     "raster": ""}

Style lists cycle, as matplotlib's do: part ``k`` of a path item uses
``fill[k % len(fill)]``.  What the scene cannot say (images, contour fills,
meshes) is drawn by Agg into a transparent PNG, ``raster``, laid under the
vector items; only axes that hold such artists pay for a PNG.

>>> from reference_impl.kit.render import Canvas, draw_points, draw_triangles
>>> c = Canvas(200, 160)
>>> ax = c.clear(bounds=(0, 0, 4, 3), title="one triangle")
>>> pts = [(0, 0), (4, 0), (2, 3)]
>>> draw_triangles(ax, pts, [(0, 1, 2)]); draw_points(ax, pts)
>>> s = axes_scene(c, pts)
>>> [item["t"] for item in s["items"]]        # the triangle, the frame's four sides, the title, the dots
['path', 'path', 'path', 'path', 'path', 'text', 'dots']
>>> s["items"][0]["ref"], s["items"][-1]["ref"]
([0, 1, 2], [0, 1, 2])
>>> s["raster"]
''
"""
from __future__ import annotations

import base64
import io
import math
from typing import Any, Iterable

import numpy as np
from matplotlib.collections import Collection, LineCollection, PathCollection, PolyCollection
from matplotlib.colors import to_hex, to_rgba
from matplotlib.image import AxesImage
from matplotlib.lines import Line2D
from matplotlib.patches import Circle, Patch
from matplotlib.path import Path
from matplotlib.text import Annotation, Text

__all__ = ["axes_scene", "pixel_points"]

MATCH_PIXELS = 1e-6
"""A vertex this close (in pixels) to a picker point is written as that point's index."""

_VECTOR_COLLECTIONS = (PolyCollection, LineCollection, PathCollection)


def pixel_points(canvas, points) -> np.ndarray:
    """The points' positions in image pixels (origin top-left), an (n, 2) array: ``Canvas.to_pixels``.

    >>> from reference_impl.kit.render import Canvas
    >>> c = Canvas(100, 100); _ = c.clear(bounds=(0, 0, 1, 1))
    >>> pixel_points(c, [(0.5, 0.5)]).round(1).tolist()
    [[50.0, 53.0]]
    """
    return canvas.to_pixels(points)


class _Refs:
    """Index lookup: which picker point (if any) sits on a pixel position."""

    def __init__(self, pixels: np.ndarray) -> None:
        self.pixels = pixels
        self.order = np.lexsort((pixels[:, 1], pixels[:, 0])) if len(pixels) else np.zeros(0, int)
        self.sorted_x = pixels[self.order, 0] if len(pixels) else np.zeros(0)

    def of(self, xy: np.ndarray) -> list[int]:
        """The index of the picker point on each row of ``xy`` (-1 where there is none)."""
        out = np.full(len(xy), -1, dtype=np.int64)
        if len(self.pixels) == 0 or len(xy) == 0:
            return out.tolist()
        lo = np.searchsorted(self.sorted_x, xy[:, 0] - MATCH_PIXELS, side="left")
        hi = np.searchsorted(self.sorted_x, xy[:, 0] + MATCH_PIXELS, side="right")
        for row in np.nonzero(hi > lo)[0]:
            for k in self.order[lo[row]:hi[row]]:
                if abs(self.pixels[k, 1] - xy[row, 1]) <= MATCH_PIXELS:
                    out[row] = k
                    break
        return out.tolist()


def _flip(canvas, xy: np.ndarray) -> np.ndarray:
    xy = np.asarray(xy, dtype=float).reshape(-1, 2).copy()
    xy[:, 1] = canvas.height - xy[:, 1]
    return xy


def _colors(rgba: Iterable, alpha: float | None) -> tuple[list[str], list[float]]:
    """(hex colours, opacities) of a colour array; 'none' where a colour is fully transparent."""
    arr = np.asarray(rgba, dtype=float).reshape(-1, 4) if len(np.asarray(rgba)) else np.zeros((0, 4))
    if len(arr) == 0:
        return ["none"], [0.0]
    hexes, ops = [], []
    for r, g, b, a in arr:
        a = a if alpha is None else alpha
        hexes.append("none" if a == 0 else to_hex((r, g, b)))
        ops.append(round(float(a), 4))
    return hexes, ops


def _dash(style: Any, lw: float) -> str:
    if style in ("--", "dashed"):
        return f"{3.7 * lw:.3g} {1.6 * lw:.3g}"
    if style in (":", "dotted"):
        return f"{1 * lw:.3g} {1.65 * lw:.3g}"
    if style in ("-.", "dashdot"):
        return f"{6.4 * lw:.3g} {1.6 * lw:.3g} {1 * lw:.3g} {1.6 * lw:.3g}"
    return ""


def _collection_dash(c) -> str:
    dashes = c.get_dashes()
    if not dashes or dashes[0][1] is None:
        return ""
    return " ".join(f"{v:.3g}" for v in dashes[0][1])


def _rounded(xy: np.ndarray) -> list[float]:
    return [round(float(v), 3) for v in xy.ravel()]


def _path_item(canvas, refs, parts: list[np.ndarray], *, closed: bool, fill, fo, stroke, so, lw, dash,
               z) -> dict | None:
    parts = [p for p in parts if len(p)]
    if not parts:
        return None
    xy = _flip(canvas, np.vstack(parts))
    return {"t": "path", "xy": _rounded(xy), "ref": refs.of(xy), "n": [len(p) for p in parts],
            "closed": bool(closed), "fill": fill, "fo": fo, "stroke": stroke, "so": so,
            "lw": [round(float(v), 3) for v in lw], "dash": dash, "z": float(z)}


def _simple_parts(paths, transform) -> list[np.ndarray] | None:
    """Polylines of paths made only of one MOVETO and LINETOs (a CLOSEPOLY dropped), transformed in
    one call; ``None`` when some path has curves or several parts (``to_polygons`` handles those)."""
    verts = []
    for path in paths:
        codes = path.codes
        v = path.vertices
        if codes is not None:
            if codes[-1] == Path.CLOSEPOLY:
                codes, v = codes[:-1], v[:-1]
            if len(codes) and (codes[0] != Path.MOVETO or np.any(codes[1:] != Path.LINETO)):
                return None
        verts.append(v)
    if not verts:
        return []
    sizes = np.cumsum([len(v) for v in verts])[:-1]
    return np.split(transform.transform(np.vstack(verts)), sizes)


def _pt(canvas) -> float:
    """Pixels per typographic point."""
    return canvas.dpi / 72.0


def _collection(canvas, refs, c) -> list[dict]:
    alpha = c.get_alpha()
    lw = [w * _pt(canvas) for w in (np.atleast_1d(c.get_linewidths()) if len(c.get_linewidths()) else [0.0])]
    fill, fo = _colors(c.get_facecolors(), alpha)
    stroke, so = _colors(c.get_edgecolors(), alpha)
    if isinstance(c, PathCollection) and len(c.get_offsets()):          # scatter: one marker per offset
        offsets = c.get_offset_transform().transform(np.asarray(c.get_offsets(), dtype=float))
        xy = _flip(canvas, offsets)
        sizes = np.atleast_1d(c.get_sizes()) if len(c.get_sizes()) else np.array([36.0])
        radius = [round(float(math.sqrt(s) / 2 * _pt(canvas)), 3) for s in sizes]
        return [{"t": "dots", "xy": _rounded(xy), "ref": refs.of(xy), "r": radius, "fill": fill, "fo": fo,
                 "stroke": stroke, "so": so, "lw": [round(v, 3) for v in lw], "z": float(c.get_zorder())}]
    transform = c.get_transform()
    parts = _simple_parts(c.get_paths(), transform)
    if parts is None:                                  # curves or several sub-paths: let matplotlib flatten
        parts = [poly for path in c.get_paths() for poly in path.to_polygons(transform, closed_only=False)]
    closed = not isinstance(c, LineCollection)
    if closed:
        parts = [p[:-1] if len(p) > 1 and np.array_equal(p[0], p[-1]) else p for p in parts]
    item = _path_item(canvas, refs, parts, closed=closed, fill=fill if closed else ["none"],
                      fo=fo if closed else [0.0], stroke=stroke, so=so, lw=lw, dash=_collection_dash(c),
                      z=c.get_zorder())
    return [item] if item else []


def _style(canvas, patch: Patch) -> dict:
    alpha = patch.get_alpha()
    fill, fo = _colors([patch.get_facecolor()] if patch.get_fill() else [(0, 0, 0, 0)], alpha)
    stroke, so = _colors([patch.get_edgecolor()], alpha)
    lw = patch.get_linewidth() * _pt(canvas)
    return {"fill": fill, "fo": fo, "stroke": stroke, "so": so, "lw": [round(lw, 3)],
            "dash": _dash(patch.get_linestyle(), lw), "z": float(patch.get_zorder())}


def _patch(canvas, refs, patch: Patch, points_px: np.ndarray) -> list[dict]:
    if hasattr(patch, "_adjust_location"):      # a spine: its path is placed when it is drawn
        patch._adjust_location()
    style = _style(canvas, patch)
    if isinstance(patch, Circle):               # its path is the unit circle, placed by its transform
        centre, edge = _flip(canvas, patch.get_transform().transform([(0.0, 0.0), (1.0, 0.0)]))
        r = float(np.hypot(*(edge - centre)))
        through: list[int] = []
        if len(points_px) and r > 0:
            d = np.abs(np.hypot(points_px[:, 0] - centre[0], points_px[:, 1] - centre[1]) - r)
            on = np.nonzero(d <= 1e-6 * max(r, 1.0) + 1e-6)[0]
            through = [int(i) for i in on[:3]] if len(on) >= 3 else []
        return [{"t": "circle", "c": _rounded(centre), "r": round(r, 3), "through": through, **style}]
    parts = patch.get_path().to_polygons(patch.get_transform(), closed_only=False)
    closed = bool(patch.get_fill()) or any(len(p) > 2 and np.array_equal(p[0], p[-1]) for p in parts)
    parts = [p[:-1] if len(p) > 1 and np.array_equal(p[0], p[-1]) else p for p in parts]
    item = _path_item(canvas, refs, parts, closed=closed, **style)
    return [item] if item else []


_MARKERS_ROUND = {"o", ".", "8", "h", "H", "p", "*", "s", "D", "d", "^", "v", "<", ">", "P", "X", "x", "+"}


def _line(canvas, refs, line: Line2D) -> list[dict]:
    xy = line.get_transform().transform(np.asarray(line.get_xydata(), dtype=float))
    xy = xy[np.all(np.isfinite(xy), axis=1)]
    out = []
    alpha = line.get_alpha()
    color, op = _colors([to_rgba(line.get_color())], alpha)
    lw = line.get_linewidth() * _pt(canvas)
    if line.get_linestyle() not in ("None", "none", "", " ") and len(xy) >= 2:
        item = _path_item(canvas, refs, [xy], closed=False, fill=["none"], fo=[0.0], stroke=color, so=op,
                          lw=[lw], dash=_dash(line.get_linestyle(), lw), z=line.get_zorder())
        if item:
            out.append(item)
    marker = line.get_marker()
    if marker in _MARKERS_ROUND and len(xy):
        pix = _flip(canvas, xy)
        face, fop = _colors([to_rgba(line.get_markerfacecolor())], alpha)
        edge, eop = _colors([to_rgba(line.get_markeredgecolor())], alpha)
        r = line.get_markersize() / 2 * _pt(canvas)
        if marker == ".":
            r /= 2
        out.append({"t": "dots", "xy": _rounded(pix), "ref": refs.of(pix), "r": [round(r, 3)], "fill": face,
                    "fo": fop, "stroke": edge, "so": eop,
                    "lw": [round(line.get_markeredgewidth() * _pt(canvas), 3)], "z": float(line.get_zorder())})
    return out


_HA = {"left": "left", "center": "center", "right": "right"}
_VA = {"top": "top", "center": "center", "center_baseline": "center", "baseline": "baseline", "bottom": "bottom"}


def _text(canvas, refs, text: Text) -> list[dict]:
    s = text.get_text()
    if not s or not text.get_visible():
        return []
    dx = dy = 0.0
    ref = -1
    if isinstance(text, Annotation):
        text.update_positions(canvas.figure.canvas.get_renderer())   # where Agg would put the text
        pos = _flip(canvas, text.get_transform().transform([text.get_position()]))[0]
        r = -1
        if text.xycoords == "data":                 # the annotated point, in pixels
            anchor = _flip(canvas, canvas.ax.transData.transform([text.xy]))[0]
            r = refs.of(anchor[None, :])[0]
        if r >= 0:                                  # a label that follows its point: keep the offset
            ref, dx, dy = r, float(pos[0] - anchor[0]), float(pos[1] - anchor[1])
        xy = pos
    else:
        xy = _flip(canvas, text.get_transform().transform([text.get_position()]))[0]
    color, _ = _colors([to_rgba(text.get_color())], None)
    return [{"t": "text", "xy": _rounded(xy), "ref": int(ref), "dx": round(dx, 3), "dy": round(dy, 3), "s": s,
             "size": round(text.get_fontsize() * _pt(canvas), 3), "color": color[0],
             "ha": _HA.get(text.get_horizontalalignment(), "left"),
             "va": _VA.get(text.get_verticalalignment(), "baseline"),
             "rot": round(float(text.get_rotation()), 3), "z": float(text.get_zorder())}]


def _raster(canvas, hidden: list) -> str:
    """A transparent PNG of the axes with every artist in ``hidden`` switched off (a data: URL)."""
    fig, ax = canvas.figure, canvas.ax
    was = [(a, a.get_visible()) for a in hidden]
    face = ax.patch.get_visible(), fig.patch.get_alpha()
    try:
        for a in hidden:
            a.set_visible(False)
        ax.patch.set_visible(False)
        fig.patch.set_alpha(0.0)
        buf = io.BytesIO()
        fig.savefig(buf, format="png", dpi=canvas.dpi, transparent=True, pil_kwargs={"compress_level": 1})
    finally:
        for a, v in was:
            a.set_visible(v)
        ax.patch.set_visible(face[0])
        fig.patch.set_alpha(face[1])
    return "data:image/png;base64," + base64.b64encode(buf.getvalue()).decode("ascii")


def axes_scene(canvas, points=()) -> dict:
    """The scene of ``canvas.ax`` as it stands (see the module's docstring for the format).

    ``points`` are the picker's points: vertices on them are written by index.
    """
    ax = canvas.ax
    P = pixel_points(canvas, points)
    refs = _Refs(P)
    items: list[dict] = []
    converted: list = []
    raster_needed = False
    for artist in ax.get_children():
        if not artist.get_visible() or artist is ax.patch:
            continue
        got: list[dict] | None = None
        if isinstance(artist, _VECTOR_COLLECTIONS) and type(artist).__name__ != "PolyQuadMesh":
            got = _collection(canvas, refs, artist)
        elif isinstance(artist, Line2D):
            got = _line(canvas, refs, artist)
        elif isinstance(artist, Patch):
            got = _patch(canvas, refs, artist, P)
        elif isinstance(artist, Text) and artist.axes is ax:
            got = _text(canvas, refs, artist)
        elif isinstance(artist, (AxesImage, Collection)):      # contour fills, meshes, pictures
            raster_needed = True
            continue
        else:
            continue                              # the axes' ticks (the kit hides them), legends
        clipped = bool(artist.get_clip_on() and artist.get_clip_box() is not None)
        for item in got:
            item["clip"] = clipped
        items.extend(got)
        converted.append(artist)
    items.sort(key=lambda item: item["z"])       # a stable sort: equal zorders keep their drawing order
    raster = _raster(canvas, converted) if raster_needed else ""
    x0, y0, x1, y1 = ax.bbox.extents
    clip = [round(float(x0), 3), round(float(canvas.height - y1), 3), round(float(x1 - x0), 3), round(float(y1 - y0), 3)]
    return {"w": canvas.width, "h": canvas.height, "clip": clip, "items": items, "raster": raster}
