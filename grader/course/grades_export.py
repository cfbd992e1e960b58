"""The course's grades as files a learning management system imports as they are: Canvas, Moodle.

Reads every assignment's grades after late penalties from nbgrader's gradebook (score minus the
late penalty nbgrader recorded, extensions included) and from the judge's results stores (each
student's last judged submission, times its late factor; a timed attempt's factor recomputed from
the deadline as it is now, extensions included), then writes into ``OUT``:

* ``canvas.csv``: Canvas's gradebook import columns ``Student, ID, SIS User ID, SIS Login ID,
  Section``, then one column per assignment named as in the assignment map (Canvas's
  ``Name (id)`` of an existing assignment, or a new name), and the ``Points Possible`` row;
* ``moodle.csv``: the identifier columns ``Email address`` and ``ID number`` (map either to the
  user in Moodle's "Import grades: CSV file"), then one column per grade item;
* ``grades-long.csv``: one row per student and assignment, with where the grade came from;
* ``missing.txt``: roster students without a grade, graded students not on the roster, graded
  assignments not in the map. Nobody is silently dropped: these are also printed.

The roster is a CSV with columns ``course_id`` (the id in the course: nbgrader's student id, the
submission folder's name), ``lms_id`` (Canvas's user ID / Moodle's ID number), ``name``,
``email``, and optionally ``sis_user_id``, ``sis_login_id``, ``section``. The assignment map is a
CSV with ``assignment`` (the problem id), ``canvas`` and ``moodle`` (the LMS's column names) and
optionally ``points`` (the LMS's points possible; scores are scaled to it).

Example:
    python -m grader export-grades --roster roster.csv --assignments lms-map.csv \\
        --gradebook assignments/gradebook.db --db results.sqlite --db exam.sqlite --out grades/
"""

from __future__ import annotations

import csv
from pathlib import Path

from ..classroom.scoreboard import final_multiplier
from ..classroom.store import ResultStore
from ..judging.text import csv_cell

ROSTER_COLUMNS = ("course_id", "lms_id", "name", "email")
MAP_COLUMNS = ("assignment", "canvas", "moodle")
CANVAS_ID_COLUMNS = ("Student", "ID", "SIS User ID", "SIS Login ID", "Section")
MOODLE_ID_COLUMNS = ("Email address", "ID number")


def _read_csv(path: str | Path, required: tuple[str, ...], what: str) -> list[dict]:
    path = Path(path)
    if not path.is_file():
        raise ValueError(f"{what} {path} does not exist")
    with open(path, newline="", encoding="utf-8-sig") as f:
        reader = csv.DictReader(f)
        missing = [c for c in required if c not in (reader.fieldnames or [])]
        if missing:
            raise ValueError(f"{what} {path}: missing column(s) {', '.join(missing)} (has {reader.fieldnames})")
        rows = [{k: (v or "").strip() for k, v in r.items() if k} for r in reader]
    return rows


def read_roster(path: str | Path) -> list[dict]:
    """The roster's rows; a ``ValueError`` for a missing column, an empty or repeated id."""
    rows = _read_csv(path, ROSTER_COLUMNS, "roster")
    for col in ("course_id", "lms_id"):
        seen: set[str] = set()
        for k, r in enumerate(rows, 2):
            if not r[col]:
                raise ValueError(f"roster {path}, line {k}: empty {col}")
            if r[col] in seen:
                raise ValueError(f"roster {path}, line {k}: {col} {r[col]!r} repeats")
            seen.add(r[col])
    return rows


def read_assignment_map(path: str | Path) -> list[dict]:
    """The assignment map's rows (``points`` a positive number or empty)."""
    rows = _read_csv(path, MAP_COLUMNS, "assignment map")
    for k, r in enumerate(rows, 2):
        if not r["assignment"] or not r["canvas"] or not r["moodle"]:
            raise ValueError(f"assignment map {path}, line {k}: assignment, canvas and moodle must not be empty")
        if r.get("points"):
            try:
                if float(r["points"]) <= 0:
                    raise ValueError
            except ValueError:
                raise ValueError(f"assignment map {path}, line {k}: points must be a positive number, "
                                 f"got {r['points']!r}") from None
    return rows


def store_grades(path: str | Path) -> dict[tuple[str, str], dict]:
    """(student, assignment) -> grade from a judge's results store: the last judged submission."""
    if not Path(path).is_file():
        raise ValueError(f"no results store at {path}")
    store = ResultStore(path)
    try:
        starts = {(r[0], r[1]): r[2] for r in store.db.execute("SELECT student, problem, started_at FROM timed")}
        out = {}
        for s in store.submissions():
            if s["status"] != "done":
                continue
            mult = final_multiplier(s, starts)
            score = round((s["score"] or 0) * mult, 2)
            out[(s["student"], s["problem"])] = {
                "score": score, "max_score": s["max_score"] or 100, "late_penalty": round((s["score"] or 0) - score, 2),
                "source": Path(path).name, "note": s["note"] or ""}
        return out
    finally:
        store.close()


def gradebook_grades(path: str | Path) -> dict[tuple[str, str], dict]:
    """(student, assignment) -> grade from nbgrader's gradebook: score minus its late penalty."""
    from nbgrader.api import Gradebook

    if not Path(path).is_file():
        raise ValueError(f"no nbgrader gradebook at {path}")
    out = {}
    with Gradebook(f"sqlite:///{Path(path).resolve()}") as gb:
        for a in gb.assignments:
            for sub in a.submissions:
                penalty = float(sub.late_submission_penalty or 0.0)
                out[(sub.student.id, a.name)] = {
                    "score": round(max(0.0, float(sub.score) - penalty), 2), "max_score": float(a.max_score),
                    "late_penalty": round(penalty, 2), "source": "gradebook", "note": ""}
    return out


