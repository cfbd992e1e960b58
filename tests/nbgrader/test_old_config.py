"""A course deployed before the grader's rooms keeps working: its ``nbgrader_config.py`` (the text
below is ``assignments/nbgrader_config.py`` as it was before the move) still loads, and every class
and name it imports from the grader resolves to the moved module's own object.

    .venv/bin/python -m pytest tests/nbgrader/test_old_config.py -n 0 -q   (a second)
"""
from __future__ import annotations

import subprocess
import sys

from traitlets.config.loader import PyFileConfigLoader
from traitlets.utils.importstring import import_item

from grader.course import nbgrader_autograde
from grader.judging.submissions import CODE_STUB
from grader.problems import REPO

OLD_CONFIG = '''\
import os

from nbgrader.preprocessors import AssignLatePenalties, CheckCellMetadata, LimitOutput, SaveAutoGrades

from grader.course_notebooks import CODE_STUB
from grader.nbgrader_autograde import CourseLatePolicy, JudgeCells

c = get_config()  # noqa: F821 - provided by nbgrader when it loads this file

c.CourseDirectory.root = os.path.dirname(os.path.abspath(__file__))
c.CourseDirectory.course_id = "delaunay-course"
c.CourseDirectory.ignore = [".ipynb_checkpoints", "*.pyc", "__pycache__", "feedback", ".cache"]
c.Autograde.autograde_preprocessors = [JudgeCells, LimitOutput, SaveAutoGrades, AssignLatePenalties,
                                       CheckCellMetadata]
c.AssignLatePenalties.plugin_class = CourseLatePolicy
c.LateSubmissionPlugin.penalty_method = "none"
c.ClearSolutions.code_stub = {"python": CODE_STUB}
'''


def test_an_old_course_config_still_loads(tmp_path):
    (tmp_path / "nbgrader_config.py").write_text(OLD_CONFIG)
    config = PyFileConfigLoader("nbgrader_config.py", path=str(tmp_path)).load_config()
    assert config.Autograde.autograde_preprocessors[0] is nbgrader_autograde.JudgeCells
    assert config.AssignLatePenalties.plugin_class is nbgrader_autograde.CourseLatePolicy
    assert config.ClearSolutions.code_stub == {"python": CODE_STUB}
    # a config that names the classes as strings (traitlets' Type traits accept both)
    for name in ("JudgeCells", "CourseLatePolicy"):
        assert import_item(f"grader.nbgrader_autograde.{name}") is getattr(nbgrader_autograde, name)


def test_the_course_config_names_the_new_modules():
    text = (REPO / "assignments" / "nbgrader_config.py").read_text()
    assert "from grader.course.nbgrader_autograde import" in text and "grader.nbgrader_autograde " not in text


def test_the_old_commands_still_run():
    """Each ``python -m grader.<old name>`` prints what the moved module's own command prints."""
    statement = str(REPO / "assignments" / "delaunay" / "statement" / "problem.en.md")
    for old, new, args in (("nbgrader_autograde", "course.nbgrader_autograde", ["--help"]),
                           ("smallcases", "problems.smallcases", ["--help"]),
                           ("student_edition", "course.student_edition", ["--help"]),
                           ("course_notebooks", "course.course_notebooks", ["--help"]),
                           ("public_problems", "course.public_problems", ["--help"]),
                           ("course_markdown", "course.course_markdown", [statement])):
        runs = [subprocess.run([sys.executable, "-m", f"grader.{name}", *args], capture_output=True, text=True,
                               timeout=300, cwd=REPO) for name in (old, new)]
        assert runs[0].returncode == runs[1].returncode == 0, (old, runs[0].stderr, runs[1].stderr)
        assert runs[0].stdout == runs[1].stdout and runs[0].stdout.strip(), old
