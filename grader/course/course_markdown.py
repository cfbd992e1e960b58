"""Statement markdown made to render the same in JupyterLab, formgrader and the feedback page.

A problem statement is written for a reader with MathJax and a styled page: ``$n \\le 250$``,
pipe tables, ``![picture](sample.png)`` beside the statement. nbgrader's formgrader and the
feedback HTML it returns load MathJax from a CDN (no network on a course server: the reader sees
raw ``$n \\le 250$``), give tables no padding (the limits table's headers read
"pointstestslargest nnote"), and a notebook cannot see a picture next to the statement file.
:func:`notebook_markdown` rewrites a statement so that it needs none of these:

- inline maths becomes HTML text: symbols as Unicode (``\\le`` as ≤, ``\\sqrt{10}`` as √10),
  ``^``/``_`` as ``<sup>``/``<sub>``, variables in italics;
- a pipe table becomes an HTML ``<table>`` whose cells carry their own padding and rules;
- a picture beside the statement becomes an attachment of the markdown cell (``attachment:``),
  which JupyterLab, nbconvert and formgrader all show.

Code (fenced or indented blocks, ``inline code``) is left exactly as written.

Run:
    python -m grader.course_markdown assignments/emst/statement/problem.en.md   # print the rewrite

Example:
    >>> tex_to_html(r"0 \\le n \\le 200\\,000")
    '0 ≤ <i>n</i> ≤ 200\\u202f000'
    >>> notebook_markdown("| a | b |\\n|---|---|\\n| `x` | 1 |")[0].startswith("<table")
    True
"""

from __future__ import annotations

import base64
import html
import re
import sys
from pathlib import Path

#: TeX commands the statements use, and the text each stands for.
SYMBOLS = {
    "le": "≤", "ge": "≥", "ne": "≠", "approx": "≈", "cdot": "·", "times": "×", "pm": "±",
    "infty": "∞", "varepsilon": "ε", "epsilon": "ε", "lt": "&lt;", "gt": "&gt;", "log": "log",
    "max": "max", "min": "min", "to": "→", "in": "∈", "sum": "∑", "alpha": "α", "beta": "β",
    "delta": "δ", "pi": "π", "theta": "θ", "lambda": "λ", "ldots": "…", "dots": "…",
}
#: Spacing commands: ``\\,`` (a thin space, as in 200,000 written ``200\\,000``) and ``\\ ``.
SPACES = {",": "\u202f", " ": " ", ";": " ", "!": ""}
#: Relations and binary operators: a space each side, as TeX sets them.
RELATIONS = {"le", "ge", "ne", "approx", "cdot", "times", "to", "in", "lt", "gt"}
#: Multi-letter names typed upright, not as a product of italic variables.
UPRIGHT = {"min", "max", "log", "inf"}

_MATH = re.compile(r"(?<![\\$])\$(?!\$)([^$\n]+?)\$")
_CODE_SPAN = re.compile(r"(`+)(.+?)\1")
_PICTURE = re.compile(r"!\[([^\]]*)\]\(([^)\s]+)\)")
_TABLE_RULE = re.compile(r"^\s*\|?\s*:?-{3,}:?\s*(\|\s*:?-{3,}:?\s*)*\|?\s*$")
_CELL_STYLE = "padding: 2px 12px; border-bottom: 1px solid #ccc; text-align: left"
_HEAD_STYLE = "padding: 2px 12px; border-bottom: 2px solid #888; text-align: left"


