"""Text that came from a submission, made safe once, at the boundary, before the judge keeps it.

Everything a student controls and the judge shows or stores (exception messages, traceback
lines, violation reports, student folder names, file names) passes through :func:`clean` when it
enters the grader: the result is valid UTF-8 (no lone surrogates), printable (no ANSI escapes or
other control characters; newlines kept only where asked), and capped in length. CSV cells that
a spreadsheet would read as a formula are neutralised by :func:`csv_cell`.

Example:
    >>> clean("ValueError: \\ud800 \\x1b[31mred\\x1b[0m\\nforged line")
    'ValueError: \\\\ud800 \\\\x1b[31mred\\\\x1b[0m\\\\nforged line'
    >>> csv_cell('=HYPERLINK("http://x")')
    '\\'=HYPERLINK("http://x")'
"""

from __future__ import annotations

import unicodedata

#: Default cap for one message (characters, after escaping).
MAX_TEXT = 2000
_FORMULA_START = ("=", "+", "-", "@", "\t", "\r", "\n")


def _escape(ch: str) -> str:
    code = ord(ch)
    if code < 0x100:
        return f"\\x{code:02x}"
    if code < 0x10000:
        return f"\\u{code:04x}"
    return f"\\U{code:08x}"


def clean(value: object, limit: int = MAX_TEXT, newlines: bool = False) -> str:
    """``value`` as safe display text: control, format and surrogate characters become visible
    escapes (``\\x1b``, ``\\ud800``), newlines too unless ``newlines``; at most ``limit`` characters.

    >>> clean("a\\tb\\u202ec", limit=80)
    'a\\\\tb\\\\u202ec'
    >>> clean("line 1\\nline 2", newlines=True)
    'line 1\\nline 2'
    >>> len(clean("x" * 5000, limit=100))
    100
    """
    if isinstance(value, bytes):
        value = value.decode("utf-8", errors="replace")
    text = value if isinstance(value, str) else str(value)
    out = []
    size = 0
    for ch in text[: limit * 2]:
        if ch == "\t":
            piece = "\\t"
        elif ch == "\n" and newlines:
            piece = ch
        elif ch == "\n":
            piece = "\\n"
        elif ch.isprintable() and unicodedata.category(ch) not in ("Cf", "Cs", "Co"):
            piece = ch
        else:
            piece = _escape(ch)
        if size + len(piece) > limit:
            break
        out.append(piece)
        size += len(piece)
    return "".join(out)


def last_lines(value: object, lines: int = 10, limit: int = 1500) -> str:
    """The end of ``value`` (a program's stderr, say) as safe display text: its last ``lines``
    lines, each through :func:`clean` (newlines kept between them), about ``limit`` characters in
    all (lines dropped from the front, a longer line keeps its end); ``...`` marks a cut.

    >>> last_lines("one\\ntwo\\nthree\\x1b[0m\\n", lines=2)
    '...\\ntwo\\nthree\\\\x1b[0m'
    >>> last_lines("x" * 50, limit=10)
    '...xxxxxxx'
    """
    if isinstance(value, bytes):
        value = value.decode("utf-8", errors="replace")
    text = (value if isinstance(value, str) else str(value))[-4 * limit:].rstrip("\n")
    all_lines = text.splitlines()
    kept = []
    for line in all_lines[-lines:]:
        safe = clean(line[-limit:], 4 * limit)
        kept.append("..." + safe[-(limit - 3):] if len(line) > limit or len(safe) > limit else safe)
    cut = len(all_lines) > len(kept)
    while len(kept) > 1 and sum(len(k) + 1 for k in kept) > limit + 1:
        kept.pop(0)
        cut = True
    return ("...\n" if cut else "") + "\n".join(kept)


def csv_cell(value: object) -> str:
    """A CSV cell a spreadsheet shows as text: a leading ``= + - @`` (a formula) gets a ``'``.

    >>> csv_cell("ada"), csv_cell("-1+1"), csv_cell(42)
    ('ada', "'-1+1", '42')
    """
    text = clean(value, limit=500)
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return text
    return "'" + text if text.startswith(_FORMULA_START) else text
