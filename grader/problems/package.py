"""Problem packages: load, validate, list, and materialise their tests.

A problem is a directory ``assignments/<id>/`` in the Kattis layout (``problem.yaml``,
``statement/``, ``data/sample``, ``generators/``, ``input_validators/``, ``output_validators/``)
plus ``course.yaml`` with the grader's settings (entry function, forbidden modules, groups with
points and generated cases). Hidden tests are generated with a fixed seed, their answers come
from ``reference_impl`` (in the grader's process), and they are cached under
``<checkout>/.cache/grader/`` keyed by a digest of the package (:mod:`grader.problems.cache`:
who may write that cache, what it was made for, ``python -m grader warm``). A group marked ``withheld`` (as in
the students' copy, :mod:`grader.course.public_problems`) keeps its name and points but has no tests here.

Example:
    >>> p = load_problem("delaunay")
    >>> [g.name for g in p.groups][:2], p.entry
    (['sample', 'tiny'], 'delaunay')
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import subprocess
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from types import ModuleType
from typing import IO, Any

from ..judging import checker_runtime, feedback_policy
from ..judging.checker_runtime import load_checker, read_answer
from . import cache
from .cache import load_yaml, tests_folder

REPO = Path(__file__).resolve().parent.parent.parent
ALWAYS_FORBIDDEN = ("reference_impl", "grader")


COURSE_CONFIG = "nbgrader_config.py"


def _holds_problems(folder: Path) -> bool:
    return folder.is_dir() and any((d / "problem.yaml").is_file() and (d / "course.yaml").is_file()
                                   for d in folder.iterdir())


def course_folder(start: str | Path | None = None) -> Path | None:
    """The nbgrader course folder a command run in ``start`` (default: the current directory) acts on.

    nbgrader's own rule: the folder you are in, holding ``nbgrader_config.py``. From the folder
    above it (a checkout or a copy of the course), its ``assignments/``. None when neither holds one.

    >>> course_folder(REPO) == REPO / "assignments"
    True
    """
    start = Path(start) if start is not None else Path.cwd()
    for folder in (start, start / "assignments"):
        if (folder / COURSE_CONFIG).is_file():
            return folder.resolve()
    return None


def problems_root() -> Path:
    """Where problems live: ``$GRADER_PROBLEMS``; else the course folder the user is in
    (:func:`course_folder`) when it holds problem packages; else ``<checkout>/assignments``.

    >>> problems_root() == (course_folder() or REPO / "assignments")  # in a checkout or a course copy
    True
    """
    if os.environ.get("GRADER_PROBLEMS"):
        return Path(os.environ["GRADER_PROBLEMS"])
    here = course_folder()
    if here is not None and _holds_problems(here):
        return here
    return REPO / "assignments"


@contextmanager
def using_course(course_root: str | Path, problem_id: str | None = None) -> Iterator[Path]:
    """Within the block, the judge reads problems from the nbgrader course ``course_root`` that a
    command names (``--course``, a ``submitted/`` folder), unless ``$GRADER_PROBLEMS`` already says
    where; then :func:`check_course` refuses a mismatch. Yields the course folder, resolved.

    >>> with using_course(REPO / "assignments", "delaunay") as course:
    ...     problems_root().resolve() == course
    True
    """
    course = Path(course_root).resolve()
    saved = os.environ.get("GRADER_PROBLEMS")
    if not saved:
        os.environ["GRADER_PROBLEMS"] = str(course)
    try:
        yield check_course(course, problem_id)
    finally:
        if saved is None:
            os.environ.pop("GRADER_PROBLEMS", None)
        else:
            os.environ["GRADER_PROBLEMS"] = saved


def check_course(course_root: str | Path, problem_id: str | None = None) -> Path:
    """Refuse a mismatch between nbgrader's course folder and the judge's problems.

    The judge reads a problem's tests and points from :func:`problems_root`; nbgrader reads
    notebooks and the gradebook from ``course_root``. They must be the same folder (and hold
    ``problem_id``), else ``ValueError`` says which two folders differ and how to fix it.
    Returns the course folder, resolved.

    >>> check_course(REPO / "assignments", "delaunay") == (REPO / "assignments").resolve()
    True
    """
    course = Path(course_root).resolve()
    judged = problems_root().resolve()
    if judged != course:
        why = ("$GRADER_PROBLEMS points there" if os.environ.get("GRADER_PROBLEMS")
               else f"{course} holds no problem package" if not _holds_problems(course)
               else "that is the course folder of the current directory")
        raise ValueError(f"the judge would read problems from {judged} ({why}) but nbgrader's course is {course}: "
                         f"run the command in {course} (cd there), copy the problem packages "
                         f"(assignments/<id>/) into it, or set GRADER_PROBLEMS={course}")
    if problem_id is not None and not (course / problem_id / "problem.yaml").is_file():
        raise ValueError(f"nbgrader's course {course} has no problem package {problem_id!r} "
                         f"(expected {course / problem_id / 'problem.yaml'}); copy assignments/{problem_id}/ into it")
    return course


@dataclass
class Group:
    name: str
    points: int
    cases: list[dict] = field(default_factory=list)
    data: str | None = None  # a directory of committed .in/.ans files
    withheld: bool = False  # its tests are not in this copy (the student edition): points only

    @property
    def public(self) -> bool:
        """A sample group: committed under ``data/sample``, worth no points, its tests public."""
        return self.points == 0 and bool(self.data) and "sample" in Path(self.data).parts


@dataclass
class TestCase:
    """One test: its input text and the reference answer text (parent side only)."""

    __test__ = False  # not a pytest test class

    name: str
    group: str
    input_text: str
    answer_text: str


def _load_module(path: Path, name: str) -> ModuleType:
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise ValueError(f"cannot load {path}")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _time_limits(problem: str, raw: Any) -> dict[str, float]:
    """course.yaml's ``time_limits`` (language name -> seconds), validated."""
    if raw is None:
        return {}
    if not isinstance(raw, dict):
        raise ValueError(f"problem {problem!r}: course.yaml 'time_limits' must map a language to seconds, got {raw!r}")
    out = {}
    for lang, seconds in raw.items():
        if isinstance(seconds, bool) or not isinstance(seconds, (int, float)) or not 0 < seconds <= 600:
            raise ValueError(f"problem {problem!r}: time_limits[{lang!r}] must be a number of seconds in (0, 600], "
                             f"got {seconds!r}")
        out[str(lang)] = float(seconds)
    return out


