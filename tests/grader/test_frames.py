"""Float answers as binary frames (grader/judging/frames.py): the decoder refuses every malformed
frame with a message naming the fault, a decoded frame is exactly the JSON value, and in the jail a
forged or malformed frame is a verdict (PE) with that message, never a judge error; a frame where
none was asked for is a write on the judge's channel. The voronoi checker's ``from_arrays`` accepts
and rejects exactly what ``from_result`` does, with the same messages.

Run: .venv/bin/python -m pytest tests/grader/test_frames.py -q
"""
from __future__ import annotations

import base64
import json
import math
import random
import struct
import sys
from pathlib import Path

import pytest

from grader.contest.judge import Judge
from grader.judging import frames, runner
from grader.judging.verdicts import Verdict
from grader.problems import load_problem

CELLS = [[[0.5, -0.0], [2.0, 3.25], [1e300, -5e-324]], [], [[4.0, 5.0]]] * 75   # 300 vertices


def _b64(fmt: str, values) -> str:
    return base64.b64encode(struct.pack(f"<{len(values)}{fmt}", *values)).decode()


def test_a_frame_is_the_json_value_bit_for_bit():
    decoded = frames.decode(frames.frame_of(CELLS))
    assert decoded.tolist() == CELLS and len(decoded) == len(CELLS)
    assert decoded.counts.tolist()[:3] == [3, 0, 1] and decoded.rows.shape == (300, 2)
    assert math.copysign(1.0, decoded.tolist()[0][0][1]) == -1.0                 # -0.0 kept
    special = [[math.nan, math.inf]] + [[-math.inf, 1.0]] * 200                  # rows, no groups
    back = frames.decode(frames.frame_of(special))
    assert back.counts is None and back.tolist()[1:] == special[1:] and math.isnan(back.tolist()[0][0])


@pytest.mark.parametrize("value", [
    [[0.5, 1.0]] * 10,                                   # too small: JSON is as cheap
    [[0.5, 1]] * 200,                                    # an int among the floats
    [[0.5, 1.0], [0.5]] * 100,                           # rows of two widths
    [[[0.5, 1.0]] * 100, [[0.5, 1.0, 2.0]] * 100],       # groups whose rows differ in width
    [[[0.5] * 17] * 20],                                 # rows wider than a frame carries
    [[], []],                                            # nothing inside
    [(0.5, 1.0)] * 200,                                  # tuples (the child sends lists only)
    "not a list",
])
def test_only_rows_of_floats_of_one_width_make_a_frame(value):
    assert frames.frame_of(value) is None


GOOD = frames.frame_of(CELLS)


@pytest.mark.parametrize("frame,fault", [
    ([1, 2], "an object with the keys counts, rows and w"),
    ({**GOOD, "extra": 1}, "an object with the keys counts, rows and w"),
    ({**GOOD, "w": 0}, "an integer from 1 to 16"),
    ({**GOOD, "w": True}, "an integer from 1 to 16"),
    ({**GOOD, "w": 2.0}, "an integer from 1 to 16"),
    ({**GOOD, "rows": 17}, "the rows should be a base64 string, got int"),
    ({**GOOD, "counts": [3, 0, 1]}, "the counts should be a base64 string, got list"),
    ({**GOOD, "rows": GOOD["rows"][:-8]}, "not a whole number of rows of 2 float64"),      # truncated
    ({**GOOD, "counts": _b64("i", [3, 0, 1])}, "not a whole number of int64"),
    ({**GOOD, "counts": _b64("q", [3, -1, 298])}, "a group's row count is -1, outside 0..300"),
    ({**GOOD, "counts": _b64("q", [2 ** 62, 2 ** 62, 0])}, f"a group's row count is {2 ** 62}, outside 0..300"),
    ({**GOOD, "counts": _b64("q", [300] * 3)}, "add up to 900, but 300 rows were sent"),
    ({**GOOD, "counts": _b64("q", [])}, "add up to 0, but 300 rows were sent"),
    ({**GOOD, "w": 7}, "not a whole number of rows of 7 float64"),
])
def test_a_malformed_frame_is_refused_naming_the_fault(frame, fault):
    with pytest.raises(ValueError, match="^.*" + fault.replace("(", r"\(").replace(")", r"\)")):
        frames.decode(frame)


def test_base64_is_checked():
    if not frames._STRICT:
        pytest.skip("Python 3.10's base64 decoder skips stray characters (the lengths are still checked)")
    with pytest.raises(ValueError, match="the rows: not valid base64"):
        frames.decode({**GOOD, "rows": "AAAA*AAA"})


