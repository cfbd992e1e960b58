"""Command line of the judge: ``python -m grader <command>``.

    python -m grader list
    python -m grader judge PROBLEM FILE [--json] [--report out.html]
    python -m grader grade PROBLEM SUBMISSIONS_DIR [--db results.sqlite] [--jobs N] [--csv grades.csv]
                           [--reports DIR] [--scheduler tcp://host:8786] [--similarity]
    python -m grader regrade PROBLEM SUBMISSIONS_DIR [--db results.sqlite] [--student S]... [--all] [--diff diff.csv]
    python -m grader export-grades --roster roster.csv --assignments lms-map.csv [--gradebook gradebook.db]
                                   [--db results.sqlite]... --out grades/
    python -m grader deadlines publish FOLDER [--course DIR]     (root: each student's own deadlines file)
    python -m grader deadlines show [--folder DIR]               (a student: their own deadlines)
    python -m grader similarity PROBLEM SUBMISSIONS_DIR [--reports DIR] [--reference DIR]... [--threshold 0.5]
    python -m grader timed start PROBLEM STUDENT [--db timed.sqlite]
    python -m grader timed status PROBLEM STUDENT [--db timed.sqlite]
    python -m grader timed submit PROBLEM STUDENT FILE [--db timed.sqlite] [--json]
    python -m grader scoreboard [--db results.sqlite] [--start ISO|EPOCH] [--problems a,b] [--json]
    python -m grader export-kattis PROBLEM OUTDIR [--groups g1,g2] [--no-judge]
    python -m grader validate PROBLEM
    python -m grader statements [--check] [PROBLEM...]
    python -m grader stress PROBLEM FILE [--seconds N]
    python -m grader warm [PROBLEM...]

Exit status (for scripts and the CI of students' own repositories):
    0  success; for ``judge`` and ``timed submit``: the verdict is AC
    1  ``judge``/``timed submit``: any verdict but AC; ``validate``: the package has problems;
       ``statements --check``: a statement is stale or lacks its generated block; ``stress``:
       a failing input was found (it is printed)
    2  bad usage or input: unknown problem, missing file or folder, a results store that does
       not exist (commands that only read a store never create one), with a one-line message
A closed output pipe (``python -m grader list | head -1``) ends the command quietly.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from .problems import list_problems, load_problem
from .judging.languages import CPP, LANGUAGES, PYTHON, Language

if TYPE_CHECKING:
    from .classroom.store import ResultStore

# Each command imports what it uses when it runs: `list` and `--help` never load the jail, the
# judging loop, SQLite or the class tools (tests/grader/test_startup.py checks which modules a
# light command leaves out).


def _existing_store(path: str) -> ResultStore:
    """Open a results store that must already exist (a mistyped ``--db`` is an error, not a new file)."""
    from .classroom.store import ResultStore

    if not Path(path).is_file():
        raise ValueError(f"no results store at {path} (check --db; it is created by `grade` or `timed start`)")
    return ResultStore(path)


def compiled_languages() -> list[Language]:
    """The compiled languages whose limits ``list`` shows: those the judge accepts and C++ (whose
    limits the statements already give), each once, in :data:`LANGUAGES` order."""
    return [lang for lang in dict.fromkeys((*LANGUAGES, CPP)) if lang.compile]


def _cmd_list(a: argparse.Namespace) -> int:
    """One row per problem: the first columns (id, entry, Python's time, memory, points) are as they
    always were for scripts; then the time limit of each compiled language, then the title. The
    compile commands follow the table once, on stderr, so that stdout stays the table."""
    langs = compiled_languages()
    rows = [(p.id, p.entry, f"{p.time_limit:g}s", f"{p.memory_mb}MB", str(p.points),
             *(f"{p.time_limit_for(lang.name):g}s" for lang in langs), p.title) for p in list_problems()]
    if a.json:
        keys = ("id", "entry", "time_limit", "memory", "points", *(f"time_limit_{lang.name}" for lang in langs), "title")
        print(json.dumps([dict(zip(keys, r)) for r in rows], indent=1))
        return 0
    for r in [("id", "entry", "time", "memory", "points", *(lang.name for lang in langs), "title"), *rows]:
        print(f"{r[0]:22} {r[1]:22} {r[2]:6} {r[3]:7} {r[4]:6} " + "".join(f"{c:5} " for c in r[5:-1]) + r[-1])
    print(f"time: the CPU-time limit per test for Python ({', '.join(PYTHON.all_suffixes)})", file=sys.stderr)
    for lang in langs:
        command = " ".join(lang.compile_command("main" + lang.suffixes[0], "main"))
        print(f"{lang.name}: the limit for {', '.join(lang.suffixes)} files, compiled as `{command}`, "
              f"run in {'/'.join(lang.modes)} mode", file=sys.stderr)
    return 0


def _cmd_judge(a: argparse.Namespace) -> int:
    from .contest.judge import Judge
    from .judging.verdicts import format_table

    path = Path(a.file)
    if not path.is_file():
        raise ValueError(f"submission file {path} does not exist")
    judge = Judge(a.problem, hide=[str(path.resolve().parent)], trusted=True if a.trusted else None)
    judge.keep_build = a.counterexample_seconds != 0   # a C++ file's build serves the search too
    try:
        result = judge.judge_path(path, follow_links=True)  # the file named on the command line
        if a.counterexample_seconds != 0:  # a failing group: a small input of the grader's own the file fails too
            from .contest.counterexample import attach

            attach(result, judge.problem, path, a.counterexample_seconds, trusted=True if a.trusted else None,
                   build_from=judge)
    finally:
        judge.drop_build()
    if a.report:
        from .contest.report import write_report

        write_report(result, a.report, judge.problem)
    print(json.dumps(result.to_json(), indent=1) if a.json else format_table(result) + "\n" + judged_in())
    return 0 if result.verdict == "AC" else 1


def _seconds(text: str) -> float:
    """A number of seconds from 0 to 600 (an argparse type)."""
    try:
        value = float(text)
    except ValueError:
        value = -1.0
    if not 0 <= value <= 600:
        raise argparse.ArgumentTypeError(f"expected a number of seconds from 0 to 600, got {text!r}")
    return value


def judged_in() -> str:
    """Which jail judged (the table's last line; ``--json`` has it as ``sandbox``)."""
    from .jail import mechanism

    mech = mechanism()
    if mech == "trusted":
        return "judged in the trusted mode: NO kernel jail (for your own code only; see python -m grader.sandbox)"
    return f"judged in the jail: {mech}"


def _cmd_stress(a: argparse.Namespace) -> int:
    from .contest.stress import main as stress_main

    return stress_main(a.problem, a.file, a.seconds)


def _cmd_grade(a: argparse.Namespace) -> int:
    from .classroom.classgrade import grade_class

    if a.nbgrader:  # SUBMISSIONS is nbgrader's submitted/; results go into its gradebook
        from .course.nbgrader_autograde import grade_course

        summaries = grade_course(a.problem, a.submissions, jobs=a.jobs, progress=None if a.quiet else sys.stderr,
                                 counterexample_seconds=a.counterexample_seconds, scheduler=a.scheduler)
    else:
        summaries = grade_class(a.problem, a.submissions, a.db, jobs=a.jobs, scheduler=a.scheduler, csv_path=a.csv,
                                report_dir=a.reports, progress=not a.quiet, diff_path=a.diff,
                                counterexample_seconds=a.counterexample_seconds)
    if a.similarity:
        _similarity(a.problem, a.submissions, a.reports or SIMILARITY_DIR, a.reference, a.boilerplate, a.threshold,
                    sys.stderr)
    if a.json:
        print(json.dumps(summaries, indent=1))
    else:
        for s in sorted(summaries, key=lambda s: s["student"]):
            print(f"{s['student']:20} {s.get('verdict', ''):4} {s.get('score', '')}/{s.get('max_score', '')} "
                  f"{s.get('skipped', '')}{gradebook_note(s)}")
    return 0


def _cmd_regrade(a: argparse.Namespace) -> int:
    from .classroom.classgrade import grade_class

    summaries = grade_class(a.problem, a.submissions, a.db, jobs=a.jobs, csv_path=a.csv, progress=not a.quiet,
                            regrade_students=a.student or ([] if a.all else None), diff_path=a.diff)
    moved = [s for s in summaries if "regrade" in s]
    for s in sorted(moved, key=lambda s: s["student"]):
        from .classroom.regrade import diff_line

        print(diff_line(s["regrade"]))
    print(f"{a.problem}: {len(moved)} regraded, "
          f"{sum(s['regrade']['old_score'] != s['regrade']['new_score'] for s in moved)} scores moved"
          + (f"; diff in {a.diff}" if a.diff else ""))
    return 0


def _cmd_export_grades(a: argparse.Namespace) -> int:
    from .course.grades_export import export, missing_lines

    report = export(a.roster, a.assignments, a.out, gradebook=a.gradebook, stores=a.db or [])
    for line in missing_lines(report):
        print(line, file=sys.stderr)
    for f in report["files"]:
        print(f)
    return 0


def _cmd_deadlines(a: argparse.Namespace) -> int:
    from .course import deadlines
    from .problems import course_folder

    if a.action == "publish":
        if not a.folder:
            raise ValueError("deadlines publish needs the FOLDER to write into")
        course = Path(a.course) if a.course else course_folder()
        if course is None:
            raise ValueError("no course here: pass --course DIR (the folder with nbgrader_config.py)")
        written, skipped = deadlines.publish(course, a.folder)
        print(f"{len(written)} students' deadlines written to {a.folder}")
        for s in skipped:
            print(f"{s}: no account here, not written", file=sys.stderr)
        return 0
    for text in deadlines.show(a.folder):
        print(text)
    return 0


def gradebook_note(summary: dict) -> str:
    """What ``grade --nbgrader`` adds to a row: the gradebook's score when the late policy changed it.

    >>> gradebook_note({"score": 40, "gradebook_score": 20.0, "late_penalty": 20.0})
    '  gradebook: 20 (late penalty -20)'
    >>> gradebook_note({"score": 40, "gradebook_score": 40.0, "late_penalty": 0.0})
    ''
    """
    if "gradebook_score" not in summary or not summary.get("late_penalty"):
        return ""
    return f"  gradebook: {summary['gradebook_score']:g} (late penalty -{summary['late_penalty']:g})"


SIMILARITY_DIR = "similarity-report"


def _similarity(problem, submissions, report_dir, references, boilerplate, threshold, out) -> None:
    from .classroom.similarity import summary_lines
    from .classroom.similarity_report import run

    analysis = run(problem, submissions, report_dir, references or [], boilerplate or [], threshold)
    for line in summary_lines(analysis):
        print(line, file=out)
    print(f"report: {Path(report_dir) / 'similarity.html'}", file=out)


def _cmd_similarity(a: argparse.Namespace) -> int:
    _similarity(a.problem, a.submissions, a.reports or SIMILARITY_DIR, a.reference, a.boilerplate, a.threshold,
                sys.stdout)
    return 0


def _similarity_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--reference", action="append", metavar="DIR",
                   help="also compare every student with the .py/.ipynb files under DIR (repeatable; "
                        "the tutorial's code is always a reference)")
    p.add_argument("--boilerplate", action="append", metavar="DIR",
                   help="code under DIR is given to everyone: it counts for nobody (repeatable; the starter "
                        "notebook and the statement's snippets always do)")
    p.add_argument("--threshold", type=float, default=0.5, help="flag pairs scoring at least this (default 0.5)")


def _cmd_timed(a: argparse.Namespace) -> int:
    from .classroom import timed
    from .classroom.store import ResultStore
    from .judging.verdicts import format_table

    if a.action == "start":
        timed._settings(a.problem)  # refuse a problem without timed settings before creating a store
    store = ResultStore(a.db) if a.action == "start" else _existing_store(a.db)
    code = 0
    try:
        if a.action in ("start", "status"):
            info = (timed.start if a.action == "start" else timed.status)(a.problem, a.student, store)
            print(json.dumps(info) if a.json else timed.describe(info))
        else:
            if not a.file or not Path(a.file).is_file():
                raise ValueError("timed submit needs an existing FILE")
            out = timed.submit(a.problem, a.student, a.file, store)
            if a.json:
                print(json.dumps({**out.result.to_json(), "elapsed_s": round(out.elapsed_s, 1), "late": out.late,
                                  "multiplier": out.multiplier, "final_score": out.final_score, "note": out.note}, indent=1))
            else:
                print(format_table(out.result))
                print(f"{out.note}; final score {out.final_score:g}/{out.result.max_score}")
            code = 0 if out.result.verdict == "AC" else 1
    finally:
        store.close()
    return code


def _cmd_scoreboard(a: argparse.Namespace) -> int:
    from .classroom import scoreboard as sb

    store = _existing_store(a.db)
    rows = sb.compute(store, sb.parse_start(a.start), a.problems.split(",") if a.problems else None)
    store.close()
    print(json.dumps(rows, indent=1) if a.json else sb.format_board(rows))
    return 0


def _cmd_export(a: argparse.Namespace) -> int:
    from .contest.kattis import export

    dest = export(a.problem, a.outdir, groups=a.groups.split(",") if a.groups else None, judge=not a.no_judge)
    print(dest)
    return 0


def _cmd_validate(a: argparse.Namespace) -> int:
    p = load_problem(a.problem)
    errors = p.validate()
    errors += (p.validate_checker() + p.validate_inputs()) if not errors else []
    for e in errors:
        print(f"{p.id}: {e}")
    print(f"{p.id}: {len(p.tests())} tests, {'OK' if not errors else f'{len(errors)} problems'}")
    return 1 if errors else 0


def _cmd_warm(a: argparse.Namespace) -> int:
    from .jail import launcher
    from .problems.package import warm

    warm(a.problems or None, sys.stdout)
    launcher.ensure()  # the C launcher of compiled programs (none without a C compiler: said here)
    print(launcher.status(), flush=True)
    return 0


def _cmd_statements(a: argparse.Namespace) -> int:
    from .problems.statements import update_statements

    stale = update_statements(a.problems or None, check=a.check)
    for pid, why in stale:
        print(f"{pid}: {why}", file=sys.stderr if a.check else sys.stdout)
    if a.check and stale:
        print("run `python -m grader statements` to regenerate", file=sys.stderr)
        return 1
    return 1 if any(not why.startswith("rewrote") for _, why in stale) else 0


def build_parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="python -m grader", description="Sandboxed contest-style judge for the course.")
    sub = ap.add_subparsers(dest="command", required=True)
    p = sub.add_parser("list", help="list problems")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=_cmd_list)
    p = sub.add_parser("judge", help="judge one submission",
                       description="Judge one submission: a .py file, an .ipynb notebook, or a C++ file (.cpp, .cc, "
                                   ".cxx: compiled once with g++ -std=gnu++17 -O2 -static in the compile jail, a "
                                   "compile error is CE, then run per test in the jail, reading standard input).")
    p.add_argument("problem")
    p.add_argument("file", help="the submission (.py, .ipynb, .cpp, .cc or .cxx)")
    p.add_argument("--json", action="store_true", help="one JSON object instead of the table")
    p.add_argument("--report", help="also write an HTML report here")
    p.add_argument("--trusted", action="store_true",
                   help="where no kernel jail can be built, judge without one (your own code only; the output "
                        "says 'judged in the trusted mode')")
    p.add_argument("--counterexample-seconds", type=_seconds, default=None, metavar="N",
                   help="when a group fails (WA, PE, RE), search small public inputs for one the file gets wrong "
                        "for up to N seconds (0: no search; default: the problem's course.yaml, else 10)")
    p.set_defaults(func=_cmd_judge)
    p = sub.add_parser("grade", help="grade a class: SUBMISSIONS/<student>/<file>")
    p.add_argument("problem")
    p.add_argument("submissions")
    p.add_argument("--db", default="results.sqlite")
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--csv")
    p.add_argument("--reports", help="directory for one HTML report per student")
    p.add_argument("--scheduler", help="Dask distributed scheduler address")
    p.add_argument("--json", action="store_true")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.add_argument("--nbgrader", action="store_true",
                   help="SUBMISSIONS is an nbgrader course's submitted/ dir: judge in parallel, then nbgrader autograde")
    p.add_argument("--similarity", action="store_true",
                   help=f"then write the class's similarity report (into --reports, else {SIMILARITY_DIR}/)")
    p.add_argument("--diff", help="write the diff of the students judged again (CSV) here")
    p.add_argument("--counterexample-seconds", type=_seconds, default=None, metavar="N",
                   help="after every score is stored, search up to N seconds per failing submission for a small "
                        "input it gets wrong (0: none now; a later run searches those not done; default: the "
                        "problem's course.yaml, else 10)")
    _similarity_options(p)
    p.set_defaults(func=_cmd_grade)
    p = sub.add_parser("regrade", help="judge students again on demand and show whose score moved and why",
                       description="Judge again the groups whose tests, checker or limits changed since "
                                   "SUBMISSIONS/<student>/<file> was graded (nothing else), and each --student (or "
                                   "with --all everyone) from scratch; print and save each student's diff (old "
                                   "score, new score, which groups changed and why). An interrupted regrade "
                                   "resumes when run again.")
    p.add_argument("problem")
    p.add_argument("submissions")
    p.add_argument("--db", default="results.sqlite")
    p.add_argument("--student", action="append", help="judge this student again from scratch (repeatable)")
    p.add_argument("--all", action="store_true", help="judge every student again from scratch")
    p.add_argument("--diff", help="also write the diff as CSV here")
    p.add_argument("--csv", help="the grades CSV, as `grade --csv`")
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=_cmd_regrade)
    p = sub.add_parser("export-grades", help="the course's grades as Canvas and Moodle gradebook imports",
                       description="Write OUT/canvas.csv, OUT/moodle.csv (their gradebook import formats), "
                                   "OUT/grades-long.csv and OUT/missing.txt from nbgrader's gradebook and the "
                                   "judge's results stores, after late penalties and extensions.")
    p.add_argument("--roster", required=True, help="CSV: course_id, lms_id, name, email [, sis_user_id, "
                                                   "sis_login_id, section]")
    p.add_argument("--assignments", required=True, help="CSV: assignment, canvas, moodle [, points]")
    p.add_argument("--gradebook", help="nbgrader's gradebook.db")
    p.add_argument("--db", action="append", help="a results store (repeatable)")
    p.add_argument("--out", required=True, help="the folder to write into")
    p.set_defaults(func=_cmd_export_grades)
    p = sub.add_parser("deadlines", help="each student's own deadlines: publish (root) / show (a student)")
    p.add_argument("action", choices=["publish", "show"])
    p.add_argument("folder", nargs="?", help="where the files are (default for show: next to the problems)")
    p.add_argument("--course", help="publish: the course folder (default: the one you are in)")
    p.set_defaults(func=_cmd_deadlines)
    p = sub.add_parser("similarity", help="similarity report of a class: who shares code with whom and the tutorial",
                       description="Compare every pair of SUBMISSIONS/<student>/<file> (or nbgrader's collected "
                                   "submitted/<student>/PROBLEM/PROBLEM.ipynb: the solution cells) and every "
                                   "student with the tutorial's code; write DIR/similarity.html (ranked class, "
                                   "flagged pairs side by side) and DIR/similarity.csv. Exit 0; 2 on bad input.")
    p.add_argument("problem")
    p.add_argument("submissions")
    p.add_argument("--reports", metavar="DIR", help=f"where the report goes (default {SIMILARITY_DIR}/)")
    _similarity_options(p)
    p.set_defaults(func=_cmd_similarity)
    p = sub.add_parser("timed", help="timed attempts: start / status / submit")
    p.add_argument("action", choices=["start", "status", "submit"])
    p.add_argument("problem")
    p.add_argument("student")
    p.add_argument("file", nargs="?")
    p.add_argument("--db", default="timed.sqlite")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=_cmd_timed)
    p = sub.add_parser("scoreboard", help="ICPC-style scoreboard")
    p.add_argument("--db", default="results.sqlite")
    p.add_argument("--start")
    p.add_argument("--problems")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=_cmd_scoreboard)
    p = sub.add_parser("export-kattis", help="write a Kattis problem package")
    p.add_argument("problem")
    p.add_argument("outdir")
    p.add_argument("--groups", help="only these hidden groups (comma-separated; 'large:1' keeps the first test of large)")
    p.add_argument("--no-judge", action="store_true",
                   help="place the reference solutions by their expected verdict, without judging them")
    p.set_defaults(func=_cmd_export)
    p = sub.add_parser("validate", help="check a problem package and its test inputs")
    p.add_argument("problem")
    p.set_defaults(func=_cmd_validate)
    p = sub.add_parser("warm", help="generate every problem's tests into the cache (make warm does it)",
                       description="Generate the hidden tests of every problem (or of PROBLEM...) into the test "
                                   "cache, so that no judging waits for them; a cached copy that is trusted and made "
                                   "for this package is kept. One line per problem; then the C launcher of compiled "
                                   "programs is built (once per machine and account).")
    p.add_argument("problems", nargs="*", help="problem ids (default: every problem)")
    p.set_defaults(func=_cmd_warm)
    p = sub.add_parser("statements", help="write the limits-and-scoring block of each statement")
    p.add_argument("problems", nargs="*", help="problem ids (default: every problem)")
    p.add_argument("--check", action="store_true", help="only report stale statements (exit 1 if any)")
    p.set_defaults(func=_cmd_statements)
    p = sub.add_parser("stress", help="search small inputs for one that FILE gets wrong")
    p.add_argument("problem")
    p.add_argument("file")
    p.add_argument("--seconds", type=float, default=10.0, help="how long to search (default 10)")
    p.set_defaults(func=_cmd_stress)
    return ap


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        code = args.func(args)
        sys.stdout.flush()  # a closed pipe shows up here, inside the handler
        return code
    except BrokenPipeError:  # `... | head`: the reader has gone; say nothing more
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except Exception as exc:
        if _jail_refusal(exc) or isinstance(exc, ValueError):  # never judge without a jail unless asked (--trusted)
            print(f"error: {exc}", file=sys.stderr)
            return 2
        if isinstance(exc, OSError):  # a missing or unreadable path the checks above did not name
            print(f"error: {exc.strerror or exc}: {exc.filename or ''}".rstrip(": "), file=sys.stderr)
            return 2
        raise


def _jail_refusal(exc: BaseException) -> bool:
    """True for :class:`grader.jail.JailUnavailable` (only a command that loaded the jail can raise it)."""
    errors = sys.modules.get("grader.jail.errors")
    return errors is not None and isinstance(exc, errors.JailUnavailable)


if __name__ == "__main__":
    sys.exit(main())
