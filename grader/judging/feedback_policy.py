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
KEYS = ("hidden", "public", "groups")


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
