"""nbgrader autograding through the sandboxed judge: no student code runs in nbgrader's kernel.

``assignments/nbgrader_config.py`` puts :class:`JudgeCells` in place of nbgrader's ``Execute``
preprocessor. After nbgrader's own sanitising (outputs cleared, locked and test cells restored
from the gradebook), ``JudgeCells`` writes the notebook to a private temporary file, judges it with
:class:`grader.contest.judge.Judge` exactly as ``python -m grader judge <id> <notebook>`` does (same code
extraction, same sandbox, same tests), and writes each scored group's result into that group's test
cell: a short stdout line when every test passed (full points), an error output with the verdict
and message when not (zero). nbgrader's gradebook, ``generate_feedback`` and ``export`` then work
unchanged. No kernel is started, so nothing a student writes can rewrite cells, monkeypatch the
tests or reach ``gradebook.db``. Feedback never holds hidden data: scored groups show the verdict,
time and the kind of mistake (:mod:`grader.judging.hidden_feedback`), never the checker's detail, the
student's exception text or prints, or the test input.

Results are kept per (student, problem, code) in ``judged.sqlite`` next to the gradebook, so the
parallel path (:func:`grade_course`, ``python -m grader grade PROBLEM assignments/submitted
--nbgrader --jobs N``) judges the class in a process pool first and nbgrader's autograde then only
copies the results into the gradebook.

Example:
    nbgrader autograde delaunay                                  # in assignments/, venv bin/ on PATH
    python -m grader grade delaunay assignments/submitted --nbgrader --jobs 2
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from datetime import datetime, timedelta, timezone
from pathlib import Path
from typing import TextIO

import nbformat
from nbgrader.plugins import LateSubmissionPlugin
from nbgrader.preprocessors import NbGraderPreprocessor
from traitlets import Unicode

from .course_notebooks import CHECK_ID, group_cell_id
from ..contest.sample_check import is_sample_group
from ..jail import JailUnavailable, require_jail
from ..contest.judge import Judge
from ..problems import Problem, check_course, course_folder, load_problem, problems_root, using_course
from ..classroom import regrade
from ..classroom.regrade import fingerprints, version
from ..classroom.class_counterexamples import pending, run_searches
from ..classroom.store import ResultStore
from ..judging.submissions import Submission, SubmissionError, read_submission_bytes
from ..judging.verdicts import DESCRIPTIONS, JudgeResult, TestResult, Verdict

STORE_NAME = "judged.sqlite"
_FLOAT = re.compile(r"(?<![\w.])[-+]?(?:\d+\.\d*|\.\d+|\d+(?=[eE]))(?:[eE][-+]?\d+)?|\b(?:inf|nan)\b")
_problems: dict[str, Problem] = {}
_fps: dict[str, dict] = {}
_judges: dict[tuple, Judge] = {}


def mask_numbers(message: str) -> str:
    """Hide floating-point literals (coordinates of a hidden input) in a checker message.

    >>> mask_numbers("point 7 (0.25, -1e-300) is not a vertex of any triangle")
    'point 7 (#, #) is not a vertex of any triangle'
    """
    return _FLOAT.sub("#", message)


def _problem(problem_id: str) -> Problem:
    key = f"{problems_root().resolve()}\0{problem_id}"
    if key not in _problems:
        _problems[key] = load_problem(problem_id)
    return _problems[key]


def _judge(problem: Problem, hide: list[str]) -> Judge:
    """This process's (and thread's) judge of ``problem``, hiding ``hide`` for the next submission:
    one judge per problem keeps the tests' parsed inputs, answers and encoded arguments from one
    student to the next (a class judged in a pool parses them once per worker, not once a student)."""
    key = (str(problem.path.resolve()), problem.id, threading.get_ident())
    judge = _judges.get(key)
    if judge is None or judge.problem is not problem:
        judge = _judges[key] = Judge(problem)
    judge.hide = list(hide)
    return judge


def nbgrader_course_root(config) -> Path:
    """nbgrader's course folder under ``config`` (``CourseDirectory.root``, nbgrader's default: the
    current directory)."""
    root = config.get("CourseDirectory", {}).get("root") if config is not None else None
    return Path(root or os.getcwd()).resolve()


def _fingerprints(problem: Problem) -> dict[str, dict]:
    key = f"{problem.path.resolve()}\0fingerprints"
    if key not in _fps:
        _fps[key] = fingerprints(problem)
    return _fps[key]


def code_key(problem: Problem, source: str) -> str:
    """The store key of a piece of code for a problem: ``<code hash>-<problem version>`` (the version
    changes when a group's tests, the checker, the limits or the points change; not when the
    statement does: :mod:`grader.classroom.regrade`)."""
    return f"{hashlib.sha256(f'{problem.id}{chr(0)}{source}'.encode()).hexdigest()[:16]}-" \
           f"{version(_fingerprints(problem))}"


def legacy_code_key(problem: Problem, source: str) -> str:
    """The key a store made before per-group keys used: the code and the whole package's digest."""
    return hashlib.sha256(f"{problem.id}\0{problem.digest()}\0{source}".encode()).hexdigest()[:16]


