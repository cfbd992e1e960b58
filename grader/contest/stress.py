"""``python -m grader stress PROBLEM FILE [--seconds N]``: find a small input that FILE gets wrong.

The tool competitive programmers use to find their bug. Inputs come smallest first: the problem's
``exhaustive`` group (every configuration of a few lattice points, :mod:`grader.problems.smallcases`, and
the group's hand-made cases), then random small inputs that grow with time (:func:`random_case`:
uniform lattice points, and families aimed at shortcuts the lattice misses: columns whose close
pairs lie far apart in sorted order, rooms listed from every corner, walls with a tiny dip, starts
whose nearest obstacle is not a corner of their Delaunay triangle). Each input is checked
by the problem's input validators, answered by the reference (the generator's ``solve``), and
FILE's answer is judged in the sandbox by the problem's checker, 48 inputs per sandboxed run.

A failure seen in such a batch is judged again *alone* (a fresh sandbox, the problem's per-test
limits, a fresh idle budget) before it counts: a batch shares one idle budget and, in function
mode, one worker process, so a sleeper, state left by earlier calls or a loaded machine can fail
an input in a batch that passes alone. Such a *fluke* is counted and never reported. An input that
is over the time limit alone is slow, not wrong: never a counterexample (``judge`` reports TLE);
it is counted too. A confirmed failure is shrunk (runs of points, holes or operations dropped,
each smaller input accepted only when it fails alone) and printed with its verdict, the
checker's message and the end of the program's stderr; the exit status is 1. No sandboxed run
starts after the deadline (``--seconds``; checked before each input of a batch, so the search
ends within ``--seconds`` plus one test's limits): when it passes while shrinking, the smallest
confirmed input so far is printed (exit 1, with a note). When nothing fails in the time given the
exit status is 0. Notes below the report count the flukes and slow inputs.

Example (the zoo solution that orders collinear points by x alone):

    python -m grader stress emst solutions/emst/wrong_collinear_sort_x.py --seconds 20
"""
from __future__ import annotations

import contextlib
import copy
import io
import math
import random
import runpy
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Collection, Iterator

from ..problems import smallcases
from .judge import Judge
from ..problems import Problem, TestCase, load_problem
from ..judging.submissions import Submission
from ..judging.verdicts import TestResult, Verdict

BATCH = 48  # inputs per sandboxed run
STDERR_LINES = 12  # a failure shows this many last lines of the submission's stderr
_PASSING = (Verdict.AC, Verdict.SKIPPED, Verdict.JE)


@dataclass
class Failure:
    """The smallest failing input found (it fails when judged alone): its generator case, input
    text, verdict and message, the end of the submission's stderr in it, and the search's counts.
    ``shrunk`` is False when the time ran out while shrinking (a smaller one may exist)."""

    case: dict
    input_text: str
    verdict: str
    message: str
    tried: int
    stderr: str = ""
    shrunk: bool = True
    flukes: int = 0
    slow: int = 0
    answer: str = ""  #: the submission's answer on ``input_text`` (text, capped; empty after a crash)


@dataclass
class Stats:
    """Counts of one search: inputs judged in batches; failures that did not happen again alone
    (``flukes``); inputs over the time limit alone (``slow``: never reported); failures seen when
    no time was left to judge them alone (``unconfirmed``: not reported)."""

    tried: int = 0
    flukes: int = 0
    slow: int = 0
    unconfirmed: int = 0
    excluded: int = 0  #: inputs never judged: equal to an excluded input (a test of the problem)
    other: int = 0  #: failures alone with a verdict the search does not report (``verdicts``)


