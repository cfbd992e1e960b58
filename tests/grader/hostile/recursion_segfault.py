# expect: RE
# Recursion through a C function (map) uses the C stack: with the limit raised, it overflows
# the stack (SIGSEGV) instead of raising RecursionError.
import sys

sys.setrecursionlimit(10 ** 8)


def deep(n):
    return list(map(deep, [n + 1]))


def delaunay(points):
    return deep(0)
