"""The course notebooks' statements as formgrader converts them: nbconvert's HTMLExporter with
nbgrader's ``formgrade`` template (the exporter formgrader builds in its server extension).

Checks what the converter makes of the markdown: the limits and grading tables are real
``<table>``s with one ``<th>`` per header, and the maths keeps its ``$...$`` delimiters and TeX
(backslashes, braces, no ``<em>`` from underscores), which MathJax's ``tex2jax`` picks up. It does
not check that a browser shows them styled: formgrader's template loads MathJax from cdnjs only
and leaves out nbconvert's notebook CSS (see the report of issue 26 item 7).

Run: .venv/bin/python -m pytest tests/nbgrader/test_formgrade_render.py -n 0 -q
"""
from __future__ import annotations

import re

import nbformat
import pytest

from grader.course_notebooks import notebook_path
from grader.problems import list_problems

nbgrader_handlers = pytest.importorskip("nbgrader.server_extensions.formgrader.handlers")


@pytest.fixture(scope="module")
def exporter():
    from nbconvert.exporters import HTMLExporter
    from traitlets.config import Config

    c = Config()
    c.HTMLExporter.template_name = "formgrade"  # as FormgradeExtension.build_extra_config sets it
    c.HTMLExporter.extra_template_basedirs = [nbgrader_handlers.template_path]
    return HTMLExporter(config=c)


RESOURCES = {"base_url": "", "submission_id": "x", "notebook_id": "n", "assignment_id": "a", "index": 0,
             "total": 1, "notebook_path": "x"}


@pytest.mark.parametrize("problem_id", [p.id for p in list_problems()])
def test_statement_tables_and_maths_survive_the_formgrade_converter(exporter, problem_id):
    nb = nbformat.read(notebook_path(problem_id), as_version=4)
    html, _ = exporter.from_notebook_node(nb, resources=dict(RESOURCES))
    tables = re.findall(r"<table>(.*?)</table>", html, re.S)
    heads = [re.findall(r"<th(?:\s[^>]*)?>(.*?)</th>", t, re.S) for t in tables]
    assert ["group", "points", "tests", "data"] in heads, heads  # the grading table of every notebook
    limits = [h for h in heads if h[:2] == ["group", "points"] and "largest n" in h]
    if "BEGIN GENERATED: limits" in nb.cells[0].source:
        assert limits, heads
    source_maths = re.findall(r"(?<![\\$])\$([^$\n]+)\$", nb.cells[0].source)
    for tex in source_maths:
        if "`" in tex:
            continue  # a dollar inside code, not maths
        escaped = tex.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
        assert f"${tex}$" in html or f"${escaped}$" in html, (problem_id, tex)
    assert "inlineMath: [ ['$','$']" in html  # the MathJax configuration that reads $...$
