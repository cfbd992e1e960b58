"""Export a problem as a Kattis problem package (format 2023-07-draft) for problemtools/DOMjudge.

The package gets ``problem.yaml`` (as a ``scoring`` problem), the statement, the input
validators, the output validator (with the shared checker runtime and the library modules it
names embedded, so it runs without this checkout), ``data/sample``, one directory per scored
group under ``data/secret``, the generator, and the reference solutions from
``solutions/<problem>/expected.yaml`` under ``submissions/``. The directory is named after the
problem id without dashes (Kattis short names are ``[a-z0-9]+``).

Scoring is kept as the grader does it: a group's points count only if every test in it passes,
and the score is the sum over groups. Each ``data/secret/NN-<group>/testdata.yaml`` says
``accept_score: <points>`` with the ``min`` aggregation (all tests must pass) and stops at the
first failure; ``data/secret/testdata.yaml`` sums the groups and accepts a submission that
passes at least one (``accept_if_any_accepted``), so a partly correct submission is AC with a
partial score, as on Kattis; a submission that passes none gets the verdict of its first failing
group (``first_error``, the judge's own rule), so a wrong answer killed fast by an early group is
WA even when a later, large test runs near the time limit (problemtools' default, ``worst_error``,
would let that test's TLE decide, and placement would depend on timing); the samples score nothing (``ignore_sample`` at the top).
A reference solution that scores part of the points goes to ``submissions/partially_accepted``;
where each goes is decided by judging it on the exported groups (``judge=False``: by its
expected verdict only).

Example:
    python -m grader export-kattis delaunay build/kattis --groups tiny,large:1   # -> build/kattis/delaunay
    verifyproblem -p config data validators submissions build/kattis/delaunay
"""

from __future__ import annotations

import dataclasses
import re
import shutil
import sys
from pathlib import Path

import yaml

from ..judging import checker_runtime
from ..problems import REPO, Group, Problem, load_problem
from ..problems.cache import load_yaml_text

KATTIS_DIRS = {"AC": "accepted", "WA": "wrong_answer", "TLE": "time_limit_exceeded", "RE": "run_time_error",
               "PE": "wrong_answer", "MLE": "run_time_error", "SV": "run_time_error"}
#: problemtools' default grader ranks verdicts (worst first) when no group is accepted
KATTIS_ORDER = ("run_time_error", "time_limit_exceeded", "wrong_answer")


def shortname(problem_id: str) -> str:
    name = re.sub(r"[^a-z0-9]", "", problem_id.lower())
    if not name:
        raise ValueError(f"problem id {problem_id!r} gives an empty Kattis short name")
    return name


def _expected(problem_id: str) -> dict[str, list[str]]:
    f = REPO / "solutions" / problem_id / "expected.yaml"
    if not f.is_file():
        return {}
    data = load_yaml_text(f.read_text()) or {}
    return {str(k): str(v).split() for k, v in data.items()}


def expected_verdicts(problem_id: str) -> dict[str, str]:
    """``solutions/<problem>/expected.yaml``: file name -> expected verdict (a value may name,
    after the verdict, the scored group that must kill the file: ``WA exhaustive``)."""
    return {k: v[0] for k, v in _expected(problem_id).items()}


def killing_groups(problem_id: str) -> dict[str, str]:
    """The files of ``expected.yaml`` that name a group that must kill them: file -> group."""
    return {k: v[1] for k, v in _expected(problem_id).items() if len(v) > 1}


def scored_groups(p: Problem, groups: list[str] | None = None) -> list[tuple[Group, int | None]]:
    """The hidden (non-sample) groups to export, in the problem's order, each with how many of its
    tests to keep (``"large:1"``: only the first test of ``large``; None: all).

    ``ValueError`` for an unknown group name or a bad count."""
    hidden = [g for g in p.groups if g.name != "sample"]
    if groups is None:
        return [(g, None) for g in hidden]
    wanted: dict[str, int | None] = {}
    for item in groups:
        name, _, count = item.partition(":")
        if count and not (count.isdigit() and int(count) > 0):
            raise ValueError(f"problem {p.id!r}: {item!r}: the number after ':' must be a positive integer")
        wanted[name] = int(count) if count else None
    unknown = sorted(set(wanted) - {g.name for g in hidden})
    if unknown:
        raise ValueError(f"problem {p.id!r}: no hidden group {', '.join(unknown)}; "
                         f"groups: {', '.join(g.name for g in hidden)}")
    return [(g, wanted[g.name]) for g in hidden if g.name in wanted]


def group_dirname(p: Problem, group: str) -> str:
    """``data/secret/<this>``: judges sort by name, so the index keeps the groups' order."""
    return f"{[g.name for g in p.groups].index(group):02d}-{group}"


def selection(p: Problem, chosen: list[tuple[Group, int | None]]) -> Problem:
    """``p`` with only the exported groups and tests (what a judge of the package would run)."""
    keep = {g.name: n for g, n in chosen}
    tests, seen = [], dict.fromkeys(keep, 0)
    for t in p.tests():
        if t.group in keep and (keep[t.group] is None or seen[t.group] < keep[t.group]):
            seen[t.group] += 1
            tests.append(t)
    q = dataclasses.replace(p, groups=[g for g, _ in chosen])
    q.__dict__["_tests"] = tests
    return q