class _Tex:
    """A tiny recursive reader of the inline TeX the statements use (no macros, no environments)."""

    def __init__(self, tex: str):
        self.s, self.i = tex, 0

    def group(self, upright_words: bool) -> str:
        """One argument of ``^``, ``_`` or ``\\sqrt``: ``{...}`` or a single token."""
        s = self.s
        while self.i < len(s) and s[self.i] == " ":
            self.i += 1
        if self.i < len(s) and s[self.i] == "{":
            self.i += 1
            out = self.run(upright_words, closing="}")
            self.i += 1  # the "}"
            return out
        return self.token(upright_words)

    def token(self, upright_words: bool) -> str:
        s, i = self.s, self.i
        c = s[i]
        if c == "\\":
            m = re.match(r"\\([A-Za-z]+)|\\(.)", s[i:])
            if m is None:
                raise ValueError(f"a lone backslash ends the TeX {s!r}")
            self.i += m.end()
            if m.group(2) is not None:
                return SPACES.get(m.group(2), html.escape(m.group(2)))
            name = m.group(1)
            if name == "sqrt":
                arg = self.group(upright_words)
                plain = re.fullmatch(r"(<i>)?[\w.]+(</i>)?", arg) is not None
                return "√" + (arg if plain else f"({arg})")
            if name not in SYMBOLS:
                raise ValueError(f"TeX command \\{name} in {s!r} has no HTML rendering (add it to SYMBOLS)")
            while self.i < len(s) and s[self.i] == " ":  # as in TeX, spaces after a command are not text
                self.i += 1
            if name in RELATIONS:
                return f" {SYMBOLS[name]} "
            if name in UPRIGHT and self.i < len(s) and s[self.i] != "(":
                return SYMBOLS[name] + " "
            return SYMBOLS[name]
        if c in "^_":
            self.i += 1
            tag = "sup" if c == "^" else "sub"
            return f"<{tag}>{self.group(upright_words=True)}</{tag}>"
        m = re.match(r"[A-Za-z]+", s[i:])
        if m:
            self.i += m.end()
            word = m.group(0)
            if word in UPRIGHT or (upright_words and len(word) > 1):
                return word
            return f"<i>{word}</i>"
        self.i += 1
        if c in "{}":
            return ""
        if c == " ":  # TeX ignores spaces in maths; keep one around operators for reading
            return " "
        return {"<": "&lt;", ">": "&gt;", "&": "&amp;", "*": "&#42;", "|": "&#124;", "-": "−"}.get(c, c)

    def run(self, upright_words: bool, closing: str = "") -> str:
        out = []
        while self.i < len(self.s) and self.s[self.i] != closing:
            out.append(self.token(upright_words))
        return "".join(out)


def tex_to_html(tex: str) -> str:
    """Inline TeX (the part between ``$`` signs) as HTML text.

    >>> tex_to_html(r"|r - r^*| \\le 10^{-6} \\cdot r^*")
    '&#124;<i>r</i> − <i>r</i><sup>&#42;</sup>&#124; ≤ 10<sup>−6</sup> · <i>r</i><sup>&#42;</sup>'
    >>> tex_to_html(r"\\sqrt{10} + \\sqrt 5"), tex_to_html(r"x_{min}"), tex_to_html(r"\\sqrt{3 \\cdot 0.375^2}")
    ('√10 + √5', '<i>x</i><sub>min</sub>', '√(3 · 0.375<sup>2</sup>)')
    """
    return re.sub(r" {2,}", " ", _Tex(tex.strip()).run(upright_words=False)).strip()


def _inline(text: str) -> str:
    """Maths of one line of prose, code spans left alone."""
    parts, last = [], 0
    for m in _CODE_SPAN.finditer(text):
        parts.append(_MATH.sub(lambda x: tex_to_html(x.group(1)), text[last:m.start()]))
        parts.append(m.group(0))
        last = m.end()
    parts.append(_MATH.sub(lambda x: tex_to_html(x.group(1)), text[last:]))
    return "".join(parts)


def _cell_html(text: str) -> str:
    """A table cell's markdown as HTML (markdown inside an HTML block is not read as markdown)."""
    out, last = [], 0
    for m in _CODE_SPAN.finditer(text):
        out.append(_prose_html(text[last:m.start()]))
        out.append(f"<code>{html.escape(m.group(2))}</code>")
        last = m.end()
    out.append(_prose_html(text[last:]))
    return "".join(out).strip()


def _prose_html(text: str) -> str:
    pieces, last = [], 0
    for m in _MATH.finditer(text):
        pieces.append(html.escape(text[last:m.start()], quote=False))
        pieces.append(tex_to_html(m.group(1)))
        last = m.end()
    pieces.append(html.escape(text[last:], quote=False))
    return re.sub(r"\*\*(.+?)\*\*", r"<b>\1</b>", "".join(pieces))