def _valid(problem: Problem, text: str) -> bool:
    """The problem's input validators accept ``text`` (run in this process: exit 42 = valid)."""
    for v in problem.input_validators():
        before = set(sys.modules)
        old_argv, old_stdin, old_path = sys.argv, sys.stdin, list(sys.path)
        sys.argv, sys.stdin = [str(v)], io.StringIO(text)
        sys.path.insert(0, str(v.parent))
        code: object = 0
        try:
            with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
                runpy.run_path(str(v), run_name="__main__")
        except SystemExit as exc:
            code = exc.code
        except Exception:
            code = 1
        finally:
            sys.argv, sys.stdin, sys.path[:] = old_argv, old_stdin, old_path
            for name in set(sys.modules) - before:  # validators of other problems share module names
                del sys.modules[name]
        if code != 42:
            return False
    return True


def _test(problem: Problem, case: dict, name: str) -> TestCase | None:
    """The test of one case (None when the case is not a valid input of the problem)."""
    try:
        args = problem.generate_args(case, 0)
        text = problem.checker.write_input(args)
        if not _valid(problem, text):
            return None
        answer = problem.checker.write_output(problem.generator.solve(*args))
    except Exception:  # a random case the generator or the reference refuses: not an input
        return None
    return TestCase(name, "stress", text, answer)


def normalized(text: str) -> str:
    """``text`` with its layout and number spellings made canonical, to compare inputs
    (``1``, ``1.0`` and ``1e0`` read the same; so do any runs of blanks and newlines).

    >>> normalized("2\\n0 1.0\\n  3 4\\n") == normalized("2 0.0e0 1 3 4")
    True
    >>> normalized("2\\n0 1\\n") == normalized("2\\n1 0\\n")
    False
    """
    out = []
    for token in text.split():
        try:
            out.append(repr(float(token)))
        except ValueError:
            out.append(token)
    return " ".join(out)


def _random_points(rng: random.Random, n: int, span: int, dim: int = 2) -> list[list[int]]:
    return [[rng.randint(0, span) for _ in range(dim)] for _ in range(n)]


def _columns(rng: random.Random, size: int) -> list[list[int]]:
    """Two or three columns one apart, their points ten apart in y (shifted by 0..4): the closest
    pairs join the columns and lie a column's length apart in (x, y) order (past a fixed window),
    in a random order."""
    cols, per = rng.choice((2, 3)), rng.randint(3, 12) + size // 4
    pts = [[c, 10 * k + rng.randint(0, 4)] for c in range(cols) for k in range(per)]
    rng.shuffle(pts)
    return pts


def _across_edge(rng: random.Random) -> dict:
    """``obstacle-clearance``: an obtuse Delaunay triangle a, b, c (c above the long edge ab) and d
    far below it; start (and often goal) just below ab, in the triangle a, b, d, whose nearest
    obstacle is c, not a corner of its own triangle. Mirrored, turned and moved at random."""
    m = rng.randint(2, 5)
    h = rng.randint(1, m - 1)
    k = (h * h - m * m) / (2 * h)             # the circumcentre (m, k) of a, b, c lies below ab
    depth = int(math.hypot(m, k) - k) + rng.randint(1, 3)   # d outside that circle
    pts = [[0, 0], [2 * m, 0], [m, h], [m, -depth]]
    q = [m + rng.randint(-2, 2) / 4, -0.25]
    other = [rng.randint(-2, 4 * m + 2) / 2, rng.randint(-2 * depth, 2 * h + 2) / 2]
    ends = [q, q if rng.random() < 0.5 else other]
    rng.shuffle(ends)
    flip, swap, dx, dy = rng.choice((1, -1)), rng.random() < 0.5, rng.randint(0, 3), rng.randint(0, 3)

    def move(p: list) -> list:
        x, y = p[0], p[1] * flip
        x, y = (y, x) if swap else (x, y)
        return [x + dx, y + dy]

    pts = [move(p) for p in pts]
    rng.shuffle(pts)
    return {"kind": "points", "points": pts, "shuffle": False, "start": move(ends[0]), "goal": move(ends[1])}


def _rotated(ring: list, rng: random.Random) -> list:
    """``ring`` listed from a random corner (the same polygon, the same orientation)."""
    k = rng.randrange(len(ring))
    return ring[k:] + ring[:k]


