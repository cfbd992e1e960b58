"""Benchmark of the judge's own cost when grading a class: where the CPU goes beyond the students' code.

For each problem (and language: ``python`` now; a language is a parameter, C++ joins once
``solutions/<id>/`` holds an accepted ``.cpp``) a class of ``--students`` copies of the problem's
accepted solution (``solutions/<id>/expected.yaml``: the first file marked ``AC``; each copy gets
one comment line so no two are identical) is graded in ONE run of
``python -m grader grade <id> <class> --jobs 1``. Printed per student:

* ``total``: CPU of the grader and everything it starts (pool worker, bubblewrap, the sandboxed
  child, helpers), counted from outside: the grade process is put in a fresh cgroup of its own
  (v1 ``cpuacct.usage``, else v2 ``cpu.stat``; the jail makes its groups below the caller's, so
  they are included). Where no cgroup can be made (an ordinary account) the process tree below
  this process is sampled from ``/proc`` every 20 ms and each process's last-seen utime+stime is
  summed (a lower bound, in 10 ms ticks; this process is made the subreaper of orphans so none
  leaves the tree). ``getrusage(RUSAGE_CHILDREN)`` is no substitute: the sandboxed child dies with
  its pid namespace and the kernel reaps it without passing its times to any parent (it is
  printed beside, as ``rusage``). The method used is printed.
  A student's share is the CPU between the stderr progress lines that ``grade`` prints when a
  student is done (``--jobs 1``: one student at a time), sampled when each line arrives.
* ``own``: the student's own CPU, the sum of the tests' ``time_s`` read back from the results
  store (SQLite table ``results``). It includes the child's decoding of the arguments and
  encoding of the answer (the jail measures the call as a whole).
* ``overhead = total - own`` (for a compiled language ``- compile``: the judge's compile is in
  the student's total; the compile line's figure, measured outside the jail, is subtracted),
  ``ratio = overhead / own``, and wall time (noisy under load).

Where the overhead goes (per problem, a later student, i.e. the mean of students 2..n):

* ``jail+child start``: the fixed cost of one submission (jail, a child interpreter with the
  bootstrap, the worker), and ``per-test fixed``: the fixed cost of a test (pipe round trip,
  a tiny check, a SQLite commit), both measured by difference from two classes of EMPTY-work
  submissions: ``def delaunay(points): return []`` on a 1-test and a 30-test problem of collinear
  points (``[]`` is the right answer there, so every test is AC at once and no failure path
  runs); they borrow the ``delaunay`` checker, in problem packages made in a temporary
  ``$GRADER_PROBLEMS``.
* ``imports``: the child importing the solution's modules: ``python -I`` running the solution's
  top level (``runpy``, not as ``__main__``) minus ``python -I -c pass``, measured outside the jail.
* ``transport``: the parent's side of moving inputs and answers: ``json.dumps`` of each call and
  ``json.loads`` of each reply, replayed on the reference answers (measured); where the checker
  reads binary frames (``from_arrays``), a long float answer's reply is a frame, decoded.
* ``checker``: ``from_result`` (or ``from_arrays``) + ``check`` of the problem's checker on the reference answers,
  replayed through the public API (``load_problem(id).checker``; measured). Both replays run in
  a fresh process that, like the judge, keeps every test's arguments (median of ``--repeat``).
* ``rest``: overhead minus the parts above (by difference): bookkeeping (store, progress),
  accounting, whatever the replay does not see; noise makes it negative at times.

Per grade run: ``start-up`` (CPU before the first progress line: interpreter, imports, loading
the problem, discovering the class, loading the tests), ``1st extra`` (student 1 minus a later
student: the pool worker's Judge reading and parsing every test, first-time costs) and ``tail``
(after the last line: exit). Separately, one judge command's start-up alone: ``python -c pass``,
``python -c 'import grader'``, ``load_problem(id)`` in-process, ``python -m grader list``, and
one whole ``python -m grader judge`` of the 30-test empty-work submission (the course's target:
under 1.5 s of judge overhead for 30 function-mode tests). C++: a compile line of its own,
not counted in the ratio (the judge compiles in its jail; the line times the same command outside it).

Run (as root or as an ordinary user; the worktree's code via PYTHONPATH):
    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_judge_overhead.py [--students 3]
        [--problems delaunay emst] [--languages python] [--repeat 3] [--quick] [--json out.json]
        [--method auto|cgroup-v1|cgroup-v2|proc] [--startup-only]

``--startup-only`` prints only the start-up table, with two more rows: ``python -m grader judge``
of a submission with a syntax error (``CE`` before any test runs: the command's whole start-up,
problem and tests loaded, no jail) and the notebooks' sample check as its first call in a fresh
process (``judge_samples`` alone: what the verdict table waits for; then with ``picture_png``, of
the delaunay accepted solution; its target is wall time: under 1 s on a quiet machine).

Example (an excerpt of the full run; all of it is in benchmarks/README.md):
    cpu method: cgroup-v1 cpuacct (a fresh group around each command; the jail's groups below it)
    == per student: one grade run per problem, 3 copies of the accepted solution ==
    problem               lang    student  tests  total s  own s  overhead s  ratio  wall s  verdict
    closest-pair          python  s1         199    3.022  1.591       1.431   0.90    5.13       AC
    closest-pair          python  s2         199    2.509  1.582       0.927   0.59    4.53       AC
    ...
    == where a later student's overhead goes (CPU s; mean of students 2..n) ==
    problem   lang    tests  own s  overhead s  jail+child start  imports  per-test fixed  transport  checker    rest  ms/test
    delaunay  python  200    1.599       1.137             0.059    0.000           0.247      0.076    0.914  -0.159      5.7

Prints numbers only; nothing is asserted (tests assert behaviour, not timings). CPU times are the
guide; wall times depend on the machine's load (printed).
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import sqlite3
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, Callable

import yaml

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

from grader import list_problems, load_problem  # noqa: E402
from grader.judging import frames  # noqa: E402
from grader.judging.languages import LANGUAGES as JUDGED, Language  # noqa: E402

CLK_TCK = os.sysconf("SC_CLK_TCK")
# the notebooks' sample check (%check_samples) as its first call in a fresh kernel: judge the samples
# in the jail, then draw the picture (argv[1]: a submission; a notebook is judged the same way)
SAMPLE_CHECK = ("import sys; from pathlib import Path; from grader.contest.sample_check import judge_samples, picture_png; "
                "r, p = judge_samples('delaunay', Path(sys.argv[1])); assert r.verdict == 'AC', r.verdict; "
                "assert picture_png(p, r)")
QUICK_PROBLEMS = ("closest-pair", "largest-empty-circle")
TRIVIAL = "def delaunay(points):\n    return []  # every test is collinear: no triangle is the right answer\n"


#: the languages as the judge lists them (grader.judging.languages), by name
LANGUAGES = {lang.name: lang for lang in JUDGED}


# -- measuring the CPU of a command and everything it starts -------------------------------------
def _own_group(controller: str) -> str:
    """This process's group path in the hierarchy of ``controller`` ('' for cgroup2)."""
    for line in Path("/proc/self/cgroup").read_text().splitlines():
        _, ctrls, path = line.split(":", 2)
        if controller in (ctrls.split(",") if ctrls else [""]):
            return path
    raise OSError(f"no {controller or 'cgroup2'} line in /proc/self/cgroup")


