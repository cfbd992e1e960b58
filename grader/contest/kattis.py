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

The C++ reference solutions (``solutions/<problem>/expected_cpp.yaml``) go into ``submissions/``
beside the Python ones, but a Kattis package has one time limit, the Python one of
``problem.yaml``, while a C++ verdict was measured under the problem's C++ limit (course.yaml
``time_limits``). So (:func:`cpp_placements`): an accepted one goes to ``accepted/``; a
wrong one (WA, PE, RE, MLE: the time limit does not change them) where its expected failing
groups say, from ``expected_cpp.yaml``; a too-slow one (TLE) only when the judge takes ``.cpp``
and judging it under twice the package's limit (problemtools' safety margin) still fails
(otherwise it is left out: under Python's limit an O(n^2) C++ program may pass); a compile error never (problemtools has no directory for
it and reports it as an error). What was left out and why is printed on stderr and written in the
package's ``README.md``. verifyproblem compiles C++ with its own flags (``g++ -O2 -static``, a
newer ``-std``), not the course's, and the accepted programs pass there too
(``tests/grader/test_kattis.py``).

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


def _expected(problem_id: str, name: str = "expected.yaml") -> dict[str, list[str]]:
    f = REPO / "solutions" / problem_id / name
    if not f.is_file():
        return {}
    data = load_yaml_text(f.read_text()) or {}
    return {str(k): str(v).split() for k, v in data.items()}


def expected_verdicts(problem_id: str) -> dict[str, str]:
    """``solutions/<problem>/expected.yaml``: file name -> expected verdict (a value may name,
    after the verdict, the scored group that must kill the file: ``WA exhaustive``)."""
    return {k: v[0] for k, v in _expected(problem_id).items()}


def expected_cpp(problem_id: str) -> dict[str, tuple[str, list[str]]]:
    """``solutions/<problem>/expected_cpp.yaml``: C++ file -> (expected verdict, the groups it fails,
    in the problem's order; empty for AC and CE)."""
    return {k: (v[0], v[1:]) for k, v in _expected(problem_id, "expected_cpp.yaml").items()}


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
        placed = placements(exported, judge=judge, partial=groups is not None)
        cpp, left_out = cpp_placements(exported, judge=judge, partial=groups is not None)
        for name, sub_dir in {**placed, **cpp}.items():
            (dest / "submissions" / sub_dir).mkdir(parents=True, exist_ok=True)
            shutil.copy(REPO / "solutions" / p.id / name, dest / "submissions" / sub_dir / Path(name).name)
        for name, why in left_out.items():
            print(f"export-kattis: {p.id}/{name} left out of submissions/: {why}", file=sys.stderr)
        (dest / "README.md").write_text(package_readme(p, {**placed, **cpp}, left_out))
    return dest