def _adopt_legacy(store: ResultStore, student: str, problem: Problem, source: str, key: str) -> None:
    """Results stored under the previous key of this very code and package (nothing changed since)
    are taken over under the new key instead of being judged again."""
    old = legacy_code_key(problem, source)
    if not store.is_done(student, problem.id, old) or store.prior(student, problem.id, key):
        return
    cols = "test, grp, verdict, time_s, memory_mb, message, input_preview, judged_at, hidden_message"
    store.db.execute(f"INSERT OR IGNORE INTO results (student, problem, sha, {cols}) SELECT student, problem, ?, "
                     f"{cols} FROM results WHERE student=? AND problem=? AND sha=?", (key, student, problem.id, old))


def collection_time(folder: Path) -> float | None:
    """nbgrader's collection timestamp of a submission (``timestamp.txt`` in its folder, written
    by ``nbgrader collect``), as epoch seconds; None when there is none or it does not parse.
    A submission's time is this or the grader's clock, never a file's modification time."""
    from nbgrader.utils import parse_utc

    try:
        text = (Path(folder) / "timestamp.txt").read_text().strip()
        return parse_utc(text).timestamp() if text else None
    except (OSError, ValueError, TypeError, OverflowError):
        return None


def _prepare(problem: Problem, path: Path, student: str, store: ResultStore,
             submitted_at: float | None) -> tuple[str, dict[str, TestResult], JudgeResult | None]:
    """A notebook about to be judged: (its store key, the test results already stored under it, the
    whole stored result when every test is stored (nothing to judge)). Otherwise the submission is
    recorded as started (results carried over from an earlier version of the tests, and a regrade
    begun, when only some groups changed)."""
    try:
        code = Submission.from_path(path).source
    except SubmissionError:  # the judge gives it CE; key it by its bytes
        code = "\0raw\0" + hashlib.sha256(path.read_bytes()).hexdigest()
    key = code_key(problem, code)
    prior = store.prior(student, problem.id, key)
    if store.is_done(student, problem.id, key) and len(prior) == len(problem.tests()):
        return key, prior, JudgeResult(problem.id, str(path), [prior[t.name] for t in problem.tests()],
                                       problem.group_points)
    _adopt_legacy(store, student, problem, code, key)
    fps = _fingerprints(problem)
    prev, changed = regrade.carry_over(store, student, problem, key.split("-")[0], key, fps)
    if prev is not None:
        regrade.start(store, problem.id, student, prev, key, changed)
    prior = store.prior(student, problem.id, key)
    store.begin(student, problem.id, str(path), key, time.time() if submitted_at is None else submitted_at,
                json.dumps(fps, sort_keys=True))
    return key, prior, None


def judge_notebook_file(problem_id: str, path: Path, student: str, store_path: Path,
                        hide: tuple[str, ...] = (), submitted_at: float | None = None) -> JudgeResult:
    """Judge one notebook file like ``python -m grader judge`` does, reusing stored results of the
    same code. ``submitted_at``: nbgrader's collection time (default: now, on the grader's clock)."""
    problem = _problem(problem_id)
    store = ResultStore(store_path)
    try:
        key, prior, done = _prepare(problem, path, student, store, submitted_at)
        if done is not None:
            stored = store.counterexamples(student, problem.id, key)  # searched after the class was judged
            if stored is not None:
                done.counterexamples, done.extra["counterexample_search"] = stored
            return done
        judge = _judge(problem, [*hide, str(path.resolve().parent), str(store_path.resolve().parent)])
        with store.deferred_tests(student, problem.id, key) as add:  # a commit a second, not a test
            result = judge.judge_path(path, on_test=add, prior=prior)
        store.finish(student, problem.id, key, result)
        return result
    finally:
        store.close()


