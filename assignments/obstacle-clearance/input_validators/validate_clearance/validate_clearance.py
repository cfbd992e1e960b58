"""Input validator (Kattis convention: exit 42 = valid, 43 = invalid) for `obstacle-clearance`.

Format: a line with n (0 <= n <= 200000), n lines "x y" (the obstacles), then the line "sx sy"
(start) and the line "gx gy" (goal): finite decimal floats, one space, nothing else.
Run: python3 validate_clearance.py < case.in; echo $?

Example:
    >>> validate("1\\n0 0\\n1 1\\n-2 5e-300\\n")
    []
"""
import math
import re
import sys

NUMBER = re.compile(r"-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
MAX_N = 200000


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
    if len(lines) != n + 3:
        return [f"expected {n} obstacle lines, a start line and a goal line, got {len(lines) - 1} lines"]
    for k, line in enumerate(lines[1:], start=2):
        parts = line.split(" ")
        if len(parts) != 2 or not all(NUMBER.fullmatch(p) for p in parts):
            return [f"line {k}: expected 'x y', got {line[:60]!r}"]
        if not all(math.isfinite(float(p)) for p in parts):
            return [f"line {k}: coordinates must be finite"]
    return []


if __name__ == "__main__":
    problems = validate(sys.stdin.read())
    for p in problems:
        print(p, file=sys.stderr)
    sys.exit(43 if problems else 42)