def _u_room(rng: random.Random) -> dict:
    """``navmesh``: a U-shaped room (two reflex corners at the bottom of its notch) in either
    orientation, start and goal in its two arms (the route bends at both reflex corners)."""
    w, h = rng.randint(3, 6), rng.randint(2, 5)
    b = rng.randint(1, h - 1)
    ring = [[0, 0], [w, 0], [w, h], [w - 1, h], [w - 1, b], [1, b], [1, h], [0, h]]
    ends = [[0.5, rng.randint(2 * b + 1, 2 * h) / 2], [w - 0.5, rng.randint(2 * b + 1, 2 * h) / 2]]
    rng.shuffle(ends)
    return {"kind": "room", "boundary": ring[::-1] if rng.random() < 0.5 else ring, "holes": [],
            "start": ends[0], "goal": ends[1]}


def _dip(room: dict, rng: random.Random) -> dict:
    """``room`` with one wall bent into the free space by 2**-40 at its midpoint (a reflex corner
    whose turn is about -1e-13 after scaling), start and goal often at that wall's ends (the route
    must bend there)."""
    rings = [room["boundary"]] + list(room["holes"])
    r = rng.randrange(len(rings))
    ring = [list(map(float, p)) for p in rings[r]]
    i = rng.randrange(len(ring))
    a, b = ring[i], ring[(i + 1) % len(ring)]
    area = sum(p[0] * q[1] - p[1] * q[0] for p, q in zip(ring, ring[1:] + ring[:1]))
    side = 1 if (area > 0) == (r == 0) else -1   # the free space is on the left of a ccw boundary
    dx, dy = b[0] - a[0], b[1] - a[1]
    tiny = 2.0 ** -40
    mid = [(a[0] + b[0]) / 2 - side * tiny * dy, (a[1] + b[1]) / 2 + side * tiny * dx]
    ring = ring[:i + 1] + [mid] + ring[i + 1:]
    rings[r] = ring
    out = {**room, "boundary": rings[0], "holes": rings[1:]}
    if rng.random() < 0.5:
        out["start"], out["goal"] = (a, b) if rng.random() < 0.5 else (b, a)
    return out


def random_case(problem_id: str, rng: random.Random, size: int) -> dict:
    """A random small case of ``problem_id`` with about ``size`` elements (integer coordinates;
    ``navmesh`` walls with a dip of 2**-40 and the start of ``obstacle-clearance``'s obtuse family
    are dyadic fractions). Besides uniform points: columns whose close pairs lie far apart in sorted
    order (closest-pair, emst, proximity-network), a start whose nearest obstacle is not a corner of
    its own Delaunay triangle (obstacle-clearance), rooms listed from a random corner and with a
    tiny dip in a wall, U-shaped rooms (navmesh)."""
    n, span = rng.randint(1, size), rng.choice((2, 3, 4, 6, 10))
    if problem_id == "navmesh":
        room = dict(rng.choice(smallcases.cases_for("navmesh")))
        room["holes"] = [h for h in room["holes"] if rng.random() < 0.7]
        spot = [[rng.randint(-2, 10) / 2, rng.randint(-2, 10) / 2] for _ in range(2)]
        room = {**room, "start": spot[0], "goal": spot[rng.randrange(2)]}
        if rng.random() < 0.25:
            room = _u_room(rng)
        if rng.random() < 0.3:
            room = _dip(room, rng)
        if rng.random() < 0.6:  # every ring listed from a random corner (reflex ones too)
            room["boundary"] = _rotated(room["boundary"], rng)
            room["holes"] = [_rotated(h, rng) for h in room["holes"]]
        return room
    if problem_id == "dynamic-network":
        ops: list = []
        joined = 0
        for _ in range(2 * n + 2):
            r = rng.random()
            if r < 0.45 or not joined:
                ops.append(["join", float(rng.randint(0, span)), float(rng.randint(0, span))])
                joined += 1
            elif r < 0.6:
                ops.append(["fail", rng.randrange(joined + 1)])
            elif r < 0.95:
                ops.append(["neighbors", rng.randrange(joined + 1)])
            else:
                ops.append(["count"])
        return {"kind": "ops", "operations": ops}
    if problem_id == "delaunay-3d":
        return {"kind": "points", "points": _random_points(rng, n + 3, min(span, 3), dim=3), "shuffle": False}
    if problem_id == "obstacle-clearance" and rng.random() < 0.3:
        return _across_edge(rng)
    if problem_id in ("closest-pair", "emst", "proximity-network") and rng.random() < 0.3:
        return {"kind": "points", "points": _columns(rng, size), "shuffle": False}
    pts = _random_points(rng, n + (2 if problem_id in ("closest-pair", "largest-empty-circle") else 0), span)
    case: dict = {"kind": "points", "points": pts, "shuffle": False}
    if problem_id == "edge-flip":
        case["start"] = "sweep"
    elif problem_id == "voronoi":
        m = rng.choice((0, 1))
        case["box"] = [-m, -m, span + m, span + m]
    elif problem_id == "obstacle-clearance":
        case["start"], case["goal"] = ([rng.randint(-2, 2 * span + 2) / 2, rng.randint(-2, 2 * span + 2) / 2]
                                       for _ in range(2))
    return case


