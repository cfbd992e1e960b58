"""Grading a whole class: ``submissions/<student>/<file>`` -> SQLite results, CSV, HTML reports.

Local runs use a process pool (``--jobs N``); each worker commits every test result as soon as it
is known, so a killed batch resumes where it stopped. ``--scheduler ADDRESS`` sends one job per
student to a Dask distributed cluster instead; the client then commits each student's results
when the job returns (workers may not share our disk).

Every student folder gets a CSV row: an empty folder (no .py/.ipynb file) scores 0 with the note
"no submission"; when a folder holds several candidate files, the note (and a line on stderr)
says which one was judged and why. The progress display names the students being judged and
counts the tests done, including results resumed from the store after an interrupted batch.
``--reports DIR`` writes each student's report to ``DIR/students/`` (file names from
:func:`grader.contest.report.report_name`: no collision, no path, no URL scheme) before marking the student
done, rebuilds a missing one on resume, and writes ``DIR/index.html`` linking them all.
Submission times are the grader's (when it first saw a file's content), never file mtimes. The
store key is the content's hash and the problem's version (:mod:`grader.classroom.regrade`: a hash
of each group's tests, the checker, the limits and the points): a statement edit judges nobody
again; a changed group is judged again for everyone, the other groups' results are carried over,
and each student's diff (old score, new score, which groups changed and why) is printed, kept in
the store and noted in the CSV.

Example:
    python -m grader grade delaunay class/ --db results.sqlite --jobs 2 --csv grades.csv
"""

from __future__ import annotations

import csv
import atexit
import ctypes
import hashlib
import json
import os
import shutil
import signal
import sys
import tempfile
import threading
import time
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterable

from ..judging.languages import SUFFIXES
from ..judging.submissions import SubmissionError, read_submission_bytes
from ..judging.text import clean, csv_cell
from ..jail import JailUnavailable, require_jail
from ..contest.judge import Judge
from ..problems import load_problem
from .store import ResultStore
from ..judging.verdicts import JudgeResult, TestResult


@dataclass
class Job:
    student: str
    path: str
    sha: str  #: the store key: the content's hash, and the problem's version when graded as a class
    submitted_at: float  #: when the grader first saw this content (never the file's mtime)
    note: str = ""  #: why this file was chosen, when the folder held several
    groups: str = ""  #: the per-group fingerprints it is judged under (JSON; :mod:`grader.classroom.regrade`)


NO_SUBMISSION = "no submission (no .py or .ipynb file in the folder)"


def choose_submission(student_dir: Path, problem: str,
                      seen: Callable[[Path], float] | None = None) -> tuple[Path | None, str]:
    """The student's file and, when there were several candidates, why it was chosen:
    ``<problem>.py``/``.ipynb`` if present, else the one the grader saw last (``seen(path)``: when
    the grader first saw that file's content; never the file's modification time, which the
    student controls), then the last by name.

    >>> import tempfile; d = Path(tempfile.mkdtemp())
    >>> _ = (d / "a.py").write_text(""); _ = (d / "delaunay.py").write_text("")
    >>> f, why = choose_submission(d, "delaunay"); f.name, why
    ('delaunay.py', 'judged delaunay.py of 2 files (a.py, delaunay.py): it is named after the problem')
    """
    seen = seen or (lambda p: 0.0)
    files = sorted(p for p in student_dir.iterdir() if p.is_file() and p.suffix in SUFFIXES)
    named = [p for p in files if p.stem == problem]
    pool = named or files
    if not pool:
        return None, NO_SUBMISSION
    chosen = max(pool, key=lambda p: (seen(p), p.name))
    if len(files) == 1:
        return chosen, ""
    why = "it is named after the problem" if named else "it is the one the grader saw last"
    if len(named) > 1:
        why += " and the one the grader saw last of those"
    return chosen, f"judged {chosen.name} of {len(files)} files ({', '.join(p.name for p in files)}): {why}"


def find_submission(student_dir: Path, problem: str) -> Path | None:
    """The student's file (see :func:`choose_submission`), or None."""
    return choose_submission(student_dir, problem)[0]


