"""The "Limits and scoring" block of every statement, generated from problem.yaml and course.yaml.

Each ``assignments/<id>/statement/problem.en.md`` holds two marker lines; what lies between them
is written by this module (the time limit per test for each language, memory, output limit, the
timed settings if any, a table of the scored groups: points, number of tests, largest input, and
the "Submitting in C++" section shared by every problem: compiler and flags from
:data:`grader.judging.languages.CPP`, the sandbox, the number formats, exactness), so the
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

from ..judging.languages import CPP, PYTHON
from .package import ALWAYS_FORBIDDEN, Group, Problem, list_problems, load_problem

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
        time_line(p),
        f"- Memory limit: {p.memory_mb} MiB (in C++ the stack counts in it)",
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
        "",
        *cpp_section(p),
    ]
    return "\n".join(lines)


def time_line(p: Problem) -> str:
    """The time limit per test for Python and for C++ (:meth:`Problem.time_limit_for`).

    >>> time_line(load_problem("delaunay")).startswith("- Time limit: 6 s of CPU time per test for Python, ")
    True
    """
    return (f"- Time limit: {p.time_limit_for(PYTHON.name):g} s of CPU time per test for Python, "
            f"{p.time_limit_for(CPP.name):g} s for C++")


def cpp_command() -> str:
    """The judge's C++ compile command, for a source ``main.cpp`` (from :data:`CPP`, never retyped).

    >>> cpp_command()
    'g++ -std=gnu++17 -O2 -pipe -static -s -o main main.cpp'
    """
    return " ".join(CPP.compile_command("main.cpp", "main"))


def cpp_section(p: Problem) -> list[str]:
    """The "Submitting in C++" section: the same text in every statement, plus one paragraph for a
    problem that forbids libraries doing its work (``forbidden`` in course.yaml beyond the course's
    own packages): the checker judges the answer, not the algorithm."""
    lines = [
        "## Submitting in C++",
        "",
        "A `.cpp` file is judged as a program (the program mode above): it reads the input from",
        "standard input and prints the answer on standard output, in this statement's formats.",
        "",
        "- Compiler: Debian's GCC, the C++ standard library only, as",
        f"  `{cpp_command()}`. A program that does not compile gets `CE`",
        "  with the compiler's first lines.",
        "- Limits: the C++ time limit above is CPU time per test. The stack may grow as large as the",
        "  memory limit and counts in it, so deep recursion is fine.",
        "- The sandbox: no other processes (`system`, `fork`, `popen` are a security violation,",
        "  `SV`), no network and no files but standard input and output (opening one fails, as",
        "  for a file that does not exist; a program that then exits with an error code gets `RE`).",
        "- Numbers in the input are decimal, as Python's `repr` writes doubles: `3`, `0.1`, `-0.0`,",
        "  `1e+300`, `7.1e-303`; one space between the numbers of a line, a newline after every",
        "  line, never `inf` or `nan`. `scanf(\"%lf\", &x)` and `strtod` read each as exactly the",
        "  double written. A count of 0, where the input allows it, means that no lines of that",
        "  kind follow (the other lines still do); the Output section says what to print then.",
        "- Numbers in the output: integers as they are; a floating-point answer with",
        "  `printf(\"%.17g\", x)`: 17 significant digits read back as the same double (`%f` prints",
        "  `1e-300` as `0.000000`, `std::cout` keeps 6 digits). Infinity is `inf`, as `%.17g` prints it.",
        "- Exact decisions (orientation, in-circle, comparing distances): the doubles from `1e-300`",
        "  to `1e300` span about 2,100 bits, so `double`, `long double` (64-bit mantissa) and",
        "  `__int128` all round or overflow on the degenerate tests. Use a floating-point filter with",
        "  an exact fallback: expansion arithmetic (Shewchuk's predicates) or a big-integer type of",
        "  your own (every double is an integer times a power of two), as `fractions.Fraction` or",
        "  Python's integers do in Python.",
    ]
    if set(p.forbidden) - set(ALWAYS_FORBIDDEN):
        lines += [
            "- Your own algorithm: only the standard library is linked (no CGAL, no Triangle). The",
            "  checker judges the answer, not how it was found: in program mode any algorithm that",
            "  gives a correct answer within the limits is accepted, in C++ or in Python without the",
            "  forbidden libraries (for a triangulation, divide and conquer or a sweep too). The course",
            "  asks for the algorithm it teaches so that you learn it.",
        ]
    return lines


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