def candidates(case: dict) -> Iterator[dict]:
    """Smaller variants of ``case``: a run of points, holes or operations dropped, halves first
    and single elements last (so a long failing input shrinks in few rounds)."""
    for key in ("points", "holes", "operations"):
        items = case.get(key)
        if not isinstance(items, list) or len(items) <= (1 if key == "points" else 0):
            continue
        size = len(items) // 2
        while size >= 1:
            for i in range(0, len(items), size):
                rest = items[:i] + items[i + size:]
                if rest or key != "points":
                    yield {**case, key: rest}
            size //= 2


class _Runner:
    """Judges lists of cases with the submission, many per sandboxed run, and confirms each
    failure by judging its input again alone; nothing starts after the deadline."""

    def __init__(self, problem: Problem, path: Path, deadline: float, stats: Stats,
                 exclude: frozenset[str] = frozenset(), verdicts: frozenset[Verdict] | None = None,
                 max_chars: int | None = None, trusted: bool | None = None):
        problem = copy.copy(problem)               # the caller's problem keeps its tests
        problem.__dict__["_tests"] = []            # no hidden tests: ours are set per batch
        self.problem = problem
        self.judge = Judge(problem, hide=[str(path.resolve().parent)], stop_at_first_failure=True,
                           stderr_lines=STDERR_LINES, trusted=trusted)
        self.judge.keep_build = True  # a compiled submission is compiled once for the whole search
        self.sub = Submission.from_path(path, follow_links=True)
        self.deadline = deadline
        self.stats = stats
        self.exclude = exclude  #: normalized inputs never judged (:func:`normalized`)
        self.verdicts = verdicts  #: the failures to report (None: every failure but TLE)
        self.max_chars = max_chars  #: inputs longer than this are never judged (None: any length)

    def _judge(self, tests: list[TestCase]) -> list[TestResult]:
        """Judge ``tests`` in one sandboxed run (one idle budget; none starts after the deadline)."""
        j = self.judge
        j.use_tests(tests)
        return j.judge(self.sub, str(self.sub.filename), deadline=self.deadline).tests

    def _alone(self, test: TestCase) -> TestResult | None:
        """``test`` judged on its own, with the problem's per-test limits and a fresh sandbox and
        idle budget: its result when it fails there too (not by time alone), else None, counted."""
        if time.monotonic() >= self.deadline:
            self.stats.unconfirmed += 1
            return None
        return self._counted(self._judge([test])[0])

    def _counted(self, r: TestResult) -> TestResult | None:
        """``r`` (a result judged alone) when it is a failure to report; else None, counted."""
        if r.verdict == Verdict.SKIPPED:
            self.stats.unconfirmed += 1
        elif r.verdict in (Verdict.AC, Verdict.JE):
            self.stats.flukes += 1
        elif r.verdict == Verdict.TLE:
            self.stats.slow += 1       # slow, not wrong: never a counterexample
        elif self.verdicts is not None and r.verdict not in self.verdicts:
            self.stats.other += 1
        else:
            return r
        return None

    def first_failure(self, cases: list[dict]) -> tuple[dict, TestCase, TestResult] | None:
        """The first of ``cases`` (in order) that fails when judged alone, or None when none does
        before the deadline. A failure seen in a batch that does not happen again alone is a fluke
        (batching: one idle budget, one worker process, a loaded machine): the batch goes on after it."""
        tests: list[tuple[dict, TestCase]] = []
        for case in cases:
            if time.monotonic() >= self.deadline:
                break
            t = _test(self.problem, case, f"stress/{self.stats.tried + len(tests) + 1}")
            if t is not None and ((self.max_chars is not None and len(t.input_text) > self.max_chars)
                                  or (self.exclude and normalized(t.input_text) in self.exclude)):
                self.stats.excluded += 1
            elif t is not None:
                tests.append((case, t))
        while tests and time.monotonic() < self.deadline:
            results = self._judge([t for _, t in tests])
            bad = next((k for k, r in enumerate(results) if r.verdict not in _PASSING), None)
            self.stats.tried += sum(r.verdict != Verdict.SKIPPED for r in results[:None if bad is None else bad + 1])
            if bad is None:
                return None
            case, test = tests[bad]
            # the first test of a run was judged alone already (a fresh sandbox, worker and budget)
            alone = self._counted(results[0]) if bad == 0 else self._alone(test)
            if alone is not None:
                return case, test, alone
            tests = tests[bad + 1:]
        return None


