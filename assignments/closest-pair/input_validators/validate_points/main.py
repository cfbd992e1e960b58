"""Input validator for `closest-pair` (Kattis: exit 42 = valid, 43 = invalid): the points format of
the Delaunay problems (points_format.py, the same file) with at least 2 points.

Run: python3 main.py < case.in; echo $?

Example:
    >>> problems("1\\n0 0\\n")
    ['closest-pair needs n >= 2 points, got 1']
"""
import sys

from points_format import validate


def problems(text: str) -> list:
    found = validate(text)
    if not found and int(text.split("\n", 1)[0]) < 2:
        found = [f"closest-pair needs n >= 2 points, got {int(text.split(chr(10), 1)[0])}"]
    return found


if __name__ == "__main__":
    found = problems(sys.stdin.read())
    for p in found:
        print(p, file=sys.stderr)
    sys.exit(43 if found else 42)