def test_line(t: TestResult, hidden: bool, level: str = "message") -> str:
    """One test's feedback line at a feedback ``level`` (:mod:`grader.judging.feedback_policy`).
    A hidden test shows at most its ``hidden_message`` (the kind of mistake: never the checker's
    detail, the student's exception text or prints; :mod:`grader.judging.hidden_feedback`), and
    never its input, whatever the level."""
    failed = t.verdict != Verdict.AC
    if level == "verdict" or not failed:
        msg = ""
    elif hidden:
        msg = mask_numbers(t.hidden_message or DESCRIPTIONS.get(str(t.verdict), ""))
    else:
        msg = (t.message.splitlines() or [""])[0][:300]
    line = f"{t.name:16} {str(t.verdict):3} {t.time_s:7.3f} s  {msg}".rstrip()
    if level == "input" and not hidden and failed and t.verdict != Verdict.SKIPPED and t.input_preview:
        line += "\n    input:\n" + "\n".join("    " + ln for ln in t.input_preview.splitlines()[:24])
    return line


def counterexample_text(cx: dict | None, searched: bool = True) -> list[str]:
    """A group's counterexample as feedback lines (:mod:`grader.contest.counterexample`: an input
    of the grader's own, never a test's): the input, the student's answer, why it is wrong.

    >>> counterexample_text({"input": "2\\n0 0\\n1 1\\n", "answer": "0 1\\n", "reason": "not minimal",
    ...                      "verdict": "WA", "size": 2, "seconds": 1.5, "certificate": None})[0]
    'a small input your code also gets wrong (WA, 2 elements; not one of the tests):'
    """
    if cx is None:
        return ["counterexample search: no failing input found among small public inputs"] if searched else []
    indent = lambda text: ["    " + ln for ln in (text.rstrip("\n").splitlines() or ["(nothing)"])[:24]]  # noqa: E731
    return [f"a small input your code also gets wrong ({cx['verdict']}, {cx['size']} elements; not one of the tests):",
            *indent(cx["input"]), "  your answer:", *indent(cx["answer"]), f"  why: {cx['reason'][:300]}"]


def group_output(result: JudgeResult, group: str, points: int, level: str = "message") -> dict:
    """The nbgrader output of a hidden group's test cell at a feedback ``level``: stdout when passed
    (full points), an error when not (with the group's counterexample, when a search ran)."""
    tests = [t for t in result.tests if t.group == group]
    lines = [test_line(t, hidden=True, level=level) for t in tests]
    if group in result.counterexamples:
        lines += counterexample_text(result.counterexamples[group])
    if result.group_passed(group):
        return nbformat.v4.new_output("stream", name="stdout",
                                      text=f"group {group}: all {len(tests)} tests accepted, {points}/{points} points\n"
                                           + "\n".join(lines) + "\n")
    bad = next((t for t in tests if t.verdict not in (Verdict.AC, Verdict.SKIPPED)), None)
    verdict = str(bad.verdict) if bad else "JE"
    name = bad.name if bad else "(no tests)"
    return nbformat.v4.new_output("error", ename=verdict,
                                  evalue=f"group {group} failed at {name}: {DESCRIPTIONS.get(verdict, verdict)}; 0/{points} points",
                                  traceback=[f"group {group}: 0/{points} points (hidden tests; inputs are not shown)", *lines])


