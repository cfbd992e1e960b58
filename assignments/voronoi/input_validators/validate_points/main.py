"""Input validator for `voronoi` (Kattis: exit 42 = valid, 43 = invalid): the points format of the
Delaunay problems (points_format.py, the same file) with n >= 1 sites, then one line
"xmin ymin xmax ymax" in the same number format, with xmin < xmax, ymin < ymax and every site
inside the closed box.

Run: python3 main.py < case.in; echo $?

Example:
    >>> problems("1\\n0.5 1\\n0 0 1 1\\n")
    []
    >>> problems("1\\n2 1\\n0 0 1 1\\n")
    ['line 2: the site (2.0, 1.0) is outside the box']
"""
import sys

from points_format import validate


def problems(text: str) -> list:
    head = text.partition("\n")[0]
    if not head.isdigit():
        return validate(text)
    lines = text.split("\n")
    n = int(head)
    if n < 1:
        return ["voronoi needs n >= 1 sites"]
    if len(lines) != n + 3 or lines[-1] != "":
        return [f"expected a box line after the {n} sites, got {max(0, len(lines) - n - 2)} lines"]
    box_line = lines[n + 1].split(" ")
    found = validate("\n".join(lines[:n + 1]) + "\n")
    if not found and len(box_line) != 4:
        found = [f"last line: expected 'xmin ymin xmax ymax', got {lines[n + 1][:60]!r}"]
    if not found:   # the box's numbers are two more points of the format: (xmin, ymin), (xmax, ymax)
        found = validate("2\n" + " ".join(box_line[:2]) + "\n" + " ".join(box_line[2:]) + "\n")
    if found:
        return found
    x0, y0, x1, y1 = (float(v) for v in box_line)
    if not (x0 < x1 and y0 < y1):
        return [f"the box {[x0, y0, x1, y1]} needs xmin < xmax and ymin < ymax"]
    for k, line in enumerate(lines[1:n + 1], start=2):
        x, y = (float(v) for v in line.split(" "))
        if not (x0 <= x <= x1 and y0 <= y <= y1):
            return [f"line {k}: the site ({x}, {y}) is outside the box"]
    return []


if __name__ == "__main__":
    found = problems(sys.stdin.read())
    for p in found:
        print(p, file=sys.stderr)
    sys.exit(43 if found else 42)