def placements(p: Problem, judge: bool = True, partial: bool = False) -> dict[str, str]:
    """Reference solution file -> Kattis ``submissions/`` directory for a package holding ``p``'s
    groups and tests (see :func:`selection`).

    With ``judge`` the non-AC solutions are judged on those tests: full marks -> ``ValueError``
    (the package cannot tell it from a correct one), or, when only some groups are exported
    (``partial``), the solution is left out with a note on stderr (the group that kills it was not
    exported); part -> ``partially_accepted``, none -> the directory of the first failure's
    verdict in the judge's order (``first_error`` in ``data/secret``)."""
    out = {}
    for name, verdict in expected_verdicts(p.id).items():
        src = REPO / "solutions" / p.id / name
        if src.suffix != ".py" or not src.is_file() or verdict not in KATTIS_DIRS:
            continue
        if verdict == "AC" or not judge:
            out[name] = KATTIS_DIRS[verdict]
            continue
        from .judge import Judge

        result = Judge(p, hide=[str(src.parent)]).judge_path(src)
        if result.score == result.max_score and partial:
            print(f"export-kattis: {name} left out of submissions/: it passes every exported group "
                  f"({', '.join(g.name for g in p.groups)}); the group that kills it is not exported",
                  file=sys.stderr)
            continue
        if result.score == result.max_score:
            raise ValueError(f"{p.id}: {name} (expected {verdict}) passes every exported test "
                             f"(groups {', '.join(g.name for g in p.groups)}); export a group it fails")
        close = near_limit(result, p.time_limit)
        if close:
            print(f"export-kattis: {p.id}/{name}: passed {', '.join(close)}, over {NEAR_LIMIT:g} of the "
                  f"{p.time_limit:g} s limit: its placement may depend on the judge machine's speed",
                  file=sys.stderr)
        if result.score > 0:
            out[name] = "partially_accepted"
        else:
            # the first failure's verdict: what data/secret's first_error aggregation reports
            out[name] = KATTIS_DIRS.get(str(result.verdict), "wrong_answer")
    return out


#: a passed test slower than this share of the time limit makes a placement depend on timing
NEAR_LIMIT = 0.5


def near_limit(result, time_limit: float, share: float = NEAR_LIMIT) -> list[str]:
    """The tests ``result`` passed in more than ``share`` of ``time_limit`` seconds, as
    ``"name (t s)"``: where a slower or busier judge could turn a pass into a TLE and so change
    the solution's score and its ``submissions/`` directory.

    >>> from grader.judging.verdicts import JudgeResult, TestResult, Verdict
    >>> r = JudgeResult("p", "s.py", [TestResult("large/01", "large", Verdict.AC, 3.8),
    ...                               TestResult("tiny/01", "tiny", Verdict.AC, 0.1)], {"large": 30, "tiny": 10})
    >>> near_limit(r, 6.0)
    ['large/01 (3.8 s)']
    """
    return [f"{t.name} ({t.time_s:.1f} s)" for t in result.tests
            if str(t.verdict) == "AC" and t.time_s > share * time_limit]


def _testdata(path: Path, **settings) -> None:
    path.mkdir(parents=True, exist_ok=True)
    (path / "testdata.yaml").write_text(yaml.safe_dump(settings, sort_keys=False))


def export(problem: Problem | str, outdir: str | Path, groups: list[str] | None = None,
           with_submissions: bool = True, judge: bool = True) -> Path:
    """Write the package to ``outdir/<shortname>`` and return that path. ``groups`` limits the
    hidden groups exported (default: all; ``"large:1"`` keeps the first test of ``large``);
    ``judge`` places the reference solutions by judging
    them (see :func:`placements`)."""
    p = load_problem(problem) if isinstance(problem, str) else problem
    chosen = scored_groups(p, groups)
    exported = selection(p, chosen)
    dest = Path(outdir) / shortname(p.id)
    if dest.exists():
        shutil.rmtree(dest)
    dest.mkdir(parents=True)
    meta = load_yaml_text((p.path / "problem.yaml").read_text()) or {}
    meta["type"] = "scoring"
    (dest / "problem.yaml").write_text(yaml.safe_dump(meta, sort_keys=False, allow_unicode=True))
    for d in ("statement", "input_validators", "generators"):
        if (p.path / d).is_dir():
            shutil.copytree(p.path / d, dest / d, ignore=shutil.ignore_patterns("__pycache__"))
    ov = dest / "output_validator"
    ov.mkdir()
    (ov / p.checker_path.name).write_text(embed_checker(p))
    data = dest / "data"
    _testdata(data, on_reject="continue", grader_flags="ignore_sample")
    _testdata(data / "sample", on_reject="continue", grader_flags="sum", accept_score=0, range="0 0")
    total = sum(g.points for g, _ in chosen)
    _testdata(data / "secret", on_reject="continue", grader_flags="sum accept_if_any_accepted first_error", range=f"0 {total}")
    for g, _ in chosen:
        _testdata(data / "secret" / group_dirname(p, g.name), on_reject="break", grader_flags="min",
                  accept_score=g.points, range=f"0 {g.points}")
    samples = [t for t in p.tests() if t.group == "sample"]
    for t in samples + exported.tests():
        stem = t.name.split("/", 1)[1]
        base = data / "sample" / stem if t.group == "sample" else data / "secret" / group_dirname(p, t.group) / stem
        base.with_suffix(".in").write_text(t.input_text)
        base.with_suffix(".ans").write_text(t.answer_text)
    if with_submissions:
        for name, sub_dir in placements(exported, judge=judge, partial=groups is not None).items():
            (dest / "submissions" / sub_dir).mkdir(parents=True, exist_ok=True)
            shutil.copy(REPO / "solutions" / p.id / name, dest / "submissions" / sub_dir / Path(name).name)
    return dest


def embed_checker(p: Problem) -> str:
    """The checker as one self-contained file: the shared runtime and the library modules it names
    in ``LIBRARY`` embedded, plus the Kattis ``__main__`` entry (see :mod:`grader.judging.checker_runtime`)."""
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
