"""Judging one submission on one problem: run every test in the sandbox, check, give verdicts.

Function mode keeps one worker process for all tests (restarted after a crash or timeout);
stdio mode starts one process per test. The checker runs here, in the grader's process, on data
that crossed the boundary as JSON (function mode) or text (stdio mode) and was type-checked
first. Within a group, tests after the first failure are skipped (the group scores 0 anyway).

Example:
    >>> from grader import judge_file
    >>> judge_file("delaunay", "solutions/delaunay/accepted_walk.py").verdict   # doctest: +SKIP
    'AC'
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import os
import shutil
import stat
import sys
import time
import traceback
import weakref
from pathlib import Path
from typing import Callable, Sequence

from ..judging import hidden_feedback
from ..judging.check_budget import CheckTimeout, check_seconds, cpu_budget
from ..judging.frames import FloatRows
from ..judging.compile import BINARY_NAME, COMPILE_LIMITS, COMPILE_WALL_S, CompileResult, build_dir, compile_source
from ..problems import Problem, TestCase, load_problem
from ..judging.program_server import run_compiled
from ..judging.runner import FunctionWorker, RunOutcome, idle_budget_for, output_paths, run_stdio
from ..jail import Limits, Sandbox
from ..judging.submissions import Submission, SubmissionError
from ..judging.text import clean, last_lines
from ..judging.verdicts import JudgeResult, TestResult, Verdict

PREVIEW_MAX_LINES = 24
PRINTED_MAX_BYTES = 2000  #: function mode: a failing test's print() output shown up to this many bytes
ANSWER_MAX_CHARS = 4000  #: a failing test's answer (``TestResult.answer``) kept up to this many characters
_CE_TYPES = {"SyntaxError", "IndentationError", "TabError", "ImportError", "ModuleNotFoundError", "MissingEntry"}
_cover_cache: dict[tuple[str, ...], list[str]] = {}


def installed_paths(modules: Sequence[str]) -> list[str]:
    """Directories/files of installed forbidden modules (found on sys.path without importing them)."""
    key = tuple(modules)
    if key not in _cover_cache:
        found = []
        for mod in modules:
            parts = mod.split(".")
            for base in sys.path:
                if not base or not os.path.isdir(base):
                    continue
                stem = os.path.join(base, *parts)
                if os.path.isdir(stem):
                    found.append(stem)
                elif os.path.isfile(stem + ".py"):
                    found.append(stem + ".py")
                else:
                    parent = os.path.dirname(stem)
                    if os.path.isdir(parent):
                        found += [os.path.join(parent, f) for f in os.listdir(parent)
                                  if f.startswith(parts[-1] + ".") and f.endswith(".so")]
        _cover_cache[key] = found
    return _cover_cache[key]


def preview(test: TestCase) -> str:
    """The test's input for the student when it is small enough to read."""
    lines = test.input_text.splitlines()
    return test.input_text if len(lines) <= PREVIEW_MAX_LINES else ""


def _file_size(path: str) -> int:
    try:
        return os.path.getsize(path)
    except OSError:
        return 0


def _printed_since(path: str, offset: int) -> tuple[str, int]:
    """What the function-mode worker printed to stdout after ``offset`` (capped), and the new size."""
    size = _file_size(path)
    if size < offset:  # the worker was restarted: its stdout file starts over
        offset = 0
    if size == offset:
        return "", size
    with open(path, "rb") as f:
        f.seek(offset)
        data = f.read(PRINTED_MAX_BYTES + 1)
    text = data[:PRINTED_MAX_BYTES].decode("utf-8", "replace")
    text = "".join(c if c.isprintable() or c in "\n\t" else "?" for c in text)
    if len(data) > PRINTED_MAX_BYTES:
        text += f"\n... ({size - offset - PRINTED_MAX_BYTES} more bytes not shown)"
    return text, size


def _stderr_since(path: str, offset: int, lines: int) -> str:
    """The last ``lines`` lines the submission wrote to its stderr file after ``offset``, made safe."""
    size = _file_size(path)
    if size < offset:  # the worker was restarted: its stderr file starts over
        offset = 0
    if size == offset:
        return ""
    with open(path, "rb") as f:
        f.seek(max(offset, size - 16384))
        data = f.read()
    return last_lines(data, lines)


