"""Which installed files a problem's forbidden modules stand for, in every copy on the machine.

A problem forbids names (``scipy.spatial``, ``matplotlib.tri``, ``triangle``, ``shapely``...).
Forbidding a name is not enough: the same compiled engine ships under other names
(matplotlib bundles Qhull as ``matplotlib._qhull``), and other Python installations on the
machine (the base interpreter a venv was made from, Debian's ``dist-packages``) hold more
copies that can be loaded by file path. This module maps forbidden names to

* :func:`engine_modules`: compiled engine modules, forbidden whoever imports them (the
  student, or a library on the student's behalf: ``plt.triplot`` needs ``matplotlib._qhull``);
* :func:`cover_paths`: every installed copy of the forbidden packages and engines, in every
  site directory and library directory, which the jail makes unreadable.

``matplotlib.tri`` and ``scipy.spatial`` stay readable because allowed libraries import them
(``matplotlib.pyplot``, ``scipy.optimize``: :data:`IMPORTED_BY_LIBRARIES`): the student's own
``import matplotlib.tri`` is still a violation, and when a library imports an engine the child
gives it a stand-in module whose every function and class is a violation when used
(:data:`ENGINE_API`); the real engine files are covered in every copy.

Run ``python -m grader.jail.engines scipy.spatial matplotlib.tri`` to list what would be covered.

Example:
    >>> sorted(engine_modules(["matplotlib.tri"]))
    ['matplotlib._qhull', 'scipy.spatial._qhull']
    >>> engine_modules(["triangle"])
    {'triangle.core': 'Triangle'}
"""

from __future__ import annotations

import glob
import os
import site
import sys
from typing import Iterable, Sequence

#: engine -> (forbidden names that imply it, its compiled modules, shared-library name prefixes)
ENGINES: dict[str, tuple[tuple[str, ...], tuple[str, ...], tuple[str, ...]]] = {
    "Qhull": (("scipy.spatial", "matplotlib.tri", "qhull", "pyhull"),
              ("scipy.spatial._qhull", "matplotlib._qhull"), ("libqhull",)),
    "Triangle": (("triangle",), ("triangle.core",), ("libtriangle",)),
    "GEOS": (("shapely", "pygeos"), ("shapely.lib", "pygeos.lib"), ("libgeos",)),
}
#: Forbidden wrappers that allowed libraries import on their own (pyplot imports matplotlib.tri,
#: scipy.optimize imports scipy.spatial): readable, and forbidden to the student's own imports.
IMPORTED_BY_LIBRARIES = ("matplotlib.tri", "scipy.spatial")
#: Public names of an engine module, for the stand-in a library gets when it imports the engine
#: (``from ._qhull import *``); every name is a class whose use is a violation.
ENGINE_API = {
    "scipy.spatial._qhull": ("ConvexHull", "Delaunay", "HalfspaceIntersection", "QhullError", "Voronoi", "tsearch"),
    "matplotlib._qhull": ("delaunay", "version"),
}
#: Never covered: the grader's own packages are hidden with the checkout instead.
_NOT_INSTALLED = ("reference_impl", "grader")
_LIB_DIRS = ("/usr/lib", "/usr/lib64", "/usr/local/lib", f"/usr/lib/{sys.implementation._multiarch}"
             if hasattr(sys.implementation, "_multiarch") else "/usr/lib/x86_64-linux-gnu")


def _matches(name: str, prefixes: Iterable[str]) -> bool:
    return any(name == p or name.startswith(p + ".") for p in prefixes)


def engine_modules(forbidden: Sequence[str]) -> dict[str, str]:
    """Compiled engine module -> engine name, for the engines the forbidden names imply."""
    out = {}
    for engine, (names, modules, _) in ENGINES.items():
        if any(_matches(n, forbidden) or _matches(f, names) for n in names for f in forbidden):
            out.update({m: engine for m in modules})
    return out


def engine_libraries(forbidden: Sequence[str]) -> list[str]:
    """Shared-library file name prefixes of the implied engines (``libqhull``...)."""
    engines = set(engine_modules(forbidden).values())
    return sorted({p for e in engines for p in ENGINES[e][2]})


def site_dirs() -> list[str]:
    """Every package directory of every Python installation the jail can see."""
    ver = f"python{sys.version_info.major}.{sys.version_info.minor}"
    dirs = [p for p in sys.path if p]
    for prefix in {sys.prefix, sys.base_prefix, sys.exec_prefix, sys.base_exec_prefix, "/usr", "/usr/local"}:
        for sub in (f"lib/{ver}/site-packages", f"lib/{ver}/dist-packages", "lib/python3/dist-packages",
                    f"lib64/{ver}/site-packages"):
            dirs.append(os.path.join(prefix, sub))
    try:
        dirs += site.getsitepackages()
    except AttributeError:  # pragma: no cover - old virtualenv's site.py
        pass
    seen, out = set(), []
    for d in dirs:
        r = os.path.realpath(d)
        if r not in seen and os.path.isdir(r):
            seen.add(r)
            out.append(r)
    return out


def _module_files(base: str, module: str) -> list[str]:
    parts = module.split(".")
    stem = os.path.join(base, *parts)
    if os.path.isdir(stem):
        return [stem]
    found = [stem + ".py"] if os.path.isfile(stem + ".py") else []
    parent = os.path.dirname(stem)
    if os.path.isdir(parent):
        found += [os.path.join(parent, f) for f in os.listdir(parent)
                  if f.startswith(parts[-1] + ".") and f.endswith((".so", ".pyd"))]
    return found


def cover_paths(forbidden: Sequence[str]) -> list[str]:
    """Every installed copy (directory, ``.py``, extension, bundled shared library) of the
    forbidden packages and of the engines they imply, in every site and library directory."""
    engines = engine_modules(forbidden)
    modules = [m for m in forbidden if not _matches(m, _NOT_INSTALLED) and m not in IMPORTED_BY_LIBRARIES]
    modules += sorted(engines)
    libs = tuple(engine_libraries(forbidden))
    found: list[str] = []
    bases = site_dirs()
    for base in bases:
        for m in modules:
            found += _module_files(base, m)
        for pkg_libs in glob.glob(os.path.join(glob.escape(base), "*.libs")):  # auditwheel-bundled copies
            found += [os.path.join(pkg_libs, f) for f in os.listdir(pkg_libs) if f.startswith(libs)]
    for d in _LIB_DIRS:
        if libs and os.path.isdir(d):
            found += [os.path.join(d, f) for f in os.listdir(d) if f.startswith(libs)]
    paths = sorted({os.path.realpath(p) for p in found if os.path.exists(p)})
    dirs = [p for p in paths if os.path.isdir(p)]
    return [p for p in paths if not any(p != d and p.startswith(d + os.sep) for d in dirs)]


def modules_of(paths: Sequence[str]) -> list[str]:
    """The module names of covered paths (inverse of :func:`cover_paths` for one site dir)."""
    out = []
    bases = sorted(site_dirs(), key=len, reverse=True)  # the deepest: sys.path may hold the checkout too
    for p in paths:
        r = os.path.realpath(p)
        for base in bases:
            if r.startswith(base + os.sep):
                rel = os.path.relpath(r, base).split(os.sep)
                rel[-1] = rel[-1].split(".", 1)[0]
                out.append(".".join(rel))
                break
    return list(dict.fromkeys(out))


def main() -> None:
    """The command ``python -m grader.jail.engines``."""
    for path in cover_paths(sys.argv[1:] or ["scipy.spatial", "matplotlib.tri", "triangle", "shapely"]):
        print(path)


if __name__ == "__main__":
    main()