def _num(x: float) -> str:
    return f"{round(x, 2):g}"


def export(roster_path: str | Path, map_path: str | Path, out_dir: str | Path, gradebook: str | Path | None = None,
           stores: list[str | Path] = ()) -> dict:
    """Write canvas.csv, moodle.csv, grades-long.csv and missing.txt into ``out_dir``; returns what
    was written and who is missing (``missing_grades``, ``not_on_roster``, ``not_in_map``)."""
    roster, amap = read_roster(roster_path), read_assignment_map(map_path)
    if gradebook is None and not stores:
        raise ValueError("no grades to export: give nbgrader's gradebook (--gradebook) and/or results stores (--db)")
    grades: dict[tuple[str, str], dict] = {}
    for path in stores:
        grades.update(store_grades(path))
    if gradebook is not None:  # nbgrader's gradebook wins over a store for the same assignment
        grades.update(gradebook_grades(gradebook))
    on_roster = {r["course_id"] for r in roster}
    mapped = {m["assignment"] for m in amap}
    graded_assignments = {a for _, a in grades}
    report = {"missing_grades": [], "not_on_roster": sorted({s for s, _ in grades} - on_roster),
              "not_in_map": sorted(graded_assignments - mapped), "not_graded_yet": []}
    cells: dict[tuple[str, str], str] = {}
    long_rows = []
    for m in amap:
        a = m["assignment"]
        if a not in graded_assignments:
            report["not_graded_yet"].append(a)
        for r in roster:
            g = grades.get((r["course_id"], a))
            if g is None and a in graded_assignments:
                report["missing_grades"].append((r["course_id"], a))
                g = {"score": 0.0, "max_score": None, "late_penalty": 0.0, "source": "", "note": "no submission: 0"}
            if g is None:
                continue
            max_score = g["max_score"] or next((x["max_score"] for (_, b), x in grades.items() if b == a), 100)
            points = float(m["points"]) if m.get("points") else float(max_score)
            lms = g["score"] * points / float(max_score) if max_score else 0.0
            cells[(r["course_id"], a)] = _num(lms)
            long_rows.append([r["course_id"], r["lms_id"], r["name"], a, m["canvas"], _num(g["score"]),
                              _num(float(max_score)), _num(lms), _num(points), _num(g["late_penalty"]), g["source"],
                              g["note"]])
    for (student, a), g in sorted(grades.items()):  # what the LMS files cannot hold is still written here
        if student not in on_roster or a not in mapped:
            long_rows.append([student, "", "", a, "", _num(g["score"]), _num(float(g["max_score"])), "", "",
                              _num(g["late_penalty"]), g["source"],
                              "not on the roster" if student not in on_roster else "not in the assignment map"])
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    points = {m["assignment"]: m.get("points") or "" for m in amap}
    with open(out / "canvas.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow([*CANVAS_ID_COLUMNS, *(m["canvas"] for m in amap)])
        w.writerow(["Points Possible", "", "", "", "", *(points[m["assignment"]] or _max_of(grades, m["assignment"])
                                                         for m in amap)])
        for r in roster:
            w.writerow([csv_cell(r["name"]), csv_cell(r["lms_id"]), csv_cell(r.get("sis_user_id", "")),
                        csv_cell(r.get("sis_login_id", "")), csv_cell(r.get("section", "")),
                        *(cells.get((r["course_id"], m["assignment"]), "") for m in amap)])
    with open(out / "moodle.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow([*MOODLE_ID_COLUMNS, *(m["moodle"] for m in amap)])
        for r in roster:
            w.writerow([csv_cell(r["email"]), csv_cell(r["lms_id"]),
                        *(cells.get((r["course_id"], m["assignment"]), "") for m in amap)])
    with open(out / "grades-long.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["course_id", "lms_id", "name", "assignment", "lms_column", "score", "max_score", "lms_score",
                    "lms_points", "late_penalty", "source", "note"])
        w.writerows([[csv_cell(v) for v in row] for row in long_rows])
    (out / "missing.txt").write_text("\n".join(missing_lines(report)) + "\n")
    report["files"] = [str(out / n) for n in ("canvas.csv", "moodle.csv", "grades-long.csv", "missing.txt")]
    return report


def _max_of(grades: dict, assignment: str) -> str:
    return _num(float(next((g["max_score"] for (_, a), g in grades.items() if a == assignment), 100)))


def missing_lines(report: dict) -> list[str]:
    """Who and what the LMS files lack, one line each ('nothing missing' when complete).

    >>> missing_lines({"missing_grades": [("eve", "emst")], "not_on_roster": [], "not_in_map": [],
    ...                "not_graded_yet": []})
    ['eve: no grade for emst (exported as 0)']
    """
    lines = [f"{s}: no grade for {a} (exported as 0)" for s, a in report["missing_grades"]]
    lines += [f"{s}: graded but not on the roster (only in grades-long.csv)" for s in report["not_on_roster"]]
    lines += [f"{a}: graded but not in the assignment map (only in grades-long.csv)" for a in report["not_in_map"]]
    lines += [f"{a}: in the assignment map, no grades yet (column left empty)" for a in report["not_graded_yet"]]
    return lines or ["nothing missing"]
