"""The similarity report of a class (see :mod:`grader.classroom.similarity`): HTML and CSV.

``DIR/similarity.html`` ranks the class by each student's highest score (with a classmate or a
reference) and lists the flagged pairs; ``DIR/similarity/pair-N.html`` shows one flagged pair side
by side with the shared regions highlighted; ``DIR/similarity.csv`` has one row per compared pair.
A submission that runs code from data (``Document.marks``, :mod:`grader.classroom.code_from_data`) is listed
with its reasons on the index, on its pair pages and in the CSV; the code decoded from its data is
shown under its own code, below a comment line naming where it was found.
Everything that came from a submission (folder names, file names, code) is escaped for HTML;
links to a student's grading report (``DIR/students/...``, when ``grade --reports`` wrote one)
are URL-quoted; CSV cells go through :func:`grader.judging.text.csv_cell`.

Example:
    python -m grader similarity delaunay class/ --reports sim/     # then open sim/similarity.html

    >>> show_code("a\\x1b[2J<b>", np.array([[1], [3]]))
    'a<mark>\\\\x1b[</mark>2J&lt;b&gt;'
"""

from __future__ import annotations

import csv
import html
import re
from pathlib import Path
from urllib.parse import quote

import numpy as np

from ..contest.report import STUDENTS_DIR, report_name
from .similarity import THRESHOLD, Analysis, Document, Pair, analyse
from ..judging.text import clean, csv_cell

MEANING = """The score is the share of a submission's code (after dropping comments, whitespace and the
starter code and statement snippets everyone is given, with every name replaced by a placeholder) whose
fingerprints (runs of 25 characters of that filtered code, a name counting as one, chosen by
copydetect's winnowing) also occur in the other file; a pair's
score is the larger of its two shares, and against a reference it is the student's share. 1.0: all of it
is shared; independent solutions of the same problem score about 0.1-0.3 here (they share short idioms
and the input-reading code); a score at or above the threshold is flagged. A high score is a reason to
look at the two files, not a verdict: the highlighted regions are the evidence."""

_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f]")
_CSS = """body{font-family:sans-serif;margin:2em} td,th{border:1px solid #ccc;padding:3px 6px;vertical-align:top}
table{border-collapse:collapse} .flag{color:#b00;font-weight:bold} .side{display:flex;gap:1em}
.side>div{flex:1;min-width:0} pre{background:#f7f7f7;padding:.5em;overflow-x:auto;font-size:12px}
mark{background:#ffd27f} p.meaning{max-width:60em}"""


def _text(piece: str) -> str:
    """Code for display: control and format characters shown as escapes, tabs and newlines kept."""
    if piece.isascii() and not _CONTROL.search(piece):
        return piece  # the common case, without a pass per character
    return "\n".join("\t".join(clean(part, limit=len(part) * 10 + 1) for part in line.split("\t"))
                     for line in piece.split("\n"))


def _word(ch: str) -> bool:
    return ch.isalnum() or ch == "_"


def show_code(code: str, slices: np.ndarray) -> str:
    """``code`` as escaped HTML with the character ranges ``slices`` (2 x n: starts, ends) in ``<mark>``."""
    out, pos = [], 0
    for start, end in sorted(zip(slices[0].tolist(), slices[1].tolist())) if slices.size else []:
        start, end = max(int(start), pos), min(int(end), len(code))
        while pos < start < len(code) and _word(code[start - 1]) and _word(code[start]):
            start -= 1  # copydetect's offsets can fall inside a name: mark whole names
        while 0 < end < len(code) and _word(code[end - 1]) and _word(code[end]):
            end += 1
        if end <= start:
            continue
        out += [html.escape(_text(code[pos:start])), "<mark>", html.escape(_text(code[start:end])), "</mark>"]
        pos = end
    out.append(html.escape(_text(code[pos:])))
    return "".join(out)


def _page(title: str, body: str) -> str:
    return (f'<!doctype html><html><head><meta charset="utf-8"><title>{html.escape(title)}</title>'
            f"<style>{_CSS}</style></head><body>{body}</body></html>")


def _student_link(report_dir: Path, name: str, kind: str, prefix: str = "") -> str:
    """The name, linked to the student's grading report when there is one."""
    target = f"{STUDENTS_DIR}/{report_name(name)}"   # where ``grade --reports`` puts it
    if kind == "student" and (report_dir / target).is_file():
        return f'<a href="{html.escape(prefix + quote(target))}">{html.escape(name)}</a>'
    return html.escape(name)


def pair_page(analysis: Analysis, pair: Pair, number: int) -> str:
    """One flagged pair side by side."""
    a, b = pair.a, pair.b
    body = (f"<h1>{html.escape(analysis.problem)}: pair {number}</h1>"
            f"<p><a href=\"../similarity.html\">back to the class</a></p>"
            f"<p>Score <b class='flag'>{pair.score:.2f}</b> (flagged at {analysis.threshold:g}); "
            f"{pair.tokens} shared tokens; {pair.share_a:.0%} of {html.escape(a.name)}'s code is in the other file, "
            f"{pair.share_b:.0%} of {html.escape(b.name)}'s.</p><p class='meaning'>{html.escape(MEANING)}</p>"
            "<div class='side'>"
            + "".join(f"<div><h2>{html.escape(d.name)}</h2><p>{html.escape(d.path)}</p>{_marks(d)}"
                      f"<pre>{show_code(d.compared, sl)}</pre></div>"
                      for d, sl in ((a, pair.slices_a), (b, pair.slices_b)))
            + "</div>")
    return _page(f"{analysis.problem}: {a.name} ~ {b.name}", body)


