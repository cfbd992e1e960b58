# expect: AC
# A correct submission that imports matplotlib.pyplot (and numpy) and plots: it was SV in every
# problem ("operation 'subprocess.Popen' is not allowed": matplotlib's font cache ran fc-list,
# and pyplot imports the forbidden matplotlib.tri). Allowed libraries import and work
# (scipy.optimize too: tests/grader/test_sandbox.py, with a load timeout for a busy machine).
import matplotlib.pyplot as plt
import numpy as np

def delaunay(points):
    fig, ax = plt.subplots()
    xs = [p[0] for p in points]; ys = [p[1] for p in points]
    ax.plot(xs, ys, "o"); ax.set_title("points")
    fig.savefig("plot.png"); plt.close(fig)
    assert np.allclose(np.mean(points, axis=0), [sum(xs) / len(xs), sum(ys) / len(ys)])
    from itertools import combinations
    n = len(points); out = []
    from fractions import Fraction as F
    P = [(F(x), F(y)) for x, y in points]
    def orient(a, b, c): return (b[0]-a[0])*(c[1]-a[1]) - (b[1]-a[1])*(c[0]-a[0])
    def incircle(a, b, c, d):
        m = [[p[0]-d[0], p[1]-d[1], (p[0]-d[0])**2 + (p[1]-d[1])**2] for p in (a, b, c)]
        return (m[0][0]*(m[1][1]*m[2][2]-m[1][2]*m[2][1]) - m[0][1]*(m[1][0]*m[2][2]-m[1][2]*m[2][0])
                + m[0][2]*(m[1][0]*m[2][1]-m[1][1]*m[2][0]))
    for i, j, k in combinations(range(n), 3):
        o = orient(P[i], P[j], P[k])
        if o == 0: continue
        if o < 0: j, k = k, j
        if all(incircle(P[i], P[j], P[k], P[l]) <= 0 for l in range(n) if l not in (i, j, k)):
            out.append([i, j, k])
    return out
