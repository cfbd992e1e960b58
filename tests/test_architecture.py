"""The package map of reference_impl/README.md, checked: which package may import which, and no
module importing another module's private name.

    python -m pytest tests/test_architecture.py

The layers (each may import those below it, never above):

    teaching     the readable Bowyer-Watson, the tutorial's bugs   -> exact, validate, mesh.ordering
    structures   Voronoi, hull, proximity, CDT, navmesh, ...        -> exact, mesh, validate, structures
    mesh         the kernels and Delaunay, Delaunay3D               -> exact, validate, mesh
    exact        predicates, expansions, checkers                   -> exact, validate
    validate     input rules                                        -> (numpy only)

and the room map of grader/README.md (each room may import the rooms below it, never above; the
old module names kept as aliases sit on top):

    course       nbgrader autograde, course notebooks, student edition  -> classroom and below
    classroom    class grading, store, scoreboard, timed, similarity    -> contest and below
    contest      the judging loop; report, stress, kattis, sample check -> problems and below
    problems     problem packages, small cases, statements              -> judging, jail
    judging      runner, languages, submissions, verdicts, checkers     -> jail
    jail         the sandbox                                            -> (standard library)
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


def _imports(f: Path, pkg: Path = PKG) -> list[tuple[str, list[str], int]]:
    """(absolute module, imported names, line) for every import of the file of package ``pkg``."""
    rel = f.relative_to(pkg).with_suffix("").parts
    package = [pkg.name, *rel[:-1]]
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


# ---- grader: the room map of grader/README.md ------------------------------------------------

GRADER = PKG.parent / "grader"
ROOMS = {  # room (first part below grader) -> floor; a module may import its own floor and below
    "jail": 1,
    "judging": 2,
    "problems": 3,
    "contest": 4,
    "classroom": 5,
    "course": 6,
}
TOP = 7  # the package's face: __init__ (the public API), __main__, cli, and the aliases below (_alias makes them)
TOP_MODULES = {"__init__", "__main__", "cli", "_alias"}
# old module names kept for courses deployed before the move (grader/README.md, "Upgrading ...")
ALIASES = {"sandbox": "jail.sandbox", "nbgrader_autograde": "course.nbgrader_autograde",
           "course_notebooks": "course.course_notebooks", "course_markdown": "course.course_markdown",
           "student_edition": "course.student_edition", "public_problems": "course.public_problems",
           "smallcases": "problems.smallcases", "sample_check": "contest.sample_check"}
LONG_LINES = 600
GRADER_STDLIB_ONLY = {"judging/checker_runtime.py",  # exported Kattis validators load it by path
                      "judging/languages.py", "jail/child_bootstrap.py"}


def _grader_modules() -> list[Path]:
    return sorted(f for f in GRADER.rglob("*.py") if "__pycache__" not in f.parts)


def _floor(rel_parts: tuple[str, ...]) -> int:
    """The floor of a module or package named by its parts below ``grader`` (``()``: the package)."""
    if not rel_parts or len(rel_parts) == 1 and rel_parts[0] not in ROOMS:
        return TOP
    return ROOMS[rel_parts[0]]


def _grader_targets(module: str, names: list[str]) -> list[tuple[str, ...]]:
    """The grader modules an import reaches, as parts below ``grader`` (none for another package)."""
    if module != "grader" and not module.startswith("grader."):
        return []
    parts = tuple(module.split(".")[1:])
    package = GRADER.joinpath(*parts)
    subs = [(*parts, n) for n in names if package.is_dir() and (package / f"{n}.py").is_file()]
    # `from grader import cli`, `from . import cgroups` name modules; `from .problems import Problem` a name
    return subs + ([parts] if len(subs) < len(names) else [])


def test_every_grader_module_sits_in_a_room():
    loose = [f.name for f in GRADER.glob("*.py") if f.stem not in TOP_MODULES | set(ALIASES)]
    rooms = {d.name for d in GRADER.iterdir() if (d / "__init__.py").is_file()}
    assert not loose, f"modules outside the rooms (put them in one, see grader/README.md): {loose}"
    assert rooms == set(ROOMS), "a room was added or removed: update ROOMS and grader/README.md's map"
    for alias, target in ALIASES.items():  # an alias is a name only: it re-exports the module it names
        text = (GRADER / f"{alias}.py").read_text(encoding="utf-8")
        assert (GRADER / (target.replace(".", "/") + ".py")).is_file(), alias
        assert f'alias(__name__, "grader.{target}"' in text, f"grader/{alias}.py is not an alias of {target}"


@pytest.mark.parametrize("f", _grader_modules(), ids=lambda f: f.relative_to(GRADER).as_posix())
def test_grader_imports_run_down_the_rooms(f):
    rel = f.relative_to(GRADER).with_suffix("").parts
    own = TOP if len(rel) == 1 else ROOMS[rel[0]]
    bad = []
    for module, names, line in _imports(f, GRADER):
        targets = _grader_targets(module, names)
        if not targets and rel_posix(f) in GRADER_STDLIB_ONLY:
            if module.split(".")[0] not in __import__("sys").stdlib_module_names and module != "__future__":
                bad.append(f"line {line}: {module} (this module must stay standard-library only)")
        for t in targets:
            if rel_posix(f) in GRADER_STDLIB_ONLY:
                bad.append(f"line {line}: grader.{'.'.join(t)} (this module must stay standard-library only)")
            elif _floor(t) > own:
                bad.append(f"line {line}: grader.{'.'.join(t)} (floor {_floor(t)}, above this module's {own})")
    assert not bad, f"grader/{rel_posix(f)} imports from a higher room:\n" + "\n".join(bad)


def rel_posix(f: Path) -> str:
    return f.relative_to(GRADER).as_posix()


def test_no_import_circle_in_grader():
    """No module reaches itself through imports (module level or inside functions)."""
    graph: dict[str, set[str]] = {}
    known = {".".join(f.relative_to(GRADER).with_suffix("").parts) for f in _grader_modules()}
    for f in _grader_modules():
        me = ".".join(f.relative_to(GRADER).with_suffix("").parts)
        if me.split(".")[0] in ALIASES:
            continue
        edges = set()
        for module, names, _ in _imports(f, GRADER):
            for t in _grader_targets(module, names):
                for cand in (".".join(t), ".".join((*t, "__init__"))):
                    if cand in known and cand != me and cand.split(".")[0] not in ALIASES:
                        edges.add(cand)
        graph[me] = edges

    def reach(start: str) -> set[str]:
        seen, todo = set(), [start]
        while todo:
            for n in graph.get(todo.pop(), ()):
                if n not in seen:
                    seen.add(n)
                    todo.append(n)
        return seen

    circles = sorted(m for m in graph if m in reach(m) and not m.endswith("__init__"))
    assert not circles, f"modules that import themselves through others: {circles}"


@pytest.mark.parametrize("f", [f for f in _grader_modules()
                               if len(f.read_text(encoding="utf-8").splitlines()) > LONG_LINES],
                         ids=lambda f: f.relative_to(GRADER).as_posix())
def test_a_long_grader_module_says_why(f):
    doc = ast.get_docstring(ast.parse(f.read_text(encoding="utf-8"))) or ""
    assert "Why one module:" in doc, (f"{rel_posix(f)} has over {LONG_LINES} lines: split it, or say in its "
                                      "docstring why it is one module (a paragraph starting 'Why one module:')")
