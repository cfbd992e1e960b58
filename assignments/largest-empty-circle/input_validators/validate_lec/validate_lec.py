"""Input validator (Kattis convention: exit 42 = valid, 43 = invalid) for `largest-empty-circle`.

Format: a line with n (3 <= n <= 200000), then n lines "x y" of finite decimal floats, one space,
nothing else; the points must not all lie on one line (checked exactly, with fractions).
Run: python3 validate_lec.py < case.in; echo $?

Example:
    >>> validate("3\\n0 0\\n1 0\\n0 1e-300\\n")
    []
    >>> validate("3\\n0 0\\n1 1\\n2 2\\n")
    ['the points are all collinear']
"""
import math
import re
import sys
from fractions import Fraction

NUMBER = re.compile(r"-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
MAX_N = 200000


def validate(text: str) -> list[str]:
    """Return a list of problems (empty when the input is valid)."""
    if not text.endswith("\n"):
        return ["the input must end with a newline"]
    lines = text[:-1].split("\n")
    if not re.fullmatch(r"[1-9]\d*", lines[0]) or int(lines[0]) < 3:
        return [f"first line must be n >= 3, got {lines[0][:40]!r}"]
    n = int(lines[0])
    if n > MAX_N:
        return [f"n = {n} exceeds {MAX_N}"]
    if len(lines) != n + 1:
        return [f"expected {n} point lines, got {len(lines) - 1}"]
    pts = []
    for k, line in enumerate(lines[1:], start=2):
        parts = line.split(" ")
        if len(parts) != 2 or not all(NUMBER.fullmatch(p) for p in parts):
            return [f"line {k}: expected 'x y', got {line[:60]!r}"]
        if not all(math.isfinite(float(p)) for p in parts):
            return [f"line {k}: coordinates must be finite"]
        pts.append((float(parts[0]), float(parts[1])))
    a = pts[0]
    b = next((p for p in pts if p != a), None)
    if b is None:
        return ["the points are all equal"]
    ax, ay, bx, by = (Fraction(v) for v in (*a, *b))
    for px, py in pts:
        if (bx - ax) * (Fraction(py) - ay) != (by - ay) * (Fraction(px) - ax):
            return []
    return ["the points are all collinear"]


if __name__ == "__main__":
    problems = validate(sys.stdin.read())
    for p in problems:
        print(p, file=sys.stderr)
    sys.exit(43 if problems else 42)
