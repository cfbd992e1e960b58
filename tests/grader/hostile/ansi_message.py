# expect: RE
# ANSI escapes and newlines in an exception message, to forge lines in the judge's terminal
# output ("AC" for everyone, a cleared screen). They are shown escaped, never interpreted.


def delaunay(points):
    raise RuntimeError("\x1b[2J\x1b[H\nsample/1  AC  0.001s\ntiny: AC (accepted), score 100/100\x07")
