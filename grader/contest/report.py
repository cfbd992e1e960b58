"""HTML reports: one per judged submission (verdicts, scores, messages, and for geometry problems
a picture of the first failing test, expected vs received, drawn by the checker's ``draw``), and a
class index page linking every student's report.

The picture highlights what the checker's message names (a triangle, an edge, a point). A
checker may say it directly with an optional ``hint(message, args, received)`` returning
``{"triangles": [[i, j, k]], "edges": [[u, v]], "points": [i]}`` (any subset); without one the
message is read ("triangle 3 = (0, 2, 1)", "edge 4-7", "point 5"). At most ``MAX_DRAW_ITEMS``
answer elements are drawn (a forged answer with millions of triangles costs no more than a
normal one); the picture says how many were not drawn.

Example:
    python -m grader judge delaunay mine.py --report mine.html
    python -m grader grade delaunay class/ --reports reports/    # + reports/index.html

    >>> parse_hint("triangle 2 = (0, 3, 1) is clockwise", [[0, 1, 2]])
    {'triangles': [[0, 3, 1]], 'edges': [], 'points': []}
"""

from __future__ import annotations

import base64
import hashlib
import html
import io
import json
import re
import textwrap
import urllib.parse
from pathlib import Path
from typing import Any

from ..problems import Problem
from ..judging.verdicts import DESCRIPTIONS, JudgeResult, Verdict

MAX_DRAW_POINTS = 3000
MAX_DRAW_ITEMS = 1700  #: answer elements (triangles) drawn per side: about 5,000 segments
CAPTION_WIDTH = 110
CAPTION_LINES = 4

_TRIANGLE = re.compile(r"triangle (\d+)(?: = \((\d+), (\d+), (\d+)\))?")
_EDGE = re.compile(r"edge (\d+) ?-[>]? ?(\d+)")
_POINT = re.compile(r"point (\d+)")


def parse_hint(message: str, received: Any) -> dict:
    """The triangles, edges and points a checker's message names (indices into the input)."""
    tris: list[list[int]] = []
    for m in _TRIANGLE.finditer(message):
        if m.group(2) is not None:
            tris.append([int(m.group(k)) for k in (2, 3, 4)])
        elif isinstance(received, list) and int(m.group(1)) < len(received):
            tris.append(list(received[int(m.group(1))]))
    edges = [[int(m.group(1)), int(m.group(2))] for m in _EDGE.finditer(message)]
    points = [int(m.group(1)) for m in _POINT.finditer(message)]
    return {"triangles": tris, "edges": edges, "points": points}


def _hint(problem: Problem, message: str, args: list, received: Any) -> dict:
    hint = getattr(problem.checker, "hint", None)
    if callable(hint):
        try:
            got = hint(message, args, received)
            if isinstance(got, dict):
                return got
        except Exception:  # noqa: BLE001 - an optional nicety must not break the report
            pass
    return parse_hint(message, received)


def _highlight(ax, points: list, hint: dict) -> None:
    n = len(points)
    ok = lambda ids: all(isinstance(v, int) and 0 <= v < n for v in ids)  # noqa: E731
    for t in hint.get("triangles", [])[:20]:
        if len(t) == 3 and ok(t):
            cyc = [*t, t[0]]
            ax.fill([points[v][0] for v in t], [points[v][1] for v in t], color="orange", alpha=0.45, zorder=4)
            ax.plot([points[v][0] for v in cyc], [points[v][1] for v in cyc], color="darkorange", lw=2.5, zorder=5)
    for e in hint.get("edges", [])[:20]:
        if len(e) == 2 and ok(e):
            ax.plot([points[v][0] for v in e], [points[v][1] for v in e], color="darkorange", lw=3, zorder=5)
    for v in hint.get("points", [])[:20]:
        if ok([v]):
            ax.scatter([points[v][0]], [points[v][1]], s=90, facecolors="none", edgecolors="darkorange",
                       linewidths=2, zorder=6)


def _capped(answer: Any) -> tuple[Any, int]:
    if isinstance(answer, list) and len(answer) > MAX_DRAW_ITEMS:
        return answer[:MAX_DRAW_ITEMS], len(answer) - MAX_DRAW_ITEMS
    return answer, 0


def caption(name: str, message: str) -> str:
    """The picture's title: the whole message, wrapped (at most a few lines)."""
    lines = textwrap.wrap(f"{name}: {message}", CAPTION_WIDTH) or [name]
    if len(lines) > CAPTION_LINES:
        lines = lines[:CAPTION_LINES - 1] + [lines[CAPTION_LINES - 1][:CAPTION_WIDTH - 4] + " ..."]
    return "\n".join(lines)