@dataclass
class Problem:
    """A loaded problem package; see the module docstring."""

    id: str
    path: Path
    title: str
    time_limit: float
    memory_mb: int
    output_mb: int
    entry: str
    forbidden: tuple[str, ...]
    groups: list[Group]
    checker_path: Path
    generator_path: Path | None
    seed: int
    timed: dict
    #: per-language time limits (course.yaml ``time_limits: {cpp: 1.0}``); a language not named
    #: here gets ``time_limit`` (problem.yaml's, the limit of the Python solutions and of Kattis)
    time_limits: dict[str, float] = field(default_factory=dict)
    #: group -> feedback level (course.yaml ``feedback``; :mod:`grader.judging.feedback_policy`)
    feedback: dict[str, str] = field(default_factory=dict)
    #: the counterexample search's budget per failing submission, seconds (0: off; course.yaml
    #: ``feedback: {counterexample, counterexample_seconds}``; :mod:`grader.contest.counterexample`)
    counterexample_seconds: float = feedback_policy.COUNTEREXAMPLE_SECONDS

    @classmethod
    def load(cls, path: str | Path) -> "Problem":
        path = Path(path)
        meta_file, course_file = path / "problem.yaml", path / "course.yaml"
        for f in (meta_file, course_file):
            if not f.is_file():
                raise ValueError(f"problem {path.name!r}: missing {f.name}")
        meta = load_yaml(meta_file) or {}
        course = load_yaml(course_file) or {}
        limits = meta.get("limits") or {}
        name = meta.get("name", path.name)
        groups = []
        for g in course.get("groups") or []:
            if "name" not in g or "points" not in g:
                raise ValueError(f"problem {path.name!r}: every group needs a name and points, got {g!r}")
            groups.append(Group(str(g["name"]), int(g["points"]), list(g.get("cases") or []), g.get("data"),
                                bool(g.get("withheld", False))))
        if "entry" not in course:
            raise ValueError(f"problem {path.name!r}: course.yaml needs 'entry' (the function students define)")
        forbidden = tuple(dict.fromkeys([*ALWAYS_FORBIDDEN, *(course.get("forbidden") or [])]))
        return cls(
            id=path.name, path=path, title=name if isinstance(name, str) else name.get("en", path.name),
            time_limit=float(limits.get("time_limit", 2.0)), memory_mb=int(limits.get("memory", 1024)),
            output_mb=int(limits.get("output", 16)), entry=str(course["entry"]), forbidden=forbidden,
            groups=groups, checker_path=path / course.get("checker", "output_validator/checker.py"),
            generator_path=(path / course["generator"]) if course.get("generator") else None,
            seed=int(course.get("seed", 0)), timed=dict(course.get("timed") or {}),
            time_limits=_time_limits(path.name, course.get("time_limits")),
            feedback=feedback_policy.resolve(path.name, course.get("feedback"), {g.name: g.public for g in groups}),
            counterexample_seconds=feedback_policy.counterexample_seconds(path.name, course.get("feedback")),
        )

    def feedback_level(self, group: str) -> str:
        """How much a student's feedback shows of a failing test of ``group`` (a level of
        :mod:`grader.judging.feedback_policy`)."""
        return self.feedback.get(group, feedback_policy.DEFAULT)

    def time_limit_for(self, language: str) -> float:
        """The CPU-time limit per test for a language (its name in :mod:`grader.judging.languages`).

        >>> p = load_problem("delaunay")
        >>> p.time_limit_for("python") == p.time_limit
        True
        """
        return float(self.time_limits.get(language, self.time_limit))

    # -- validation -----------------------------------------------------------------------
    def validate(self) -> list[str]:
        """Structural problems of the package (an empty list when it is sound)."""
        errors = []
        if not (self.path / "statement" / "problem.en.md").is_file():
            errors.append("statement/problem.en.md is missing")
        if not self.checker_path.is_file():
            errors.append(f"checker {self.checker_path} is missing")
        if not (self.path / "input_validators").is_dir() or not self.input_validators():
            errors.append("input_validators/ holds no validator program (<name>.py, or <dir>/main.py)")
        names = [g.name for g in self.groups]
        if len(set(names)) != len(names):
            errors.append("group names repeat")
        for g in self.present_groups:
            if g.data and not (self.path / g.data).is_dir():
                errors.append(f"group {g.name}: data directory {g.data} is missing")
            if g.cases and self.generator_path is None:
                errors.append(f"group {g.name}: generated cases but no generator")
            if not g.cases and not g.data:
                errors.append(f"group {g.name}: no tests")
        if sum(g.points for g in self.groups) != 100:
            errors.append(f"group points sum to {sum(g.points for g in self.groups)}, not 100")
        if self.generator_path is not None and self.generator_path.is_file():
            if not callable(getattr(self.generator, "solve", None)):
                errors.append("generator lacks solve()")
            if not any(callable(getattr(self.generator, a, None)) for a in ("generate", "generate_args")):
                errors.append("generator lacks generate() (or generate_args())")
        return errors

    def validate_checker(self) -> list[str]:
        """The checker protocol on every test (see :mod:`grader.judging.checker_protocol`)."""
        from ..judging.checker_protocol import validate_checker

        return validate_checker(self)

    def input_validators(self) -> list[Path]:
        """The validator programs: each ``input_validators/<name>.py``, and for each directory (one
        program, as Kattis sees it) its ``main.py``, else its ``<name>.py``."""
        out = []
        for entry in sorted((self.path / "input_validators").iterdir()):
            if entry.is_dir():
                main = next((f for f in (entry / "main.py", entry / f"{entry.name}.py") if f.is_file()), None)
                if main is not None:
                    out.append(main)
            elif entry.suffix == ".py":
                out.append(entry)
        return out

    def validate_inputs(self) -> list[str]:
        """Run the package's input validators on every test input (Kattis: exit 42 = valid)."""
        errors = []
        validators = self.input_validators()
        for t in self.tests():
            for v in validators:
                r = subprocess.run([sys.executable, str(v)], input=t.input_text, text=True, capture_output=True)
                if r.returncode != 42:
                    errors.append(f"{t.name}: {v.name} rejected it: {r.stderr.strip()[:200]}")
        return errors

    # -- modules --------------------------------------------------------------------------
    @cached_property
    def checker(self) -> ModuleType:
        return load_checker(self.checker_path, f"_checker_{self.id.replace('-', '_')}")

    def read_answer(self, test: TestCase, args: list) -> Any:
        """The reference answer of ``test`` in the checker's form (``None`` when there is none)."""
        return read_answer(self.checker, test.answer_text, args) if test.answer_text else None

    @cached_property
    def generator(self) -> ModuleType:
        if self.generator_path is None:
            raise ValueError(f"problem {self.id!r} has no generator")
        return _load_module(self.generator_path, f"_generator_{self.id.replace('-', '_')}")

    @property
    def present_groups(self) -> list[Group]:
        """The groups whose tests this copy holds (all but the withheld ones of a student edition)."""
        return [g for g in self.groups if not g.withheld]

    @property
    def group_points(self) -> dict[str, int]:
        """Points of each group that can be judged here (a withheld group cannot)."""
        return {g.name: g.points for g in self.present_groups}

    @property
    def points(self) -> int:
        """The problem's total points, withheld groups included (100 for a sound package)."""
        return sum(g.points for g in self.groups)

    # -- tests ----------------------------------------------------------------------------
    def _code_files(self) -> list[Path]:
        """Files the tests depend on beyond the package: the checker and generator (which may sit
        behind symlinked directories), the checker's LIBRARY modules, and the point-case modules
        of other packages that the generator loads."""
        files = [f for f in (self.checker_path, self.generator_path) if f is not None and f.is_file()]
        if self.checker_path.is_file():
            files += [checker_runtime.library_file(n)
                      for n in checker_runtime.library_names(self.checker_path.read_text())]
        if self.generator_path is not None and self.generator_path.is_file():
            root, seen, todo = str(problems_root()), set(), [self.generator]
            while todo:  # modules loaded by path from other packages, transitively
                for m in vars(todo.pop()).values():
                    f = getattr(m, "__file__", None) if isinstance(m, ModuleType) else None
                    if f and str(f).startswith(root) and f not in seen:
                        seen.add(f)
                        todo.append(m)
            files += sorted(Path(f) for f in seen)
        return files

    def digest(self) -> str:
        h = hashlib.sha256()
        for f in self._code_files():
            h.update(f.read_bytes())
        for f in sorted(p for p in self.path.rglob("*") if p.is_file() and "__pycache__" not in p.parts):
            h.update(str(f.relative_to(self.path)).encode())
            h.update(f.read_bytes())
        return h.hexdigest()[:16]

    def tests(self) -> list[TestCase]:
        """All tests in judging order: groups as listed, cases as listed."""
        if "_tests" not in self.__dict__:
            self.__dict__["_tests"] = self._load_tests()
        return self.__dict__["_tests"]

    def _load_tests(self) -> list[TestCase]:
        out: list[TestCase] = []
        folder = None
        for g in self.present_groups:
            if g.data:
                for f in sorted((self.path / g.data).glob("*.in")):
                    ans = f.with_suffix(".ans")
                    out.append(TestCase(f"{g.name}/{f.stem}", g.name, f.read_text(),
                                        ans.read_text() if ans.exists() else ""))
            if g.cases:
                folder = folder or self._materialise()
                for k in range(len(g.cases)):
                    stem = folder / g.name / f"{k + 1:02d}"
                    out.append(TestCase(f"{g.name}/{k + 1:02d}", g.name, stem.with_suffix(".in").read_text(),
                                        stem.with_suffix(".ans").read_text()))
        return out

    def _materialise(self) -> Path:
        """The folder of the generated tests: from the cache when a trusted copy made for this
        package is there, else generated now (:mod:`grader.problems.cache`)."""
        return tests_folder(self.id, self.digest(), self._generate_into)

    def _generate_into(self, folder: Path) -> None:
        """Write every generated case's ``<group>/<NN>.in`` and ``.ans`` into ``folder``."""
        for g in self.present_groups:
            (folder / g.name).mkdir()
            for k, case in enumerate(g.cases):
                args = self.generate_args(case, self.seed + 1000 * k + sum(map(ord, g.name)))
                stem = folder / g.name / f"{k + 1:02d}"
                stem.with_suffix(".in").write_text(self.checker.write_input(args))
                stem.with_suffix(".ans").write_text(self.checker.write_output(self.generator.solve(*args)))

    def generate_args(self, case: dict, seed: int) -> list[Any]:
        """The entry function's argument list for one generated case: the generator's
        ``generate_args(case, seed)`` when it has one (problems with several arguments), else
        ``[generate(case, seed)]``."""
        gen = self.generator
        return list(gen.generate_args(case, seed)) if hasattr(gen, "generate_args") else [gen.generate(case, seed)]

    def parse_args(self, test: TestCase) -> list[Any]:
        return self.checker.read_input(test.input_text)


