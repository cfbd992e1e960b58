"""A class's counterexample searches: run after every score is stored, so grades never wait for them.

``python -m grader grade`` judges every student first (scores in the store, per test); then, for
each graded submission that failed a group with WA, PE or RE and has no search stored yet, it
searches small public inputs for one the submission gets wrong
(:func:`grader.contest.counterexample.attach`, the problem's budget from ``course.yaml``
``feedback: {counterexample_seconds}`` or ``--counterexample-seconds``), ``jobs`` at a time, and
keeps each search in the store as soon as it ends (table ``counterexamples``): an interrupted
batch loses at most the searches that were running, and a rerun of ``grade`` does only the rest.
With a budget of 0 nothing is searched, and a later ``grade`` with a budget searches on demand.
A student's report (``--reports``) is written again with the counterexample.

Run:
    python -m grader grade emst submissions/ --db results.sqlite --counterexample-seconds 10

Example:
    >>> run_searches("emst", [], ":memory:", seconds=0)   # doctest: +SKIP
    (0, 0.0)
"""
from __future__ import annotations

import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path
from typing import Callable

from ..contest.counterexample import attach, failing_groups
from ..judging.verdicts import JudgeResult
from ..problems import load_problem
from .store import ResultStore


def _stored_result(store: ResultStore, problem, student: str, sha: str, file: str) -> JudgeResult:
    """A graded submission's result rebuilt from the store (its tests in judging order)."""
    prior = store.prior(student, problem.id, sha)
    return JudgeResult(problem.id, file, [prior[t.name] for t in problem.tests() if t.name in prior],
                       problem.group_points)


def search_one(problem_id: str, student: str, sha: str, file: str, db_path: str, seconds: float | None,
               report_dir: str | None, builds: str | None = None) -> dict:
    """Worker side: search for one stored submission and store the search (and rewrite its report).
    ``builds``: where grading left the submission's binary (a compiled one is not compiled again)."""
    problem = load_problem(problem_id)
    store = ResultStore(db_path)
    try:
        result = _stored_result(store, problem, student, sha, file)
        cx = attach(result, problem, file, seconds, build_store=builds)
        store.add_counterexamples(student, problem_id, sha, result)
        if report_dir:
            from ..contest.report import student_report_path, write_report

            write_report(result, student_report_path(report_dir, student), problem, student=student)
        search = result.extra.get("counterexample_search") or {}
        return {"student": student, "found": cx is not None, "seconds": float(search.get("seconds", 0.0)),
                "size": cx.size if cx else None}
    finally:
        store.close()


def pending(store: ResultStore, problem, file_of: dict[str, str] | None = None) -> list[tuple[str, str, str]]:
    """(student, sha, file) of each latest graded submission that failed a group with WA, PE or RE
    and has no stored search (``file_of``: only these students, with their current files)."""
    out = []
    for student, row in sorted(store.latest(problem.id).items()):
        if file_of is not None and student not in file_of:
            continue
        if store.counterexamples(student, problem.id, row["sha"]) is not None:
            continue
        result = _stored_result(store, problem, student, row["sha"], row["file"])
        if failing_groups(result) and Path(row["file"]).is_file():
            out.append((student, row["sha"], row["file"]))
    return out


def run_searches(problem_id: str, todo: list[tuple[str, str, str]], db_path: str | Path, seconds: float | None = None,
                 jobs: int = 1, report_dir: str | Path | None = None,
                 say: Callable[[str], None] = lambda s: None, initializer: Callable | None = None,
                 initargs: tuple = (), builds: str | None = None) -> tuple[int, float]:
    """Search for every (student, sha, file) of ``todo``, ``jobs`` at a time; (searches run, their
    total seconds). ``seconds``: the budget of each (None: the problem's ``course.yaml``; 0: none);
    ``initializer(*initargs)`` runs in each worker (``grade``: die with the parent); ``builds``: the
    grader's private folder where grading left the compiled submissions' binaries."""
    problem = load_problem(problem_id)
    budget = problem.counterexample_seconds if seconds is None else seconds
    if budget <= 0 or not todo:
        return 0, 0.0
    problem.tests()  # materialised once, before the workers start
    total, n = 0.0, 0
    t0 = time.monotonic()
    with ProcessPoolExecutor(max_workers=max(1, jobs), initializer=initializer, initargs=initargs) as pool:
        futures = {pool.submit(search_one, problem_id, st, sha, file, str(db_path), budget,
                               str(report_dir) if report_dir else None, builds): st for st, sha, file in todo}
        for fut in as_completed(futures):
            try:
                r = fut.result()
            except Exception as exc:  # noqa: BLE001 - a search fault costs that student the counterexample only
                say(f"{futures[fut]}: counterexample search failed: {type(exc).__name__}: {exc}")
                continue
            n, total = n + 1, total + r["seconds"]
            say(f"counterexample {n}/{len(todo)}: {r['student']}: "
                + (f"{r['size']} elements, {r['seconds']:.1f} s" if r["found"] else f"none found in {r['seconds']:.1f} s"))
    say(f"{problem_id}: {n} counterexample searches after grading: {total:.1f} s of searching "
        f"({total / max(1, n):.1f} s each), {time.monotonic() - t0:.1f} s wall with {max(1, jobs)} at a time")
    return n, total