def _row(line: str) -> list[str]:
    cells = line.strip()
    cells = cells[1:] if cells.startswith("|") else cells
    cells = cells[:-1] if cells.endswith("|") else cells
    return [c.strip() for c in cells.split("|")]


def table_html(lines: list[str]) -> str:
    """A pipe table (header, rule, rows) as HTML with inline cell styles, a line per row.

    >>> print(table_html(["| a | b |", "|---|---|", "| `x` | $n$ |"]))  # doctest: +ELLIPSIS
    <table style=...>
    <thead><tr><th style=...>a</th>...</tr></thead>
    <tbody>
    <tr><td style=...><code>x</code></td><td style=...><i>n</i></td></tr>
    </tbody></table>
    """
    head, body = _row(lines[0]), [_row(r) for r in lines[2:]]
    th = "".join(f'<th style="{_HEAD_STYLE}">{_cell_html(c)}</th>' for c in head)
    rows = "".join("\n<tr>" + "".join(f'<td style="{_CELL_STYLE}">{_cell_html(c)}</td>' for c in r) + "</tr>"
                   for r in body)
    return (f'<table style="border-collapse: collapse; margin: 0.5em 0">\n'
            f"<thead><tr>{th}</tr></thead>\n<tbody>{rows}\n</tbody></table>")


def notebook_markdown(text: str, pictures: Path | None = None) -> tuple[str, dict]:
    """``text`` rewritten for a notebook cell, and the cell's attachments (pictures found in ``pictures``).

    A picture that is not a file in ``pictures`` (or when ``pictures`` is None) is left as written.

    >>> md, att = notebook_markdown("Here $n \\\\ge 2$:\\n\\n    $ not maths in code\\n")
    >>> md
    'Here <i>n</i> ≥ 2:\\n\\n    $ not maths in code\\n'
    """
    lines = text.split("\n")
    out: list[str] = []
    attachments: dict = {}
    fence = None
    prev_blank = True
    k = 0
    while k < len(lines):
        line = lines[k]
        stripped = line.lstrip()
        if fence:
            out.append(line)
            if stripped.startswith(fence):
                fence = None
            k += 1
            continue
        if stripped.startswith(("```", "~~~")):
            fence = stripped[:3]
            out.append(line)
            k += 1
            continue
        if line.startswith(("    ", "\t")) and (prev_blank or (out and out[-1].startswith(("    ", "\t")))):
            out.append(line)  # an indented code block
            k += 1
            continue
        if "|" in line and k + 1 < len(lines) and _TABLE_RULE.match(lines[k + 1]):
            end = k + 2
            while end < len(lines) and lines[end].strip().startswith("|"):
                end += 1
            out.append(table_html(lines[k:end]))
            prev_blank = False
            k = end
            continue

        def picture(m: re.Match) -> str:
            path = pictures / m.group(2) if pictures is not None else None
            if path is None or "://" in m.group(2) or not path.is_file():
                return m.group(0)
            mime = {".png": "image/png", ".jpg": "image/jpeg", ".jpeg": "image/jpeg", ".gif": "image/gif",
                    ".svg": "image/svg+xml"}.get(path.suffix.lower())
            if mime is None:
                raise ValueError(f"picture {path}: no MIME type for {path.suffix!r}")
            data = path.read_bytes()
            attachments[path.name] = {mime: data.decode() if mime == "image/svg+xml" else
                                      base64.b64encode(data).decode("ascii")}
            return f"![{m.group(1)}](attachment:{path.name})"

        out.append(_PICTURE.sub(picture, _inline(line)))
        prev_blank = not line.strip()
        k += 1
    return "\n".join(out), attachments


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        print("usage: python -m grader.course_markdown STATEMENT.md", file=sys.stderr)
        return 2
    path = Path(args[0])
    md, attachments = notebook_markdown(path.read_text(encoding="utf-8"), path.parent)
    print(md)
    for name in attachments:
        print(f"[attachment: {name}]", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
