"""Input validator for `obstacle-clearance` (Kattis: exit 42 = valid, 43 = invalid): the points
format of the Delaunay problems (points_format.py, the same file) for the obstacles, then the line
"sx sy" (start) and the line "gx gy" (goal), in the same number format.

Run: python3 main.py < case.in; echo $?

Example:
    >>> problems("1\\n0 0\\n1 1\\n-2 5e-300\\n")
    []
    >>> problems("1\\n0 0\\n1 1\\n")
    ['expected a start line and a goal line after the 1 obstacles, got 1 lines']
"""
import sys

from points_format import validate


def problems(text: str) -> list:
    head = text.partition("\n")[0]
    if not head.isdigit():
        return validate(text)
    lines = text.split("\n")
    n = int(head)
    if len(lines) != n + 4 or lines[-1] != "":
        return [f"expected a start line and a goal line after the {n} obstacles, got {max(0, len(lines) - n - 2)} lines"]
    # the obstacles are in the points format; start and goal are two more points of that format
    return validate("\n".join(lines[:n + 1]) + "\n") or validate("2\n" + "\n".join(lines[n + 1:n + 3]) + "\n")


if __name__ == "__main__":
    found = problems(sys.stdin.read())
    for p in found:
        print(p, file=sys.stderr)
    sys.exit(43 if found else 42)
