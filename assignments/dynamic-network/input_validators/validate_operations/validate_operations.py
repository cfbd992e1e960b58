"""Input validator (Kattis convention: exit 42 = valid, 43 = invalid) for `dynamic-network`.

Format: a line with q (0 <= q <= 200000), then q lines, each one of ``join x y`` (finite decimal
floats), ``fail i``, ``neighbors i`` (0 <= i <= 10^9), ``count``; single spaces, nothing after.
Run: python3 validate_operations.py < case.in; echo $?

Example:
    >>> validate("3\\njoin 0.5 1\\nneighbors 0\\ncount\\n")
    []
"""
import math
import re
import sys

NUMBER = re.compile(r"-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
ID = re.compile(r"0|[1-9]\d{0,8}|1000000000")
MAX_Q = 200000


def validate(text: str) -> list[str]:
    """Return a list of problems (empty when the input is valid)."""
    if not text.endswith("\n"):
        return ["the input must end with a newline"]
    lines = text[:-1].split("\n")
    if not re.fullmatch(r"0|[1-9]\d*", lines[0]):
        return [f"first line must be q, got {lines[0][:40]!r}"]
    q = int(lines[0])
    if q > MAX_Q:
        return [f"q = {q} exceeds {MAX_Q}"]
    if len(lines) != q + 1:
        return [f"expected {q} operation lines, got {len(lines) - 1}"]
    for k, line in enumerate(lines[1:], start=2):
        p = line.split(" ")
        if p[0] == "join" and len(p) == 3 and all(NUMBER.fullmatch(v) for v in p[1:]):
            if not all(math.isfinite(float(v)) for v in p[1:]):
                return [f"line {k}: coordinates must be finite"]
        elif not (p[0] in ("fail", "neighbors") and len(p) == 2 and ID.fullmatch(p[1]) or p == ["count"]):
            return [f"line {k}: expected 'join x y', 'fail i', 'neighbors i' or 'count', got {line[:60]!r}"]
    return []


if __name__ == "__main__":
    problems = validate(sys.stdin.read())
    for p in problems:
        print(p, file=sys.stderr)
    sys.exit(43 if problems else 42)