def student_ids(dirs: list[Path]) -> tuple[dict[Path, str], list[str]]:
    """Each student folder's id (its name made safe by :func:`grader.judging.text.clean`), unique: when
    two names clean to the same id (``bob<ESC>`` and ``bob\\x1b``), each name that is not its own
    clean form gets a suffix from its raw bytes; and one warning per collision.

    >>> esc, shown = "bob" + chr(27), "bob" + chr(92) + "x1b"    # clean(esc) == shown
    >>> ids, warnings = student_ids([Path("bob"), Path(esc), Path(shown)])
    >>> ids[Path(shown)] == shown, ids[Path(esc)].startswith(shown + "~"), len(warnings)
    (True, True, 1)
    """
    by_id: dict[str, list[Path]] = {}
    for d in dirs:
        by_id.setdefault(clean(d.name, 200), []).append(d)
    ids, warnings = {}, []
    for cid, group in by_id.items():
        if len(group) == 1:
            ids[group[0]] = cid
            continue
        for d in group:
            raw = os.fsencode(d.name)
            ids[d] = cid if d.name == cid else f"{cid}~{hashlib.sha256(raw).hexdigest()[:8]}"
        warnings.append(f"{len(group)} student folders read as {cid!r}: kept apart as "
                        + ", ".join(repr(ids[d]) for d in group))
    return ids, warnings


def _student_dirs(root: str | Path) -> list[Path]:
    root = Path(root)
    if not root.is_dir():
        raise ValueError(f"submissions directory {root} does not exist (expected submissions/<student>/<file>)")
    return sorted(p for p in root.iterdir() if p.is_dir())


def content_sha(path: Path) -> str:
    """SHA-256 (16 hex digits) of a submission file's bytes, or of the reason it cannot be read."""
    try:  # links, special files and oversize files are not read: judging reports them as CE
        data = read_submission_bytes(path)
    except SubmissionError as exc:
        data = f"unreadable: {exc}".encode()
    return hashlib.sha256(data).hexdigest()[:16]


def discover(root: str | Path, problem: str, store: ResultStore | None = None, digest: str = "") -> list[Job]:
    """One job per student directory under ``root`` that holds a submission. With a ``store``,
    submission times are when the grader first saw each file's content (recorded now if never);
    the store key is the content's hash and ``digest``, the problem's version
    (:func:`grader.classroom.regrade.version`: changed tests, checker, limits or points make a new key)."""
    jobs = []
    ids, _ = student_ids(_student_dirs(root))
    for d, student in ids.items():
        shas: dict[Path, str] = {}

        def seen(p: Path) -> float:
            shas[p] = content_sha(p)
            return store.first_seen(student, problem, shas[p]) if store is not None else 0.0

        f, why = choose_submission(d, problem, seen)
        if f is not None:
            sha = shas.get(f) or content_sha(f)
            key = f"{sha}-{digest[:8]}" if digest else sha
            jobs.append(Job(student, str(f), key, seen(f) if store is not None else 0.0, clean(why, 500)))
    return jobs


def empty_students(root: str | Path, problem: str) -> list[str]:
    """Student directories under ``root`` without any submission file."""
    ids, _ = student_ids(_student_dirs(root))
    return [ids[d] for d in ids if choose_submission(d, problem)[0] is None]


def _die_with_parent(parent: int) -> None:
    """Pool worker initialiser: the kernel kills this worker when the grading process dies
    (``PR_SET_PDEATHSIG``), so a ``kill -9`` of ``grade`` leaves no worker judging or idling."""
    PR_SET_PDEATHSIG = 1
    try:
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (OSError, AttributeError):
        pass
    if os.getppid() != parent:  # the parent died before the signal was armed
        os._exit(1)


_judges: dict[tuple, Judge] = {}


def _judge_for(problem: str, hide: tuple[str, ...], per_thread: bool = False) -> Judge:
    """This process's judge of ``problem`` hiding ``hide`` (``per_thread``: one per thread, for a
    caller that sets the judge's ``hide`` per submission, as a Dask worker with threads does)."""
    key = (problem, hide, threading.get_ident() if per_thread else None)
    if key not in _judges:
        _judges[key] = Judge(problem, hide=list(hide))
    return _judges[key]


