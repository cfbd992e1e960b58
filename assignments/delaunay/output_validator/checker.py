"""Checker for the Delaunay problems: accepts any valid Delaunay triangulation (exact arithmetic).

Two uses, one logic:

* the grader imports this file and calls ``read_input``, ``from_result`` / ``read_output`` and
  ``check`` in its own process (answers never reach the student's side);
* Kattis / problemtools run the exported copy (``python -m grader export-kattis delaunay OUT``) as an
  output validator: ``python3 checker.py input answer feedback_dir < team_output`` (exit 42
  accept, 43 reject, the reason in ``feedback_dir/judgemessage.txt``).

The exact test itself is ``reference_impl.verify.check_delaunay`` (Python integers), named in
``LIBRARY``: the shared loader (``grader/checker_runtime.py``) binds it without importing the rest
of ``reference_impl`` (which would pull in numba), and ``export-kattis`` embeds it together with
the Kattis entry point.

Example:
    >>> check([[[0, 0], [1, 0], [0, 1]]], [[0, 1, 2]], None)
    (True, 'ok')
"""
from __future__ import annotations

import math

LIBRARY = ("verify",)  # reference_impl/verify.py, bound as the global `verify` by the shared loader


class PresentationError(Exception):
    """The output has the wrong shape or type (verdict PE), as opposed to a wrong triangulation."""


def read_input(text: str) -> list:
    """Parse the input format into the entry function's argument list ``[points]``."""
    tok = text.split()
    n = int(tok[0])
    return [[[float(tok[1 + 2 * i]), float(tok[2 + 2 * i])] for i in range(n)]]


def write_input(args: list) -> str:
    (points,) = args
    return f"{len(points)}\n" + "".join(f"{x!r} {y!r}\n" for x, y in points)


def write_output(triangles: list) -> str:
    return f"{len(triangles)}\n" + "".join(f"{a} {b} {c}\n" for a, b, c in triangles)


def _index(v, where: str) -> int:
    if type(v) is int:
        return v
    if type(v) is float:
        hint = " (not a number)" if math.isnan(v) else " (use integer indices: dtype=int)"
        raise PresentationError(f"{where}: vertex index {v!r} is a float{hint}")
    raise PresentationError(f"{where}: vertex index {v!r} is a {type(v).__name__}, not an int")


def from_result(value, args: list) -> list[list[int]]:
    """Type-check what the entry function returned (JSON data): a list of [i, j, k] int triples."""
    if not isinstance(value, list):
        raise PresentationError(f"expected a list of triangles, got {type(value).__name__}: {str(value)[:60]}")
    out = []
    for k, t in enumerate(value):
        if not isinstance(t, list) or len(t) != 3:
            raise PresentationError(f"triangle {k} should be 3 vertex indices, got {str(t)[:60]}")
        out.append([_index(v, f"triangle {k}") for v in t])
    return out


def read_output(text: str, args: list) -> list[list[int]]:
    """Parse program output: m, then m lines 'i j k'."""
    lines = text.split("\n")
    if not lines or not lines[0].strip():
        raise PresentationError("empty output: expected the number of triangles on the first line")
    try:
        m = int(lines[0].strip())
    except ValueError:
        raise PresentationError(f"first line should be the number of triangles, got {lines[0][:60]!r}") from None
    body = [ln for ln in lines[1:] if ln.strip()]
    if m < 0 or len(body) != m:
        raise PresentationError(f"announced {m} triangles but {len(body)} lines follow")
    out = []
    for k, ln in enumerate(body):
        parts = ln.split()
        if len(parts) != 3:
            raise PresentationError(f"line {k + 2}: expected 'i j k', got {ln[:60]!r}")
        try:
            out.append([int(p) for p in parts])
        except ValueError:
            raise PresentationError(f"line {k + 2}: indices must be integers, got {ln[:60]!r}") from None
    return out


def check(args: list, triangles: list[list[int]], expected: list[list[int]] | None) -> tuple[bool, str]:
    """Exact check; ``expected`` (the reference answer) only improves the message."""
    (points,) = args
    n = len(points)
    for k, t in enumerate(triangles):
        bad = [v for v in t if not 0 <= v < n]
        if bad:
            return False, f"triangle {k} = {t} uses index {bad[0]}, outside 0..{n - 1}"
    ok, message = verify.check_delaunay(points, triangles)
    if not ok and expected is not None and len(expected) != len(triangles):
        message += f" (a valid answer has {len(expected)} triangles, you gave {len(triangles)})"
    return ok, message


def draw(axes, args: list, received: list[list[int]], expected: list[list[int]] | None) -> None:
    """Picture for reports: expected triangulation (left) and the received one (right).

    ``axes`` is a pair of matplotlib Axes; only the grader's HTML report calls this.
    """
    (points,) = args
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    for ax, tris, title, colour in ((axes[0], expected or [], "expected (one valid answer)", "tab:blue"),
                                    (axes[1], received or [], "received", "tab:red")):
        for t in tris:
            if all(0 <= v < len(points) for v in t):
                cyc = [t[0], t[1], t[2], t[0]]
                ax.plot([xs[v] for v in cyc], [ys[v] for v in cyc], color=colour, lw=0.8)
        ax.scatter(xs, ys, s=12, color="black", zorder=3)
        if len(points) <= 30:
            for i, (x, y) in enumerate(points):
                ax.annotate(str(i), (x, y), fontsize=7, xytext=(3, 3), textcoords="offset points")
        ax.set_title(f"{title}: {len(tris)} triangles", fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
