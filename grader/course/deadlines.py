"""Each student's own deadlines, where a student can read them but the instructor's files are private.

On the hub the course folder (gradebook, ``extensions.yaml``) is the instructor's alone, so a
student cannot run ``timed status`` against it. ``publish`` (the instructor, as root, after
setting a due date or an extension) writes one file per student into a folder next to the
students' problems (``<problems>/../deadlines/`` by default): ``<student>.json``, owned by that
student's account and readable by them only (mode 0400), in a folder nobody can list (0711).
Each file holds that student's deadlines only: every nbgrader assignment with a due date, moved by
their extension, and the timed problems' durations with their extra minutes. ``show`` (the
student) reads their own file.

Example:
    sudo python -m grader deadlines publish /opt/delaunay-course/deadlines --course /opt/delaunay-course/course
    python -m grader deadlines show                    # as a student: your own deadlines

    >>> line({"assignment": "delaunay", "due": "2026-12-03T12:00:00+00:00", "extension": "2 days"})
    'delaunay: due 2026-12-03T12:00:00+00:00 (with your extension of 2 days)'
"""

from __future__ import annotations

import json
import os
import pwd
from datetime import datetime, timedelta, timezone
from pathlib import Path

from ..classroom import extensions
from ..problems import list_problems, problems_root

FOLDER = "deadlines"


def _amount(seconds: float) -> str:
    for unit, size in (("days", 86400), ("hours", 3600), ("minutes", 60)):
        if seconds >= size and seconds % size == 0:
            return f"{seconds / size:g} {unit}"
    return f"{seconds / 60:g} minutes"


def student_deadlines(course_root: str | Path) -> dict[str, list[dict]]:
    """student -> their deadlines, from the course's gradebook (due dates), ``extensions.yaml`` and
    the timed problems' ``course.yaml``. Students: the gradebook's and those with an extension."""
    course_root = Path(course_root)
    ext = extensions.load(course_root)
    dues: dict[str, datetime] = {}
    students: set[str] = {s for s, _ in ext}
    gradebook = course_root / "gradebook.db"
    if gradebook.is_file():
        from nbgrader.api import Gradebook

        with Gradebook(f"sqlite:///{gradebook.resolve()}") as gb:
            dues = {a.name: a.duedate.replace(tzinfo=timezone.utc) for a in gb.assignments if a.duedate}
            students |= {s.id for s in gb.students}
    timed = {p.id: p.timed for p in list_problems(course_root) if p.timed}
    out: dict[str, list[dict]] = {}
    for student in sorted(students):
        rows = []
        for a in sorted(set(dues) | set(timed)):
            extra = ext.get((student, a), 0.0)
            row: dict = {"assignment": a}
            if a in dues:
                row["due"] = (dues[a] + timedelta(seconds=extra)).isoformat()
            if a in timed:
                row["duration_min"] = float(timed[a].get("duration_min", 30)) + extra / 60
            if extra:
                row["extension"] = _amount(extra)
            rows.append(row)
        out[student] = rows
    return out


def publish(course_root: str | Path, folder: str | Path) -> tuple[list[Path], list[str]]:
    """Write ``folder/<student>.json`` for every student with an account here (owned by them, 0400;
    the folder 0711, so nobody lists it); returns the files written and the students skipped (no
    account). Root only: the files are given to the students' accounts."""
    if os.geteuid() != 0:
        raise ValueError("publishing deadlines gives each file to its student's account: run it as root")
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    os.chmod(folder, 0o711)
    written, skipped = [], []
    for student, rows in student_deadlines(course_root).items():
        try:
            pw = pwd.getpwnam(student)
        except KeyError:
            skipped.append(student)
            continue
        path = folder / f"{student}.json"
        tmp = folder / f".{student}.json.tmp"
        tmp.unlink(missing_ok=True)
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o400)
        with os.fdopen(fd, "w") as f:
            json.dump({"student": student, "deadlines": rows}, f, indent=1)
        os.chown(tmp, pw.pw_uid, pw.pw_gid)
        os.replace(tmp, path)
        written.append(path)
    return written, skipped


def default_folder() -> Path:
    """Next to the students' problems: ``<problems>/../deadlines``."""
    return problems_root().resolve().parent / FOLDER


def line(row: dict) -> str:
    """One deadline as a student reads it."""
    parts = [f"{row['assignment']}:"]
    if "due" in row:
        parts.append(f"due {row['due']}")
    if "duration_min" in row:
        parts.append(f"{'; ' if 'due' in row else ''}{row['duration_min']:g} minutes from your start")
    text = " ".join(parts).replace(" ; ", "; ")
    return text + (f" (with your extension of {row['extension']})" if row.get("extension") else "")


def show(folder: str | Path | None = None, user: str | None = None) -> list[str]:
    """The current account's deadlines (``ValueError`` when none were published for it)."""
    folder = Path(folder) if folder else default_folder()
    user = user or pwd.getpwuid(os.getuid()).pw_name
    path = folder / f"{user}.json"
    try:
        data = json.loads(path.read_text())
    except FileNotFoundError:
        raise ValueError(f"no deadlines published for {user} in {folder} (ask the instructor)") from None
    return [line(r) for r in data["deadlines"]] or ["no deadlines"]