# -- the voronoi checker's from_arrays --------------------------------------------------------------
VOR = load_problem("voronoi")
CHK = VOR.checker


def _big_test():
    for t in VOR.tests():
        args = CHK.read_input(t.input_text)
        expected = VOR.read_answer(t, args)
        if 150 <= sum(map(len, expected)) <= 400:
            return t, args, expected
    raise AssertionError("no voronoi test of 150-400 vertices")


def _both(args, value):
    """(from_result's outcome, from_arrays' outcome) on the same value: answer or PresentationError text."""
    out = []
    for parse in (lambda: CHK.from_result(json.loads(json.dumps(value)), args),
                  lambda: CHK.from_arrays(frames.decode(frames.frame_of(value)), args)):
        try:
            answer = parse()
        except CHK.PresentationError as exc:
            out.append(("PE", str(exc)))
        else:
            out.append(("ok", answer))
    return out


def test_from_arrays_rejects_what_from_result_rejects_with_its_message():
    _, args, expected = _big_test()
    n = len(args[0])
    per_cell, total = CHK.max_vertices(n)
    nan = [c[:] for c in expected]
    nan[1] = [[math.nan, 0.5]] + nan[1][1:]
    inf = [c[:] for c in expected]
    inf[2] = [[0.5, -math.inf]] + inf[2][1:]
    for value in (expected[:-1], expected + [expected[0]], nan, inf,
                  [[[0.5, 0.5]] * (per_cell + 1)] + expected[1:],          # one cell over its bound
                  [[[0.5, 0.5]] * (total // n + 2)] * n):                  # too many vertices in all
        assert frames.frame_of(value) is not None
        (kind_a, a), (kind_b, b) = _both(args, value)
        assert kind_a == kind_b == "PE" and a == b


def test_from_arrays_gives_check_the_same_verdicts_and_messages():
    _, args, expected = _big_test()
    rng = random.Random(7)
    answers = [expected, expected[::-1], [c[::-1] for c in expected]]
    for _ in range(6):
        moved = [[v[:] for v in c] for c in expected]
        i = rng.randrange(len(moved))
        if moved[i]:
            moved[i][0] = [moved[i][0][0] + rng.choice([1e-12, 1e-6, 0.1]), moved[i][0][1]]
        answers.append(moved)
    verdicts = set()
    for value in answers:
        (kind_a, a), (kind_b, b) = _both(args, value)
        assert kind_a == kind_b == "ok"
        assert CHK.check(args, a, expected) == CHK.check(args, b, expected)
        verdicts.add(CHK.check(args, a, expected)[0])
    assert verdicts == {True, False}                                       # both kinds were reached


# -- in the jail --------------------------------------------------------------------------------------
FORGE = '''import json, os, time
FRAME = {frame}
def voronoi_cells(points, bbox):
    fd = json.loads(open("/proc/self/cmdline", "rb").read().split(b"\\0")[4])["ctl_out"]
    os.write(fd, json.dumps({{"id": 1, "frame": FRAME}}).encode() + b"\\n")
    time.sleep(5)
'''


@pytest.fixture(scope="module")
def one_test_judge():
    test, _, _ = _big_test()
    judge = Judge("voronoi")
    judge.use_tests([test])
    return judge


def test_the_accepted_solution_is_judged_through_frames(one_test_judge, monkeypatch):
    seen = []
    monkeypatch.setattr(runner, "decode_frame", lambda f: seen.append(1) or frames.decode(f))
    result = one_test_judge.judge_path(Path(__file__).parents[2] / "solutions/voronoi/accepted_clip.py")
    assert [t.verdict for t in result.tests] == [Verdict.AC] and seen == [1]


@pytest.mark.parametrize("frame,fault", [
    ({**GOOD, "counts": _b64("q", [2 ** 62, 2 ** 62, 0])}, "outside 0..300"),
    ({**GOOD, "rows": GOOD["rows"][:-8]}, "not a whole number of rows"),
    ({**GOOD, "counts": _b64("q", [300] * 3)}, "add up to 900"),
    ({"w": 2, "counts": None, "rows": 5}, "the rows should be a base64 string"),
])
def test_a_forged_malformed_frame_is_pe_with_its_fault(one_test_judge, tmp_path, frame, fault):
    path = tmp_path / "forge.py"
    path.write_text(FORGE.format(frame=repr(frame)))
    t = one_test_judge.judge_path(path).tests[0]
    assert t.verdict == Verdict.PE and "the answer's binary frame is malformed" in t.message and fault in t.message


def test_a_well_formed_forged_frame_is_judged_as_its_value(one_test_judge, tmp_path):
    """A NaN in a frame: the checker's own message, as for a NaN sent as JSON; a wrong cell count: PE."""
    _, args, expected = _big_test()
    nan = [c[:] for c in expected]
    nan[0] = [[math.nan, 0.5]] + nan[0][1:]
    for value in (nan, expected[:-1]):
        path = tmp_path / "forge.py"
        path.write_text(FORGE.format(frame=repr(frames.frame_of(value))))
        t = one_test_judge.judge_path(path).tests[0]
        with pytest.raises(CHK.PresentationError) as exc:
            CHK.from_result(value, args)
        assert t.verdict == Verdict.PE and t.message.startswith(str(exc.value))


def test_a_frame_nobody_asked_for_is_a_write_on_the_channel(tiny_judge, tmp_path):
    path = tmp_path / "forge.py"
    path.write_text(FORGE.format(frame=repr(GOOD)).replace("voronoi_cells(points, bbox)", "delaunay(points)"))
    t = tiny_judge.judge_path(path).tests[0]
    assert t.verdict == Verdict.PE and "wrote on the judge's channel" in t.message


def test_corrupted_frames_are_refused_or_read_never_a_crash():
    """500 random corruptions of a good frame (cut, changed characters, other widths and counts):
    ``decode`` raises ValueError or gives consistent arrays, and ``from_arrays`` then answers or
    raises ``PresentationError``: nothing else reaches the judge."""
    _, args, expected = _big_test()
    good = frames.frame_of(expected)
    rng = random.Random(42)
    alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/=*-_ \n\x00é"
    outcomes = {"refused": 0, "read": 0}
    for _ in range(500):
        frame = dict(good)
        key = rng.choice(["rows", "counts", "w", "both"])
        for k in (["rows", "counts"] if key == "both" else [key]):
            if k == "w":
                frame["w"] = rng.choice([1, 2, 3, 4, 16, 17, -1, 2 ** 70, None, "2"])
                continue
            text = list(frame[k])
            for _ in range(rng.randint(1, 4)):
                at = rng.randrange(len(text) + 1)
                op = rng.random()
                if op < 0.3:
                    del text[at:]                                     # cut
                elif op < 0.7 and at < len(text):
                    text[at] = rng.choice(alphabet)                  # a changed character
                else:
                    text[at:at] = rng.choices(alphabet, k=rng.randint(1, 12))
            frame[k] = "".join(text)
        try:
            rows = frames.decode(frame)
        except ValueError:
            outcomes["refused"] += 1
            continue
        outcomes["read"] += 1
        assert rows.rows.dtype.kind == "f" and rows.rows.ndim == 2
        assert rows.counts is None or int(rows.counts.sum()) == len(rows.rows)
        try:
            CHK.check(args, CHK.from_arrays(rows, args), expected)
        except CHK.PresentationError:
            pass
    assert outcomes["refused"] > 100 and outcomes["read"] > 10, outcomes


def test_the_childs_copy_builds_the_same_frames():
    """The jailed child builds frames with its own copy of ``frame_of`` (it imports nothing of the
    grader): on the same values both copies give the same frame, or both none."""
    import ast
    import binascii
    from array import array
    from itertools import chain

    from grader.jail import BOOTSTRAP_PATH
    # the child reads its configuration when it starts, so its function is taken out of its source
    tree = ast.parse(BOOTSTRAP_PATH.read_text())
    source = next(n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == "_frame_of")
    space = {"chain": chain, "array": array, "sys": sys, "binascii": binascii}
    exec(compile(ast.Module([source], []), str(BOOTSTRAP_PATH), "exec"), space)
    child = type("Child", (), {"_frame_of": staticmethod(space["_frame_of"])})
    rng = random.Random(7)
    values = [CELLS, [[0.5, 1.5]] * 128, [[0.5, 1.5]] * 127, [[[1.0, 2.0]] * 100, [[3.0, 4.0]] * 60, []],
              [[1.0, 2.0, 3.0]] * 100, [[1.0] * 17] * 20, [[1, 2]] * 200, [[math.nan, math.inf]] * 200, [], "x",
              [[rng.random(), rng.random()] for _ in range(300)], [[[0.25, 0.75]] * 70] * 2 + [[[1.0]]]]
    for value in values:
        assert child._frame_of(value) == frames.frame_of(value), repr(value)[:80]
