"""The checker rule, fuzzed: on any input, ``from_result``, ``read_output`` and ``check`` of every
checker raise nothing but ``PresentationError`` (or the checker's ``WrongAnswer``), and every
exported Kattis output validator exits 42 or 43 with a message, never a traceback.

Hostile values come from hypothesis (unicode digits, huge ints, ints where floats go, NaN/inf,
bools, strings, bytes, deep nesting, long lists) put into the reference answer of a sample at a
random position, or on their own; hostile texts replace tokens of the reference output.
"""

from __future__ import annotations

import io
import json
import sys

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from grader.judging import checker_runtime
from grader.judging.checker_attacks import HOSTILE_TEXTS, HOSTILE_TOKENS, HOSTILE_VALUES, check_one, rule_violations, sample_data
from grader.problems import list_problems

PROBLEMS = {p.id: p for p in list_problems()}
SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=list(HealthCheck), database=None)


def test_all_twelve_checkers_are_fuzzed():
    assert len(PROBLEMS) == 12


leaves = st.one_of(
    st.sampled_from(HOSTILE_VALUES),
    st.none(), st.booleans(),
    st.integers(), st.integers(min_value=10 ** 300, max_value=10 ** 1000), st.floats(allow_nan=True),
    st.text(alphabet=st.sampled_from("0123456789²³¹١٢٣𝟙.-+eE naif_x\u200b\n"), max_size=40),
    st.binary(max_size=8),
)
values = st.recursive(leaves, lambda inner: st.lists(inner, max_size=5) | st.tuples(inner, inner), max_leaves=25)
tokens = st.one_of(st.sampled_from(HOSTILE_TOKENS), st.text(alphabet=st.sampled_from("0123456789²١.-+eEnaif_ \n"),
                                                            min_size=1, max_size=12),
                   st.integers().map(str), st.floats().map(repr))


def _plant(base, path: list[int], leaf):
    if not path or not isinstance(base, list) or not base:
        return leaf
    k = path[0] % len(base)
    return base[:k] + [_plant(base[k], path[1:], leaf)] + base[k + 1:]


def _sample(pid: str, data):
    """A problem's checker and one of its samples, drawn."""
    p = PROBLEMS[pid]
    samples = sample_data(p)
    return (p.checker, *samples[data.draw(st.integers(0, len(samples) - 1))])


@pytest.mark.parametrize("pid", sorted(PROBLEMS))
@SETTINGS
@given(data=st.data())
def test_from_result_and_check_raise_only_presentation_errors(pid, data):
    chk, args, expected = _sample(pid, data)
    base = json.loads(json.dumps(expected, allow_nan=True))
    value = data.draw(st.one_of(values, st.builds(_plant, st.just(base), st.lists(st.integers(0, 50), max_size=4),
                                                  values)))
    assert check_one(chk, args, expected, "from_result", value) == ""


@pytest.mark.parametrize("pid", sorted(PROBLEMS))
@SETTINGS
@given(data=st.data())
def test_read_output_and_check_raise_only_presentation_errors(pid, data):
    chk, args, expected = _sample(pid, data)
    words = chk.write_output(expected).split(" ")
    k = data.draw(st.integers(0, len(words)))
    text = data.draw(st.one_of(
        st.sampled_from(HOSTILE_TEXTS),
        st.builds(lambda t: " ".join(words[:k] + [t] + words[k + 1:]), tokens),
        st.lists(tokens, max_size=12).map(" ".join)))
    assert check_one(chk, args, expected, "read_output", text) == ""


@pytest.mark.parametrize("pid", sorted(PROBLEMS))
def test_fixed_corpus_on_every_sample(pid):
    p = PROBLEMS[pid]
    for args, expected in sample_data(p):
        assert rule_violations(p.checker, args, expected) == []


def _kattis_namespace(p) -> dict:
    ns = {"__name__": f"kattis_{p.id.replace('-', '_')}"}
    exec(compile(checker_runtime.embed(p.checker_path.read_text()), "checker.py", "exec"), ns)
    return ns


@pytest.fixture(scope="module")
def kattis():
    return {pid: _kattis_namespace(p) for pid, p in PROBLEMS.items()}


def _run_kattis(ns: dict, tmp_path, input_text: str, answer_text: str, team: bytes) -> tuple[int, str]:
    (tmp_path / "in").write_text(input_text)
    (tmp_path / "ans").write_text(answer_text)
    old = sys.stdin
    sys.stdin = io.TextIOWrapper(io.BytesIO(team))
    try:
        code = ns["_checker_runtime"]["kattis_main"](ns, ["checker.py", str(tmp_path / "in"), str(tmp_path / "ans"),
                                                          str(tmp_path)])
    finally:
        sys.stdin = old
    return code, (tmp_path / "judgemessage.txt").read_text()


@pytest.mark.parametrize("pid", sorted(PROBLEMS))
@settings(max_examples=25, deadline=None, suppress_health_check=list(HealthCheck), database=None)
@given(data=st.data())
def test_exported_kattis_validator_never_crashes(pid, data, kattis, tmp_path_factory):
    p = PROBLEMS[pid]
    sample = sorted((p.path / "data" / "sample").glob("*.in"))[0]
    input_text, answer_text = sample.read_text(), sample.with_suffix(".ans").read_text()
    words = answer_text.split(" ")
    k = data.draw(st.integers(0, len(words)))
    team = data.draw(st.one_of(
        st.sampled_from(HOSTILE_TEXTS).map(str.encode),
        st.builds(lambda t: " ".join(words[:k] + [t] + words[k + 1:]).encode(), tokens),
        st.binary(max_size=30)))
    code, message = _run_kattis(kattis[pid], tmp_path_factory.mktemp("fb"), input_text, answer_text, team)
    assert code in (42, 43) and message.strip()


@pytest.mark.parametrize("pid", sorted(PROBLEMS))
def test_exported_kattis_validator_accepts_the_answer_and_rejects_the_issue_attacks(pid, kattis, tmp_path):
    p = PROBLEMS[pid]
    sample = sorted((p.path / "data" / "sample").glob("*.in"))[0]
    input_text, answer_text = sample.read_text(), sample.with_suffix(".ans").read_text()
    assert _run_kattis(kattis[pid], tmp_path, input_text, answer_text, answer_text.encode())[0] == 42
    for team in ("²\n", "5" * 5000 + "\n", "1" * 401 + " " + answer_text, "\u00b9 0 0\n"):
        code, message = _run_kattis(kattis[pid], tmp_path, input_text, answer_text, team.encode())
        assert code == 43, (team[:20], message)
