"""The course notebooks read right where there is no MathJax and no table CSS: formgrader's
submission page and the feedback page nbgrader returns (both nbconvert HTML, MathJax from a CDN
a course server cannot reach), and JupyterLab.

Every statement's maths becomes HTML text (no ``$...$`` left for MathJax to miss), every pipe
table a ``<table>`` whose cells carry their own padding (the limits table's headers no longer read
"pointstestslargest nnote"), and every statement picture an attachment of its cell, which the
formgrade and feedback templates embed. The pages are rendered with nbgrader's own templates.

Run: .venv/bin/python -m pytest tests/nbgrader/test_formgrade_render.py -q
"""

from __future__ import annotations

import re
from pathlib import Path
from html.parser import HTMLParser

import nbformat
import pytest
from nbconvert.exporters import HTMLExporter
from traitlets.config import Config

from grader.course.course_markdown import notebook_markdown, table_html, tex_to_html
from grader.course.course_notebooks import notebook_path
from grader.problems import list_problems

PROBLEMS = list_problems()
IDS = [p.id for p in PROBLEMS]
_CODE = re.compile(r"`+[^`]*`+")
_TABLE_RULE = re.compile(r"^\s*\|?\s*:?-{3,}:?\s*\|", re.M)


def _prose(markdown: str) -> str:
    """``markdown`` without its code (indented blocks, fences, code spans): where maths may not stay."""
    out, fence, prev_blank = [], False, True
    for line in markdown.split("\n"):
        if line.lstrip().startswith("```"):
            fence = not fence
            continue
        if fence or (line.startswith("    ") and prev_blank):
            continue
        prev_blank = not line.strip()
        out.append(_CODE.sub("", line))
    return "\n".join(out)


@pytest.mark.parametrize("problem", PROBLEMS, ids=IDS)
def test_statement_cell_has_no_tex_and_no_pipe_table(problem):
    statement = (problem.path / "statement" / "problem.en.md").read_text()
    nb = nbformat.read(notebook_path(problem.id), 4)
    cell = next(c for c in nb.cells if c.id == "statement")
    prose = _prose(cell.source)
    assert "$" not in prose, re.findall(r".{20}\$.{20}", prose)
    assert not re.search(r"\\[A-Za-z,]", prose), re.findall(r".{20}\\[A-Za-z,].{20}", prose)
    assert not re.search(r"^\s*\|?\s*-{3,}\s*\|", cell.source, re.M), "a pipe table is left"
    assert cell.source.count("<table") == len(_TABLE_RULE.findall(_prose(statement)))
    # every maths symbol a statement uses came through as its character
    for tex, char in ((r"\le", "≤"), (r"\ge", "≥"), (r"\sqrt", "√"), (r"\varepsilon", "ε"), (r"\approx", "≈")):
        if tex in statement:
            assert char in cell.source, f"{tex} was not rendered as {char}"
    # a picture beside the statement travels in the cell
    if (problem.path / "statement" / "sample.png").is_file():
        assert "attachment:sample.png" in cell.source
        assert set(cell.attachments) == {"sample.png"}
        assert cell.attachments["sample.png"]["image/png"].startswith("iVBOR")  # base64 of a PNG header


def test_code_is_left_exactly_as_written():
    text = "Cost $n$ here.\n\n    $ 4 cost $5\n    x_1 \\le 2\n\nand `$n$` and\n```\n$x$\n```\n"
    md, attachments = notebook_markdown(text)
    assert md == "Cost <i>n</i> here.\n\n    $ 4 cost $5\n    x_1 \\le 2\n\nand `$n$` and\n```\n$x$\n```\n"
    assert attachments == {}