def _verdict_for(outcome: RunOutcome) -> tuple[Verdict, str]:
    where = ("\n  " + "\n  ".join(outcome.where)) if outcome.where else ""
    status = outcome.status
    if status == "violation":
        return Verdict.SV, outcome.message
    if status == "timeout":
        return Verdict.TLE, outcome.message
    if status == "memory":
        return Verdict.MLE, (outcome.message or "MemoryError") + where
    if status == "output_limit":
        return Verdict.OLE, outcome.message
    if status == "bad_type":
        return Verdict.PE, outcome.message
    if status == "load_error":
        kind = outcome.message.split(":", 1)[0]
        verdict = Verdict.CE if kind in _CE_TYPES or outcome.message.startswith("no function") else Verdict.RE
        return verdict, outcome.message + where
    if status in ("error", "crash"):
        return Verdict.RE, outcome.message + where
    return Verdict.JE, f"unexpected run status {status!r}"


class Judge:
    """Judges submissions for one problem; reusable (keeps the parsed tests)."""

    def __init__(self, problem: Problem | str, hide: Sequence[str | os.PathLike] = (), stop_at_first_failure: bool = False,
                 trusted: bool | None = None, stderr_lines: int = 0, compile_limits: Limits | None = None):
        """``trusted``: where no kernel jail can be built, judge without one instead of raising
        :class:`grader.jail.JailUnavailable` (a student's own code; default ``$GRADER_TRUSTED``).
        ``stderr_lines``: a failing test keeps the last that many lines of the submission's stderr
        in ``TestResult.stderr`` (0: none). ``compile_limits``: the compile step's limits for a
        compiled language (default :data:`grader.judging.compile.COMPILE_LIMITS`; its wall-clock
        cap is :data:`grader.judging.compile.COMPILE_WALL_S`, or twice the CPU time if longer)."""
        self.stderr_lines = stderr_lines
        self.compile_limits = compile_limits or COMPILE_LIMITS
        self._build: tuple[tuple[str, str], CompileResult, weakref.finalize] | None = None
        #: keep the last build between judgings (``stress`` judges one submission many times; it
        #: calls :meth:`drop_build` when done); otherwise the binary is removed after each judging
        self.keep_build = False
        #: a private folder of the grader (mode 0700) where :meth:`store_build` leaves a build for a
        #: later judge of the same source in another process (a class's counterexample searches),
        #: and where :meth:`compiled` takes one from (None: no such folder)
        self.build_store: str | None = None
        self.problem = load_problem(problem) if isinstance(problem, str) else problem
        self.trusted = trusted
        self.stop_at_first_failure = stop_at_first_failure
        self.hide = list(hide)
        self.tests = self.problem.tests()
        self.limits = Limits(cpu_s=self.problem.time_limit, memory_mb=self.problem.memory_mb, output_mb=self.problem.output_mb)
        self.check_cpu_s = check_seconds(self.problem.time_limit)  #: CPU budget of one check (grader.judging.check_budget)
        self.cover = installed_paths([m for m in self.problem.forbidden if m not in ("reference_impl", "grader")])
        self._args = [None] * len(self.tests)
        self._answers = [None] * len(self.tests)
        self._encoded: dict[int, tuple[TestCase, str]] = {}

    def _test_data(self, k: int):
        if self._args[k] is None:
            chk, t = self.problem.checker, self.tests[k]
            self._args[k] = chk.read_input(t.input_text)
            self._answers[k] = self.problem.read_answer(t, self._args[k])
        return self._args[k], self._answers[k]

    def use_tests(self, tests: list[TestCase]) -> None:
        """Judge ``tests`` from now on (stress and the counterexample search set a batch at a time)."""
        self.tests, self._args, self._answers = tests, [None] * len(tests), [None] * len(tests)
        self._encoded = {}

    def _args_json(self, k: int) -> str:
        """Test ``k``'s arguments encoded for the child once per judge (it judges many submissions).
        The encoding is kept with the test it was made from and used only for that same test:
        ``self.tests`` may be replaced (:meth:`use_tests`, or by hand), and a stale encoding would
        send another test's input."""
        kept = self._encoded.get(k)
        if kept is None or kept[0] is not self.tests[k]:
            kept = self._encoded[k] = (self.tests[k], json.dumps(self._test_data(k)[0], allow_nan=True,
                                                                 separators=(",", ":")))
        return kept[1]

    def judge_path(self, path: str | Path, on_test: Callable[[TestResult], None] | None = None,
                   prior: dict[str, TestResult] | None = None, follow_links: bool = False) -> JudgeResult:
        """Judge the file at ``path``; a symbolic link is CE unless ``follow_links`` (a file the
        caller named itself, not one found in a class folder)."""
        try:
            sub = Submission.from_path(path, follow_links=follow_links)
        except SubmissionError as exc:
            return self._all(str(path), Verdict.CE, str(exc), "none", on_test)
        return self.judge(sub, str(path), on_test, prior)

    def _all(self, name: str, verdict: Verdict, message: str, mode: str,
             on_test: Callable[[TestResult], None] | None = None) -> JudgeResult:
        tests = []
        message = clean(message, 4000, newlines=True)
        for t in self.tests:
            r = TestResult(t.name, t.group, verdict, 0.0, 0.0, message)
            tests.append(r)
            if on_test:
                on_test(r)
        return JudgeResult(self.problem.id, name, tests, self.problem.group_points, mode=mode)

    def judge(self, sub: Submission, name: str = "submission.py",
              on_test: Callable[[TestResult], None] | None = None,
              prior: dict[str, TestResult] | None = None, deadline: float | None = None) -> JudgeResult:
        """Judge ``sub``; ``on_test`` is called after each newly run test; tests in ``prior`` (results
        already stored by an interrupted batch) are reused, not run again. No test starts after
        ``deadline`` (a ``time.monotonic()`` value): the rest are skipped."""
        prior = prior or {}
        t0 = time.monotonic()
        syntax = sub.syntax_error()
        if syntax:
            return self._all(name, Verdict.CE, syntax, "none", on_test)
        mode = sub.mode(self.problem.entry)
        if mode == "missing":
            return self._all(name, Verdict.CE, sub.missing_entry_message(self.problem.entry), mode, on_test)
        if not sub.compiled or all(t.name in prior for t in self.tests):
            return self._judge(sub, name, mode, t0, on_test, prior, deadline)
        try:
            built = self.compiled(sub)  # a compiled language: compiled once, before any test
            if not built.ok:
                result = self._all(name, Verdict.CE, built.message, mode, on_test)
                result.judge_time_s = time.monotonic() - t0
                return result
            return self._judge(sub, name, mode, t0, on_test, prior, deadline, built.binary)
        finally:
            if not self.keep_build:
                self.drop_build()

    def drop_build(self) -> None:
        """Remove the kept build (the binary of the last compiled submission), if any."""
        if self._build is not None:
            self._build[2]()
            self._build = None

    def adopt_build(self, other: "Judge") -> None:
        """Take ``other``'s kept build (see :attr:`keep_build`): this judge reuses it for the same
        source instead of compiling again, and removes it when done; ``other`` keeps none."""
        if other._build is not None:
            self.drop_build()
            self._build, other._build = other._build, None

    def store_build(self) -> bool:
        """Move the kept build's binary (a successful compile) into :attr:`build_store`, named after
        its source's hash, for a later judge of the same source (:meth:`compiled` takes it from
        there); the build is dropped either way. False when nothing was stored."""
        build, self._build = self._build, None
        if build is None:
            return False
        try:
            (lang, digest), built, done = build
            if not (self.build_store and built.ok and os.path.isfile(built.binary)):
                return False
            stored = os.path.join(self.build_store, f"{lang}-{digest}")
            shutil.move(built.binary, stored + ".part")
            os.replace(stored + ".part", stored)
            return True
        finally:
            build[2]()

    def _stored_build(self, key: tuple[str, str]) -> CompileResult | None:
        """The build :meth:`store_build` left in :attr:`build_store` for ``key``, moved into a folder
        of this judge's own (taken once), or None."""
        if not self.build_store:
            return None
        stored = os.path.join(self.build_store, f"{key[0]}-{key[1]}")
        try:
            st = os.lstat(stored)
        except OSError:
            return None
        if not stat.S_ISREG(st.st_mode) or st.st_uid != os.geteuid():
            return None
        folder = build_dir()
        binary = os.path.join(folder, BINARY_NAME)
        try:
            os.replace(stored, binary)
        except OSError:  # another process took it first, or another file system: compile again
            shutil.rmtree(folder, ignore_errors=True)
            return None
        done = weakref.finalize(self, _remove_build, folder, os.getpid())
        self._build = (key, CompileResult(ok=True, binary=binary), done)
        return self._build[1]

    def compiled(self, sub: Submission) -> CompileResult:
        """``sub`` compiled in the compile jail; the build is kept until :meth:`drop_build`, the next
        build or the end of this judge (with :attr:`keep_build`, ``stress`` compiles once). A build
        of the same source left in :attr:`build_store` is taken instead of compiling again."""
        key = (sub.language.name, hashlib.sha256(sub.source.encode("utf-8", "surrogatepass")).hexdigest())
        if self._build is not None and self._build[0] == key:
            return self._build[1]
        self.drop_build()
        stored = self._stored_build(key)
        if stored is not None:
            return stored
        folder = build_dir()
        done = weakref.finalize(self, _remove_build, folder, os.getpid())
        built = compile_source(sub.source, sub.language, folder, hide=self.hide, trusted=self.trusted,
                               limits=self.compile_limits, wall_s=max(COMPILE_WALL_S, 2 * self.compile_limits.cpu_s))
        self._build = (key, built, done)
        return built

    def _judge(self, sub: Submission, name: str, mode: str, t0: float, on_test: Callable[[TestResult], None] | None,
               prior: dict[str, TestResult], deadline: float | None, binary: str = "") -> JudgeResult:
        """The loop over the tests (``binary``: a compiled submission's program, run per test)."""
        time_limit = self.problem.time_limit_for(sub.language.name)
        limits = dataclasses.replace(self.limits, cpu_s=time_limit)
        results: list[TestResult] = []
        failed_groups: set[str] = set()
        load_failure: tuple[Verdict, str] | None = None
        idle_left = idle_budget_for(time_limit)
        with Sandbox(limits, hide=self.hide, cover=self.cover, trusted=self.trusted, program=binary or None,
                     no_processes=True if binary else None) as box:
            worker = None
            if mode == "function":
                budget = self.problem.time_limit * len(self.tests) + 30
                worker = FunctionWorker(box, sub.source, self.problem.entry, self.problem.forbidden,
                                        filename=sub.filename, total_cpu_s=budget,
                                        frames=callable(getattr(self.problem.checker, "from_arrays", None)))
            try:
                for k, test in enumerate(self.tests):
                    if test.name in prior:
                        r = prior[test.name]
                        if r.verdict not in (Verdict.AC, Verdict.SKIPPED):
                            failed_groups.add(test.group)
                        results.append(r)
                        continue
                    if load_failure is not None:
                        r = TestResult(test.name, test.group, load_failure[0], 0.0, 0.0, load_failure[1])
                    elif test.group in failed_groups or (failed_groups and self.stop_at_first_failure):
                        r = TestResult(test.name, test.group, Verdict.SKIPPED, message="an earlier test of this group failed")
                    elif deadline is not None and time.monotonic() >= deadline:
                        r = TestResult(test.name, test.group, Verdict.SKIPPED, message="not run: the time given ran out")
                    else:
                        r, idle = self._run_one(box, worker, sub, k, idle_left, time_limit, bool(binary))
                        idle_left -= idle
                        if worker is not None and worker.load_failure is not None and r.verdict in (Verdict.CE, Verdict.SV):
                            load_failure = (r.verdict, r.message)
                    if r.verdict not in (Verdict.AC, Verdict.SKIPPED):
                        failed_groups.add(test.group)
                    results.append(r)
                    if on_test:
                        on_test(r)
            finally:
                if worker is not None:
                    worker.stop()
        result = JudgeResult(self.problem.id, name, results, self.problem.group_points, mode=mode)
        result.judge_time_s = time.monotonic() - t0
        return result

    def _check(self, r: TestResult, value, args, expected, function_mode: bool) -> None:
        """Type-check and check one answer into ``r``, under a CPU budget of its own
        (:mod:`grader.judging.check_budget`): a check that runs too long is ``TLE``, never a hung grader.
        A binary frame (:class:`FloatRows`) goes to the checker's ``from_arrays``; a wrong answer's
        ``received`` is the checker's reading of the same value as lists, as without frames."""
        chk = self.problem.checker
        budget = self.check_cpu_s
        framed = function_mode and isinstance(value, FloatRows)
        try:
            with cpu_budget(budget):
                try:
                    if framed:
                        answer = chk.from_arrays(value, args)
                    else:
                        answer = chk.from_result(value, args) if function_mode else chk.read_output(value, args)
                except chk.PresentationError as exc:
                    r.verdict, r.message = Verdict.PE, str(exc)
                    r.hidden_message = hidden_feedback.for_checker("PE", exc)
                    return
                except getattr(chk, "WrongAnswer", ()) as exc:  # optional: wrong before any real check
                    r.verdict, r.message = Verdict.WA, str(exc)
                    r.hidden_message = hidden_feedback.for_checker("WA", exc)
                    return
                ok, message = chk.check(args, answer, expected)
                if framed and not ok:
                    answer = chk.from_result(value.tolist(), args)
        except CheckTimeout:
            r.verdict = Verdict.TLE
            r.message = (f"checking your answer took more than {budget:g} s of the grader's CPU time: the answer "
                         "is far larger, or far harder to check, than a correct one")
            r.hidden_message = "time limit exceeded: checking the answer took too long"
            return
        r.verdict, r.message = (Verdict.AC, "") if ok else (Verdict.WA, message)
        if not ok:
            r.received = answer
            r.hidden_message = hidden_feedback.for_checker("WA", message)

    def _answer_text(self, value, parsed, function_mode: bool) -> str:
        """A failing answer as the problem's output text (stdio: as printed; function mode: the
        parsed answer written by the checker's ``write_output``, else the value as JSON), capped.
        A function's ``None`` is an answer too (navmesh: no path): written by ``write_output``."""
        if not function_mode:
            text = value if isinstance(value, str) else str(value)
        else:
            text = ""
            if parsed is not None or value is None:
                try:
                    with cpu_budget(self.check_cpu_s):
                        text = self.problem.checker.write_output(parsed)
                except Exception:  # noqa: BLE001 - a shape write_output does not take: JSON below
                    text = ""
            if not text:
                try:
                    text = json.dumps(value)
                except (TypeError, ValueError):
                    text = repr(value)
        if len(text) > ANSWER_MAX_CHARS:
            text = text[:ANSWER_MAX_CHARS] + f"\n... ({len(text) - ANSWER_MAX_CHARS} more characters not shown)"
        return clean(text, ANSWER_MAX_CHARS + 80, newlines=True)

    def _run_one(self, box: Sandbox, worker: FunctionWorker | None, sub: Submission, k: int,
                 idle_left: float, time_limit: float | None = None, program: bool = False) -> tuple[TestResult, float]:
        """One test's result and the wall time the submission spent not computing in it
        (``time_limit``: the language's, default the problem's; ``program``: run the sandbox's binary)."""
        time_limit = self.problem.time_limit if time_limit is None else time_limit
        test = self.tests[k]
        idle = 0.0
        before = err_before = 0
        err_path = worker.out_paths[1] if worker is not None else output_paths(box)[1]
        try:
            args, expected = self._test_data(k)
            if worker is not None:
                before = _file_size(worker.out_paths[0])
                err_before = _file_size(err_path)
                outcome = worker.call(args, time_limit, idle_left=idle_left, args_json=self._args_json(k))
            elif program:  # one jail per submission, a fresh process per test
                outcome = run_compiled(box, test.input_text, time_limit, self.problem.forbidden,
                                       filename=sub.filename, idle_left=idle_left)
            else:
                outcome = run_stdio(box, sub.source, test.input_text, time_limit, self.problem.forbidden,
                                    filename=sub.filename, idle_left=idle_left)
            idle = outcome.idle_s
            r = TestResult(test.name, test.group, Verdict.JE, outcome.time_s, round(outcome.memory_mb, 1))
            if outcome.status == "ok":
                self._check(r, outcome.value, args, expected, function_mode=worker is not None)
                if r.verdict != Verdict.AC:
                    value = outcome.value.tolist() if isinstance(outcome.value, FloatRows) else outcome.value
                    r.answer = self._answer_text(value, r.received, function_mode=worker is not None)
            else:
                r.verdict, r.message = _verdict_for(outcome)
                r.hidden_message = hidden_feedback.for_run(str(r.verdict), outcome.message, outcome.where,
                                                           len(sub.source.splitlines()))
        except Exception as exc:  # noqa: BLE001 - only the judge's own code runs here
            r = TestResult(test.name, test.group, Verdict.JE, 0.0, 0.0,
                           f"judge error: {type(exc).__name__}: {exc}\n{traceback.format_exc(limit=3)}")
            r.hidden_message = "judge error"
        if r.verdict not in (Verdict.AC, Verdict.SKIPPED):
            r.input_preview = preview(test)
            if worker is not None and r.verdict != Verdict.JE:
                printed, _ = _printed_since(worker.out_paths[0], before)
                if printed.strip():
                    r.message += f"\n--- your print() output in this test ---\n{printed}"
            if self.stderr_lines and r.verdict != Verdict.JE:
                r.stderr = _stderr_since(err_path, err_before, self.stderr_lines)
        r.message = clean(r.message, 4000, newlines=True)  # checker messages quote student data
        r.hidden_message = clean(r.hidden_message, 300)
        return r, idle


def _remove_build(folder: str, owner: int) -> None:
    """Remove a build folder, in the process that made it only (a forked worker leaves it)."""
    if os.getpid() == owner:
        shutil.rmtree(folder, ignore_errors=True)


def judge_file(problem: str | Problem, path: str | Path, hide: Sequence[str] = ()) -> JudgeResult:
    """Judge one file (``.py``, ``.ipynb`` or C++) on one problem.

    >>> judge_file("delaunay", "solutions/delaunay/accepted_walk.py").score   # doctest: +SKIP
    100
    """
    path = Path(path)
    return Judge(problem, hide=[*hide, str(path.resolve().parent)]).judge_path(path, follow_links=True)