def stress(problem_id: str | Problem, path: str | Path, seconds: float = 10.0, seed: int = 1,
           log: Callable[[str], None] = lambda s: None, stats: Stats | None = None,
           first: list[dict] | None = None, exclude: Collection[str] = (),
           verdicts: Collection[Verdict] | None = None, max_chars: int | None = None,
           trusted: bool | None = None, build_from: Judge | None = None,
           build_store: str | None = None) -> Failure | None:
    """Search for a failing input of ``path`` on ``problem_id`` (an id or a loaded problem) for
    ``seconds``; the smallest failure found that fails alone too (shrunk as far as the time
    allows), or None. Ends within ``seconds`` plus one test's limits. ``stats`` (if given) receives
    the counts of the search: inputs judged, flukes, inputs only slow, failures left unconfirmed.

    The engine of :mod:`grader.contest.counterexample` too: ``first`` replaces the first cases
    (default :func:`_first_cases`), an input whose :func:`normalized` text is in ``exclude`` is
    never judged (nor reported, nor kept while shrinking), nor one longer than ``max_chars``
    characters, and with ``verdicts`` only a failure with one of them counts (TLE never does).
    ``trusted``: as :class:`grader.contest.judge.Judge`'s. A compiled submission is compiled
    once, before the clock starts (the build is not the search's time), or not at all when
    ``build_from`` (a judge that kept its build of the same file, :attr:`Judge.keep_build`)
    hands its build over (:meth:`Judge.adopt_build`), or ``build_store`` holds one
    (:meth:`Judge.store_build`: a judge of another process left it there)."""
    problem = load_problem(problem_id) if isinstance(problem_id, str) else problem_id
    if problem.generator_path is None or not problem.generator_path.is_file():
        raise ValueError(f"problem {problem.id!r}: stress needs the problem's generator (the reference answers)")
    path = Path(path)
    if not path.is_file():
        raise ValueError(f"submission file {path} does not exist")
    stats = stats if stats is not None else Stats()
    runner = _Runner(problem, path, time.monotonic() + seconds, stats, frozenset(exclude),
                     None if verdicts is None else frozenset(verdicts), max_chars, trusted)
    try:
        if runner.sub.compiled:
            runner.judge.build_store = build_store
            if build_from is not None:
                runner.judge.adopt_build(build_from)
            runner.judge.compiled(runner.sub)   # reused when adopted; a compile error is judged CE below
        runner.deadline = deadline = time.monotonic() + seconds
        return _search(problem, runner, stats, deadline, seed, log, first)
    finally:
        runner.judge.drop_build()