@pytest.mark.parametrize("tex, html", [
    (r"0 \le n \le 200\,000", "0 ≤ <i>n</i> ≤ 200\u202f000"),
    (r"n(n-1)/2", "<i>n</i>(<i>n</i>−1)/2"),
    (r"10^{-300}", "10<sup>−300</sup>"),
    (r"x_{min}\ y_{min}", "<i>x</i><sub>min</sub> <i>y</i><sub>min</sub>"),
    (r"\sqrt{10} + 2 + \sqrt{18} \approx 9.405", "√10 + 2 + √18 ≈ 9.405"),
    (r"\sqrt{3 \cdot 0.375^2}", "√(3 · 0.375<sup>2</sup>)"),
    (r"3\sqrt 5", "3√5"),
    (r"y_{min} < y_{max}", "<i>y</i><sub>min</sub> &lt; <i>y</i><sub>max</sub>"),
    (r"|ab| \ge 2r", "&#124;<i>ab</i>&#124; ≥ 2<i>r</i>"),
    (r"L \le L^* (1 + 10^{-9})", "<i>L</i> ≤ <i>L</i><sup>&#42;</sup> (1 + 10<sup>−9</sup>)"),
    (r"D = \max(x_{max} - x_{min}, y_{max} - y_{min})",
     "<i>D</i> = max(<i>x</i><sub>max</sub> − <i>x</i><sub>min</sub>, <i>y</i><sub>max</sub> − <i>y</i><sub>min</sub>)"),
    (r"O(n \log n)", "<i>O</i>(<i>n</i> log <i>n</i>)"),
    (r"10^{\pm 300}", "10<sup>±300</sup>"),
    (r"r^* = \infty", "<i>r</i><sup>&#42;</sup> = ∞"),
])
def test_tex_to_html(tex, html):
    assert tex_to_html(tex) == html


def test_an_unknown_tex_command_is_named():
    with pytest.raises(ValueError, match=r"\\frac"):
        tex_to_html(r"\frac{1}{2}")


class _Table(HTMLParser):
    """The header cells of the first table and whether each carries padding."""

    def __init__(self):
        super().__init__()
        self.headers, self._in = [], False

    def handle_starttag(self, tag, attrs):
        if tag == "th":
            self._in = True
            self.headers.append(["", "padding" in dict(attrs).get("style", "")])

    def handle_endtag(self, tag):
        self._in = self._in and tag != "th"

    def handle_data(self, data):
        if self._in:
            self.headers[-1][0] += data


def test_table_cells_are_padded_and_read_their_markdown():
    t = table_html(["| group | points | note |", "| --- | --- | --- |", "| `sample` | 0 | **shown** $n \\le 3$ |"])
    parser = _Table()
    parser.feed(t)
    assert parser.headers == [["group", True], ["points", True], ["note", True]]
    assert "<code>sample</code>" in t and "<b>shown</b> <i>n</i> ≤ 3" in t


def _exporter(template: str) -> HTMLExporter:
    from nbgrader.server_extensions.formgrader import handlers
    c = Config()  # as formgrader (formgrader.py) and GenerateFeedback (generate_feedback.py) set it
    c.HTMLExporter.template_name = template
    c.HTMLExporter.extra_template_basedirs = [handlers.template_path]
    c.HTMLExporter.extra_template_paths = [str(Path(handlers.__file__).parent / "static" / "node_modules" / "bootstrap"
                                               / "dist" / "css")]
    return HTMLExporter(config=c)


@pytest.mark.parametrize("template", ["formgrade", "feedback"])
def test_nbgraders_pages_show_maths_tables_and_pictures(template):
    """Each problem's notebook through formgrader's (and feedback's) own nbconvert template."""
    exporter = _exporter(template)
    resources = {"assignment_id": "a", "notebook_id": "n", "submission_id": "s", "index": 0, "total": 1,
                 "base_url": "", "student": "ada", "last_name": "L", "first_name": "F", "notebook_path": "/n"}
    for problem in PROBLEMS:
        nb = nbformat.read(notebook_path(problem.id), 4)
        for cell in nb.cells:  # what GetGrades leaves on a graded notebook, which the feedback page reads
            if cell.metadata["nbgrader"].get("grade"):
                cell.metadata["nbgrader"]["score"] = 0
        res = dict(resources, nbgrader={"notebook": problem.id, "score": 0, "max_score": 100, "late_penalty": 0})
        page, _ = exporter.from_notebook_node(nb, resources=res)
        body = page[page.index("<body"):]
        body = re.sub(r"<script.*?</script>", "", body, flags=re.S)
        text = re.sub(r"<pre.*?</pre>|<code.*?</code>", "", body, flags=re.S)
        assert not re.search(r"\$[^$\n]{1,60}\$", text), (problem.id, re.findall(r".{30}\$[^$\n]{1,60}\$", text))
        assert "\\le" not in text and "\\sqrt" not in text, problem.id
        parser = _Table()
        parser.feed(body)
        names = " | ".join(h for h, _ in parser.headers)
        assert "group | points | tests | largest n | note" in names, (problem.id, names)  # the limits table
        assert all(padded for _, padded in parser.headers), problem.id
        if (problem.path / "statement" / "sample.png").is_file():
            assert re.search(r'<img[^>]+src="data:image/png;base64,iVBOR', body), f"{problem.id}: picture missing"
