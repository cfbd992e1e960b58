"""Grading a whole class: ``submissions/<student>/<file>`` -> SQLite results, CSV, HTML reports.

Local runs use a process pool (``--jobs N``); each worker commits every test result as soon as it
is known, so a killed batch resumes where it stopped. ``--scheduler ADDRESS`` sends one job per
student to a Dask distributed cluster instead; the client then commits each student's results
when the job returns (workers may not share our disk).

Example:
    python -m grader grade delaunay class/ --db results.sqlite --jobs 2 --csv grades.csv
"""

from __future__ import annotations

import ctypes
import hashlib
import os
import signal
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable

from .judge import Judge
from .problems import load_problem
from .store import ResultStore
from .submissions import SubmissionError, read_submission_bytes
from .text import clean
from .verdicts import JudgeResult, TestResult


@dataclass
class Job:
    student: str
    path: str
    sha: str
    submitted_at: float


def find_submission(student_dir: Path, problem: str) -> Path | None:
    """The student's file: ``<problem>.py``/``.ipynb`` if present, else the newest .py/.ipynb."""
    files = [p for p in student_dir.iterdir() if p.is_file() and p.suffix in (".py", ".ipynb")]
    named = [p for p in files if p.stem == problem]
    pool = named or files
    return max(pool, key=lambda p: (p.stat().st_mtime, p.name)) if pool else None


def discover(root: str | Path, problem: str) -> list[Job]:
    """One job per student directory under ``root`` that holds a submission."""
    root = Path(root)
    if not root.is_dir():
        raise ValueError(f"submissions directory {root} does not exist (expected submissions/<student>/<file>)")
    jobs = []
    for d in sorted(p for p in root.iterdir() if p.is_dir()):
        f = find_submission(d, problem)
        if f is not None:
            try:  # links, special files and oversize files are not read: judging reports them as CE
                data = read_submission_bytes(f)
            except SubmissionError as exc:
                data = f"unreadable: {exc}".encode()
            jobs.append(Job(clean(d.name, 200), str(f), hashlib.sha256(data).hexdigest()[:16], f.lstat().st_mtime))
    return jobs


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


def _judge_for(problem: str, hide: tuple[str, ...]) -> Judge:
    key = (problem, hide)
    if key not in _judges:
        _judges[key] = Judge(problem, hide=list(hide))
    return _judges[key]


def grade_local(problem: str, job: Job, db_path: str, hide: tuple[str, ...], report_dir: str | None) -> dict:
    """Worker side: judge one student's file, committing each test result to the store."""
    store = ResultStore(db_path)
    try:
        store.begin(job.student, problem, job.path, job.sha, job.submitted_at)
        prior = store.prior(job.student, problem, job.sha)
        judge = _judge_for(problem, hide)
        result = judge.judge_path(job.path, on_test=lambda r: store.add_test(job.student, problem, job.sha, r),
                                  prior=prior)
        store.finish(job.student, problem, job.sha, result)
        if report_dir:
            from .report import write_report

            write_report(result, Path(report_dir) / f"{job.student}.html", judge.problem, student=job.student)
        return {"student": job.student, "verdict": result.verdict, "score": result.score,
                "max_score": result.max_score, "resumed": len(prior)}
    finally:
        store.close()


def grade_remote(problem: str, student: str, filename: str, data: bytes, prior: list[dict]) -> dict:
    """Dask worker side: judge source bytes sent by the client; return plain data."""
    import tempfile

    with tempfile.TemporaryDirectory(prefix="grader-remote-") as tmp:
        path = Path(tmp) / filename
        path.write_bytes(data)
        judge = _judge_for(problem, (tmp,))
        result = judge.judge_path(path, prior={d["name"]: TestResult.from_json(d) for d in prior})
    out = result.to_json()
    out["student"] = student
    return out


class Progress:
    """A progress bar on stderr (plain lines when stderr is not a terminal)."""

    def __init__(self, total: int, stream=None):
        stream = stream if stream is not None else sys.stderr
        self.total, self.done, self.stream, self.t0 = total, 0, stream, time.monotonic()
        self.tty = hasattr(stream, "isatty") and stream.isatty()

    def step(self, label: str) -> None:
        self.done += 1
        el = time.monotonic() - self.t0
        if self.tty:
            width = 30
            fill = int(width * self.done / max(1, self.total))
            self.stream.write(f"\r[{'#' * fill}{'.' * (width - fill)}] {self.done}/{self.total} {el:5.1f}s {label[:40]:40}")
            if self.done == self.total:
                self.stream.write("\n")
        else:
            self.stream.write(f"graded {self.done}/{self.total} ({el:.1f}s): {label}\n")
        self.stream.flush()


def grade_class(problem: str, root: str | Path, db_path: str | Path, jobs: int = 1, scheduler: str | None = None,
                csv_path: str | Path | None = None, report_dir: str | Path | None = None,
                progress: bool = True) -> list[dict]:
    """Grade every student's submission for ``problem``; returns one summary dict per student."""
    load_problem(problem)  # clear error for an unknown id
    todo_all = discover(root, problem)
    store = ResultStore(db_path)
    todo = [j for j in todo_all if not store.is_done(j.student, problem, j.sha)]
    summaries = [{"student": j.student, "skipped": "already graded"} for j in todo_all if j not in todo]
    store.close()  # pool workers are forked: none may inherit an open SQLite connection
    hide = tuple(str(Path(p).resolve()) for p in (root, Path(db_path).parent, report_dir) if p)
    bar = Progress(len(todo)) if progress else None
    # materialise tests once in the parent, before workers race for it
    Judge(problem)
    if report_dir:
        Path(report_dir).mkdir(parents=True, exist_ok=True)
    if scheduler:
        store = ResultStore(db_path)
        summaries += _grade_dask(problem, todo, store, scheduler, bar)
        store.close()
    else:
        with ProcessPoolExecutor(max_workers=max(1, jobs), initializer=_die_with_parent,
                                 initargs=(os.getpid(),)) as pool:
            futures = {pool.submit(grade_local, problem, j, str(db_path), hide, str(report_dir) if report_dir else None): j
                       for j in todo}
            for fut in as_completed(futures):
                j = futures[fut]
                try:
                    s = fut.result()
                except Exception as exc:  # noqa: BLE001 - a judge fault; the batch goes on
                    s = {"student": j.student, "verdict": "JE", "error": f"{type(exc).__name__}: {exc}"}
                summaries.append(s)
                if bar:
                    bar.step(f"{s['student']} {s.get('verdict')} {s.get('score', '')}/{s.get('max_score', '')}")
    if csv_path:
        store = ResultStore(db_path)
        store.export_csv(problem, csv_path)
        store.close()
    return summaries


def _grade_dask(problem: str, todo: Iterable[Job], store: ResultStore, scheduler: str, bar: Progress | None) -> list[dict]:
    from distributed import Client, as_completed as dask_completed

    out = []
    with Client(scheduler) as client:
        futures = {}
        for j in todo:
            store.begin(j.student, problem, j.path, j.sha, j.submitted_at)
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
            store.finish(j.student, problem, j.sha, result)
            s = {"student": j.student, "verdict": result.verdict, "score": result.score, "max_score": result.max_score}
            out.append(s)
            if bar:
                bar.step(f"{j.student} {result.verdict} {result.score}/{result.max_score}")
    return out