def _mount_of(controller: str) -> Path:
    """Mount point of a v1 controller, or of the cgroup2 hierarchy for ''."""
    for line in Path("/proc/self/mounts").read_text().splitlines():
        _, mnt, fstype, opts = line.split()[:4]
        if controller == "" and fstype == "cgroup2":
            return Path(mnt)
        if controller and fstype == "cgroup" and controller in opts.split(","):
            return Path(mnt)
    raise OSError(f"no {controller or 'cgroup2'} mount")


def _stat(pid: int | str) -> list[str] | None:
    """Fields 3.. of /proc/<pid>/stat (index 1 ppid, 11 utime, 12 stime, 19 starttime), or None."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            raw = f.read()
    except OSError:
        return None
    return raw[raw.rindex(")") + 2:].split()


def _children(pid: int) -> list[int] | None:
    """Children of ``pid`` from /proc/<pid>/task/*/children (None where the kernel lacks that file)."""
    out: list[int] = []
    try:
        tasks = os.listdir(f"/proc/{pid}/task")
    except OSError:
        return []
    for tid in tasks:
        try:
            with open(f"/proc/{pid}/task/{tid}/children") as f:
                out += [int(x) for x in f.read().split()]
        except FileNotFoundError:
            return None
        except OSError:
            continue
    return out


def become_subreaper() -> bool:
    """Make this process the reaper of its orphaned descendants (``PR_SET_CHILD_SUBREAPER``), so a
    process whose parent died (a sandbox torn down with SIGKILL) stays below us in the tree."""
    try:
        import ctypes

        return ctypes.CDLL(None, use_errno=True).prctl(36, 1, 0, 0, 0) == 0  # PR_SET_CHILD_SUBREAPER
    except (OSError, AttributeError):
        return False


def reap(keep: int) -> None:
    """Wait for every exited child of this process except ``keep`` (the command still being read)."""
    while True:
        try:
            info = os.waitid(os.P_ALL, 0, os.WEXITED | os.WNOHANG | os.WNOWAIT)
        except ChildProcessError:
            return
        if info is None or info.si_pid in (0, keep):
            return
        try:
            os.waitpid(info.si_pid, 0)
        except ChildProcessError:
            return


class TreeSampler(threading.Thread):
    """Samples the processes below this one every ``interval`` s and keeps each one's last-seen
    own CPU (utime+stime; keyed by pid and start time). The sum is the tree's CPU, short of what a
    process used after its last sample (a lower bound). Used where no cgroup can be made: there
    ``RUSAGE_CHILDREN`` misses the sandboxed child, which dies with its pid namespace and is
    reaped by the kernel without its times reaching any parent."""

    def __init__(self, interval: float = 0.02):
        super().__init__(daemon=True)
        self.interval, self.seen, self.lock = interval, {}, threading.Lock()
        self.stopping = threading.Event()

    def scan(self) -> float:
        """One sample now; returns the running total (s)."""
        me = os.getpid()
        todo = _children(me)
        if todo is None:  # no children files: scan all of /proc by parent
            by_parent: dict[int, list[int]] = {}
            for d in os.listdir("/proc"):
                st = _stat(d) if d.isdigit() else None
                if st:
                    by_parent.setdefault(int(st[1]), []).append(int(d))
            todo, kids = list(by_parent.get(me, [])), by_parent
        else:
            kids = None
        with self.lock:
            while todo:
                pid = todo.pop()
                st = _stat(pid)
                if st is None:
                    continue
                self.seen[(pid, st[19])] = (int(st[11]) + int(st[12])) / CLK_TCK
                todo += (kids.get(pid, []) if kids is not None else (_children(pid) or []))
            return sum(self.seen.values())

    def run(self) -> None:
        while not self.stopping.wait(self.interval):
            self.scan()

    def stop(self) -> float:
        self.stopping.set()
        self.join()
        return self.scan()


class Meter:
    """Runs commands and measures the CPU of each with everything it starts (see the docstring)."""

    def __init__(self, method: str = "auto"):
        self.method, self._base, self._n = "proc", None, 0
        tries = ["cgroup-v1", "cgroup-v2"] if method == "auto" else [method]
        for m in tries:
            if m == "proc":
                break
            try:
                ctrl = "cpuacct" if m == "cgroup-v1" else ""
                base = _mount_of(ctrl) / _own_group(ctrl).lstrip("/")
                probe = base / f"bench-judge-overhead-{os.getpid()}-probe"
                probe.mkdir()
                ok = (probe / ("cpuacct.usage" if ctrl else "cpu.stat")).exists()
                probe.rmdir()
                if ok:
                    self.method, self._base = m, base
                    break
            except OSError:
                continue
        else:
            if method not in ("auto", "proc"):
                raise SystemExit(f"--method {method}: no writable cgroup here")
        self.subreaper = self.method == "proc" and become_subreaper()

    @property
    def description(self) -> str:
        return {"cgroup-v1": "cgroup-v1 cpuacct (a fresh group around each command; the jail's groups below it)",
                "cgroup-v2": "cgroup-v2 cpu.stat (a fresh group around each command)",
                "proc": "proc: no writable cgroup; the process tree below this one sampled from /proc every "
                        "20 ms, each process's last-seen utime+stime summed (a lower bound: a process's last "
                        "<20 ms is missed), this process the subreaper of orphans" +
                        ("" if self.subreaper else " (WARNING: could not become a subreaper)")}[self.method]

    def _group_cpu(self, group: Path) -> float:
        if self.method == "cgroup-v1":
            return int((group / "cpuacct.usage").read_text()) / 1e9
        stat = dict(line.split() for line in (group / "cpu.stat").read_text().splitlines())
        return int(stat["usage_usec"]) / 1e6

    @staticmethod
    def _remove(group: Path) -> None:
        for d in sorted((p for p in group.rglob("*") if p.is_dir()), key=lambda p: -len(p.parts)):
            try:
                d.rmdir()
            except OSError:
                pass
        try:
            group.rmdir()
        except OSError as exc:
            print(f"warning: could not remove {group}: {exc}", file=sys.stderr)

    def run(self, cmd: list[str], env: dict[str, str] | None = None, cwd: Path = REPO,
            on_line: Callable[[str], bool] | None = None) -> "Measured":
        """Run ``cmd``; ``on_line(stderr_line)`` True marks the line (CPU and wall sampled then)."""
        group = sampler = None
        if self._base is not None:
            self._n += 1
            group = self._base / f"bench-judge-overhead-{os.getpid()}-{self._n}"
            group.mkdir()
        else:
            sampler = TreeSampler()
            sampler.start()
        procs = str(group / "cgroup.procs") if group else None

        def join() -> None:
            if procs:
                with open(procs, "w") as f:
                    f.write(str(os.getpid()))

        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        with tempfile.TemporaryFile() as out:
            proc = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=out, stderr=subprocess.PIPE, text=True,
                                    preexec_fn=join)

            def cpu_now() -> float:
                return self._group_cpu(group) if group else sampler.scan()

            marks, err_lines = [], []
            assert proc.stderr is not None
            for line in proc.stderr:
                err_lines.append(line)
                if on_line and on_line(line):
                    marks.append((line.rstrip("\n"), cpu_now(), time.perf_counter() - t0))
            rc = proc.wait()
            wall = time.perf_counter() - t0
            if sampler is not None:
                cpu = sampler.stop()
                reap(keep=0)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            out.seek(0)
            stdout = out.read().decode("utf-8", "replace")
        reaped = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        if group:
            cpu = self._group_cpu(group)
            self._remove(group)
        return Measured(cmd, rc, cpu, wall, stdout, "".join(err_lines), marks, reaped)


@dataclass
class Measured:
    """One command's result: exit code, CPU (s) of its whole tree, wall (s), output, marks."""

    cmd: list[str]
    rc: int
    cpu: float
    wall: float
    stdout: str
    stderr: str
    marks: list[tuple[str, float, float]]
    reaped: float = 0.0  #: getrusage(RUSAGE_CHILDREN) over the command (misses what dies unreaped)

    def ok(self) -> "Measured":
        if self.rc != 0:
            raise SystemExit(f"command failed ({self.rc}): {' '.join(self.cmd)}\n{self.stderr[-3000:]}")
        return self


def child_env(extra: dict[str, str] | None = None) -> dict[str, str]:
    """The environment for our commands: this checkout's code first on the path."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(REPO), env.get("PYTHONPATH", "")]))
    env.update(extra or {})
    return env


def best(meter: Meter, cmd: list[str], repeat: int, env: dict[str, str] | None = None,
         expect_rc: int = 0) -> dict[str, float]:
    """Median and min CPU and median wall of ``repeat`` runs of ``cmd`` (each must exit ``expect_rc``)."""
    runs = [meter.run(cmd, env or child_env()) for _ in range(repeat)]
    for r in runs:
        if r.rc != expect_rc:
            raise SystemExit(f"{' '.join(cmd)} exited {r.rc}, not {expect_rc}:\n{r.stderr[-3000:]}")
    return {"cpu_median": statistics.median(r.cpu for r in runs), "cpu_min": min(r.cpu for r in runs),
            "wall_median": statistics.median(r.wall for r in runs)}


# -- classes, grading and reading the store ------------------------------------------------------
def accepted_solution(problem: str, lang: Language) -> Path | None:
    """The first file marked AC in ``solutions/<problem>/expected.yaml`` (``expected_cpp.yaml`` for
    a compiled language) with one of the language's suffixes."""
    table = "expected_cpp.yaml" if lang.compile else "expected.yaml"
    path = REPO / "solutions" / problem / table
    expected = (yaml.safe_load(path.read_text()) or {}) if path.is_file() else {}
    for name, verdict in expected.items():
        if str(verdict).split()[0] == "AC" and name.endswith(lang.suffixes) and "/" not in name:
            return REPO / "solutions" / problem / name
    return None


def make_class(root: Path, problem: str, source: str, students: int, lang: Language) -> None:
    """``root/s1..sN/<problem><suffix>``: copies of ``source``, each with its own comment line."""
    comment = "//" if lang.name == "cpp" else "#"
    for k in range(1, students + 1):
        d = root / f"s{k}"
        d.mkdir(parents=True)
        (d / f"{problem}{lang.suffixes[0]}").write_text(f"{source.rstrip()}\n{comment} benchmark copy for student {k}\n")


@dataclass
class StudentRow:
    """One student of one grade run (CPU in seconds)."""

    problem: str
    lang: str
    student: str
    tests: int
    verdict: str
    total: float | None
    own: float
    wall: float | None
    overhead: float | None = None
    ratio: float | None = None

    def __post_init__(self) -> None:
        if self.total is not None:
            self.overhead = self.total - self.own
            self.ratio = self.overhead / self.own if self.own > 0 else None


@dataclass
class RunResult:
    """A whole grade run: its students and the CPU before, between and after them."""

    problem: str
    lang: str
    students: list[StudentRow]
    cpu: float
    wall: float
    startup: float | None
    tail: float | None
    reaped: float = 0.0  #: what getrusage(RUSAGE_CHILDREN) saw of the run (for comparison)
    extra: dict[str, Any] = field(default_factory=dict)


def grade_run(meter: Meter, problem: str, class_dir: Path, db: Path, jobs: int, lang: str,
              env: dict[str, str] | None = None) -> RunResult:
    """Grade ``class_dir`` in one ``grade`` run; per-student CPU from the progress lines."""
    cmd = [sys.executable, "-m", "grader", "grade", problem, str(class_dir), "--db", str(db), "--jobs", str(jobs),
           "--json"]
    m = meter.run(cmd, env or child_env(),
                  on_line=lambda s: s.startswith(f"{problem}: ") and "student folders" in s or s.startswith("graded "))
    m.ok()
    summaries = {s["student"]: s for s in json.loads(m.stdout)}
    with sqlite3.connect(db) as con:
        own = dict(con.execute("SELECT student, SUM(time_s) FROM results WHERE problem=? GROUP BY student",
                               (problem,)).fetchall())
    head = [mk for mk in m.marks if "student folders" in mk[0]]
    done = [mk for mk in m.marks if mk[0].startswith("graded ")]
    per_student = jobs == 1 and len(head) == 1 and len(done) == len(summaries)
    rows, prev = [], (head[0] if head else None)
    for mk in done if per_student else []:
        student = mk[0].split(": ", 1)[1].split()[0]
        s = summaries[student]
        rows.append(StudentRow(problem, lang, student, s["tests"], s["verdict"], mk[1] - prev[1], own.get(student, 0.0),
                               mk[2] - prev[2]))
        prev = mk
    if not per_student:  # overlapping students: only the run's totals mean something
        rows = [StudentRow(problem, lang, st, s["tests"], s["verdict"], None, own.get(st, 0.0), None)
                for st, s in sorted(summaries.items())]
    return RunResult(problem, lang, rows, m.cpu, m.wall, head[0][1] if head else None,
                     (m.cpu - done[-1][1]) if per_student and done else None, m.reaped)


# -- the empty-work problems ---------------------------------------------------------------------
def make_empty_problems(root: Path, sizes: tuple[int, ...]) -> list[str]:
    """Problem packages ``bench-empty-<n>``: n collinear tests of the delaunay checker (``[]`` is AC)."""
    delaunay = load_problem("delaunay")
    chk = delaunay.checker
    ids = []
    for n in sizes:
        p = root / f"bench-empty-{n}"
        data = p / "data" / "all"
        data.mkdir(parents=True)
        (p / "statement").mkdir()
        (p / "statement" / "problem.en.md").write_text("# empty-work benchmark\n")
        (p / "input_validators").mkdir()
        (p / "problem.yaml").write_text("problem_format_version: 2023-07-draft\nname: empty-work benchmark\n"
                                        "limits: {time_limit: 6, memory: 1024, output: 16}\n")
        (p / "course.yaml").write_text(f"entry: delaunay\nforbidden: [scipy.spatial]\nchecker: {delaunay.checker_path}\n"
                                       "groups:\n  - name: all\n    points: 100\n    data: data/all\n")
        for k in range(n):
            pts = [[float(i), float(2 * i + 1)] for i in range(3 + k % 20)]
            (data / f"{k + 1:02d}.in").write_text(chk.write_input([pts]))
            (data / f"{k + 1:02d}.ans").write_text(chk.write_output([]))
        ids.append(p.name)
    return ids


# -- in-process replays: the parent's transport and the checker ------------------------------------
def replay(problem_id: str, repeat: int) -> dict[str, float]:
    """CPU (s) of the parent's per-test work on the reference answers, summed over tests, replayed
    in a fresh process (as the judge, it keeps every test's arguments and answer: the heap's size
    changes the garbage collector's cost); the median of ``repeat`` processes, part by part."""
    runs = []
    for _ in range(repeat):
        run = subprocess.run([sys.executable, __file__, "--replay-one", problem_id], cwd=REPO, env=child_env(),
                             capture_output=True, text=True)
        if run.returncode != 0:
            raise SystemExit(f"replay of {problem_id} failed:\n{run.stderr[-3000:]}")
        runs.append(json.loads(run.stdout))
    return {k: statistics.median(r[k] for r in runs) for k in runs[0]}


def replay_here(problem_id: str) -> dict[str, float]:
    """:func:`replay`'s work, in this process."""
    problem = load_problem(problem_id)
    chk = problem.checker
    parse = transport = checker = 0.0
    bad = 0
    held = []
    tests = problem.tests()
    for k, t in enumerate(tests):
        c0 = time.process_time()
        args = chk.read_input(t.input_text)
        expected = problem.read_answer(t, args)
        held.append((args, expected))
        c1 = time.process_time()
        answer = chk.read_output(t.answer_text, args)
        reply_line = json.dumps({"id": k, "ok": answer}, allow_nan=True, separators=(",", ":"), default=list)
        frame = frames.frame_of(json.loads(reply_line)["ok"]) if hasattr(chk, "from_arrays") else None
        if frame is not None:  # as the child sends it
            reply_line = json.dumps({"id": k, "frame": frame}, separators=(",", ":"))
        c2 = time.process_time()
        call_line = json.dumps({"id": k, "args": args}, allow_nan=True, separators=(",", ":"))
        reply = json.loads(reply_line)
        value = frames.decode(reply["frame"]) if frame is not None else reply["ok"]
        c3 = time.process_time()
        got = chk.from_arrays(value, args) if frame is not None else chk.from_result(value, args)
        ok, _ = chk.check(args, got, expected)
        c4 = time.process_time()
        del call_line
        bad += not ok
        parse, transport, checker = parse + c1 - c0, transport + c3 - c2, checker + c4 - c3
    return {"parse": parse, "transport": transport, "checker": checker, "tests": len(tests), "rejected": bad}


def course_yaml_cost(problems: list[str], repeat: int) -> dict[str, Any]:
    """CPU (s, this process; median of ``repeat``) to parse every problem's course.yaml, pure Python vs libyaml."""
    texts = [(load_problem(p).path / "course.yaml").read_text() for p in problems]
    out: dict[str, Any] = {}
    loaders = {"safe_load": yaml.SafeLoader, "csafe_load": getattr(yaml, "CSafeLoader", None)}
    data = {}
    for name, loader in loaders.items():
        if loader is None:
            out[name] = None
            continue
        cpus = []
        for _ in range(repeat):
            c0 = time.process_time()
            data[name] = [yaml.load(t, Loader=loader) for t in texts]  # noqa: S506 - SafeLoader / CSafeLoader
            cpus.append(time.process_time() - c0)
        out[name] = statistics.median(cpus)
    out["same"] = len(data) == 2 and data["safe_load"] == data["csafe_load"]
    return out


def import_cost(meter: Meter, path: Path, repeat: int) -> float:
    """CPU of ``python -I`` running the solution's top level, minus ``python -I -c pass`` (outside the jail)."""
    run = [sys.executable, "-I", "-c", "import runpy, sys; runpy.run_path(sys.argv[1], run_name='bench')", str(path)]
    bare = [sys.executable, "-I", "-c", "import runpy, sys"]
    env = {"PATH": os.environ.get("PATH", "/usr/bin:/bin"), "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}
    return best(meter, run, repeat, env)["cpu_median"] - best(meter, bare, repeat, env)["cpu_median"]


def print_startup(startup: dict[str, dict[str, float]], loads: dict[str, float], yaml_cpu: dict[str, Any],
                  judge30: dict[str, float] | None, repeat: int, e30: str = "") -> None:
    """The start-up table (and, with ``judge30``, the whole 30-test judge command's row)."""
    print("== start-up of one judge command (CPU s, median of", repeat, "runs; measured) ==")
    srows = [[k, "", "", fmt(v["cpu_median"]), fmt(v["cpu_min"]), fmt(v["wall_median"], 2)] for k, v in startup.items()]
    srows.append(["load_problem(id), in-process, per problem", "", "",
                  fmt(statistics.median(loads.values())), fmt(min(loads.values())), "-"])
    if judge30 is not None:
        srows.append([f"python -m grader judge ({e30}, 30 empty-work tests)", "", "", fmt(judge30["cpu_median"]),
                      fmt(judge30["cpu_min"]), fmt(judge30["wall_median"], 2)])
    print(table(["command", "", "", "cpu s", "min s", "wall s"], srows))
    if judge30 is not None:
        print(f"  the 30-test judge: the submission's own time {judge30['own_median']:.3f} s, so the judge's overhead "
              f"is {judge30['cpu_median'] - judge30['own_median']:.3f} s (the course's target: under 1.5 s of judge "
              "overhead for 30 function-mode tests)")
    print("  load_problem per problem: " + ", ".join(f"{k} {v:.3f}" for k, v in loads.items()))
    print(f"  parsing the {len(loads)} course.yaml files alone (in-process): {yaml_cpu['safe_load']:.3f} s with "
          f"yaml.safe_load (pure Python), {yaml_cpu['csafe_load']:.3f} s with libyaml's CSafeLoader "
          f"(same data: {yaml_cpu['same']})")


# -- output ----------------------------------------------------------------------------------------
def fmt(x: float | None, nd: int = 3) -> str:
    return "-" if x is None else f"{x:.{nd}f}"


def table(headers: list[str], rows: list[list[str]]) -> str:
    widths = [max(len(h), *(len(r[i]) for r in rows)) if rows else len(h) for i, h in enumerate(headers)]
    line = lambda cells: "  ".join(c.ljust(w) if i < 3 else c.rjust(w) for i, (c, w) in enumerate(zip(cells, widths)))  # noqa: E731
    return "\n".join([line(headers), *(line(r) for r in rows)])


def later(rows: list[StudentRow]) -> list[StudentRow]:
    """Students after the first (the steady state), or the first when it is alone."""
    return rows[1:] or rows


def main(argv: list[str] | None = None) -> dict[str, Any]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--problems", nargs="*", help="problem ids (default: every problem)")
    ap.add_argument("--languages", nargs="*", default=["python"], choices=sorted(LANGUAGES))
    ap.add_argument("--students", type=int, default=3)
    ap.add_argument("--jobs", type=int, default=1, help="grade --jobs (per-student CPU needs 1)")
    ap.add_argument("--repeat", type=int, default=3, help="runs of each start-up measurement (median)")
    ap.add_argument("--method", default="auto", choices=["auto", "cgroup-v1", "cgroup-v2", "proc"])
    ap.add_argument("--quick", action="store_true", help=f"{', '.join(QUICK_PROBLEMS)}; 2 students; --repeat 1")
    ap.add_argument("--json", type=Path, help="also write every number here (JSON)")
    ap.add_argument("--startup-only", action="store_true",
                    help="only the start-up table (one judge command's start-up, the sample check); no classes")
    ap.add_argument("--replay-one", metavar="PROBLEM", help=argparse.SUPPRESS)  # replay()'s fresh process
    a = ap.parse_args(argv)
    if a.replay_one:
        print(json.dumps(replay_here(a.replay_one)))
        return {}
    os.environ.setdefault("GRADER_PROBLEMS", str(REPO / "assignments"))  # this process and the grade runs agree
    if a.quick:
        a.problems, a.students, a.repeat = a.problems or list(QUICK_PROBLEMS), min(a.students, 2), 1
    problems = a.problems or [p.id for p in list_problems()]
    meter = Meter(a.method)
    load0 = os.getloadavg()
    started = time.strftime("%Y-%m-%d %H:%M")
    print(f"bench_judge_overhead: {started}, uid {os.geteuid()}, {os.cpu_count()} cores, load average "
          f"{load0[0]:.1f} {load0[1]:.1f} {load0[2]:.1f}; {a.students} students per class, grade --jobs {a.jobs}")
    print(f"cpu method: {meter.description}")
    print("wall times are noisy when the machine is shared; CPU times are the guide\n")
    out: dict[str, Any] = {"started": started, "method": meter.method, "uid": os.geteuid(), "load_start": load0,
                           "students": a.students, "jobs": a.jobs}
    tmp = Path(tempfile.mkdtemp(prefix="bench-judge-overhead-"))
    try:
        # 1. tests generated once (cached by the grader; never part of a grade run measured below)
        gen = {}
        for pid in (["delaunay"] if a.startup_only else problems):  # the start-up rows judge delaunay
            c0 = time.process_time()
            gen[pid] = len(load_problem(pid).tests())
            gen_cpu = time.process_time() - c0
            if gen_cpu > 1:
                print(f"{pid}: {gen[pid]} tests generated into the grader's cache ({gen_cpu:.1f} CPU-s, not counted)")

        # 2. start-up of a judge command
        py = sys.executable
        startup = {
            "python -c pass": best(meter, [py, "-c", "pass"], a.repeat),
            "python -I -c pass (the child's interpreter)": best(meter, [py, "-I", "-c", "pass"], a.repeat),
            "python -c 'import grader'": best(meter, [py, "-c", "import grader"], a.repeat),
            "python -m grader --help": best(meter, [py, "-m", "grader", "--help"], a.repeat),
            "python -m grader list": best(meter, [py, "-m", "grader", "list"], a.repeat),
        }
        syntax_error = tmp / "syntax_error.py"
        syntax_error.write_text("def delaunay(points):\n    return [\n")
        startup["python -m grader judge delaunay (a syntax error: CE before any test runs)"] = best(
            meter, [py, "-m", "grader", "judge", "delaunay", str(syntax_error)], a.repeat, expect_rc=1)
        startup["sample check: judge_samples alone (the verdict table), fresh python"] = best(
            meter, [py, "-c", SAMPLE_CHECK.split("; assert picture_png")[0],
                    str(accepted_solution("delaunay", LANGUAGES["python"]))], a.repeat)
        startup["sample check: judge_samples + picture, delaunay accepted (fresh python)"] = best(
            meter, [py, "-c", SAMPLE_CHECK, str(accepted_solution("delaunay", LANGUAGES["python"]))], a.repeat)
        yaml_cpu = course_yaml_cost(problems, a.repeat)
        loads = {}
        for pid in problems:
            cpus = []
            for _ in range(a.repeat):
                c0 = time.process_time()
                load_problem(pid)
                cpus.append(time.process_time() - c0)
            loads[pid] = statistics.median(cpus)

        if a.startup_only:
            print_startup(startup, loads, yaml_cpu, None, a.repeat)
            out.update(startup=startup, load_problem=loads, course_yaml=yaml_cpu)
            load1 = os.getloadavg()
            print(f"\nload average at the end: {load1[0]:.1f} {load1[1]:.1f} {load1[2]:.1f}")
            if a.json:
                a.json.write_text(json.dumps(out, indent=1, default=str))
            return out

        # 3. empty-work classes: fixed cost of a submission and of a test
        eroot = tmp / "problems"
        e1, e30 = make_empty_problems(eroot, (1, 30))
        eenv = child_env({"GRADER_PROBLEMS": str(eroot)})
        empty_students = max(a.students, 2)
        empty: dict[str, RunResult] = {}
        for eid in (e1, e30):
            cdir = tmp / "class" / eid
            make_class(cdir, eid, TRIVIAL, empty_students, LANGUAGES["python"])
            empty[eid] = grade_run(meter, eid, cdir, tmp / f"{eid}.sqlite", 1, "python", eenv)
        steady = {eid: statistics.mean(r.total or 0.0 for r in later(run.students)) for eid, run in empty.items()}
        per_test = (steady[e30] - steady[e1]) / 29
        per_sub = steady[e1] - per_test
        trivial = tmp / "trivial.py"
        trivial.write_text(TRIVIAL)
        judges = [meter.run([py, "-m", "grader", "judge", e30, str(trivial), "--json"], eenv) for _ in range(a.repeat)]
        for j in judges:
            if j.rc != 0:
                j.ok()
        judge_own = [sum(t["time_s"] for t in json.loads(j.stdout)["tests"]) for j in judges]
        judge30 = {"cpu_median": statistics.median(j.cpu for j in judges), "cpu_min": min(j.cpu for j in judges),
                   "own_median": statistics.median(judge_own),
                   "wall_median": statistics.median(j.wall for j in judges)}

        print_startup(startup, loads, yaml_cpu, judge30, a.repeat, e30)
        print(f"\n== empty-work classes ({empty_students} students; 'def delaunay(points): return []', every test AC) ==")
        erows = [[eid, "python", f"{len(run.students)} st", fmt(run.startup), fmt(steady[eid]),
                  fmt(statistics.mean(r.own for r in later(run.students)), 4), fmt(run.cpu), fmt(run.wall, 2)]
                 for eid, run in empty.items()]
        print(table(["problem", "lang", "class", "start-up s", "later student s", "own s", "run cpu s", "run wall s"],
                    erows))
        print(f"  per-test fixed cost (30 - 1 tests, by difference): {1000 * per_test:.2f} ms; "
              f"per-submission fixed cost (jail + child start): {per_sub:.3f} s")
        out.update(startup=startup, load_problem=loads, course_yaml=yaml_cpu, judge30=judge30, per_test_fixed=per_test,
                   per_submission_fixed=per_sub, empty={k: asdict(v) for k, v in empty.items()})

        # 4. the real problems
        runs: list[RunResult] = []
        skipped: list[str] = []
        for lang_name in a.languages:
            lang = LANGUAGES[lang_name]
            for pid in problems:
                sol = accepted_solution(pid, lang)
                if sol is None:
                    skipped.append(f"{pid} {lang_name}: no accepted {lang.suffixes[0]} solution in solutions/{pid}/")
                    continue
                cdir = tmp / "class" / f"{pid}-{lang_name}"
                make_class(cdir, pid, sol.read_text(), a.students, lang)
                if lang.compile:  # the judge's own command, here outside the jail
                    cmd = list(lang.compile_command(str(sol), str(tmp / f"{pid}.exe")))
                    compile_cpu = meter.run(cmd).ok().cpu
                else:
                    compile_cpu = None
                run = grade_run(meter, pid, cdir, tmp / f"{pid}-{lang_name}.sqlite", a.jobs, lang_name)
                if compile_cpu is not None:  # each student's compile is in their total, not in the overhead
                    for r in run.students:
                        if r.total is not None:
                            r.overhead = r.total - r.own - compile_cpu
                            r.ratio = r.overhead / r.own if r.own > 0 else None
                run.extra = {"solution": str(sol.relative_to(REPO)), "compile": compile_cpu,
                             "replay": replay(pid, a.repeat), "imports": import_cost(meter, sol, a.repeat) if not lang.compile else 0.0}
                runs.append(run)
                print(f"graded {pid} ({lang_name}, {sol.name}): run {run.cpu:.2f} CPU-s, {run.wall:.1f} s wall",
                      file=sys.stderr)

        print(f"\n== per student: one grade run per problem, {a.students} copies of the accepted solution ==")
        prow = []
        for run in runs:
            for r in run.students:
                prow.append([r.problem, r.lang, r.student, str(r.tests), fmt(r.total), fmt(r.own), fmt(r.overhead),
                             fmt(r.ratio, 2), fmt(r.wall, 2), r.verdict])
        print(table(["problem", "lang", "student", "tests", "total s", "own s", "overhead s", "ratio", "wall s",
                     "verdict"], prow))
        compiled = [run for run in runs if run.extra["compile"] is not None]
        for run in compiled:
            print(f"  compile {run.problem} ({run.lang}): {run.extra['compile']:.3f} CPU-s (the same command outside "
                  "the jail; subtracted from each student's overhead, so not in the ratio)")

        print("\n== per grade run (CPU s): before the first student, student 1's extra, after the last ==")
        rrows = []
        for run in runs:
            first = run.students[0].total if run.students else None
            rest = [r.total for r in later(run.students) if r.total is not None]
            extra = first - statistics.mean(rest) if first is not None and rest and len(run.students) > 1 else None
            run.extra["first_extra"] = extra
            rrows.append([run.problem, run.lang, str(len(run.students)), fmt(run.startup), fmt(extra), fmt(run.tail),
                          fmt(run.cpu), fmt(run.reaped), fmt(run.wall, 2), fmt(run.extra["replay"]["parse"])])
        print(table(["problem", "lang", "students", "start-up s", "1st extra s", "tail s", "run cpu s", "rusage s",
                     "run wall s", "parse tests s"], rrows))
        print("  start-up: measured (CPU at the first progress line); 1st extra: student 1 minus the mean of the "
              "others; parse tests: read_input + read_answer of every test, replayed in a fresh process (measured; "
              "the pool worker does it during student 1); rusage: what getrusage(RUSAGE_CHILDREN) saw of the same run "
              "(it misses the sandboxed child, reaped by the kernel when its pid namespace ends)")

        print("\n== where a later student's overhead goes (CPU s; mean of students 2..n) ==")
        brows = []
        for run in runs:
            st = later(run.students)
            if any(r.total is None for r in st):
                continue
            n_tests = statistics.mean(r.tests for r in st)
            overhead = statistics.mean(r.overhead for r in st)
            rp = run.extra["replay"]
            parts = {"jail+child start": per_sub, "imports": run.extra["imports"], "per-test fixed": per_test * n_tests,
                     "transport": rp["transport"], "checker": rp["checker"]}
            rest = overhead - sum(parts.values())
            run.extra["breakdown"] = {**parts, "rest": rest, "overhead": overhead,
                                      "own": statistics.mean(r.own for r in st)}
            brows.append([run.problem, run.lang, f"{n_tests:.0f}", fmt(run.extra["breakdown"]["own"]), fmt(overhead),
                          *(fmt(v) for v in parts.values()), fmt(rest),
                          f"{1000 * overhead / n_tests:.1f}"])
        print(table(["problem", "lang", "tests", "own s", "overhead s", "jail+child start", "imports", "per-test fixed",
                     "transport", "checker", "rest", "ms/test"], brows))
        print("  jail+child start, per-test fixed: measured by difference (empty-work classes of 1 and 30 tests); "
              "imports: measured outside the jail (python -I, minus a bare start); transport (parent's json dumps/"
              "loads) and checker (from_result + check): measured, replayed in a fresh process on the reference "
              "answers; rest: by difference")
        bad = [f"{run.problem} {run.extra['replay']['rejected']}" for run in runs if run.extra["replay"]["rejected"]]
        if bad:
            print("  note: the replayed checker rejected some reference answers (its cost is still counted): " +
                  ", ".join(bad))
        for s in skipped:
            print(f"  skipped: {s}")
        load1 = os.getloadavg()
        print(f"\nload average at the end: {load1[0]:.1f} {load1[1]:.1f} {load1[2]:.1f}")
        out.update(runs=[asdict(r) for r in runs], skipped=skipped, load_end=load1)
        if a.json:
            a.json.write_text(json.dumps(out, indent=1, default=str))
        return out
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
