"""Input validator (Kattis convention: exit 42 = valid, 43 = invalid) for `voronoi`.

Format: a line with n (1 <= n <= 200000), n lines "x y" (the sites), then one line
"xmin ymin xmax ymax" with xmin < xmax, ymin < ymax, and every site inside the closed box:
finite decimal floats, one space, nothing else. Run: python3 validate_voronoi.py < case.in; echo $?

Example:
    >>> validate("1\\n0.5 1\\n0 0 1 1\\n")
    []
    >>> validate("1\\n2 1\\n0 0 1 1\\n")
    ['line 2: the site (2.0, 1.0) is outside the box']
"""
import math
import re
import sys

NUMBER = re.compile(r"-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
MAX_N = 200000


def _numbers(line: str, count: int) -> list:
    parts = line.split(" ")
    if len(parts) != count or not all(NUMBER.fullmatch(p) for p in parts):
        return []
    values = [float(p) for p in parts]
    return values if all(math.isfinite(v) for v in values) else []


def validate(text: str) -> list[str]:
    """Return a list of problems (empty when the input is valid)."""
    if not text.endswith("\n"):
        return ["the input must end with a newline"]
    lines = text[:-1].split("\n")
    if not re.fullmatch(r"[1-9]\d*", lines[0]):
        return [f"first line must be n >= 1, got {lines[0][:40]!r}"]
    n = int(lines[0])
    if n > MAX_N:
        return [f"n = {n} exceeds {MAX_N}"]
    if len(lines) != n + 2:
        return [f"expected {n} site lines and a box line, got {len(lines) - 1} lines"]
    box = _numbers(lines[-1], 4)
    if not box:
        return [f"last line: expected 'xmin ymin xmax ymax', got {lines[-1][:60]!r}"]
    x0, y0, x1, y1 = box
    if not (x0 < x1 and y0 < y1):
        return [f"the box {box} needs xmin < xmax and ymin < ymax"]
    for k, line in enumerate(lines[1:-1], start=2):
        p = _numbers(line, 2)
        if not p:
            return [f"line {k}: expected 'x y' (finite), got {line[:60]!r}"]
        if not (x0 <= p[0] <= x1 and y0 <= p[1] <= y1):
            return [f"line {k}: the site ({p[0]}, {p[1]}) is outside the box"]
    return []


if __name__ == "__main__":
    problems = validate(sys.stdin.read())
    for p in problems:
        print(p, file=sys.stderr)
    sys.exit(43 if problems else 42)