def _picture(problem: Problem, result: JudgeResult) -> str:
    bad = next((t for t in result.tests if t.verdict not in (Verdict.AC, Verdict.SKIPPED)), None)
    draw = getattr(problem.checker, "draw", None)
    if bad is None:
        return ""
    if bad.verdict != Verdict.WA or bad.received is None or draw is None:  # the judge's first failure, no picture
        return f"<h2>First failing test: {html.escape(bad.name)} ({bad.verdict})</h2>"
    test = next(t for t in problem.tests() if t.name == bad.name)
    args = problem.checker.read_input(test.input_text)
    if len(args[0]) > MAX_DRAW_POINTS:
        return ""
    expected = problem.read_answer(test, args) if test.answer_text else None
    data, hidden_r = _png(problem, args, bad.received, expected, bad.name, bad.message)
    note = " (orange: what the message names)" + (f"; {hidden_r:,} elements of the received answer not drawn" if hidden_r else "")
    return (f'<h2>First failing test: {html.escape(bad.name)}{note}</h2>'
            f'<img alt="expected vs received" src="data:image/png;base64,{data}">')


def _png(problem: Problem, args: list, received: Any, expected: Any, name: str, message: str) -> tuple[str, int]:
    """The checker's ``draw`` of expected vs received as base64 PNG, and how many received
    elements were not drawn."""
    received_capped, hidden_r = _capped(received)
    expected, hidden_e = _capped(expected)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(10, 4.8))
    try:
        problem.checker.draw(axes, args, received_capped, expected)
        for ax, hidden in ((axes[0], hidden_e), (axes[1], hidden_r)):
            if hidden:
                ax.text(0.5, -0.08, f"{hidden:,} more not drawn", transform=ax.transAxes, ha="center", fontsize=8)
        if isinstance(args[0], list) and all(isinstance(p, (list, tuple)) and len(p) >= 2 for p in args[0]):
            _highlight(axes[1], args[0], _hint(problem, message, args, received))
        fig.suptitle(caption(name, message.split("\n--- ")[0]), fontsize=8)
        buf = io.BytesIO()
        fig.savefig(buf, format="png", dpi=90, bbox_inches="tight")
    finally:
        plt.close(fig)
    return base64.b64encode(buf.getvalue()).decode(), hidden_r


def _counterexample(problem: Problem, result: JudgeResult) -> str:
    """The section on the counterexample search (:mod:`grader.contest.counterexample`): the small
    input, the submission's answer, why it is wrong, and a picture of it (when the checker draws
    and the answer reads back); or that the search found none."""
    found = {g: c for g, c in result.counterexamples.items() if c}
    if not result.counterexamples:
        return ""
    if not found:
        note = (result.extra.get("counterexample_search") or {}).get("note", "")
        return f"<h2>Counterexample search</h2><p>{html.escape(note or 'no failing input found')}</p>"
    cx = next(iter(found.values()))
    picture = ""
    chk = problem.checker
    if getattr(chk, "draw", None) is not None and cx["verdict"] == "WA" and problem.generator_path is not None:
        try:
            args = chk.read_input(cx["input"])
            received = chk.read_output(cx["answer"], args)
            expected = chk.read_output(chk.write_output(problem.generator.solve(*args)), args)
            data, _ = _png(problem, args, received, expected, "counterexample", cx["reason"])
            picture = f'<img alt="expected vs your answer" src="data:image/png;base64,{data}">'
        except Exception:  # noqa: BLE001 - an answer that does not read back as output text: no picture
            picture = ""
    cert = (f"<p>certificate:</p><pre>{html.escape(json.dumps(cx['certificate'], indent=1))}</pre>"
            if cx.get("certificate") else "")
    return (f"<h2>A small input your program also gets wrong ({html.escape(cx['verdict'])}; groups "
            f"{html.escape(', '.join(found))})</h2><p>Found in {cx['seconds']:.1f} s among small public inputs; "
            f"it is not a test of the problem.</p><pre>{html.escape(cx['input'])}</pre><p>your answer:</p>"
            f"<pre>{html.escape(cx['answer'] or '(nothing)')}</pre><p>why: {html.escape(cx['reason'])}</p>"
            f"{cert}{picture}")


def _measure(t, value: float, fmt: str) -> str:
    """A time or memory cell: "-" for a test that did not run (skipped, or judged all at once)."""
    if t.verdict == Verdict.SKIPPED or (t.time_s == 0 and t.memory_mb == 0):
        return "-"
    return fmt.format(value)