def _marks(d: Document) -> str:
    """A submission's marks as an HTML paragraph (empty when it has none)."""
    if not d.marks:
        return ""
    return ("<p class='flag'>Runs code from data: " + html.escape("; ".join(clean(m, 300) for m in d.marks))
            + ". The code decoded from its data is compared too (below its own code).</p>")


def index_page(analysis: Analysis, report_dir: Path, pages: dict[int, str]) -> str:
    """The class ranked by each student's highest score, then the flagged pairs."""
    ranked = sorted(analysis.students, key=lambda d: (-(analysis.best(d).score if analysis.best(d) else -1), d.name))
    rows = []
    for rank, d in enumerate(ranked, 1):
        best = analysis.best(d)
        other = (best.b if best.a is d else best.a) if best else None
        score = f"{best.score:.2f}" if best else "-"
        cls = " class='flag'" if best and best.flagged else ""
        link = f' (<a href="{pages[id(best)]}">side by side</a>)' if best and id(best) in pages else ""
        rows.append(f"<tr><td>{rank}</td><td>{_student_link(report_dir, d.name, d.kind)}</td><td{cls}>{score}</td>"
                    f"<td>{html.escape(other.name) if other else ''}{link}</td><td>{html.escape(d.path)}</td>"
                    f"<td>{html.escape(d.note)}</td><td class='flag'>{html.escape('; '.join(d.marks))}</td></tr>")
    flagged = "".join(
        f"<tr><td>{p.score:.2f}</td><td>{_student_link(report_dir, p.a.name, p.a.kind)}</td>"
        f"<td>{_student_link(report_dir, p.b.name, p.b.kind)}</td><td>{p.tokens}</td>"
        f'<td><a href="{pages[id(p)]}">side by side</a></td></tr>' for p in analysis.flagged)
    marked = "".join(f"<li><b>{_student_link(report_dir, d.name, d.kind)}</b>: {html.escape('; '.join(d.marks))}</li>"
                     for d in analysis.marked)
    refs = "".join(f"<li>{html.escape(r.name)} ({html.escape(r.path)})</li>" for r in analysis.references)
    body = (f"<h1>{html.escape(analysis.problem)}: similarity of {len(analysis.students)} submissions</h1>"
            f"<p class='meaning'>{html.escape(MEANING)}</p>"
            f"<p>Flagged: score at least {analysis.threshold:g} (and at least 100 shared tokens): "
            f"<b>{len(analysis.flagged)}</b> pairs. CSV of every pair: <a href=\"similarity.csv\">similarity.csv</a>. "
            f"References compared with every student:</p><ul>{refs}</ul>"
            "<h2>Flagged pairs</h2><table><tr><th>score</th><th>submission</th><th>with</th><th>shared tokens</th>"
            f"<th></th></tr>{flagged}</table>"
            f"<h2>Submissions that run code from data</h2><p>{len(analysis.marked)} marked (code run by exec, eval, "
            "compile, marshal, pickle or a computed import, or Python code held encoded in a string; "
            f"what could be decoded is compared like their own code).</p><ul>{marked}</ul>"
            "<h2>The class, highest similarity first</h2><table><tr><th>#</th><th>student</th><th>highest score</th>"
            f"<th>with</th><th>file</th><th>note</th><th>runs code from data</th></tr>{''.join(rows)}</table>")
    return _page(f"{analysis.problem}: similarity", body)


def write_csv(analysis: Analysis, path: Path) -> None:
    """One row per compared pair, highest score first."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["score", "flagged", "a", "b", "b_kind", "share_a", "share_b", "shared_tokens", "a_file", "b_file",
                    "a_marks", "b_marks"])
        for p in analysis.pairs:
            w.writerow([f"{p.score:.4f}", "yes" if p.flagged else "", csv_cell(p.a.name), csv_cell(p.b.name), p.b.kind,
                        f"{p.share_a:.4f}", f"{p.share_b:.4f}", p.tokens, csv_cell(p.a.path), csv_cell(p.b.path),
                        csv_cell("; ".join(p.a.marks)), csv_cell("; ".join(p.b.marks))])


def write_reports(analysis: Analysis, report_dir: Path) -> Path:
    """Write the index, the pair pages and the CSV; returns the index's path."""
    pair_dir = report_dir / "similarity"
    pair_dir.mkdir(parents=True, exist_ok=True)
    for old in pair_dir.glob("pair-*.html"):  # a rerun must not leave pages of pairs no longer flagged
        old.unlink()
    pages = {}
    for number, pair in enumerate(analysis.flagged, 1):
        (pair_dir / f"pair-{number}.html").write_text(pair_page(analysis, pair, number))
        pages[id(pair)] = f"similarity/pair-{number}.html"
    write_csv(analysis, report_dir / "similarity.csv")
    index = report_dir / "similarity.html"
    index.write_text(index_page(analysis, report_dir, pages))
    return index


def run(problem: str, root: str | Path, report_dir: str | Path, references: list[str | Path] = (),
        extra_boilerplate: list[str | Path] = (), threshold: float = THRESHOLD) -> Analysis:
    """Analyse the class (:func:`grader.classroom.similarity.analyse`) and write ``report_dir/similarity.html``,
    ``similarity.csv`` and one page per flagged pair under ``report_dir/similarity/``."""
    analysis = analyse(problem, root, references, extra_boilerplate, threshold)
    write_reports(analysis, Path(report_dir))
    return analysis