def write_results(nb: nbformat.NotebookNode, problem: Problem, result: JudgeResult) -> nbformat.NotebookNode:
    """Put ``result`` into the notebook: each scored group's test cell, and the sample table in the
    check cell, each at its group's feedback level (``course.yaml`` ``feedback``)."""
    by_cell = {group_cell_id(g.name): g for g in problem.groups if g.points > 0}
    public = {g.name for g in problem.groups if is_sample_group(g)}
    samples = [t for t in result.tests if t.group in public]
    for cell in nb.cells:
        nbg = cell.get("metadata", {}).get("nbgrader", {})
        if cell.get("cell_type") != "code":
            continue
        gid = nbg.get("grade_id")
        if nbg.get("grade") and gid in by_cell:
            g = by_cell[gid]
            cell.outputs = [group_output(result, g.name, g.points, problem.feedback_level(g.name))]
            cell.execution_count = 1
        elif gid == CHECK_ID:
            text = "\n".join(test_line(t, hidden=False, level=problem.feedback_level(t.group)) for t in samples)
            cell.outputs = [nbformat.v4.new_output("stream", name="stdout",
                                                   text=f"samples, as judged at grading time:\n{text}\n")]
    return nb


class JudgeCells(NbGraderPreprocessor):
    """Autograde preprocessor: judge the (sanitised) notebook in the sandbox, write the verdicts into
    the test cells. Replaces nbgrader's ``Execute`` in ``c.Autograde.autograde_preprocessors``."""

    store = Unicode("", help="results store (default: judged.sqlite next to the gradebook)").tag(config=True)

    def _store_path(self, resources: dict) -> Path:
        if self.store:
            return Path(self.store)
        url = resources["nbgrader"].get("db_url", "")
        if url.startswith("sqlite:///"):
            return Path(url[len("sqlite:///"):]).parent / STORE_NAME
        return Path.cwd() / STORE_NAME

    def preprocess(self, nb, resources):
        require_jail()  # never a silent downgrade: no kernel jail, no grading (the message names the fixes)
        info = resources["nbgrader"]
        check_course(nbgrader_course_root(self.config), info["notebook"])  # the judge's problems = nbgrader's course
        problem = _problem(info["notebook"])
        store_path = self._store_path(resources)
        with tempfile.TemporaryDirectory(prefix="nbgrader-judge-") as tmp:
            path = Path(tmp) / f"{problem.id}.ipynb"
            nbformat.write(nb, str(path))
            folder = resources.get("metadata", {}).get("path") or ""
            result = judge_notebook_file(problem.id, path, info["student"], store_path,
                                         hide=(str(store_path.resolve().parent),),
                                         submitted_at=collection_time(Path(folder)) if folder else None)
        self.log.info("%s / %s: %s, %s/%s", info["student"], problem.id, result.verdict, result.score, result.max_score)
        return write_results(nb, problem, result), resources


def late_factor(problem_id: str, seconds_late: float) -> tuple[float, str]:
    """Score multiplier of a submission ``seconds_late`` after the due date, from ``course.yaml`` ``timed``.

    >>> late_factor("bowyer-watson-timed", 30)     # within the grace period
    (1.0, 'on time')
    >>> late_factor("bowyer-watson-timed", 600)
    (0.5, 'late: score x0.5')
    """
    from ..classroom.timed import _settings, late_factor as timed_late_factor

    problem = _problem(problem_id)
    if not problem.timed or seconds_late <= 0:
        return 1.0, "on time"
    return timed_late_factor(_settings(problem_id), seconds_late)


class CourseLatePolicy(LateSubmissionPlugin):
    """nbgrader late-submission plugin: a timed problem's policy from its ``course.yaml``; other
    assignments fall back to nbgrader's ``penalty_method``. A student's extension in the course's
    ``extensions.yaml`` (:mod:`grader.classroom.extensions`) is taken off the time late first."""

    def late_submission_penalty(self, student_id, score, total_seconds_late):
        from ..classroom.extensions import extra_seconds

        assignment = getattr(self.parent, "assignment_id", "")
        extra = extra_seconds(student_id, assignment) if assignment else 0.0
        if extra:
            self.log.info("%s: extension of %s s on %s", student_id, extra, assignment)
            total_seconds_late = max(0.0, total_seconds_late - extra)
            if total_seconds_late <= 0:
                return 0.0
        try:
            timed = bool(_problem(assignment).timed)
        except ValueError:
            timed = False
        if not timed:
            return super().late_submission_penalty(student_id, score, total_seconds_late)
        factor, note = late_factor(assignment, total_seconds_late)
        self.log.info("%s: %s (%s s)", student_id, note, total_seconds_late)
        return score * (1.0 - factor)


