"""Export a problem as a Kattis problem package (format 2023-07-draft) for problemtools/DOMjudge.

The package gets ``problem.yaml``, the statement, the input validators, the output validator
(with the shared checker runtime and the library modules it names embedded, so it runs
without this checkout),
``data/sample`` and every hidden group materialised under ``data/secret``, the generator, and the
reference solutions from ``solutions/<problem>/expected.yaml`` under ``submissions/``. The
directory is named after the problem id without dashes (Kattis short names are ``[a-z0-9]+``).

Example:
    python -m grader export-kattis delaunay /tmp/kattis    # -> /tmp/kattis/delaunay
    verifyproblem -p config data validators submissions /tmp/kattis/delaunay
"""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import yaml

from . import checker_runtime
from .problems import REPO, Problem, load_problem

KATTIS_DIRS = {"AC": "accepted", "WA": "wrong_answer", "TLE": "time_limit_exceeded", "RE": "run_time_error",
               "PE": "wrong_answer"}


def shortname(problem_id: str) -> str:
    name = re.sub(r"[^a-z0-9]", "", problem_id.lower())
    if not name:
        raise ValueError(f"problem id {problem_id!r} gives an empty Kattis short name")
    return name


def expected_verdicts(problem_id: str) -> dict[str, str]:
    """``solutions/<problem>/expected.yaml``: file name -> expected verdict."""
    f = REPO / "solutions" / problem_id / "expected.yaml"
    if not f.is_file():
        return {}
    data = yaml.safe_load(f.read_text()) or {}
    return {str(k): str(v) for k, v in data.items()}


def export(problem: Problem | str, outdir: str | Path, groups: list[str] | None = None,
           with_submissions: bool = True) -> Path:
    """Write the package to ``outdir/<shortname>`` and return that path. ``groups`` limits the
    hidden groups exported (default: all)."""
    p = load_problem(problem) if isinstance(problem, str) else problem
    dest = Path(outdir) / shortname(p.id)
    if dest.exists():
        shutil.rmtree(dest)
    dest.mkdir(parents=True)
    shutil.copy(p.path / "problem.yaml", dest / "problem.yaml")
    for d in ("statement", "input_validators", "generators"):
        if (p.path / d).is_dir():
            shutil.copytree(p.path / d, dest / d, ignore=shutil.ignore_patterns("__pycache__"))
    ov = dest / "output_validator"
    ov.mkdir()
    (ov / p.checker_path.name).write_text(embed_checker(p))
    (dest / "data" / "sample").mkdir(parents=True)
    (dest / "data" / "secret").mkdir(parents=True)
    order = {g.name: i for i, g in enumerate(p.groups)}
    for t in p.tests():
        group, stem = t.name.split("/", 1)
        if t.group == "sample" or group == "sample":
            base = dest / "data" / "sample" / stem
        elif groups is None or t.group in groups:  # judges sort by name: keep the groups' order
            base = dest / "data" / "secret" / f"{order[t.group]:02d}-{group}-{stem}"
        else:
            continue
        base.with_suffix(".in").write_text(t.input_text)
        base.with_suffix(".ans").write_text(t.answer_text)
    if with_submissions:
        for name, verdict in expected_verdicts(p.id).items():
            sub_dir = KATTIS_DIRS.get(verdict)
            src = REPO / "solutions" / p.id / name
            if sub_dir and src.suffix == ".py" and src.is_file():
                (dest / "submissions" / sub_dir).mkdir(parents=True, exist_ok=True)
                shutil.copy(src, dest / "submissions" / sub_dir / src.name)
    return dest


def embed_checker(p: Problem) -> str:
    """The checker as one self-contained file: the shared runtime and the library modules it names
    in ``LIBRARY`` embedded, plus the Kattis ``__main__`` entry (see :mod:`grader.checker_runtime`)."""
    return checker_runtime.embed(p.checker_path.read_text(), REPO / "reference_impl")


LANGUAGES_YAML = """\
# problemtools language override: run Python with CPython (python3 on PATH), not PyPy.
python3:
    name: 'Python 3 (CPython)'
    priority: 850
    files: '*.py'
    compile: 'python3 -m py_compile {files}'
    run: 'python3 "{mainfile}"'
"""
