"""The "Limits and scoring" block of every statement, generated from problem.yaml and course.yaml.

Each ``assignments/<id>/statement/problem.en.md`` holds two marker lines; what lies between them
is written by this module (time limit per test, memory, output limit, the timed settings if
any, and a table of the scored groups: points, number of tests, largest input), so the
statement cannot drift from what the judge enforces.

    <!-- BEGIN GENERATED: limits -->
    (written by `python -m grader statements`)
    <!-- END GENERATED: limits -->

Run:
    python -m grader statements             # rewrite every statement's block
    python -m grader statements --check     # exit 1 if a statement is stale or lacks the markers

Example:
    >>> from grader.problems import load_problem
    >>> "| tiny | 15 |" in limits_block(load_problem("delaunay"))
    True
"""

from __future__ import annotations

import re
from pathlib import Path

from .package import Group, Problem, list_problems, load_problem

BEGIN = "<!-- BEGIN GENERATED: limits -->"
END = "<!-- END GENERATED: limits -->"
_BLOCK = re.compile(re.escape(BEGIN) + r"\n.*?" + re.escape(END), re.S)


def case_size(case: dict) -> int | None:
    """The number of input points a generated case asks for, when its settings say it."""
    if isinstance(case.get("points"), list):
        return len(case["points"])
    if "w" in case and "h" in case:
        return int(case["w"]) * int(case["h"])
    if "n" in case:
        return int(case["n"]) + (int(case.get("repeats", case["n"])) if case.get("kind") == "duplicates" else 0)
    return None


def _group_row(p: Problem, g: Group) -> str:
    count = len(g.cases)
    if g.data and (p.path / g.data).is_dir():
        count += len(list((p.path / g.data).glob("*.in")))
    sizes = [s for s in (case_size(c) for c in g.cases) if s is not None]
    largest = f"{max(sizes):,}" if sizes else "-"
    note = "examples, shown to you" if g.points == 0 and g.name == "sample" else ""
    return f"| {g.name} | {g.points} | {count} | {largest} | {note} |"


def limits_block(p: Problem) -> str:
    """The generated Markdown between the markers (without the marker lines)."""
    total = sum(g.points for g in p.groups)
    lines = [
        "## Limits and scoring",
        "",
        f"- Time limit: {p.time_limit:g} s of CPU time per test",
        f"- Memory limit: {p.memory_mb} MiB",
        f"- Output limit: {p.output_mb} MiB",
    ]
    if p.timed:
        t = p.timed
        policy = {"multiplier": f"a late submission scores x{t.get('late_multiplier', 0.5)}",
                  "reject": "a late submission scores 0", "accept": "lateness is recorded, not penalised"}
        lines.append(f"- Timed attempt: {t.get('duration_min', 30)} minutes from `timed start`"
                     f" (plus {t.get('grace_s', 0)} s grace); "
                     f"{policy.get(t.get('late_policy', 'multiplier'), t.get('late_policy'))}")
    lines += [
        "",
        f"Tests are scored by group: a group's points count only if every test in it passes "
        f"({total} points in all).",
        "",
        "| group | points | tests | largest n | note |",
        "|---|---|---|---|---|",
        *(_group_row(p, g) for g in p.groups),
    ]
    return "\n".join(lines)


def statement_path(p: Problem) -> Path:
    return p.path / "statement" / "problem.en.md"


def render(p: Problem, text: str) -> str:
    """``text`` with its generated block replaced (``ValueError`` if the markers are missing)."""
    if BEGIN not in text or END not in text or not _BLOCK.search(text):
        raise ValueError(f"problem {p.id!r}: {statement_path(p)} lacks the marker lines {BEGIN!r} ... {END!r}")
    return _BLOCK.sub(lambda _m: f"{BEGIN}\n{limits_block(p)}\n{END}", text, count=1)


def update_statements(problem_ids: list[str] | None = None, check: bool = False) -> list[tuple[str, str]]:
    """Rewrite (or with ``check``, only compare) the block of each problem's statement; returns
    ``(problem id, what is wrong or what was done)`` for every statement that was not up to date."""
    problems = [load_problem(i) for i in problem_ids] if problem_ids else list_problems()
    out = []
    for p in problems:
        path = statement_path(p)
        if not path.is_file():
            out.append((p.id, f"{path} is missing"))
            continue
        text = path.read_text()
        try:
            new = render(p, text)
        except ValueError as exc:
            out.append((p.id, str(exc)))
            continue
        if new != text:
            if check:
                out.append((p.id, f"{path.relative_to(p.path.parent)}: the limits block is stale"))
            else:
                path.write_text(new)
                out.append((p.id, f"rewrote the limits block of {path.relative_to(p.path.parent)}"))
    return out