def _search(problem: Problem, runner: _Runner, stats: Stats, deadline: float, seed: int,
            log: Callable[[str], None], first: list[dict] | None = None) -> Failure | None:
    """The search of :func:`stress` with its runner."""
    rng = random.Random(seed)
    pending = _first_cases(problem) if first is None else list(first)
    found = None
    size = 2
    while found is None and time.monotonic() < deadline:
        if not pending:  # the lattice is done: random inputs, growing
            pending = [random_case(problem.id, rng, size) for _ in range(BATCH)]
            size = min(size + 1, 40)
        batch, pending = pending[:BATCH], pending[BATCH:]
        found = runner.first_failure(batch)
    if found is None:
        return None
    case, test, result = found
    log(f"failure after {stats.tried} inputs (confirmed alone); shrinking")
    shrunk = True
    while True:
        smaller = runner.first_failure(list(candidates(case)))
        if smaller is None:
            shrunk = time.monotonic() < deadline   # else the deadline cut the last round
            break
        case, test, result = smaller
    return Failure(case, test.input_text, str(result.verdict), result.message, stats.tried, stderr=result.stderr,
                   shrunk=shrunk, flukes=stats.flukes, slow=stats.slow, answer=result.answer)


def _first_cases(problem: Problem) -> list[dict]:
    """The first inputs to try: the problem's ``exhaustive`` group (with its hand-made cases), else
    :func:`grader.problems.smallcases.cases_for` the problem, else none (random inputs at once)."""
    group = [g.cases for g in problem.groups if g.name == "exhaustive"]
    if group:
        return list(group[0])
    try:
        return smallcases.cases_for(problem.id)
    except ValueError:  # a problem smallcases does not know (a course's own, a test fixture)
        return []


def notes(stats: Stats, failure: Failure | None) -> list[str]:
    """What the search saw but did not report, one line each (flukes, slow inputs, a cut shrink)."""
    out = []
    if failure is not None and not failure.shrunk:
        out.append("note: the time ran out while shrinking: a smaller failing input may exist (more --seconds)")
    if stats.flukes:
        out.append(f"note: {stats.flukes} failure(s) seen in a batch of inputs did not happen again when the input "
                   "was judged alone (not reported)")
    if stats.slow:
        out.append(f"note: {stats.slow} input(s) went over the time limit when judged alone: slow, not wrong, so "
                   "not a counterexample (python -m grader judge reports TLE)")
    if stats.unconfirmed:
        out.append(f"note: {stats.unconfirmed} failure(s) seen at the end of the time could not be judged alone "
                   "(not reported; more --seconds)")
    return out


def main(problem_id: str | Problem, file: str, seconds: float) -> int:
    """The ``stress`` command: print the smallest failing input (exit 1) or that none was found."""
    t0 = time.monotonic()
    stats = Stats()
    failure = stress(problem_id, file, seconds, log=lambda s: print(s, file=sys.stderr), stats=stats)
    if failure is None:
        print(f"no failing input found in {time.monotonic() - t0:.1f} s ({stats.tried} inputs judged)")
        for line in notes(stats, None):
            print(line)
        return 0
    print(f"{failure.verdict} on this input (found and shrunk in {time.monotonic() - t0:.1f} s, "
          f"{failure.tried} inputs judged):\n")
    print(failure.input_text.rstrip("\n"))
    print(f"\n{failure.verdict}: {failure.message}")
    if failure.stderr:
        print(f"--- its stderr (last lines) ---\n{failure.stderr}")
    for line in notes(stats, failure):
        print(line)
    return 1
