"""How much of a failing test a student's feedback shows, per group: the ``feedback:`` schema of
a problem's ``course.yaml``, in one place.

A **level** names what a student's feedback holds about a failing test of a group. Levels are
listed in :data:`LEVELS`, weakest first; each says whether a hidden group may use it (only a
level that shows no test data may):

==========  =======  ============================================================================
level       hidden   the student sees
==========  =======  ============================================================================
verdict     yes      the test's verdict and time only
message     yes      the verdict and the checker's message: for a hidden group only the kind of
                     mistake (no number of the test, :mod:`grader.judging.hidden_feedback`); for a
                     public group the checker's message as it is
input       no       for a public group, also the failing input (what the statement's samples
                     show anyway)
==========  =======  ============================================================================

The schema (every key optional; without a ``feedback:`` section, feedback is as it always was:
``message`` for every group)::

    feedback:
      hidden: verdict          # every hidden group
      public: input            # every public group (the samples)
      groups: {large: message} # one group, by name (wins over the two above)
      counterexample: true     # search small public inputs for one a failing submission gets wrong
      counterexample_seconds: 10   # the search's budget per submission (seconds)

The counterexample (:mod:`grader.contest.counterexample`) is not test data: the grader makes it
from public generators and checks that it is no test's input, so it is shown for hidden groups
too; ``counterexample: false`` (or ``counterexample_seconds: 0``) turns it off for the problem.
:func:`counterexample_seconds` reads the two keys (a bad value is a ``ValueError`` naming the
problem).

A level that shows test data on a hidden group, an unknown level, key or group is a
``ValueError`` naming the problem. **Adding a level** (such as a small counterexample found by
the grader itself, which is not hidden data): one :class:`Level` in :data:`LEVELS`, with
``hidden_ok`` saying whether it may be used on hidden groups, and its rendering where feedback
is written (:func:`grader.course.nbgrader_autograde.test_line`).

Example:
    >>> resolve("demo", {"hidden": "verdict"}, {"sample": True, "large": False})
    {'sample': 'message', 'large': 'verdict'}
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Level:
    name: str
    hidden_ok: bool  #: may a hidden group use it (it shows no test data)
    shows: str  #: what the student sees, for docs and errors


LEVELS: dict[str, Level] = {lv.name: lv for lv in (
    Level("verdict", True, "the verdict only"),
    Level("message", True, "the verdict and the checker's message (hidden groups: the kind of mistake only)"),
    Level("input", False, "also the failing input (public groups only)"),
)}
DEFAULT = "message"
KEYS = ("hidden", "public", "groups", "counterexample", "counterexample_seconds")
COUNTEREXAMPLE_SECONDS = 10.0  #: the search's default budget per submission


def counterexample_seconds(problem: str, raw: object) -> float:
    """The counterexample search's budget from course.yaml's ``feedback`` (0: off).

    >>> counterexample_seconds("demo", None), counterexample_seconds("demo", {"counterexample": False})
    (10.0, 0.0)
    >>> counterexample_seconds("demo", {"counterexample_seconds": 2.5})
    2.5
    """
    raw = raw if isinstance(raw, dict) else {}
    on = raw.get("counterexample", True)
    if not isinstance(on, bool):
        raise ValueError(f"problem {problem!r}: course.yaml feedback counterexample must be true or false, got {on!r}")
    seconds = raw.get("counterexample_seconds", COUNTEREXAMPLE_SECONDS)
    if isinstance(seconds, bool) or not isinstance(seconds, (int, float)) or not 0 <= seconds <= 600:
        raise ValueError(f"problem {problem!r}: course.yaml feedback counterexample_seconds must be a number of "
                         f"seconds from 0 to 600, got {seconds!r}")
    return float(seconds) if on else 0.0


def _level(problem: str, where: str, value: object) -> str:
    if not isinstance(value, str) or value not in LEVELS:
        raise ValueError(f"problem {problem!r}: course.yaml feedback {where}: unknown level {value!r} "
                         f"(levels: {', '.join(LEVELS)})")
    return value


def resolve(problem: str, raw: object, groups: dict[str, bool]) -> dict[str, str]:
    """group -> level from course.yaml's ``feedback`` (``groups``: group name -> is it public)."""
    if raw is None:
        raw = {}
    if not isinstance(raw, dict) or set(raw) - set(KEYS):
        raise ValueError(f"problem {problem!r}: course.yaml 'feedback' takes {', '.join(KEYS)}, got {raw!r}")
    hidden = _level(problem, "hidden", raw.get("hidden", DEFAULT))
    public = _level(problem, "public", raw.get("public", DEFAULT))
    named = raw.get("groups") or {}
    if not isinstance(named, dict):
        raise ValueError(f"problem {problem!r}: course.yaml feedback groups must map group names to levels")
    unknown = sorted(set(named) - set(groups))
    if unknown:
        raise ValueError(f"problem {problem!r}: course.yaml feedback names unknown group(s) {', '.join(unknown)}")
    out = {}
    for g, is_public in groups.items():
        level = _level(problem, f"groups.{g}", named[g]) if g in named else (public if is_public else hidden)
        if not is_public and not LEVELS[level].hidden_ok:
            raise ValueError(f"problem {problem!r}: feedback level {level!r} ({LEVELS[level].shows}) shows test data: "
                             f"group {g!r} is hidden")
        out[g] = level
    return out
