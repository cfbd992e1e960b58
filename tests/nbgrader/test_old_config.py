"""A course deployed before the grader's rooms keeps working: its ``nbgrader_config.py`` (the
course's own with the old module names put back, which is the file as it was before the move)
still loads, every class and name it imports resolves to the moved module's own object, and the
old ``python -m grader.<name>`` commands print what the new modules print.

    .venv/bin/python -m pytest tests/nbgrader/test_old_config.py -n 0 -q   (about 20 s alone)
"""
from __future__ import annotations

import subprocess
import sys

from traitlets.config.loader import PyFileConfigLoader
from traitlets.utils.importstring import import_item

from grader.course import nbgrader_autograde
from grader.judging.submissions import CODE_STUB
from grader.problems import REPO

#: the old module names -> the new ones; the course's config with the old names put back is the
#: config as it was before the move (only these names changed in it)
RENAMED = {"grader.nbgrader_autograde": "grader.course.nbgrader_autograde",
           "grader.course_notebooks": "grader.course.course_notebooks"}


def old_config() -> str:
    """``assignments/nbgrader_config.py`` as a course deployed before the move has it."""
    text = (REPO / "assignments" / "nbgrader_config.py").read_text()
    for old, new in RENAMED.items():
        assert f"from {new} import" in text, new
        text = text.replace(new, old)
    return text


def test_an_old_course_config_still_loads(tmp_path):
    (tmp_path / "nbgrader_config.py").write_text(old_config())
    assert "from grader.nbgrader_autograde import CourseLatePolicy, JudgeCells" in old_config()
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
