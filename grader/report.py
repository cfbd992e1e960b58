"""HTML report for one judged submission: verdicts, scores, messages, and for geometry problems a
picture of the first failing test (points, expected vs received), drawn by the checker's ``draw``.

Example:
    python -m grader judge delaunay mine.py --report mine.html
"""

from __future__ import annotations

import base64
import html
import io
from pathlib import Path

from .problems import Problem
from .verdicts import DESCRIPTIONS, JudgeResult, Verdict

MAX_DRAW_POINTS = 3000


def _picture(problem: Problem, result: JudgeResult) -> str:
    bad = next((t for t in result.tests if t.verdict == Verdict.WA and t.received is not None), None)
    draw = getattr(problem.checker, "draw", None)
    if bad is None or draw is None:
        return ""
    test = next(t for t in problem.tests() if t.name == bad.name)
    args = problem.checker.read_input(test.input_text)
    if len(args[0]) > MAX_DRAW_POINTS:
        return ""
    expected = problem.read_answer(test, args)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(10, 4.8))
    try:
        draw(axes, args, bad.received, expected)
        fig.suptitle(f"{bad.name}: {bad.message[:110]}", fontsize=9)
        buf = io.BytesIO()
        fig.savefig(buf, format="png", dpi=90, bbox_inches="tight")
    finally:
        plt.close(fig)
    data = base64.b64encode(buf.getvalue()).decode()
    return f'<h2>First failing test: {html.escape(bad.name)}</h2><img alt="expected vs received" src="data:image/png;base64,{data}">'


def render(result: JudgeResult, problem: Problem, student: str = "") -> str:
    """The report as an HTML string."""
    rows = "".join(
        f"<tr class='{'ok' if t.verdict == Verdict.AC else 'bad'}'><td>{html.escape(t.name)}</td><td>{t.verdict}</td>"
        f"<td>{t.time_s:.3f}</td><td>{t.memory_mb:.0f}</td><td><pre>{html.escape(t.message[:1500])}</pre>"
        + (f"<details><summary>input</summary><pre>{html.escape(t.input_preview)}</pre></details>" if t.input_preview else "")
        + "</td></tr>" for t in result.tests)
    groups = "".join(f"<li>{html.escape(g)}: {p} points, {'passed' if result.group_passed(g) else 'failed'}</li>"
                     for g, p in result.group_points.items())
    who = f" for {html.escape(student)}" if student else ""
    return f"""<!doctype html><html><head><meta charset="utf-8"><title>{html.escape(problem.id)}{who}</title>
<style>body{{font-family:sans-serif;margin:2em}} td,th{{border:1px solid #ccc;padding:3px 6px;vertical-align:top}}
table{{border-collapse:collapse}} tr.bad td:nth-child(2){{color:#b00;font-weight:bold}} pre{{margin:0;white-space:pre-wrap}}</style>
</head><body><h1>{html.escape(problem.title)}{who}</h1>
<p>Verdict: <b>{result.verdict}</b> ({DESCRIPTIONS.get(result.verdict, '')}); score <b>{result.score}/{result.max_score}</b>;
mode: {html.escape(result.mode)}; submission: {html.escape(Path(result.submission).name)}</p>
<ul>{groups}</ul>{_picture(problem, result)}
<h2>Tests</h2><table><tr><th>test</th><th>verdict</th><th>time (s)</th><th>memory (MB)</th><th>message</th></tr>{rows}</table>
</body></html>"""


def write_report(result: JudgeResult, path: str | Path, problem: Problem, student: str = "") -> Path:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(render(result, problem, student))
    return path