def set_exam_deadline(course_root: Path, problem_id: str, start: datetime) -> datetime:
    """Create/update the nbgrader assignment of a timed problem in ``course_root/gradebook.db``,
    with due date = start + its duration (from that course's own ``<id>/course.yaml``).

    ``ValueError`` when the judge's problems are not that course's (:func:`grader.problems.check_course`)."""
    from nbgrader.api import Gradebook

    from ..classroom.timed import _settings

    with using_course(course_root, problem_id) as course_root:
        if not _problem(problem_id).timed:
            raise ValueError(f"problem {problem_id!r} is not timed (no 'timed' section in its course.yaml)")
        minutes = float(_settings(problem_id)["duration_min"])
    if start.tzinfo is None:
        start = start.replace(tzinfo=timezone.utc)
    due = start + timedelta(minutes=minutes)
    os.environ["PATH"] = nbgrader_env()["PATH"]  # a new gradebook runs `alembic` from PATH
    with Gradebook(f"sqlite:///{course_root / 'gradebook.db'}") as gb:
        gb.update_or_create_assignment(problem_id, duedate=due.astimezone(timezone.utc).replace(tzinfo=None))
    return due


def nbgrader_env() -> dict:
    """The environment for nbgrader commands: the venv's ``bin/`` first on PATH (nbgrader calls ``alembic``)."""
    env = dict(os.environ)
    env["PATH"] = str(Path(sys.executable).parent) + os.pathsep + env.get("PATH", "")
    return env


def run_nbgrader(course_root: Path, *args: str, check: bool = True) -> subprocess.CompletedProcess:
    """``nbgrader ARGS`` in ``course_root`` with :func:`nbgrader_env`."""
    cmd = [str(Path(sys.executable).parent / "nbgrader"), *args]
    r = subprocess.run(cmd, cwd=course_root, env=nbgrader_env(), capture_output=True, text=True)
    if check and r.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd[1:])} failed ({r.returncode}):\n{r.stderr[-3000:]}")
    return r


def _collected(submitted: Path, problem_id: str) -> list[tuple[str, Path]]:
    return [(d.name, d / problem_id / f"{problem_id}.ipynb") for d in sorted(submitted.iterdir())
            if (d / problem_id / f"{problem_id}.ipynb").is_file()]


def _judge_job(problem_id: str, student: str, path: str, store_path: str, hide: tuple[str, ...]) -> dict:
    r = judge_notebook_file(problem_id, Path(path), student, Path(store_path), hide,
                            submitted_at=collection_time(Path(path).parent))
    return {"student": student, "verdict": r.verdict, "score": r.score, "max_score": r.max_score}


def grade_course(problem_id: str, submitted: str | Path, jobs: int = 1, autograde: bool = True,
                 progress: TextIO | None = None, counterexample_seconds: float | None = 0.0,
                 scheduler: str | None = None) -> list[dict]:
    """Judge every collected notebook ``submitted/<student>/<id>/<id>.ipynb`` in a pool of ``jobs``
    processes (or, with ``scheduler``, on that Dask distributed cluster: :mod:`.course_dask`), then
    run ``nbgrader autograde`` (which finds the results stored and writes the same gradebook
    entries, autograded notebooks and late penalties as a one-by-one run).

    ``progress`` (a stream, e.g. ``sys.stderr``) gets a line per judged notebook and one around
    ``nbgrader autograde``. After autograde each summary also holds the gradebook's
    ``gradebook_score`` (after the late penalty) and ``late_penalty`` (points taken off).

    Then, the gradebook written, the counterexample searches run for the notebooks that failed a
    group with WA, PE or RE (:mod:`grader.classroom.class_counterexamples`; budget
    ``counterexample_seconds``, None: the problem's ``course.yaml`` (what ``python -m grader grade
    --nbgrader`` passes), 0 (the default here): none), each kept in the
    store, and ``nbgrader autograde`` runs once more to put them in the feedback."""
    require_jail()
    submitted = Path(submitted).resolve()
    if not submitted.is_dir():
        raise ValueError(f"{submitted} is not a directory (expected nbgrader's submitted/<student>/{problem_id}/)")
    with using_course(submitted.parent, problem_id) as course_root:  # the course that submitted/ belongs to
        return _grade_course(problem_id, submitted, course_root, jobs, autograde, progress, counterexample_seconds,
                             scheduler)


