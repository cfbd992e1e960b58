"""The package map of reference_impl/README.md, checked: which package may import which, and no
module importing another module's private name.

    python -m pytest tests/test_architecture.py

The layers (each may import those below it, never above):

    teaching     the readable Bowyer-Watson, the tutorial's bugs   -> exact, validate, mesh.ordering
    structures   Voronoi, hull, proximity, CDT, navmesh, ...        -> exact, mesh, validate, structures
    mesh         the kernels and Delaunay, Delaunay3D               -> exact, validate, mesh
    exact        predicates, expansions, checkers                   -> exact, validate
    validate     input rules                                        -> (numpy only)
"""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

PKG = Path(__file__).resolve().parent.parent / "reference_impl"

ALLOWED = {  # package (first part below reference_impl) -> packages it may import
    "exact": {"exact", "validate"},
    "validate": set(),
    "mesh": {"exact", "validate", "mesh"},
    "structures": {"exact", "validate", "mesh", "structures"},
    "teaching": {"exact", "validate", "mesh.ordering", "teaching"},
    "kit": {"exact", "validate", "mesh", "structures", "teaching", "kit"},
}
# d3-delaunay's composition: Delaunay.voronoi() etc. call the structures built on it, imported
# inside those methods only (the structures import mesh.delaunay at module level)
LAZY_UPWARD = {("mesh/delaunay.py", m) for m in ("structures.voronoi", "structures.proximity",
                                                  "structures.empty_circle")}
STDLIB_ONLY = {"exact/verify.py", "exact/free_space.py", "judge_io.py"}  # loaded by the judge's checkers


def _modules() -> list[Path]:
    return sorted(f for f in PKG.rglob("*.py") if "__pycache__" not in f.parts)


def _imports(f: Path) -> list[tuple[str, list[str], int]]:
    """(absolute module, imported names, line) for every import of the file."""
    rel = f.relative_to(PKG).with_suffix("").parts
    package = ["reference_impl", *rel[:-1]] if rel[-1] != "__init__" else ["reference_impl", *rel[:-1]]
    out = []
    for node in ast.walk(ast.parse(f.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out += [(a.name, [], node.lineno) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                base = ".".join(package[:len(package) - node.level + 1] + ([node.module] if node.module else []))
            out.append((base, [a.name for a in node.names], node.lineno))
    return out


def _module_level_lines(f: Path) -> set[int]:
    """Lines of the imports at the top level of a module (not inside a function or class)."""
    return {n.lineno for n in ast.parse(f.read_text(encoding="utf-8")).body
            if isinstance(n, (ast.Import, ast.ImportFrom))}


def _ours(module: str) -> str | None:
    """``reference_impl.mesh.kernel`` -> ``mesh.kernel`` (None for another package)."""
    if module == "reference_impl":
        return ""
    return module[len("reference_impl."):] if module.startswith("reference_impl.") else None


@pytest.mark.parametrize("f", _modules(), ids=lambda f: f.relative_to(PKG).as_posix())
def test_imports_follow_the_package_map(f):
    rel = f.relative_to(PKG)
    layer = rel.parts[0] if len(rel.parts) > 1 else rel.stem
    if layer not in ALLOWED:
        return  # top-level plumbing (__init__, __main__, warmup, _jitcache) may import anything
    bad = []
    for module, names, line in _imports(f):
        ours = _ours(module)
        if ours is None:
            if rel.as_posix() in STDLIB_ONLY and module.split(".")[0] not in __import__("sys").stdlib_module_names:
                bad.append(f"line {line}: {module} (this module must stay standard-library only)")
            continue
        targets = [ours] if ours else names          # `from reference_impl import mesh` names packages
        for t in targets:
            if (rel.as_posix(), t) in LAZY_UPWARD and line not in _module_level_lines(f):
                continue
            if not any(t == a or t.startswith(a + ".") for a in ALLOWED[layer]):
                bad.append(f"line {line}: reference_impl.{t}")
    assert not bad, f"{rel} ({layer}) imports what the package map forbids:\n" + "\n".join(bad)


@pytest.mark.parametrize("f", _modules(), ids=lambda f: f.relative_to(PKG).as_posix())
def test_no_module_imports_a_private_name_of_another(f):
    own = ".".join(("reference_impl", *f.relative_to(PKG).with_suffix("").parts))
    bad = [f"line {line}: {name} from {module}" for module, names, line in _imports(f)
           if _ours(module) is not None and module != own
           for name in names if name.startswith("_") and not name.startswith("__")]
    assert not bad, f"{f.relative_to(PKG)} imports private names:\n" + "\n".join(bad)


def test_importing_the_package_loads_nothing_heavy():
    import subprocess
    import sys
    code = ("import sys, reference_impl; "
            "print(sorted(m for m in ('numba', 'numpy', 'scipy', 'reference_impl.mesh') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "[]"
