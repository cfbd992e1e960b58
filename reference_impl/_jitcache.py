"""Keep numba's on-disk cache honest across modules.

numba re-compiles a cached function when *its own* source file changes, but not
when a function it inlines or calls from *another* module changes: edit
``predicates.py`` and the cached kernels in ``_mesh.py`` would keep running the
old predicates.  So, once per process, for every module of the package we hash
its source together with the sources of the package modules it imports
(transitively); when that hash differs from the one stamped in numba's cache
directory, we drop that module's cached machine code (numba recompiles it on
next use).  Editing a module thus invalidates exactly its dependants.

The cache directory is the one numba itself picks (its own locator classes):
``__pycache__`` beside the sources, ``$NUMBA_CACHE_DIR``, or the user-wide
``~/.cache/numba`` when the package directory is read-only.

>>> sorted(dependencies()["_mesh"])[:2]
['_mesh', 'expansion']
"""
from __future__ import annotations

import hashlib
import re
from pathlib import Path

_PKG = Path(__file__).resolve().parent
_IMPORT = re.compile(r"^\s*(?:from\s+(?:\.|reference_impl\.)(\w+)\s+import|import\s+reference_impl\.(\w+))",
                     re.MULTILINE)


def dependencies() -> dict[str, set[str]]:
    """module -> the package modules it depends on, itself included (transitive closure)."""
    sources = {f.stem: f.read_text(encoding="utf-8") for f in _PKG.glob("*.py")}
    direct = {m: {a or b for a, b in _IMPORT.findall(src)} & sources.keys() for m, src in sources.items()}
    closure = {}
    for m in sources:
        seen, todo = {m}, [m]
        while todo:
            for d in direct[todo.pop()]:
                if d not in seen:
                    seen.add(d)
                    todo.append(d)
        closure[m] = seen
    return closure


def _probe() -> None:  # a function in this directory, for numba's cache locators
    pass


def purge_stale_cache() -> list[str]:
    """Drop cached numba code whose dependencies changed; return the modules dropped."""
    try:
        from numba.core.caching import CacheImpl
        locator = None
        for cls in CacheImpl._locator_classes:
            locator = cls.from_function(_probe, str(_PKG / "_jitcache.py"))
            if locator is not None:
                break
        if locator is None:
            return []
        cache_dir = Path(locator.get_cache_path())
        cached = {}
        if cache_dir.is_dir():
            for f in cache_dir.iterdir():
                if f.suffix in (".nbi", ".nbc"):
                    cached.setdefault(f.name.split(".")[0], []).append(f)
        if not cached:
            return []
        dropped = []
        source: dict[str, bytes] = {}  # each file read once
        for mod, deps in dependencies().items():
            if mod not in cached:
                continue
            h = hashlib.sha1()
            for d in sorted(deps):
                if d not in source:
                    source[d] = (_PKG / f"{d}.py").read_bytes()
                h.update(d.encode())
                h.update(source[d])
            stamp = cache_dir / f"{mod}.deps.sha1"
            if stamp.exists() and stamp.read_text() == h.hexdigest():
                continue
            if stamp.exists():  # a dependency changed since these files were compiled
                for f in cached[mod]:
                    f.unlink()
                dropped.append(mod)
            stamp.write_text(h.hexdigest())
        return dropped
    except (OSError, ImportError, AttributeError, UnicodeDecodeError):
        return []  # never let cache housekeeping break an import
