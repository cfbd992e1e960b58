"""Keep numba's on-disk cache honest across modules.

numba re-compiles a cached function when *its own* source file changes, but not
when a function it inlines or calls from *another* module changes: edit
``exact/predicates.py`` and the cached kernels in ``mesh/kernel.py`` would keep
running the old predicates.  So :func:`purge_stale_cache` hashes every module of
the package together with the sources of the package modules it imports
(transitively); when that hash differs from the one stamped in numba's cache
directory, it drops that module's cached machine code (numba recompiles it on
next use).  Editing a module thus invalidates exactly its dependants.

Importing the package never touches the cache: ``python -m reference_impl warm``
(run by ``make demo``, ``make test`` and ``make lab``) and the test suite's
``conftest.py`` call :func:`purge_stale_cache`.

The cache directory is the one numba itself picks for each source file (its own
locator classes): ``__pycache__`` beside the source, ``$NUMBA_CACHE_DIR``, or the
user-wide ``~/.cache/numba`` when the package directory is read-only.

>>> {"exact.predicates", "mesh.ordering"} <= dependencies()["mesh.kernel"]
True
"""
from __future__ import annotations

import ast
import hashlib
from pathlib import Path

_PKG = Path(__file__).resolve().parent


def modules() -> dict[str, Path]:
    """Dotted name below the package (``"mesh.kernel"``; ``"__init__"`` for the package itself,
    ``"kit"`` for a subpackage's ``__init__``) -> source file, for every module."""
    out = {}
    for f in sorted(_PKG.rglob("*.py")):
        parts = f.relative_to(_PKG).with_suffix("").parts
        if "__pycache__" in parts:
            continue
        out[".".join(parts[:-1] if parts[-1] == "__init__" else parts) or "__init__"] = f
    return out


def _imports(name: str, source: str, known: set[str]) -> set[str]:
    """The package modules that module ``name`` imports (absolute or relative)."""
    package = name.split(".")[:-1] if not name.endswith("__init__") else name.split(".")
    found = set()
    for node in ast.walk(ast.parse(source)):
        targets = []
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[:len(package) - node.level + 1]
                mod = ".".join(["reference_impl", *base, *([node.module] if node.module else [])])
            else:
                mod = node.module or ""
            targets = [mod] + [f"{mod}.{a.name}" for a in node.names]
        for t in targets:
            if t.startswith("reference_impl."):
                t = t[len("reference_impl."):]
                if t in known:
                    found.add(t)
    return found


def dependencies() -> dict[str, set[str]]:
    """module -> the package modules it depends on, itself included (transitive closure)."""
    files = modules()
    known = set(files)
    direct = {m: _imports(m, f.read_text(encoding="utf-8"), known) for m, f in files.items()}
    closure = {}
    for m in files:
        seen, todo = {m}, [m]
        while todo:
            for d in direct[todo.pop()]:
                if d not in seen:
                    seen.add(d)
                    todo.append(d)
        closure[m] = seen
    return closure


def _probe() -> None:  # a function, for numba's cache locators
    pass


def cache_dir_of(source: Path) -> Path | None:
    """The directory numba caches the functions of ``source`` in (None if it has none)."""
    from numba.core.caching import CacheImpl
    for cls in CacheImpl._locator_classes:
        locator = cls.from_function(_probe, str(source))
        if locator is not None:
            return Path(locator.get_cache_path())
    return None


def purge_stale_cache() -> list[str]:
    """Drop cached numba code whose dependencies changed; return the modules dropped."""
    try:
        files = modules()
        dropped = []
        source: dict[str, bytes] = {}  # each file read once
        for mod, deps in dependencies().items():
            cache_dir = cache_dir_of(files[mod])
            if cache_dir is None:
                continue
            stem = files[mod].stem
            h = hashlib.sha1()
            for d in sorted(deps):
                if d not in source:
                    source[d] = files[d].read_bytes()
                h.update(d.encode())
                h.update(source[d])
            stamp = cache_dir / f"{stem}.deps.sha1"
            if stamp.exists() and stamp.read_text() == h.hexdigest():
                continue
            # No stamp, or another one: whatever is cached was compiled against other sources
            # (or unknown ones), so it goes.  A stamp is written even before anything is cached,
            # so that code compiled after this call is known to match these sources.
            cached = [f for f in cache_dir.iterdir()
                      if f.suffix in (".nbi", ".nbc") and f.name.split(".")[0] == stem] if cache_dir.is_dir() else []
            for f in cached:
                f.unlink()
            if cached:
                dropped.append(mod)
            cache_dir.mkdir(parents=True, exist_ok=True)
            stamp.write_text(h.hexdigest())
        return dropped
    except (OSError, ImportError, AttributeError, UnicodeDecodeError, SyntaxError):
        return []  # never let cache housekeeping break a warm-up or a test run