def render(result: JudgeResult, problem: Problem, student: str = "") -> str:
    """The report as an HTML string."""
    rows = "".join(
        f"<tr class='{'ok' if t.verdict == Verdict.AC else 'bad'}'><td>{html.escape(t.name)}</td><td>{t.verdict}</td>"
        f"<td>{_measure(t, t.time_s, '{:.3f}')}</td><td>{_measure(t, t.memory_mb, '{:.0f}')}</td>"
        f"<td><pre>{html.escape(t.message[:4000])}</pre>"
        + (f"<details><summary>input</summary><pre>{html.escape(t.input_preview)}</pre></details>" if t.input_preview else "")
        + "</td></tr>" for t in result.tests)
    groups = "".join(f"<li>{html.escape(g)}: {p} points, {'passed' if result.group_passed(g) else 'failed'}</li>"
                     for g, p in result.group_points.items())
    who = f" for {html.escape(student)}" if student else ""
    return f"""<!doctype html><html><head><meta charset="utf-8"><title>{html.escape(problem.id)}{who}</title>
<style>{_CSS}</style>
</head><body><h1>{html.escape(problem.title)}{who}</h1>
<p>Verdict: <b>{result.verdict}</b> ({DESCRIPTIONS.get(result.verdict, '')}); score <b>{result.score}/{result.max_score}</b>;
mode: {html.escape(result.mode)}; submission: {html.escape(Path(result.submission).name)}</p>
<ul>{groups}</ul>{_picture(problem, result)}{_counterexample(problem, result)}
<h2>Tests</h2><table><tr><th>test</th><th>verdict</th><th>time (s)</th><th>memory (MB)</th><th>message</th></tr>{rows}</table>
</body></html>"""


_CSS = """body{font-family:sans-serif;margin:2em} td,th{border:1px solid #ccc;padding:3px 6px;vertical-align:top}
table{border-collapse:collapse} tr.bad td:nth-child(2){color:#b00;font-weight:bold} pre{margin:0;white-space:pre-wrap}
td.AC{color:#070} td.bad{color:#b00;font-weight:bold}"""


STUDENTS_DIR = "students"  #: class reports live in ``REPORTS/students/``, the index in ``REPORTS/index.html``


def report_name(student: str) -> str:
    """The file name of a student's class report: the name's safe characters and a hash of the
    whole name, so no two students (nor the index) share a file, and no name is a path or a URL.

    >>> report_name("javascript:alert(1)")
    'javascript-alert-1-d0ee0421.html'
    >>> report_name("index") != "index.html"
    True
    """
    slug = re.sub(r"[^A-Za-z0-9_.]+", "-", student).strip("-.")[:60] or "student"
    return f"{slug}-{hashlib.sha256(student.encode('utf-8', 'surrogatepass')).hexdigest()[:8]}.html"


def student_report_path(report_dir: str | Path, student: str) -> Path:
    """Where ``grade --reports DIR`` writes ``student``'s report."""
    return Path(report_dir) / STUDENTS_DIR / report_name(student)


def write_report(result: JudgeResult, path: str | Path, problem: Problem, student: str = "") -> Path:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(render(result, problem, student))
    return path


def _test_order(problem: str):
    """Sort key for test names ``group/NN``: the problem's group order (as the judge runs them), then name."""
    try:
        from ..problems import load_problem

        order = [g.name for g in load_problem(problem).groups]
    except ValueError:
        order = []
    return lambda n: (order.index(n.split("/")[0]) if n.split("/")[0] in order else len(order), n)


def write_index(report_dir: Path, problem: str, store, no_submission: list[str] = ()) -> Path:
    """``report_dir/index.html``: every student of ``problem`` in the store, with verdict, score,
    a link to their report, and the verdict of each test (plus the folders without a submission)."""
    latest = store.latest(problem)
    tests: dict[str, dict[str, str]] = {}
    names: list[str] = []
    for student, s in latest.items():
        rows = store.db.execute("SELECT test, verdict FROM results WHERE student=? AND problem=? AND sha=?",
                                (student, problem, s["sha"])).fetchall()
        tests[student] = dict(rows)
        names += [t for t, _ in rows if t not in names]
    names.sort(key=_test_order(problem))
    head = "".join(f"<th>{html.escape(n)}</th>" for n in names)
    body = []
    for student in sorted({*latest, *no_submission}):
        s = latest.get(student)
        href = f"{STUDENTS_DIR}/{urllib.parse.quote(report_name(student))}"
        link = f'<a href="{html.escape(href)}">{html.escape(student)}</a>' \
            if student_report_path(report_dir, student).is_file() else html.escape(student)
        if s is None:
            body.append(f"<tr><td>{link}</td><td>-</td><td>0</td><td>no submission</td>"
                        + "<td></td>" * len(names) + "</tr>")
            continue
        mult = 1.0 if s["multiplier"] is None else s["multiplier"]
        cells = "".join(f"<td class='{'AC' if v == 'AC' else 'bad' if v not in ('--', '') else ''}'>{html.escape(v)}</td>"
                        for v in (tests[student].get(n, "") for n in names))
        body.append(f"<tr><td>{link}</td><td class='{'AC' if s['verdict'] == 'AC' else 'bad'}'>{s['verdict']}</td>"
                    f"<td>{s['score'] * mult:g}/{s['max_score']}</td><td>{html.escape(s['note'] or '')}</td>{cells}</tr>")
    page = f"""<!doctype html><html><head><meta charset="utf-8"><title>{html.escape(problem)}: class reports</title>
<style>{_CSS}</style></head><body><h1>{html.escape(problem)}: {len(body)} students</h1>
<table><tr><th>student</th><th>verdict</th><th>score</th><th>note</th>{head}</tr>{''.join(body)}</table>
</body></html>"""
    path = report_dir / "index.html"
    path.write_text(page)
    return path