def grade_local(problem: str, job: Job, db_path: str, hide: tuple[str, ...], report_dir: str | None,
                builds: str | None = None) -> dict:
    """Worker side: judge one student's file, committing its test results to the store as they
    come (at least once a second: :meth:`ResultStore.deferred_tests`). ``builds``:
    the grader's private folder where a compiled submission that failed a group with WA, PE or RE
    leaves its binary for its counterexample search (one compile per submission)."""
    store = ResultStore(db_path)
    judge = _judge_for(problem, hide)
    try:
        store.begin(job.student, problem, job.path, job.sha, job.submitted_at, job.groups)
        prior = store.prior(job.student, problem, job.sha)
        judge.keep_build, judge.build_store = builds is not None, builds
        with store.deferred_tests(job.student, problem, job.sha) as add:  # a commit a second, not a test
            result = judge.judge_path(job.path, on_test=add, prior=prior)
        if builds is not None:
            from ..contest.counterexample import failing_groups

            if failing_groups(result):
                judge.store_build()
        if report_dir:  # before the student is marked done: a kill in between leaves them to resume
            from ..contest.report import student_report_path, write_report

            write_report(result, student_report_path(report_dir, job.student), judge.problem, student=job.student)
        store.finish(job.student, problem, job.sha, result, note=job.note)
        return {"student": job.student, "verdict": result.verdict, "score": result.score,
                "max_score": result.max_score, "resumed": len(prior), "tests": len(result.tests)}
    finally:
        judge.keep_build, judge.build_store = False, None
        judge.drop_build()
        store.close()


def grade_remote(problem: str, student: str, filename: str, data: bytes, prior: list[dict],
                 hide: tuple[str, ...] = ()) -> dict:
    """Dask worker side: judge source bytes sent by the client; return plain data. ``hide``: the
    client's folders (submissions, results) that the jail must also hide where this worker has them
    (a worker on the client's own machine, as in a local cluster)."""
    import tempfile

    with tempfile.TemporaryDirectory(prefix="grader-remote-") as tmp:
        path = Path(tmp) / filename
        path.write_bytes(data)
        judge = _judge_for(problem, (), per_thread=True)  # one per problem: its parsed tests are kept
        judge.hide = [tmp, *(h for h in hide if os.path.exists(h))]
        result = judge.judge_path(path, prior={d["name"]: TestResult.from_json(d) for d in prior})
    out = result.to_json()
    out["student"] = student
    return out


class Progress:
    """Progress on stderr: students graded, tests done (and resumed from the store), who is being
    judged. A live line on a terminal; otherwise a plain line per finished student."""

    def __init__(self, total: int, stream=None, tests_per_student: int = 0, resumed: int = 0):
        stream = stream if stream is not None else sys.stderr
        self.total, self.done, self.stream, self.t0 = total, 0, stream, time.monotonic()
        self.tty = hasattr(stream, "isatty") and stream.isatty()
        self.tests_total = total * tests_per_student
        self.tests_done, self.resumed, self.judging = resumed, resumed, ""

    def _tests(self) -> str:
        resumed = f", {self.resumed} resumed from the store" if self.resumed else ""
        return f"tests {self.tests_done}/{self.tests_total}{resumed}" if self.tests_total else ""

    def _line(self, label: str) -> None:
        el = time.monotonic() - self.t0
        width = 24
        fill = int(width * self.done / max(1, self.total))
        text = (f"[{'#' * fill}{'.' * (width - fill)}] {self.done}/{self.total} {el:5.1f}s {self._tests()} "
                f"{label}")[:110]
        self.stream.write(f"\r{text:110}")
        self.stream.flush()

    def poll(self, store: ResultStore, problem: str, jobs: dict[str, str], finished: set[str]) -> None:
        """Refresh tests done and who is being judged from the store (``jobs``: student -> sha)."""
        rows = store.db.execute("SELECT student, sha, COUNT(*) FROM results WHERE problem=? GROUP BY student, sha",
                                (problem,)).fetchall()
        counts = {st: n for st, sha, n in rows if jobs.get(st) == sha}
        started = {st for st, sha in store.db.execute(
            "SELECT student, sha FROM submissions WHERE problem=? AND status='running'", (problem,)) if jobs.get(st) == sha}
        self.tests_done = sum(counts.values())
        per = self.tests_total // max(1, self.total)
        active = sorted(started - finished)
        self.judging = "judging " + ", ".join(f"{st} {counts.get(st, 0)}/{per}" for st in active) if active else ""
        if self.tty:
            self._line(self.judging)

    def step(self, label: str) -> None:
        self.done += 1
        el = time.monotonic() - self.t0
        if self.tty:
            self._line(label)
            if self.done == self.total:
                self.stream.write("\n")
        else:
            tests_text = f"; {self._tests()}" if self._tests() else ""
            self.stream.write(f"graded {self.done}/{self.total} ({el:.1f}s): {label}{tests_text}\n")
        self.stream.flush()


