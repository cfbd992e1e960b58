"""Student-style submissions to the "circles" problems (obstacle-clearance, largest-empty-circle,
voronoi) get a contest judge's verdicts, never JE: numpy results are converted and accepted,
results of the wrong type are PE, an exception is RE.

Run: .venv/bin/python -m pytest tests/grader/test_problem_circles_students.py -q
"""
from __future__ import annotations

import pytest

from .test_problem_circles import CIRCLES, _problem


# ----------------------------------------------------------------------------- student-style submissions
WRAPPERS = {
    "largest-empty-circle": ("accepted_toussaint.py", "largest_empty_circle",
                             "import numpy as np\n_f = largest_empty_circle\n"
                             "def largest_empty_circle(points):\n    return np.array(_f(points))\n"),
    "voronoi": ("accepted_clip.py", "voronoi_cells",
                "import numpy as np\n_f = voronoi_cells\n"
                "def voronoi_cells(points, bbox):\n    return [np.array(c) for c in _f(points, bbox)]\n"),
    "obstacle-clearance": ("accepted_delaunay.py", "max_clearance",
                           "import numpy as np\n_f = max_clearance\n"
                           "def max_clearance(points, start, goal):\n    return np.float64(_f(points, start, goal))\n"),
}


@pytest.mark.parametrize("pid", CIRCLES)
def test_numpy_results_are_accepted_and_bad_shapes_are_pe_not_je(pid, tmp_path):
    from grader.contest.judge import Judge
    from grader.problems import REPO

    problem = _problem(pid)
    base, entry, wrapper = WRAPPERS[pid]
    judge = Judge(problem, stop_at_first_failure=True)
    sub = tmp_path / "numpy_answer.py"
    sub.write_text((REPO / "solutions" / pid / base).read_text().replace('if __name__ == "__main__":', wrapper + 'if __name__ == "__main__":'))
    assert judge.judge_path(sub).verdict == "AC"
    args = "points, start, goal" if pid == "obstacle-clearance" else "points, bbox" if pid == "voronoi" else "points"
    for body, verdict in (("return {'r': 1}", "PE"), ("return 'circle'", "PE"), ("raise ValueError('no idea')", "RE"),
                          ("return [[float('nan')] * 2] * len(points)", "PE")):
        bad = tmp_path / "bad.py"
        bad.write_text(f"def {entry}({args}):\n    {body}\n")
        result = judge.judge_path(bad)
        assert result.verdict == verdict, (body, [(t.name, str(t.verdict), t.message[:100]) for t in result.tests][:3])
        assert all(t.verdict != "JE" for t in result.tests)
