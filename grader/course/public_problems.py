"""The students' copy of the problem packages: what the sample check needs, nothing to rebuild a hidden test.

A course server gives every account a read-only copy of the problems, so that the assignment
notebooks' "check on the samples" cell (``%check_samples``) can judge a student's code on the
public samples. That copy must not hold what the hidden tests are made from: the generators,
their seed, or the hidden groups' cases (with those a student could rebuild every hidden input and
hard-code the answers). This writes, for each package of a course folder, its ``problem.yaml``,
statement, samples, input validators and checker, and a ``course.yaml`` reduced to its public
part (:func:`public_course_yaml`); the instructor's side keeps the full packages. The student
edition (``grader.course.student_edition``) ships the same public packages.

Run:
    python -m grader.public_problems assignments /srv/course/problems    # SOURCE DEST (replaced)

Example:
    >>> import tempfile
    >>> out = write_public_problems(REPO / "assignments", Path(tempfile.mkdtemp()) / "problems")
    >>> sorted(p.name for p in (out / "delaunay").iterdir())
    ['course.yaml', 'data', 'input_validators', 'output_validator', 'problem.yaml', 'statement']
    >>> "seed" in (out / "delaunay" / "course.yaml").read_text()
    False
"""

from __future__ import annotations

import argparse
import shutil
import sys
from pathlib import Path

import yaml

from ..problems import REPO  # noqa: F401 - the example above uses it
from ..problems.cache import load_yaml_text

__all__ = ["public_course_yaml", "write_public_problem", "write_public_problems", "PROBLEM_PARTS"]

PROBLEM_PARTS = ("problem.yaml", "statement", "data/sample", "input_validators", "output_validator")
"""What of a package a student may read: statement, samples, validators, checker."""
IGNORE = shutil.ignore_patterns("__pycache__", "*.pyc", "*.nbi", "*.nbc", ".ipynb_checkpoints", ".cache")
PUBLIC_COURSE_KEYS = ("entry", "forbidden", "checker", "timed")
PUBLIC_CASE_KEYS = ("kind", "scale")
"""What a student may know of a hidden case: the kind of input and its scale (the statement says as much)."""


def public_course_yaml(course: dict) -> dict:
    """``course.yaml`` without the generator, its seed and the hidden tests.

    The public sample groups (no points, data under ``data/sample``) stay whole. Every other group stays as ``withheld``: its name, its
    points and, per case, only the kind of input and its scale (no sizes, no seeds, no data; one
    entry per test), so that ``python -m grader list`` shows the points and a lesson can say what a
    group tests.

    >>> public_course_yaml({"entry": "f", "seed": 7, "generator": "generators/gen.py", "groups": [
    ...     {"name": "sample", "points": 0, "data": "data/sample"},
    ...     {"name": "big", "points": 100, "cases": [{"kind": "grid", "n": 9, "scale": 1e300}]}]})
    {'entry': 'f', 'groups': [{'name': 'sample', 'points': 0, 'data': 'data/sample'}, \
{'name': 'big', 'points': 100, 'withheld': True, 'cases': [{'kind': 'grid', 'scale': 1e+300}]}]}
    """
    out = {k: course[k] for k in PUBLIC_COURSE_KEYS if k in course}
    out["groups"] = []
    for g in course.get("groups") or []:
        if g.get("points", 0) == 0 and "cases" not in g and "sample" in Path(str(g.get("data", ""))).parts:
            out["groups"].append(g)
        else:
            out["groups"].append({"name": g["name"], "points": g.get("points", 0), "withheld": True,
                                  "cases": [{k: c[k] for k in PUBLIC_CASE_KEYS if k in c}
                                            for c in g.get("cases") or []]})
    return out


def print_or_fail(write, *args) -> int:
    """Run ``write(*args)`` for a command line: print the folder it wrote (exit 0) or its
    ``ValueError`` as ``error: ...`` on stderr (exit 2)."""
    try:
        print(write(*args))
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    return 0


def write_public_problem(package: Path, dest: Path) -> Path:
    """Copy the public parts of one problem package ``package`` to ``dest`` (which must not exist)."""
    package, dest = Path(package), Path(dest)
    if not (package / "problem.yaml").is_file() or not (package / "course.yaml").is_file():
        raise ValueError(f"{package} is not a problem package (no problem.yaml and course.yaml)")
    dest.mkdir(parents=True)
    for part in PROBLEM_PARTS:
        src = package / part
        if src.is_dir():
            shutil.copytree(src, dest / part, ignore=IGNORE)   # follows symlinked directories
        elif src.is_file():
            shutil.copy(src, dest / part)
    course = load_yaml_text((package / "course.yaml").read_text()) or {}
    (dest / "course.yaml").write_text(f"# {package.name}: the public part of the grader's settings\n"
                                      + yaml.safe_dump(public_course_yaml(course), sort_keys=False))
    return dest


def write_public_problems(source: Path, dest: Path) -> Path:
    """Write the public copy of every problem package in ``source`` to ``dest``, replacing it whole.

    The new copy is written beside ``dest`` and moved into place, so a reader never sees half of it.
    """
    source, dest = Path(source), Path(dest)
    packages = sorted(p for p in source.iterdir() if (p / "problem.yaml").is_file()) if source.is_dir() else []
    if not packages:
        raise ValueError(f"{source} holds no problem package (no <id>/problem.yaml)")
    fresh = dest.with_name(dest.name + ".new")
    shutil.rmtree(fresh, ignore_errors=True)
    fresh.mkdir(parents=True)
    for package in packages:
        write_public_problem(package, fresh / package.name)
    old = dest.with_name(dest.name + ".old")
    shutil.rmtree(old, ignore_errors=True)
    if dest.exists():
        dest.rename(old)
    fresh.rename(dest)
    shutil.rmtree(old, ignore_errors=True)
    return dest


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m grader.public_problems",
                                 description="write the students' copy of a course's problem packages")
    ap.add_argument("source", help="a course folder holding <id>/problem.yaml packages (e.g. assignments)")
    ap.add_argument("dest", help="the students' copy (replaced whole)")
    a = ap.parse_args(argv)
    return print_or_fail(write_public_problems, Path(a.source), Path(a.dest))


if __name__ == "__main__":
    sys.exit(main())
