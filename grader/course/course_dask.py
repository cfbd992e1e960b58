"""The course's class autograde on a Dask distributed cluster: one task per collected notebook.

``python -m grader grade PROBLEM assignments/submitted --nbgrader --scheduler ADDRESS`` judges the
class on the cluster's workers instead of a local process pool, then runs ``nbgrader autograde``
as the pool path does (it finds every result stored and judges nobody again). The client (this
process) keys each notebook exactly as the autograde step will (:func:`.nbgrader_autograde.code_key`
of the code nbgrader's sanitised copy holds), records the submission as started, sends the
notebook's bytes and any test results already stored to a worker
(:func:`grader.classroom.classgrade.grade_remote`: a fresh jail per submission there too, the hidden
tests on the worker's side only), and commits a student's results when the task returns. A killed
batch keeps every student already returned; the others are judged again on the next run.

Example (a local cluster of 2 worker processes)::

    from distributed import LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cluster:
        grade_course("delaunay", "assignments/submitted", scheduler=cluster.scheduler_address)
"""

from __future__ import annotations

import hashlib
import json
import time
from pathlib import Path
from typing import Callable

from ..classroom import regrade
from ..classroom.classgrade import grade_remote
from ..classroom.store import ResultStore
from ..contest.judge import Judge
from ..judging.submissions import Submission, SubmissionError, read_submission_bytes
from ..judging.verdicts import JudgeResult, TestResult
from . import nbgrader_autograde as na


def _summary(student: str, result: JudgeResult) -> dict:
    return {"student": student, "verdict": result.verdict, "score": result.score, "max_score": result.max_score}


def _stored(store: ResultStore, problem, student: str, key: str, path: Path) -> JudgeResult | None:
    """The stored result of this very code, when every test of it is stored."""
    prior = store.prior(student, problem.id, key)
    if store.is_done(student, problem.id, key) and len(prior) == len(problem.tests()):
        return JudgeResult(problem.id, str(path), [prior[t.name] for t in problem.tests()], problem.group_points)
    return None


def judge_on_dask(problem_id: str, collected: list[tuple[str, Path]], store_path: Path, scheduler: str,
                  hide: tuple[str, ...] = (), say: Callable[[str], None] = lambda s: None) -> list[dict]:
    """Judge every ``(student, notebook)`` of ``collected`` on the Dask cluster at ``scheduler``;
    each student's results go into ``store_path`` under the key ``nbgrader autograde`` looks up.
    Returns one summary per student (``verdict``, ``score``, ``max_score``; ``JE`` and ``error``
    when a task failed: ``nbgrader autograde`` then judges that notebook itself)."""
    from distributed import Client, as_completed

    if not scheduler or not isinstance(scheduler, str):
        raise ValueError(f"scheduler must be a Dask scheduler address such as tcp://host:8786, got {scheduler!r}")
    problem = na._problem(problem_id)
    fps = na._fingerprints(problem)
    groups = json.dumps(fps, sort_keys=True)
    out: list[dict] = []
    store = ResultStore(store_path)
    try:
        with Client(scheduler) as client:
            futures = {}
            for student, path in collected:
                try:
                    code = Submission.from_path(path).source
                except SubmissionError:  # keyed by its bytes, as the autograde step does
                    code = "\0raw\0" + hashlib.sha256(path.read_bytes()).hexdigest()
                key = na.code_key(problem, code)
                done = _stored(store, problem, student, key, path)
                if done is not None:
                    out.append(_summary(student, done))
                    continue
                na._adopt_legacy(store, student, problem, code, key)
                prev, changed = regrade.carry_over(store, student, problem, key.split("-")[0], key, fps)
                if prev is not None:
                    regrade.start(store, problem.id, student, prev, key, changed)
                submitted_at = na.collection_time(path.parent)
                store.begin(student, problem.id, str(path), key, time.time() if submitted_at is None else submitted_at,
                            groups)
                prior = store.prior(student, problem.id, key)
                try:
                    data = read_submission_bytes(path)
                except SubmissionError:  # judged here: no code runs, the verdict is CE with the reason
                    result = Judge(problem, hide=[*hide, str(path.parent)]).judge_path(path, prior=prior)
                    _commit(store, student, problem.id, key, result)
                    out.append(_summary(student, result))
                    continue
                fut = client.submit(grade_remote, problem.id, student, path.name, data,
                                    [r.to_json() for r in prior.values()], hide,
                                    key=f"course-{problem.id}-{student}-{key}", pure=False)
                futures[fut] = (student, path, key)
            say(f"{problem.id}: {len(futures)} notebook(s) sent to the Dask cluster at {scheduler}")
            for fut in as_completed(list(futures)):
                student, path, key = futures[fut]
                try:
                    data = fut.result()
                except Exception as exc:  # noqa: BLE001 - a worker fault; nbgrader autograde judges it again
                    out.append({"student": student, "verdict": "JE", "error": f"{type(exc).__name__}: {exc}"})
                else:
                    tests = [TestResult.from_json(t) for t in data["tests"]]
                    result = JudgeResult(problem.id, str(path), tests, problem.group_points)
                    _commit(store, student, problem.id, key, result)
                    out.append(_summary(student, result))
                r = out[-1]
                say(f"[{len(out)}/{len(collected)}] {student}: {r['verdict']} {r.get('score', '')}/{r.get('max_score', '')}")
    finally:
        store.close()
    return out


def _commit(store: ResultStore, student: str, problem_id: str, key: str, result: JudgeResult) -> None:
    for t in result.tests:
        store.add_test(student, problem_id, key, t)
    store.finish(student, problem_id, key, result)

