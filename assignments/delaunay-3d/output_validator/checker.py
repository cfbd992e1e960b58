"""Checker for `delaunay-3d`: accepts any valid Delaunay tetrahedralisation (exact arithmetic).

Two uses, one logic:

* the grader imports this file and calls ``read_input``, ``from_result`` / ``read_output`` and
  ``check`` in its own process (answers never reach the student's side);
* Kattis / problemtools run the exported copy (``python -m grader export-kattis delaunay-3d OUT``)
  as an output validator: ``python3 checker.py input answer feedback_dir < team_output`` (exit 42
  accept, 43 reject, the reason in ``feedback_dir/judgemessage.txt``).

The exact test is ``reference_impl.exact.verify.check_delaunay_3d`` (Python integers, standard library
only), named in ``LIBRARY`` with the shared readers of ``reference_impl/judge_io.py``: the shared
loader (``grader/checker_runtime.py``) binds both, and ``export-kattis`` embeds them.

Example:
    >>> check([[[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]], [[0, 1, 2, 3]], None)
    (True, 'ok')
"""
from __future__ import annotations

LIBRARY = ("judge_io", "verify", "bulk")  # bound as globals by the shared loader
SMALL = 24                        # inputs up to this many points are quoted in messages

PresentationError = judge_io.PresentationError  # noqa: F821 - bound by the loader
show, mistake = judge_io.show, judge_io.mistake  # noqa: F821 - safe previews, two-part messages


def read_input(text: str) -> list:
    """Parse the input format into the entry function's argument list ``[points]``."""
    tok = text.split()
    n = int(tok[0])
    return [[[float(tok[1 + 3 * i]), float(tok[2 + 3 * i]), float(tok[3 + 3 * i])] for i in range(n)]]


def write_input(args: list) -> str:
    (points,) = args
    return f"{len(points)}\n" + "".join(f"{float(x)!r} {float(y)!r} {float(z)!r}\n" for x, y, z in points)


def write_output(tets: list) -> str:
    return judge_io.write_index_rows(tets)  # noqa: F821


def max_tetrahedra(n: int) -> int:
    """The most tetrahedra any triangulation of n points in space can have, (n^2 - 3n - 2) / 2
    (Edelsbrunner, Preparata and West), so a longer answer is rejected before any geometry.

    >>> max_tetrahedra(4), max_tetrahedra(8)
    (1, 19)
    """
    return max(0, (n * n - 3 * n - 2) // 2)


def _limit(args) -> int:
    return max_tetrahedra(len(args[0])) if args is not None else 10 ** 9


def from_result(value, args: list) -> list[list[int]]:
    """Type-check what the entry function returned (JSON data): a list of [a, b, c, d] int quadruples."""
    return judge_io.index_rows(value, 4, "tetrahedron", _limit(args))  # noqa: F821


def read_output(text: str, args: list | None) -> list[list[int]]:
    """Parse program output: m, then m lines 'a b c d'."""
    return judge_io.read_index_rows(text, 4, "tetrahedron", _limit(args))  # noqa: F821


#: failure message (a substring) -> the kind of mistake a hidden test's feedback shows (no numbers)
MISTAKES = {
    "outside 0..": "a tetrahedron uses an index out of range",
    "flat": "a tetrahedron is flat",
    "coplanar": "the tetrahedra do not fit the coplanar case",
    "overlap": "tetrahedra overlap",
    "same side": "tetrahedra overlap",
    "not Delaunay": "a face is not Delaunay",
    "circumsphere": "a point lies inside a circumsphere",
    "convex hull": "the tetrahedra do not fill the convex hull",
    "not a vertex": "a point is not a vertex of any tetrahedron",
}


@judge_io.mistake_kinds(MISTAKES, "not a valid Delaunay tetrahedralisation")  # noqa: F821 - bound by the loader
def check(args: list, tets: list[list[int]], expected: list[list[int]] | None) -> tuple[bool, str]:
    """Exact check; ``expected`` (the reference answer) only improves the message."""
    (points,) = args
    n = len(points)
    flat = [v for t in tets for v in t]
    if flat and (min(flat) < 0 or max(flat) >= n):  # then name the first one out of range
        for k, t in enumerate(tets):
            bad = [v for v in t if not 0 <= v < n]
            if bad:
                return False, f"tetrahedron {k} = {t} uses index {bad[0]}, outside 0..{n - 1}"
    ok, message = verify.check_delaunay_3d(points, tets, bulk)  # noqa: F821
    if not ok:
        if expected is not None and len(expected) != len(tets):
            message += f" (a valid answer has {len(expected)} tetrahedra, you gave {len(tets)})"
        if n <= SMALL:
            message += f"; input points: {points}"
    return ok, message


def draw(axes, args: list, received: list[list[int]], expected: list[list[int]] | None) -> None:
    """Picture for reports: the points and the edges of the expected (left) and received (right)
    tetrahedra, projected on the x-y plane. ``axes`` is a pair of matplotlib Axes."""
    (points,) = args
    for ax, tets, title, colour in ((axes[0], expected or [], "expected (one valid answer)", "tab:blue"),
                                    (axes[1], received or [], "received", "tab:red")):
        edges = {tuple(sorted((t[i], t[j]))) for t in tets if all(0 <= v < len(points) for v in t)
                 for i in range(4) for j in range(i + 1, 4)}
        for a, b in edges:
            ax.plot([points[a][0], points[b][0]], [points[a][1], points[b][1]], color=colour, lw=0.5, alpha=0.6)
        ax.scatter([p[0] for p in points], [p[1] for p in points], s=10, color="black", zorder=3)
        ax.set_title(f"{title}: {len(tets)} tetrahedra (x-y view)", fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