def _say(progress: TextIO | None, text: str) -> None:
    if progress is not None:
        print(text, file=progress, flush=True)


def gradebook_scores(course_root: Path, problem_id: str, students: list[str]) -> dict[str, tuple[float, float]]:
    """student -> (score after the late penalty, late penalty) of ``problem_id`` in ``course_root/gradebook.db``;
    students without a submission there are left out."""
    from nbgrader.api import Gradebook, MissingEntry

    out = {}
    with Gradebook(f"sqlite:///{course_root / 'gradebook.db'}") as gb:
        for student in students:
            try:
                sub = gb.find_submission(problem_id, student)
            except MissingEntry:
                continue
            penalty = float(sub.late_submission_penalty or 0.0)
            out[student] = (max(0.0, float(sub.score) - penalty), penalty)
    return out


def _grade_course(problem_id: str, submitted: Path, course_root: Path, jobs: int, autograde: bool,
                  progress: TextIO | None = None, counterexample_seconds: float | None = None,
                  scheduler: str | None = None) -> list[dict]:
    problem = _problem(problem_id)
    problem.tests()  # materialise the hidden tests once, before the workers start
    store_path = course_root / STORE_NAME
    ResultStore(store_path).close()
    hide = (str(submitted), str(course_root))
    out = []
    collected = _collected(submitted, problem_id)
    if scheduler:
        _say(progress, f"{problem_id}: judging {len(collected)} collected notebook(s) from {submitted} on {scheduler}")
        out = _judge_dask(problem, collected, store_path, scheduler, hide, progress)
    else:
        _say(progress, f"{problem_id}: judging {len(collected)} collected notebook(s) from {submitted}, "
                       f"{max(1, jobs)} at a time")
        out = _judge_pool(problem_id, collected, store_path, hide, jobs, progress)
    store = ResultStore(store_path)
    try:
        for d in regrade.finish(store, problem_id):  # whose score moved since the tests were changed
            _say(progress, f"{problem_id}: regraded " + regrade.diff_line(d))
    finally:
        store.close()
    return _autograde_and_search(problem, submitted, course_root, store_path, collected, out, jobs, autograde,
                                 progress, counterexample_seconds)


def _judge_pool(problem_id: str, collected: list[tuple[str, Path]], store_path: Path, hide: tuple[str, ...],
                jobs: int, progress: TextIO | None) -> list[dict]:
    out: list[dict] = []
    with ProcessPoolExecutor(max_workers=max(1, jobs)) as pool:
        futures = {pool.submit(_judge_job, problem_id, s, str(p), str(store_path), hide): s for s, p in collected}
        for fut in as_completed(futures):
            try:
                out.append(fut.result())
            except JailUnavailable:  # root's uid pool refused (unsafe, or full): the whole batch stops
                pool.shutdown(wait=False, cancel_futures=True)
                raise
            except Exception as exc:  # noqa: BLE001 - a judge fault; nbgrader autograde judges it again
                out.append({"student": futures[fut], "verdict": "JE", "error": f"{type(exc).__name__}: {exc}"})
            r = out[-1]
            _say(progress, f"[{len(out)}/{len(collected)}] {r['student']}: {r['verdict']} "
                           f"{r.get('score', '')}/{r.get('max_score', '')}")
    return out


def _summary(student: str, result: JudgeResult) -> dict:
    return {"student": student, "verdict": result.verdict, "score": result.score, "max_score": result.max_score}