def list_problems(root: str | Path | None = None) -> list[Problem]:
    """Every problem package under ``root`` (default :func:`problems_root`), sorted by id."""
    root = Path(root) if root else problems_root()
    return [Problem.load(d) for d in sorted(root.iterdir()) if (d / "problem.yaml").is_file() and (d / "course.yaml").is_file()]


def load_problem(problem_id: str, root: str | Path | None = None) -> Problem:
    """Load one problem by id; ``ValueError`` naming the known ids when it does not exist."""
    root = Path(root) if root else problems_root()
    path = root / problem_id
    if not (path / "problem.yaml").is_file():
        known = ", ".join(p.id for p in list_problems(root)) or "none"
        raise ValueError(f"unknown problem {problem_id!r}; known problems: {known}")
    return Problem.load(path)


def warm(problem_ids: list[str] | None = None, out: IO[str] | None = None) -> dict[str, Path | None]:
    """Generate every problem's tests (or ``problem_ids``') into the cache; one line per problem on
    ``out``. Returns each problem's tests folder (None: it generates nothing)."""
    problems = [load_problem(p) for p in problem_ids] if problem_ids else list_problems()
    done: dict[str, Path | None] = {}
    for k, p in enumerate(problems, 1):
        if out is not None:
            print(f"[{k}/{len(problems)}] {p.id}: ", end="", file=out, flush=True)
        if not any(g.cases for g in p.present_groups):
            done[p.id] = None
            if out is not None:
                print("no generated tests", file=out, flush=True)
            continue
        t0, c0 = time.monotonic(), time.process_time()
        digest = p.digest()
        manifest = cache.manifest_for(p.id, digest)
        cached = [r / p.id / digest for r in (cache.cache_root(), cache.private_root())]
        fresh = not any(f.is_dir() and cache.valid_reason(f, manifest) is None for f in cached)
        tests = p.tests()
        done[p.id] = p._materialise()  # the folder tests() read (found again: nothing is generated twice)
        if out is not None:
            how = (f"generated in {time.monotonic() - t0:.1f} s ({time.process_time() - c0:.1f} CPU-s)" if fresh
                   else "cached")
            print(f"{len(tests)} tests, {how}: {done[p.id]}", file=out, flush=True)
    return done
