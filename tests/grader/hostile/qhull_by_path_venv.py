# expect: SV
# Loads scipy's compiled Qhull by file path under another name (no 'scipy.spatial' import at all).
import importlib.machinery
import importlib.util
import os

import scipy

PATH = os.path.join(os.path.dirname(scipy.__file__), "spatial", "_qhull" + importlib.machinery.EXTENSION_SUFFIXES[0])
spec = importlib.util.spec_from_file_location("not_qhull", PATH)
qhull = importlib.util.module_from_spec(spec)
spec.loader.exec_module(qhull)


def delaunay(points):
    return qhull.Delaunay(points).simplices.tolist()
