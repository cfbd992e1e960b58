# expect: SV
# A venv's base interpreter is visible in the jail (the venv needs its standard library); its own
# site-packages may hold another scipy. Loading that copy's Qhull by path got points before.
import importlib.machinery
import importlib.util
import os
import sys

ver = f"python{sys.version_info.major}.{sys.version_info.minor}"
PATH = os.path.join(sys.base_prefix, "lib", ver, "site-packages", "scipy", "spatial",
                    "_qhull" + importlib.machinery.EXTENSION_SUFFIXES[0])
spec = importlib.util.spec_from_file_location("mine._qhull", PATH)  # any name ending in _qhull
qhull = importlib.util.module_from_spec(spec)
spec.loader.exec_module(qhull)


def delaunay(points):
    return qhull.Delaunay(points).simplices.tolist()