def _judge_dask(problem: Problem, collected: list[tuple[str, Path]], store_path: Path, scheduler: str,
                hide: tuple[str, ...], progress: TextIO | None) -> list[dict]:
    """The class on a Dask cluster (:mod:`.course_dask`): each notebook keyed and recorded here as
    :func:`judge_notebook_file` does, judged on a worker, its results stored here when it returns."""
    from .course_dask import RemoteJob, judge_remote_jobs

    out, jobs = [], []
    store = ResultStore(store_path)
    try:
        for student, path in collected:
            key, prior, done = _prepare(problem, path, student, store, collection_time(path.parent))
            if done is not None:
                out.append(_summary(student, done))
                continue
            try:
                data = read_submission_bytes(path)
            except SubmissionError:  # judged here: no code runs, the verdict is CE with the reason
                result = _judge(problem, [*hide, str(path.parent)]).judge_path(path, prior=prior)
                _commit(store, student, problem.id, key, result)
                out.append(_summary(student, result))
                continue
            jobs.append(RemoteJob(student, str(path), key, data, [r.to_json() for r in prior.values()]))

        def done_one(job, tests: list[TestResult] | None, error: str) -> None:
            if tests is None:  # a worker fault: nbgrader autograde judges that notebook again
                out.append({"student": job.student, "verdict": "JE", "error": error})
            else:
                result = JudgeResult(problem.id, job.path, tests, problem.group_points)
                _commit(store, job.student, problem.id, job.key, result)
                out.append(_summary(job.student, result))
            r = out[-1]
            _say(progress, f"[{len(out)}/{len(collected)}] {r['student']}: {r['verdict']} "
                           f"{r.get('score', '')}/{r.get('max_score', '')}")

        _say(progress, f"{problem.id}: {len(jobs)} notebook(s) sent to the Dask cluster at {scheduler}")
        judge_remote_jobs(problem.id, jobs, scheduler, hide, done_one)
    finally:
        store.close()
    return out


def _commit(store: ResultStore, student: str, problem_id: str, key: str, result: JudgeResult) -> None:
    for t in result.tests:
        store.add_test(student, problem_id, key, t)
    store.finish(student, problem_id, key, result)


def _autograde_and_search(problem: Problem, submitted: Path, course_root: Path, store_path: Path,
                          collected: list[tuple[str, Path]], out: list[dict], jobs: int, autograde: bool,
                          progress: TextIO | None, counterexample_seconds: float | None) -> list[dict]:
    """nbgrader autograde from the stored results (the scores), then the counterexample searches."""
    problem_id = problem.id
    if autograde:
        _say(progress, f"{problem_id}: nbgrader autograde --force in {course_root} ({len(collected)} notebook(s); "
                       "it reads the stored results and applies the late policy)")
        run_nbgrader(course_root, "autograde", problem_id, "--force")
        scores = gradebook_scores(course_root, problem_id, [r["student"] for r in out])
        for r in out:
            if r["student"] in scores:
                r["gradebook_score"], r["late_penalty"] = scores[r["student"]]
        _say(progress, f"{problem_id}: gradebook written ({len(scores)} submission(s))")
    store = ResultStore(store_path)
    try:
        todo = pending(store, problem, {s: str(p) for s, p in collected})
    finally:
        store.close()
    searched, _ = run_searches(problem_id, todo, store_path, counterexample_seconds, jobs,
                               say=lambda line: _say(progress, line))
    if searched and autograde:
        _say(progress, f"{problem_id}: nbgrader autograde --force again: the counterexamples into the feedback")
        run_nbgrader(course_root, "autograde", problem_id, "--force")
    return sorted(out, key=lambda s: s["student"])


def main(argv: list[str] | None = None) -> int:
    """``python -m grader.nbgrader_autograde deadline PROBLEM START [--course DIR]`` (ISO time, UTC if
    no zone). The course is the one you are in (the folder with ``nbgrader_config.py``, or its
    ``assignments/``), as for nbgrader; the command prints which gradebook it wrote."""
    import argparse

    ap = argparse.ArgumentParser(prog="python -m grader.nbgrader_autograde")
    sub = ap.add_subparsers(dest="command", required=True)
    p = sub.add_parser("deadline", help="set a timed assignment's due date to START + its duration")
    p.add_argument("problem")
    p.add_argument("start", help="exam start, ISO 8601 (e.g. 2026-12-01T09:00:00+00:00)")
    p.add_argument("--course", help="the nbgrader course folder (default: the one you are in)")
    a = ap.parse_args(argv)
    try:
        course = Path(a.course) if a.course else course_folder()
        if course is None:
            raise ValueError(f"no nbgrader course here: {Path.cwd()} holds no nbgrader_config.py (nor its assignments/); "
                             "cd into the course folder or pass --course DIR")
        due = set_exam_deadline(course, a.problem, datetime.fromisoformat(a.start))
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    print(f"{a.problem}: due {due.isoformat()} (in {Path(course).resolve() / 'gradebook.db'})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
