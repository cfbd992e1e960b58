"""``%check_samples``: judge the saved notebook on a problem's public samples, from inside Jupyter.

An IPython extension used by the course notebooks' "check on the samples" cell. It reads the
notebook file from disk (``<id>.ipynb`` in the kernel's working directory, or the file JupyterLab
names in ``JPY_SESSION_NAME``), extracts its code cells exactly as ``python -m grader judge`` does
(``grader.judging.submissions``), judges them in the sandbox on the ``sample`` group only, and shows a
per-test table as soon as the samples are judged, then adds a picture of one sample (expected
vs your answer) to it: the first call of a session imports matplotlib for the picture, which
takes longer than judging the samples, so the verdicts do not wait for it. The cell holds only magics,
which the judge drops, so it is never part of what the judge runs.

``%check_samples PROBLEM FILE`` checks another file instead (a path relative to the notebook's
folder): a ``.py`` program, another notebook, or a ``.cpp`` file once C++ is among the judge's
languages. Nothing here depends on the language: the file goes to the judge as
``python -m grader judge`` would send it, and the judge says what it accepts (a file it does not
take is ``CE`` with the accepted kinds in the message).

Example (a notebook cell):
    %load_ext grader.sample_check
    %check_samples delaunay
    %check_samples delaunay mine.cpp
"""

from __future__ import annotations

import base64
import dataclasses
import html
import io
import os
import time
from pathlib import Path

from .judge import Judge
from ..problems import Group, Problem, load_problem
from ..judging.verdicts import DESCRIPTIONS, JudgeResult, Verdict

MAX_DRAW_ITEMS = 3000


def is_sample_group(group: Group) -> bool:
    """Sample groups are public (committed under ``data/sample``) and worth no points."""
    return group.public


def sample_problem(problem: Problem) -> Problem:
    """A copy of ``problem`` restricted to its public sample group(s).

    >>> [g.name for g in sample_problem(load_problem("delaunay")).groups]
    ['sample']
    """
    groups = [g for g in problem.groups if is_sample_group(g)]
    if not groups:
        raise ValueError(f"problem {problem.id!r} has no sample group (data/sample)")
    return dataclasses.replace(problem, groups=groups)


def find_notebook(problem_id: str, cwd: Path | None = None) -> Path:
    """The notebook to check: JupyterLab's session file when it is this problem's, else ``<id>.ipynb`` here."""
    cwd = cwd or Path.cwd()
    session = os.environ.get("JPY_SESSION_NAME", "")
    if session.endswith(f"{problem_id}.ipynb") and Path(session).is_file():
        return Path(session)
    path = cwd / f"{problem_id}.ipynb"
    if not path.is_file():
        raise ValueError(f"cannot find {path.name} in {cwd}: open the notebook from its own folder")
    return path


#: the judge of the last :func:`judge_samples`, by file: its build (a compiled file) is handed to the
#: counterexample search of :func:`search_samples`, then dropped
_kept: dict[str, Judge] = {}


def judge_samples(problem_id: str, notebook: Path) -> tuple[JudgeResult, Problem]:
    """Judge ``notebook`` (or any submission file the judge takes: ``.py``, ``.cpp``, ...) on the
    samples of ``problem_id`` in the sandbox."""
    problem = sample_problem(load_problem(problem_id))
    # the student's own file: in the kernel jail where there is one, else in the trusted mode
    judge = Judge(problem, hide=[str(notebook.resolve().parent)], trusted=True)
    judge.keep_build = True  # a compiled file's build serves its counterexample search too
    result = judge.judge_path(notebook)
    for earlier in _kept.values():  # one kept build at a time
        earlier.drop_build()
    _kept.clear()
    _kept[str(notebook)] = judge
    return result, problem


def parse_line(line: str, cwd: Path | None = None) -> tuple[str, Path | None]:
    """``PROBLEM [FILE]`` -> (problem id, the file to check or None for the notebook itself).

    >>> parse_line("delaunay")
    ('delaunay', None)
    """
    parts = line.split()
    if not 1 <= len(parts) <= 2:
        raise ValueError("usage: %check_samples PROBLEM_ID [FILE]")
    if len(parts) == 1:
        return parts[0], None
    path = (cwd or Path.cwd()) / parts[1]
    if not path.is_file():
        raise ValueError(f"problem {parts[0]!r}: no file {parts[1]} in {path.parent}")
    return parts[0], path


def table_html(result: JudgeResult) -> str:
    """The per-test table (samples are public, so their inputs may be shown)."""
    rows = "".join(
        f"<tr><td>{html.escape(t.name)}</td><td><b style='color:{'#080' if t.verdict == Verdict.AC else '#b00'}'>"
        f"{t.verdict}</b></td><td>{t.time_s:.3f} s</td><td><pre style='margin:0'>{html.escape(t.message[:800])}</pre></td></tr>"
        for t in result.tests)
    return (f"<p>samples: <b>{result.verdict}</b> ({DESCRIPTIONS.get(result.verdict, '')})</p>"
            f"<table><tr><th>test</th><th>verdict</th><th>time</th><th>message</th></tr>{rows}</table>")


