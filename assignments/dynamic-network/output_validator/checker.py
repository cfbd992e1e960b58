"""Checker for `dynamic-network`: every answer must equal the reference's, exactly.

Each answer is unique (ids and counts are integers, the strict Delaunay graph does not depend on
how ties are broken), so the check compares the received answers with the reference's one by one
and reports the first difference: the operation, its position, what was expected and what came,
and, for short sequences, the operations up to there. The grader loads this file with the shared
loader (``grader/checker_runtime.py``); ``export-kattis`` makes it a self-contained Kattis output
validator.

Example:
    >>> ops = [["join", 0.0, 0.0], ["join", 1.0, 0.0], ["neighbors", 0], ["count"]]
    >>> check([ops], [0, 1, [1], 2], [0, 1, [1], 2])
    (True, 'ok')
"""
from __future__ import annotations

LIBRARY = ("judge_io",)  # bound as globals by the shared loader

PresentationError = judge_io.PresentationError  # noqa: F821 - bound by the loader
show, mistake = judge_io.show, judge_io.mistake  # noqa: F821 - safe previews, two-part messages

SHOW_OPERATIONS = 30  # sequences up to this long are quoted in a wrong answer's message


def read_input(text: str) -> list:
    """``[operations]`` from ``q`` and ``q`` lines ``join x y`` / ``fail i`` / ``neighbors i`` / ``count``."""
    lines = text.split("\n")
    ops = []
    for line in lines[1:int(lines[0]) + 1]:
        p = line.split()
        ops.append([p[0], float(p[1]), float(p[2])] if p[0] == "join" else [p[0]] + [int(v) for v in p[1:]])
    return [ops]


def _op_text(op) -> str:
    return " ".join([op[0]] + [repr(float(v)) if op[0] == "join" else str(v) for v in op[1:]])


def write_input(args: list) -> str:
    (ops,) = args
    return f"{len(ops)}\n" + "".join(_op_text(op) + "\n" for op in ops)


def _answer(value, op, k: int, joins: int):
    where = f"answer {k} (operation '{_op_text(op)}')"
    name = op[0]
    if name in ("join", "count"):
        return judge_io.as_index(value, where)  # noqa: F821
    if name == "fail":
        if value in ("ok", "error") and type(value) is str:
            return value
        raise PresentationError(f"{where}: expected \"ok\" or \"error\", got {show(value, 40)}")
    if type(value) is str:
        if value == "error":
            return value
        raise PresentationError(f"{where}: expected a list of ids or \"error\", got {show(value, 40)}")
    if not isinstance(value, list):
        raise PresentationError(f"{where}: expected a list of ids or \"error\", got {type(value).__name__}")
    if len(value) > joins:
        raise PresentationError(f"{where}: {len(value)} ids, but only {joins} nodes have joined")
    return [judge_io.as_index(v, where) for v in value]  # noqa: F821


def from_result(value, args: list) -> list:
    """One answer per operation: ints for join/count, "ok"/"error" for fail, a list of ints or "error"."""
    (ops,) = args
    if not isinstance(value, list):
        raise PresentationError(f"expected a list of {len(ops)} answers, got {type(value).__name__}: {show(value, 60)}")
    if len(value) != len(ops):
        raise PresentationError(f"expected one answer per operation ({len(ops)}), got {len(value)}")
    out, joins = [], 0
    for k, (v, op) in enumerate(zip(value, ops)):
        joins += op[0] == "join"
        out.append(_answer(v, op, k, joins))
    return out


def read_output(text: str, args: list) -> list:
    """Program output: one line per operation; a neighbour list is ``m`` then the ``m`` ids, or ``error``."""
    (ops,) = args
    lines = [ln for ln in text.split("\n") if ln.strip()]  # the text is bounded by the output limit
    if len(lines) != len(ops):
        raise PresentationError(f"expected {len(ops)} lines (one per operation), got {len(lines)}")
    out, joins = [], 0
    for k, (ln, op) in enumerate(zip(lines, ops)):
        joins += op[0] == "join"
        parts = ln.split()
        where = f"line {k + 1} (operation '{_op_text(op)}')"
        if op[0] == "fail" or parts == ["error"]:
            out.append(_answer(ln.strip(), op, k, joins))
            continue
        nums = [judge_io.parse_int(p, where, "integers") for p in parts]  # noqa: F821
        if op[0] != "neighbors":
            if len(nums) != 1:
                raise PresentationError(f"{where}: expected one integer, got {show(ln, 60)}")
            out.append(nums[0])
        elif nums[0] != len(nums) - 1 or nums[0] < 0:
            raise PresentationError(f"{where}: expected m and then m ids, got {show(ln, 60)}")
        else:
            out.append(_answer(nums[1:], op, k, joins))
    return out


def write_output(answers: list) -> str:
    return "".join((" ".join(map(str, [len(a)] + a)) if isinstance(a, list) else str(a)) + "\n" for a in answers)


#: failure message (a substring) -> the kind of mistake a hidden test's feedback shows (no numbers)
MISTAKES = {
    "sorted increasing": "a neighbour list is not sorted or has repeats",
}


@judge_io.mistake_kinds(MISTAKES, "an answer differs from the correct one")  # noqa: F821 - bound by the loader
def check(args: list, answers: list, expected: list | None) -> tuple[bool, str]:
    """Exact comparison with the reference answers; the message names the first wrong one."""
    (ops,) = args
    if expected is None:
        return True, "ok (not compared with the reference answers)"
    for k, (got, want) in enumerate(zip(answers, expected)):
        if got == want:
            continue
        op = ops[k]
        msg = f"answer {k} (operation '{_op_text(op)}'): expected {_show(want)}, got {_show(got)}"
        if isinstance(got, list) and isinstance(want, list):
            if sorted(set(got)) == want:
                msg += " (the ids must be sorted increasing, each once)"
            else:
                extra, missing = sorted(set(got) - set(want)), sorted(set(want) - set(got))
                msg += f" (extra: {_show(extra)}, missing: {_show(missing)})"
        if len(ops) <= SHOW_OPERATIONS:
            msg += "; operations: " + "; ".join(_op_text(o) for o in ops[:k + 1])
        return False, msg
    return True, "ok"


def _show(a) -> str:
    if isinstance(a, list) and len(a) > 12:
        return "[" + ", ".join(map(str, a[:12])) + f", ... ({len(a)} ids)]"
    return repr(a)


def draw(axes, args: list, received: list, expected: list | None) -> None:
    """Picture for reports: every joined position, and the first wrongly answered query's node with
    the expected (left) and received (right) links."""
    (ops,) = args
    pos = [(op[1], op[2]) for op in ops if op[0] == "join"]
    k = next((k for k, (g, w) in enumerate(zip(received or [], expected or [])) if g != w and ops[k][0] == "neighbors"),
             None)
    for ax, answers, title in ((axes[0], expected, "expected"), (axes[1], received, "received")):
        if pos:
            ax.scatter([p[0] for p in pos], [p[1] for p in pos], s=10, color="black", zorder=3)
        if k is not None and answers is not None and isinstance(answers[k], list):
            node = ops[k][1]
            for j in answers[k]:
                if 0 <= node < len(pos) and 0 <= j < len(pos):
                    ax.plot([pos[node][0], pos[j][0]], [pos[node][1], pos[j][1]], color="tab:red", lw=1.0)
            title += f": neighbours of {node} (answer {k})"
        ax.set_title(title, fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
