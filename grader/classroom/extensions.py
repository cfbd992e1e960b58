"""Per-student extensions: a later due date, or extra minutes on a timed exam.

One small file in the course folder (next to the problem packages, versioned with the course),
``extensions.yaml``: student -> assignment -> how much more time, as ``<number> <unit>`` with
``minutes``, ``hours`` or ``days``::

    ada:
      delaunay: 2 days                # the due date moves two days for ada
      bowyer-watson-timed: 15 minutes # ada's exam lasts 15 minutes longer

The same extension is applied everywhere a deadline is: ``timed start/status/submit`` (the
deadline is the start plus the duration plus the extra minutes), the scoreboard and the grades
export (a timed score's late factor is computed from that deadline), and nbgrader's late penalty
(:class:`grader.course.nbgrader_autograde.CourseLatePolicy` subtracts the extension from the
seconds late). A bad file is a ``ValueError`` naming the line's student and assignment.

Example:
    >>> parse_amount("15 minutes"), parse_amount("2 days")
    (900.0, 172800.0)
"""

from __future__ import annotations

import re
from pathlib import Path

import yaml

from ..problems import problems_root

FILE_NAME = "extensions.yaml"
UNITS = {"minute": 60.0, "minutes": 60.0, "hour": 3600.0, "hours": 3600.0, "day": 86400.0, "days": 86400.0}


def parse_amount(text: object) -> float:
    """``"15 minutes"`` -> seconds; a ``ValueError`` for anything else."""
    m = re.fullmatch(r"\s*(\d+(?:\.\d+)?)\s*([a-z]+)\s*", str(text))
    if not m or m.group(2) not in UNITS:
        raise ValueError(f"an extension is '<number> minutes|hours|days', got {text!r}")
    return float(m.group(1)) * UNITS[m.group(2)]


def extensions_path(root: str | Path | None = None) -> Path:
    """The course's extensions file (in the folder of the problem packages)."""
    return Path(root if root is not None else problems_root()) / FILE_NAME


def load(root: str | Path | None = None) -> dict[tuple[str, str], float]:
    """(student, assignment) -> extra seconds, from the course's ``extensions.yaml`` (empty if none).
    An assignment that is not a problem package of the course is refused (a typo would silently
    give nobody the time)."""
    path = extensions_path(root)
    if not path.is_file():
        return {}
    data = yaml.safe_load(path.read_text()) or {}
    if not isinstance(data, dict):
        raise ValueError(f"{path}: expected student -> assignment -> '<number> minutes|hours|days'")
    folder = path.parent
    out = {}
    for student, items in data.items():
        if not isinstance(items, dict):
            raise ValueError(f"{path}: {student!r} must map assignments to extensions, got {items!r}")
        for assignment, amount in items.items():
            if not (folder / str(assignment) / "problem.yaml").is_file():
                raise ValueError(f"{path}: {student}: no assignment {assignment!r} in {folder}")
            try:
                out[(str(student), str(assignment))] = parse_amount(amount)
            except ValueError as exc:
                raise ValueError(f"{path}: {student} / {assignment}: {exc}") from None
    return out


def extra_seconds(student: str, assignment: str, root: str | Path | None = None) -> float:
    """How much more time ``student`` has for ``assignment`` (0 without an extension)."""
    return load(root).get((student, assignment), 0.0)