def cpp_placements(p: Problem, judge: bool = True, partial: bool = False) -> tuple[dict[str, str], dict[str, str]]:
    """The C++ reference solutions of ``expected_cpp.yaml`` for a package holding ``p``'s groups
    and tests (see :func:`selection`): (file -> ``submissions/`` directory, file left out -> why).

    The package's time limit is ``p.time_limit`` (Python's); a C++ verdict was measured under
    ``p.time_limit_for("cpp")``. AC stays AC under a limit at least as long; WA, PE, RE and MLE
    do not depend on it, so they are placed from the expected failing groups: none of them
    exported -> left out (``partial``) or ``ValueError``; some -> ``partially_accepted``; all ->
    the verdict's directory, when the first failing group overall is exported (else the first
    exported failure's verdict is unknown: left out). When ``judge`` and the judge takes ``.cpp``,
    every non-AC file is judged instead, under :data:`TLE_SAFETY` times the package's limit, and
    placed as :func:`placements` places Python; one that passes everything there is left out."""
    from ..judging.languages import language_of

    out: dict[str, str] = {}
    left: dict[str, str] = {}
    exported = [g.name for g in p.groups if g.points > 0]
    limit = f"the package's time limit of {p.time_limit:g} s (Python's; C++'s is {p.time_limit_for('cpp'):g} s)"
    for name, (verdict, failing) in expected_cpp(p.id).items():
        src = REPO / "solutions" / p.id / name
        if not src.is_file() or verdict not in KATTIS_DIRS:
            if verdict == "CE":
                left[name] = "a compile error (problemtools has no directory for one; verifyproblem reports it as an error)"
            elif src.is_file():
                raise ValueError(f"{p.id}: expected_cpp.yaml: {name}: unknown verdict {verdict!r}")
            continue
        if verdict == "AC":
            out[name] = "accepted"
        elif judge and language_of(src) is not None:
            placed = _judged_cpp(p, name, src, verdict, partial, limit)
            if placed is None:
                left[name] = f"it passes every exported group under {TLE_SAFETY:g} times {limit}"
            else:
                out[name] = placed
        elif verdict == "TLE":
            left[name] = (f"its TLE was measured under the C++ time limit; under {limit} it must be judged, and "
                          + ("it was not (--no-judge)" if not judge else "the judge here does not take .cpp"))
        else:
            failed = [g for g in exported if g in failing]
            if not failed:
                if not partial:
                    raise ValueError(f"{p.id}: {name} (expected {verdict} {' '.join(failing)}) fails no exported "
                                     f"group ({', '.join(exported)}): check expected_cpp.yaml")
                left[name] = f"it fails only {', '.join(failing)}, which is not exported"
            elif len(failed) < len(exported):
                out[name] = "partially_accepted"
            elif failing and failing[0] in exported:
                out[name] = KATTIS_DIRS[verdict]
            else:
                left[name] = f"its first failure ({failing[0]}) is not exported, so its verdict here is unknown"
    return out, left


#: problemtools' ``time_safety_margin``: a submission in ``time_limit_exceeded/`` must still time
#: out under this many times the package's limit, so a C++ file is judged under that limit
TLE_SAFETY = 2.0


def _judged_cpp(p: Problem, name: str, src: Path, verdict: str, partial: bool, limit: str) -> str | None:
    """Judge a C++ file on ``p``'s tests under :data:`TLE_SAFETY` times the package's time limit
    (so that a TLE placed here is a TLE for verifyproblem however fast its machine); its
    ``submissions/`` directory, or None when it passes everything."""
    from ..judging.languages import language_of
    from .judge import Judge

    lang = language_of(src)
    q = dataclasses.replace(p, time_limits={**p.time_limits, lang.name: TLE_SAFETY * p.time_limit})
    q.__dict__["_tests"] = p.tests()
    result = Judge(q, hide=[str(src.parent)]).judge_path(src)
    if result.score == result.max_score:
        if verdict != "TLE" and not partial:
            raise ValueError(f"{p.id}: {name} (expected {verdict}) passes every exported test under {limit}")
        return None  # a TLE: within twice the package's limit, where its verdict depends on the machine
    if result.score > 0:
        return "partially_accepted"
    return KATTIS_DIRS.get(str(result.verdict), "wrong_answer")


def package_readme(p: Problem, placed: dict[str, str], left_out: dict[str, str]) -> str:
    """The package's notes: where each reference solution went, what was left out and why, and
    what a judge of the package sees differently from the course's judge."""
    lines = [f"# {p.title} ({shortname(p.id)}): exported by `python -m grader export-kattis {p.id}`", "",
             "## Submissions", ""]
    lines += [f"- `submissions/{d}/{Path(n).name}`" for n, d in sorted(placed.items(), key=lambda x: (x[1], x[0]))]
    if left_out:
        lines += ["", "Left out:", ""] + [f"- `{n}`: {why}" for n, why in sorted(left_out.items())]
    lines += ["", "## Limits", "",
              f"The package has one time limit, {p.time_limit:g} s per test (`problem.yaml`), the course's "
              f"limit for Python. The course judges C++ under its own limit ({p.time_limit_for('cpp'):g} s), "
              "which a Kattis package cannot state, so a C++ program that the course stops as too slow may "
              "pass here. problemtools and other judges compile C++ with their own flags; the course uses "
              "the command in the statement's \"Submitting in C++\" section.", ""]
    return "\n".join(lines)


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
