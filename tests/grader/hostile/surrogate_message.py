# expect: RE
# A lone surrogate in an exception message: it used to crash the table output, the HTML report,
# the store (the student stayed "running" forever) and `timed submit`.


def delaunay(points):
    raise ValueError("\ud800 broken \udfff")
