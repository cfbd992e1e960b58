"""Checker for `delaunay-3d`: accepts any valid Delaunay tetrahedralisation (exact arithmetic).

Two uses, one logic:

* the grader imports this file and calls ``read_input``, ``from_result`` / ``read_output`` and
  ``check`` in its own process (answers never reach the student's side);
* Kattis / problemtools run it as an output validator:
  ``python3 checker.py input answer feedback_dir < team_output`` (exit 42 accept, 43 reject,
  the reason in ``feedback_dir/judgemessage.txt``).

The exact test is ``reference_impl.verify.check_delaunay_3d`` (Python integers, standard library
only): embedded in this file by ``export-kattis``, else loaded by path from the checkout.

Example:
    >>> check([[[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]], [[0, 1, 2, 3]], None)
    (True, 'ok')
"""
from __future__ import annotations

import importlib.util
import math
import sys
from pathlib import Path

SMALL = 24          # inputs up to this many points are quoted in messages


class PresentationError(Exception):
    """The output has the wrong shape or type (verdict PE), as opposed to a wrong tetrahedralisation."""


def _load_verify():
    embedded = globals().get("EMBEDDED_VERIFY_SOURCE")  # set by `python -m grader export-kattis`
    if embedded:
        module = type(sys)("_delaunay3d_verify")
        exec(compile(embedded, "verify.py", "exec"), module.__dict__)
        return module
    here = Path(__file__).resolve().parent
    for path in [here / "verify.py"] + [p / "reference_impl" / "verify.py" for p in here.parents]:
        if path.is_file():
            spec = importlib.util.spec_from_file_location("_delaunay3d_verify", path)
            module = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(module)
            return module
    raise ImportError("reference_impl/verify.py not found next to the checker or in a parent directory")


def read_input(text: str) -> list:
    """Parse the input format into the entry function's argument list ``[points]``."""
    tok = text.split()
    n = int(tok[0])
    return [[[float(tok[1 + 3 * i]), float(tok[2 + 3 * i]), float(tok[3 + 3 * i])] for i in range(n)]]


def write_input(args: list) -> str:
    (points,) = args
    return f"{len(points)}\n" + "".join(f"{x!r} {y!r} {z!r}\n" for x, y, z in points)


def write_output(tets: list) -> str:
    return f"{len(tets)}\n" + "".join(f"{a} {b} {c} {d}\n" for a, b, c, d in tets)


def max_tetrahedra(n: int) -> int:
    """The most tetrahedra any triangulation of n points in space can have, (n^2 - 3n - 2) / 2
    (Edelsbrunner, Preparata and West), so a longer answer is rejected before any geometry.

    >>> max_tetrahedra(4), max_tetrahedra(8)
    (1, 19)
    """
    return max(0, (n * n - 3 * n - 2) // 2)


def _index(v, where: str) -> int:
    if type(v) is int:
        return v
    if type(v) is float:
        hint = " (not a number)" if math.isnan(v) else " (use integer indices: dtype=int)"
        raise PresentationError(f"{where}: vertex index {v!r} is a float{hint}")
    raise PresentationError(f"{where}: vertex index {str(v)[:40]!r} is a {type(v).__name__}, not an int")


def from_result(value, args: list) -> list[list[int]]:
    """Type-check what the entry function returned (JSON data): a list of [a, b, c, d] int quadruples."""
    if not isinstance(value, list):
        raise PresentationError(f"expected a list of tetrahedra, got {type(value).__name__}: {str(value)[:60]}")
    if args is not None and len(value) > max_tetrahedra(len(args[0])):
        raise PresentationError(f"{len(value)} tetrahedra: no tetrahedralisation of {len(args[0])} points "
                                f"has more than {max_tetrahedra(len(args[0]))}")
    out = []
    for k, t in enumerate(value):
        if not isinstance(t, list) or len(t) != 4:
            raise PresentationError(f"tetrahedron {k} should be 4 vertex indices, got {str(t)[:60]}")
        out.append([_index(v, f"tetrahedron {k}") for v in t])
    return out


def read_output(text: str, args: list | None) -> list[list[int]]:
    """Parse program output: m, then m lines 'a b c d'."""
    lines = text.split("\n")
    if not lines or not lines[0].strip():
        raise PresentationError("empty output: expected the number of tetrahedra on the first line")
    try:
        m = int(lines[0].strip())
    except ValueError:
        raise PresentationError(f"first line should be the number of tetrahedra, got {lines[0][:60]!r}") from None
    if args is not None and m > max_tetrahedra(len(args[0])):
        raise PresentationError(f"announced {m} tetrahedra: no tetrahedralisation of {len(args[0])} points "
                                f"has more than {max_tetrahedra(len(args[0]))}")
    body = [ln for ln in lines[1:] if ln.strip()]
    if m < 0 or len(body) != m:
        raise PresentationError(f"announced {m} tetrahedra but {len(body)} lines follow")
    out = []
    for k, ln in enumerate(body):
        parts = ln.split()
        if len(parts) != 4:
            raise PresentationError(f"line {k + 2}: expected 'a b c d', got {ln[:60]!r}")
        try:
            out.append([int(p) for p in parts])
        except ValueError:
            raise PresentationError(f"line {k + 2}: indices must be integers, got {ln[:60]!r}") from None
    return out


def read_answer(text: str) -> list[list[int]]:
    return read_output(text, None)


_verify = None


def check(args: list, tets: list[list[int]], expected: list[list[int]] | None) -> tuple[bool, str]:
    """Exact check; ``expected`` (the reference answer) only improves the message."""
    global _verify
    (points,) = args
    n = len(points)
    for k, t in enumerate(tets):
        bad = [v for v in t if not 0 <= v < n]
        if bad:
            return False, f"tetrahedron {k} = {t} uses index {bad[0]}, outside 0..{n - 1}"
    if _verify is None:
        _verify = _load_verify()
    ok, message = _verify.check_delaunay_3d(points, tets)
    if not ok:
        if expected is not None and len(expected) != len(tets):
            message += f" (a valid answer has {len(expected)} tetrahedra, you gave {len(tets)})"
        if n <= SMALL:
            message += f"; input points: {points}"
    return ok, message


def main(argv: list[str]) -> int:
    input_path, answer_path, feedback_dir = argv[1], argv[2], argv[3]
    try:
        args = read_input(Path(input_path).read_text())
        team = sys.stdin.buffer.read().decode("utf-8")
        tets = read_output(team, args)
        ok, message = check(args, tets, read_answer(Path(answer_path).read_text()))
    except UnicodeDecodeError:
        ok, message = False, "presentation error: the output is not UTF-8 text"
    except PresentationError as exc:
        ok, message = False, f"presentation error: {exc}"
    Path(feedback_dir, "judgemessage.txt").write_text(message + "\n")
    return 42 if ok else 43


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


if __name__ == "__main__":
    sys.exit(main(sys.argv))
