"""nbgrader configuration of the course (the course root is this directory, `assignments/`).

Autograding never runs student code in nbgrader's kernel: nbgrader's `Execute` step is replaced
by `grader.course.nbgrader_autograde.JudgeCells`, which judges each notebook with the course's sandboxed
judge and writes every scored group's verdict into its test cell. Late submissions of a timed
problem are penalised by the `timed` policy in its `course.yaml`.

Run nbgrader from this directory with the venv's bin/ on PATH (nbgrader calls `alembic`):
    cd assignments && PATH=$PWD/../.venv/bin:$PATH nbgrader generate_assignment delaunay
"""

import os

from nbgrader.preprocessors import AssignLatePenalties, CheckCellMetadata, LimitOutput, SaveAutoGrades

from grader.course.course_notebooks import CODE_STUB
from grader.course.nbgrader_autograde import CourseLatePolicy, JudgeCells

c = get_config()  # noqa: F821 - provided by nbgrader when it loads this file

c.CourseDirectory.root = os.path.dirname(os.path.abspath(__file__))
c.CourseDirectory.course_id = "delaunay-course"
# problem packages (assignments/<id>/) sit next to source/; only source/<id>/ are assignments
c.CourseDirectory.ignore = [".ipynb_checkpoints", "*.pyc", "__pycache__", "feedback", ".cache"]

# the sandboxed judge instead of kernel execution (sanitising stays nbgrader's own: outputs
# cleared, locked and test cells restored from the gradebook, ids deduplicated)
c.Autograde.autograde_preprocessors = [JudgeCells, LimitOutput, SaveAutoGrades, AssignLatePenalties,
                                       CheckCellMetadata]
c.AssignLatePenalties.plugin_class = CourseLatePolicy
c.LateSubmissionPlugin.penalty_method = "none"

# what the student sees in place of the reference solution
c.ClearSolutions.code_stub = {"python": CODE_STUB}