def grade_class(problem: str, root: str | Path, db_path: str | Path, jobs: int = 1, scheduler: str | None = None,
                csv_path: str | Path | None = None, report_dir: str | Path | None = None,
                progress: bool = True, regrade_students: list[str] | None = None,
                diff_path: str | Path | None = None, counterexample_seconds: float | None = 0.0) -> list[dict]:
    """Grade every student's submission for ``problem``; returns one summary dict per student.

    Only what changed is judged: new submissions, and the groups whose tests, checker or limits
    changed since a submission was judged (:mod:`grader.classroom.regrade`). ``regrade_students``
    (``[]``: everyone) are judged again from scratch on demand. Every student judged again gets a
    diff (old score, new score, the groups that changed and why): printed on stderr, kept in the
    store and written to ``diff_path`` (CSV) when given; each summary of such a student has it
    under ``"regrade"``.

    After every score is stored (and the CSV written), the counterexample searches run for the
    submissions that failed a group with WA, PE or RE and have none stored
    (:mod:`grader.classroom.class_counterexamples`; ``counterexample_seconds``: each one's budget,
    None: the problem's ``course.yaml`` (what ``python -m grader grade`` passes), 0 (the default
    here): none)."""
    from . import regrade

    spec = load_problem(problem)  # also: a clear error for an unknown id
    max_score = sum(spec.group_points.values())
    _student_dirs(root)  # a missing folder is refused before a store is created
    fps = regrade.fingerprints(spec)
    store = ResultStore(db_path)
    todo_all = discover(root, problem, store, regrade.version(fps))
    empty = empty_students(root, problem)
    for warning in student_ids(_student_dirs(root))[1]:
        print(warning, file=sys.stderr)
    if regrade_students is not None:
        known = {j.student for j in todo_all}
        unknown = sorted(set(regrade_students) - known)
        if unknown:
            raise ValueError(f"no submission of {', '.join(unknown)} for {problem} under {root} "
                             f"(students with one: {', '.join(sorted(known)) or 'none'})")
        for j in todo_all:
            if not regrade_students or j.student in regrade_students:
                regrade.force(store, problem, j.student, j.sha, "regraded on demand")
    todo = [j for j in todo_all if not store.is_done(j.student, problem, j.sha)]
    rejudged = 0
    for j in todo:
        j.groups = json.dumps(fps, sort_keys=True)
        if regrade.forced(store, problem, j.student, j.sha):
            j.note = "; ".join(filter(None, [j.note, "judged again on demand"]))
            continue
        prev, changed = regrade.carry_over(store, j.student, spec, j.sha.split("-")[0], j.sha, fps)
        if prev is not None:
            regrade.start(store, problem, j.student, prev, j.sha, changed)
            rejudged += 1
            groups = ", ".join(f"{g} ({w})" for g, w in sorted(changed.items()) if w) or "no group changed"
            j.note = "; ".join(filter(None, [j.note, f"judged again: {groups}"]))
    if rejudged:
        print(f"{problem}: {rejudged} submissions judged again: the problem's tests, checker, limits or points "
              "changed since they were graded (unchanged groups are carried over)", file=sys.stderr)
    latest = store.latest(problem)
    summaries = [_graded_summary(j.student, latest.get(j.student), max_score) for j in todo_all if j not in todo]
    summaries += [{"student": st, "verdict": "", "score": 0, "max_score": max_score, "skipped": NO_SUBMISSION}
                  for st in empty]
    hide = tuple(str(Path(p).resolve()) for p in (root, Path(db_path).parent, report_dir) if p)
    t_grade = time.monotonic()
    require_jail()  # no kernel jail for this account: refuse once, with the fixes, not JE per student
    # materialise tests once in the parent, before workers race for it
    n_tests = len(Judge(problem).tests)
    resumed = sum(len(store.prior(j.student, problem, j.sha)) for j in todo)
    for j in todo_all:
        if j.note:
            print(f"{j.student}: {j.note}", file=sys.stderr)
    for st in empty:
        print(f"{st}: {NO_SUBMISSION}", file=sys.stderr)
    if progress:
        print(f"{problem}: {len(todo_all) + len(empty)} student folders: {len(todo)} to judge, "
              f"{len(todo_all) - len(todo)} already graded, {len(empty)} without a submission; "
              f"{resumed} test results resumed from the store", file=sys.stderr)
    bar = Progress(len(todo), tests_per_student=n_tests, resumed=resumed) if progress else None
    store.close()  # pool workers are forked: none may inherit an open SQLite connection
    if report_dir:
        Path(report_dir).mkdir(parents=True, exist_ok=True)
    builds = _builds_folder(spec, counterexample_seconds, scheduler)
    if scheduler:
        store = ResultStore(db_path)
        summaries += _grade_dask(problem, todo, store, scheduler, bar)
    else:
        with ProcessPoolExecutor(max_workers=max(1, jobs), initializer=_die_with_parent,
                                 initargs=(os.getpid(),)) as pool:
            futures = {pool.submit(grade_local, problem, j, str(db_path), hide, str(report_dir) if report_dir else None,
                                   builds): j
                       for j in todo}
            store = ResultStore(db_path)  # opened after the workers were forked: progress reads it
            shas, finished = {j.student: j.sha for j in todo}, set()
            pending = set(futures)
            while pending:
                done, pending = wait(pending, timeout=1.0, return_when=FIRST_COMPLETED)
                for fut in done:
                    j = futures[fut]
                    try:
                        s = fut.result()
                    except JailUnavailable:  # root's uid pool refused (unsafe, or full): the whole batch stops
                        pool.shutdown(wait=False, cancel_futures=True)
                        raise
                    except Exception as exc:  # noqa: BLE001 - a judge fault; the batch goes on
                        s = {"student": j.student, "verdict": "JE", "error": f"{type(exc).__name__}: {exc}"}
                    summaries.append(s)
                    finished.add(j.student)
                    if bar:
                        bar.poll(store, problem, shas, finished)
                        bar.step(f"{s['student']} {s.get('verdict')} {s.get('score', '')}/{s.get('max_score', '')}")
                if bar and not done:
                    bar.poll(store, problem, shas, finished)
    diffs = regrade.finish(store, problem)
    if diffs:
        print(f"{problem}: regraded {len(diffs)} students, {sum(d['old_score'] != d['new_score'] for d in diffs)} "
              "scores moved:", file=sys.stderr)
        for d in diffs:
            print("  " + regrade.diff_line(d), file=sys.stderr)
        by_student = {d["student"]: d for d in diffs}
        for s in summaries:
            if s["student"] in by_student:
                s["regrade"] = by_student[s["student"]]
    if diff_path:
        regrade.write_diff_csv(diffs, problem, diff_path)
    if csv_path:
        store.export_csv(problem, csv_path)
        if empty:
            _add_empty_rows(csv_path, problem, empty, max_score)
    t_grade = time.monotonic() - t_grade
    store = _searches(spec, store, db_path, todo_all, jobs, report_dir, counterexample_seconds,
                      progress, len(todo), t_grade, builds)
    if builds is not None:
        shutil.rmtree(builds, ignore_errors=True)
    if report_dir:
        from ..contest.report import write_index

        rebuilt = _rebuild_missing_reports(spec, todo_all, store, Path(report_dir))
        if rebuilt and progress:
            print(f"{problem}: {rebuilt} reports rebuilt from the store (they were missing)", file=sys.stderr)
        write_index(Path(report_dir), problem, store, empty)
    store.close()
    return summaries