def search_samples(problem_id: str, result: JudgeResult, path: Path, seconds: float | None = None) -> str:
    """When a sample failed with WA, PE or RE: a small input of the grader's own that ``path``
    also gets wrong (:mod:`grader.contest.counterexample`, public families only, within the
    problem's budget or ``seconds``), as HTML; a note when none was found or none can be searched
    here (a copy of the problems without the reference answers); "" when no sample failed so."""
    from .counterexample import attach, failing_groups

    kept = _kept.pop(str(path), None)  # the build of judge_samples (a C++ file: not compiled again)
    try:
        if not failing_groups(result):
            return ""
        problem = load_problem(problem_id)
        cx = attach(result, problem, path, seconds, trusted=True, build_from=kept)
    finally:
        if kept is not None:
            kept.drop_build()
    search = result.extra.get("counterexample_search") or {}
    if cx is None:
        note = search.get("note") or "none found" if search else "off for this problem"
        return f"<p>counterexample search: {html.escape(note)}</p>"
    return (f"<p>a small input your code also gets wrong ({html.escape(cx.verdict)}, {cx.size} elements, found in "
            f"{cx.seconds:.1f} s):</p><pre>{html.escape(cx.input)}</pre><p>your answer:</p>"
            f"<pre>{html.escape(cx.answer or '(nothing)')}</pre><p>why: {html.escape(cx.reason)}</p>")


def picture_png(problem: Problem, result: JudgeResult, entry_fn=None) -> bytes | None:
    """A picture of the first failing sample (the judge's copy of your answer) or, when all pass, of
    the first sample with ``entry_fn``'s answer (your function as this kernel has it)."""
    fig = picture_figure(problem, result, entry_fn)
    if fig is None:
        return None
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=80, bbox_inches="tight")
    return buf.getvalue()


def picture_figure(problem: Problem, result: JudgeResult, entry_fn=None):
    """The matplotlib Figure behind :func:`picture_png` (None when the problem draws nothing).

    With no answer of the student's to draw (the sample ended in RE, TLE, ... or nothing was
    returned), the right-hand panel says so and why, instead of drawing an empty answer."""
    draw = getattr(problem.checker, "draw", None)
    if draw is None or not result.tests:
        return None
    bad = next((t for t in result.tests if t.verdict == Verdict.WA and t.received is not None), None)
    name = bad.name if bad else result.tests[0].name
    test = next(t for t in problem.tests() if t.name == name)
    args = problem.checker.read_input(test.input_text)
    if args and hasattr(args[0], "__len__") and len(args[0]) > MAX_DRAW_ITEMS:
        return None
    expected = problem.read_answer(test, args)
    received = bad.received if bad else None
    if received is None and entry_fn is not None and result.verdict == "AC":
        try:
            received = problem.checker.from_result(entry_fn(*args), args)
        except Exception:  # noqa: BLE001 - the student's own function in their own kernel
            received = None
    from matplotlib.figure import Figure

    fig = Figure(figsize=(9, 4))
    axes = fig.subplots(1, 2)
    try:
        draw(axes, args, received, expected)
    except Exception:  # noqa: BLE001 - a picture is a bonus, never a failure
        return None
    fig.suptitle(f"{name}: {'your answer' if received is not None else 'expected answer'}", fontsize=9)
    if received is None:
        verdict = next(getattr(t.verdict, "value", t.verdict) for t in result.tests if t.name == name)
        axes[1].clear()
        axes[1].set_axis_off()
        axes[1].text(0.5, 0.5, f"no answer of yours to draw\n(verdict {verdict} on {name})", ha="center",
                     va="center", fontsize=10, transform=axes[1].transAxes)
    return fig


def check_samples(line: str) -> None:
    """The ``%check_samples PROBLEM [FILE]`` line magic."""
    from IPython import get_ipython
    from IPython.display import HTML, display

    problem_id, other = parse_line(line)
    notebook = other or find_notebook(problem_id)
    saved = time.strftime("%H:%M:%S", time.localtime(notebook.stat().st_mtime))
    result, problem = judge_samples(problem_id, notebook)
    jail = html.escape(str(result.to_json().get("sandbox", "")))
    head = f"<p>judged {html.escape(notebook.name)} as saved at {saved} (jail: {jail})</p>{table_html(result)}"
    shown = display(HTML(head), display_id=True)  # the verdicts at once; the picture follows
    ip = get_ipython()
    # the kernel's function is this notebook's answer, not another file's
    entry_fn = ip.user_ns.get(problem.entry) if ip is not None and other is None else None
    png = picture_png(problem, result, entry_fn if callable(entry_fn) else None)
    if png:
        head += f'<img alt="sample picture" src="data:image/png;base64,{base64.b64encode(png).decode()}">'
        if shown is not None:
            shown.update(HTML(head))
        else:
            display(HTML(head))
    found = search_samples(problem_id, result, notebook)  # after the verdicts and the picture: it takes seconds
    if found:
        if shown is not None:
            shown.update(HTML(head + found))
        else:
            display(HTML(found))


def load_ipython_extension(ipython) -> None:
    """Register ``%check_samples`` (``%load_ext grader.sample_check``)."""
    ipython.register_magic_function(check_samples, "line", "check_samples")
