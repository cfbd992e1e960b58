"""Input validator (Kattis convention: exit 42 = valid, 43 = invalid) for `delaunay-3d`.

Format: a line with n (0 <= n <= 20000), then n lines "x y z" of finite decimal floats, single
spaces, nothing after. Run: python3 validate_points3d.py < case.in; echo $?

Example:
    >>> validate("2\\n0.5 1 2\\n-3 4e-300 1e300\\n")
    []
"""
import math
import re
import sys

NUMBER = re.compile(r"-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
MAX_N = 20000


def validate(text: str) -> list[str]:
    """Return a list of problems (empty when the input is valid)."""
    if not text.endswith("\n"):
        return ["the input must end with a newline"]
    lines = text[:-1].split("\n")
    if not re.fullmatch(r"0|[1-9]\d*", lines[0]):
        return [f"first line must be n, got {lines[0][:40]!r}"]
    n = int(lines[0])
    if n > MAX_N:
        return [f"n = {n} exceeds {MAX_N}"]
    if len(lines) != n + 1:
        return [f"expected {n} point lines, got {len(lines) - 1}"]
    for k, line in enumerate(lines[1:], start=2):
        parts = line.split(" ")
        if len(parts) != 3 or not all(NUMBER.fullmatch(p) for p in parts):
            return [f"line {k}: expected 'x y z', got {line[:60]!r}"]
        if not all(math.isfinite(float(p)) for p in parts):
            return [f"line {k}: coordinates must be finite"]
    return []


if __name__ == "__main__":
    problems = validate(sys.stdin.read())
    for p in problems:
        print(p, file=sys.stderr)
    sys.exit(43 if problems else 42)