def _builds_folder(spec, seconds: float | None, scheduler: str | None) -> str | None:
    """A private folder of the grader (mode 0700, removed after the searches, or at exit) where a
    compiled submission that fails leaves its binary for its counterexample search; None when no
    search will run here (no budget, or Dask workers judge elsewhere)."""
    budget = spec.counterexample_seconds if seconds is None else seconds
    if budget <= 0 or scheduler:
        return None
    folder = tempfile.mkdtemp(prefix="grader-builds-")
    atexit.register(shutil.rmtree, folder, True)
    return folder


def _searches(spec, store: ResultStore, db_path: str | Path, jobs_all: list[Job], jobs: int,
              report_dir: str | Path | None, seconds: float | None, progress: bool, judged: int,
              t_grade: float, builds: str | None = None) -> ResultStore:
    """The counterexample searches, after the scores (see :func:`grade_class`); the store reopened.
    ``builds``: where the judged submissions left their binaries (:func:`grade_local`)."""
    from .class_counterexamples import pending, run_searches

    budget = spec.counterexample_seconds if seconds is None else seconds
    todo = pending(store, spec, {j.student: j.path for j in jobs_all}) if budget > 0 else []
    if progress and judged:
        print(f"{spec.id}: {judged} students judged in {t_grade:.1f} s ({t_grade / judged:.1f} s a student); "
              f"scores stored", file=sys.stderr)
    if not todo:
        return store
    store.close()  # the search workers are forked: none may inherit an open SQLite connection
    say = (lambda line: print(line, file=sys.stderr)) if progress else (lambda line: None)
    run_searches(spec.id, todo, db_path, budget, jobs, report_dir, say=say, initializer=_die_with_parent,
                 initargs=(os.getpid(),), builds=builds)
    return ResultStore(db_path)


