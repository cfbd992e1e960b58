"""Input validator for `largest-empty-circle` (Kattis: exit 42 = valid, 43 = invalid): the points
format of the Delaunay problems (points_format.py, the same file) with n >= 3 points that do not
all lie on one line (checked exactly, with fractions).

Run: python3 main.py < case.in; echo $?

Example:
    >>> problems("3\\n0 0\\n1 0\\n0 1e-300\\n")
    []
    >>> problems("3\\n0 0\\n1 1\\n2 2\\n")
    ['the points are all collinear']
"""
import sys
from fractions import Fraction

from points_format import validate


def problems(text: str) -> list:
    found = validate(text)
    if found:
        return found
    lines = text.split("\n")
    if int(lines[0]) < 3:
        return [f"largest-empty-circle needs n >= 3 points, got {int(lines[0])}"]
    pts = [tuple(Fraction(v) for v in ln.split(" ")) for ln in lines[1:int(lines[0]) + 1]]
    a = pts[0]
    b = next((p for p in pts if p != a), None)
    if b is None:
        return ["the points are all equal"]
    if all((b[0] - a[0]) * (p[1] - a[1]) == (b[1] - a[1]) * (p[0] - a[0]) for p in pts):
        return ["the points are all collinear"]
    return []


if __name__ == "__main__":
    found = problems(sys.stdin.read())
    for p in found:
        print(p, file=sys.stderr)
    sys.exit(43 if found else 42)
