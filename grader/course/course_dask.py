"""The course's class autograde on a Dask distributed cluster: one task per collected notebook.

``python -m grader grade PROBLEM assignments/submitted --nbgrader --scheduler ADDRESS`` judges the
class on the cluster's workers instead of a local process pool, then runs ``nbgrader autograde``
as the pool path does (it finds every result stored and judges nobody again). The client
(:func:`grader.course.nbgrader_autograde.grade_course`) keys each notebook exactly as the autograde
step will and records it as started; this module sends the notebook's bytes and any test results
already stored to a worker (:func:`grader.classroom.classgrade.grade_remote`: a fresh jail per
submission there too, the hidden tests on the worker's side only) and hands each returned result
back to the client, which stores it at once. A killed batch keeps every student already returned;
the others are judged again on the next run.

Example (a local cluster of 2 worker processes)::

    from distributed import LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cluster:
        grade_course("delaunay", "assignments/submitted", scheduler=cluster.scheduler_address)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from ..classroom.classgrade import grade_remote
from ..judging.verdicts import TestResult


@dataclass
class RemoteJob:
    """One notebook for a worker: whose, where it is on the client, its store key, its bytes and
    the test results already stored under that key (JSON)."""
    student: str
    path: str
    key: str
    data: bytes
    prior: list[dict]


def judge_remote_jobs(problem_id: str, jobs: list[RemoteJob], scheduler: str, hide: tuple[str, ...],
                      done: Callable[[RemoteJob, list[TestResult] | None, str], None]) -> None:
    """Judge ``jobs`` on the Dask cluster at ``scheduler``; as each returns, ``done(job, tests, "")``
    (or ``done(job, None, error)`` when its task failed). ``hide``: the client's folders, hidden
    from the jail on a worker that has them too."""
    from distributed import Client, as_completed

    if not isinstance(scheduler, str) or not scheduler:
        raise ValueError(f"scheduler must be a Dask scheduler address such as tcp://host:8786, got {scheduler!r}")
    if not jobs:
        return
    with Client(scheduler) as client:
        futures = {client.submit(grade_remote, problem_id, j.student, j.path.rsplit("/", 1)[-1], j.data, j.prior,
                                 hide, key=f"course-{problem_id}-{j.student}-{j.key}", pure=False): j for j in jobs}
        for fut in as_completed(list(futures)):
            job = futures[fut]
            try:
                data = fut.result()
            except Exception as exc:  # noqa: BLE001 - a worker fault costs that student a local judging
                done(job, None, f"{type(exc).__name__}: {exc}")
                continue
            done(job, [TestResult.from_json(t) for t in data["tests"]], "")