def _graded_summary(student: str, row, max_score: int) -> dict:
    """The summary of a student graded in an earlier run: the stored verdict and score (late factor applied)."""
    if row is None:
        return {"student": student, "skipped": "already graded"}
    mult = 1.0 if row["multiplier"] is None else row["multiplier"]
    return {"student": student, "verdict": row["verdict"], "score": round(row["score"] * mult, 2),
            "max_score": row["max_score"] or max_score, "skipped": "already graded"}


def _rebuild_missing_reports(spec, jobs: list[Job], store: ResultStore, report_dir: Path) -> int:
    """Write the report of every graded student whose report is missing (a kill between judging
    and the report, a new ``--reports`` folder, a Dask run) from the stored results (without the
    picture, which needs the answer itself); how many were written."""
    from ..contest.report import student_report_path, write_report

    n = 0
    for j in jobs:
        path = student_report_path(report_dir, j.student)
        if path.is_file() or not store.is_done(j.student, spec.id, j.sha):
            continue
        prior = store.prior(j.student, spec.id, j.sha)
        result = JudgeResult(spec.id, j.path, [prior[t.name] for t in spec.tests() if t.name in prior], spec.group_points)
        stored = store.counterexamples(j.student, spec.id, j.sha)
        if stored is not None:
            result.counterexamples, result.extra["counterexample_search"] = stored
        write_report(result, path, spec, student=j.student)
        n += 1
    return n


def _add_empty_rows(csv_path: str | Path, problem: str, students: list[str], max_score: int) -> None:
    """Add a score-0 row for every student folder without a submission, keeping the rows sorted."""
    with open(csv_path, newline="") as f:
        rows = list(csv.reader(f))
    head, body = rows[0], rows[1:]
    for st in students:
        body.append([csv_cell(st), problem, "0", str(max_score), "", "", NO_SUBMISSION])
    with open(csv_path, "w", newline="") as f:
        csv.writer(f).writerows([head, *sorted(body, key=lambda r: r[0].lstrip("'"))])


def _grade_dask(problem: str, todo: Iterable[Job], store: ResultStore, scheduler: str, bar: Progress | None) -> list[dict]:
    from distributed import Client, as_completed as dask_completed

    out = []
    with Client(scheduler) as client:
        futures = {}
        for j in todo:
            store.begin(j.student, problem, j.path, j.sha, j.submitted_at, j.groups)
            prior = [r.to_json() for r in store.prior(j.student, problem, j.sha).values()]
            try:
                data = read_submission_bytes(j.path)
            except SubmissionError:  # judged here: no code runs, the result is CE with the reason
                data = None
            if data is None:
                result = _judge_for(problem, ()).judge_path(j.path)
                for t in result.tests:
                    store.add_test(j.student, problem, j.sha, t)
                store.finish(j.student, problem, j.sha, result)
                out.append({"student": j.student, "verdict": result.verdict, "score": 0, "max_score": result.max_score})
                continue
            fut = client.submit(grade_remote, problem, j.student, Path(j.path).name, data, prior,
                                key=f"grade-{problem}-{j.student}-{j.sha}", pure=False)
            futures[fut] = j
        for fut in dask_completed(list(futures)):
            j = futures[fut]
            try:
                data = fut.result()
            except Exception as exc:  # noqa: BLE001
                out.append({"student": j.student, "verdict": "JE", "error": f"{type(exc).__name__}: {exc}"})
                continue
            tests = [TestResult.from_json(t) for t in data["tests"]]
            for t in tests:
                store.add_test(j.student, problem, j.sha, t)
            result = JudgeResult(problem, j.path, tests, {g["name"]: g["points"] for g in data["groups"]})
            store.finish(j.student, problem, j.sha, result, note=j.note)
            s = {"student": j.student, "verdict": result.verdict, "score": result.score, "max_score": result.max_score}
            out.append(s)
            if bar:
                bar.step(f"{j.student} {result.verdict} {result.score}/{result.max_score}")
    return out
