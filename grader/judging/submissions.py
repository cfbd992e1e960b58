"""Student submissions: read a ``.py`` file, the code cells of an ``.ipynb`` notebook or a C++ file,
and decide how to run it (Python: function mode when it defines the entry function, stdio mode
when it reads stdin; C++: always stdio mode, compiled by the judge in its compile jail).

Parsing here is static (``ast``), in the grader's process, on size-capped text: the code itself
only ever runs in the sandbox. Files are read with :func:`read_submission_bytes`: no symbolic
links are followed, only regular files are read, and the size is checked before reading.

Example:
    >>> s = Submission.from_source("def delaunay(points):\\n    return []\\n", "s.py")
    >>> s.mode("delaunay")
    'function'
"""

from __future__ import annotations

import ast
import difflib
import json
import os
import re
import stat
from dataclasses import dataclass
from pathlib import Path

from .languages import PYTHON, Language, accepted_files, language_of

MAX_SOURCE_BYTES = 1 << 20
#: What a student sees in place of a solution region (nbgrader's ``ClearSolutions.code_stub``,
#: set from this in ``assignments/nbgrader_config.py``; the similarity report treats it as starter code).
CODE_STUB = "# YOUR CODE HERE\nraise NotImplementedError()"
_MAGIC = re.compile(r"^\s*(%|!)")
_STDIN_NAMES = {"input", "stdin", "fileinput"}


class SubmissionError(ValueError):
    """The file cannot be a submission at all (wrong type, unreadable, too large, a link)."""


def read_submission_bytes(path: str | os.PathLike, limit: int = MAX_SOURCE_BYTES, follow_links: bool = False) -> bytes:
    """The bytes of a submission file, read safely: the last path component is opened with
    ``O_NOFOLLOW`` (a symbolic link is refused, never followed), it must be a regular file (not a
    FIFO or a device), and its size is checked on the open file before anything is read.
    Raises :class:`SubmissionError` with a message that names only the file, never its content.
    ``follow_links=True`` (for a file named explicitly on the command line, never for files found
    in a class folder) resolves links first, then reads the target under the same checks.

    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp()); (d / "a.py").write_text("x = 1\\n")
    6
    >>> read_submission_bytes(d / "a.py")
    b'x = 1\\n'
    >>> (d / "b.py").symlink_to(d / "a.py")
    >>> try:
    ...     read_submission_bytes(d / "b.py")
    ... except SubmissionError as exc:
    ...     print(exc)
    b.py is a symbolic link, not a regular file: links are not followed
    """
    path = os.path.realpath(path) if follow_links else os.fspath(path)
    parent, name = os.path.split(path)
    flags = os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC | os.O_NOCTTY
    try:  # the folder holding the file (a student's folder) must not be a link either
        dir_fd = os.open(parent or ".", os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW | os.O_CLOEXEC)
    except OSError as exc:
        what = "a symbolic link" if os.path.islink(parent) else f"unreadable ({exc.strerror})"
        raise SubmissionError(f"the folder of {name} is {what}: links are not followed") from None
    try:
        fd = os.open(name, flags, dir_fd=dir_fd)
    except OSError as exc:
        if os.path.islink(path):
            raise SubmissionError(f"{name} is a symbolic link, not a regular file: links are not followed") from None
        raise SubmissionError(f"cannot read {name}: {exc.strerror}") from None
    finally:
        os.close(dir_fd)
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise SubmissionError(f"{name} is not a regular file")
        if st.st_size > limit:
            raise SubmissionError(f"{name} is larger than {limit >> 10} KiB")
        chunks, size = [], 0
        while size <= limit:
            chunk = os.read(fd, min(1 << 16, limit + 1 - size))
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
        if size > limit:  # it grew after the check
            raise SubmissionError(f"{name} is larger than {limit >> 10} KiB")
        return b"".join(chunks)
    finally:
        os.close(fd)


def notebook_code(text: str) -> str:
    """Concatenate a notebook's code cells, dropping IPython magics (``%``, ``%%``) and ``!`` lines.

    >>> nb = {"cells": [{"cell_type": "code", "source": ["%matplotlib inline\\n", "x = 1\\n"]}]}
    >>> notebook_code(json.dumps(nb))
    'x = 1\\n'
    """
    try:
        nb = json.loads(text)
    except ValueError as exc:
        raise SubmissionError(f"not a valid notebook (JSON): {str(exc)[:100]}") from None
    except RecursionError:
        raise SubmissionError("not a valid notebook: the JSON is nested too deeply") from None
    cells = nb.get("cells") if isinstance(nb, dict) else None
    if not isinstance(cells, list):
        raise SubmissionError("not a valid notebook: no list of cells")
    chunks = []
    for cell in cells:
        if not isinstance(cell, dict) or cell.get("cell_type") != "code":
            continue
        src = cell.get("source", "")
        if isinstance(src, list) and all(isinstance(s, str) for s in src):
            src = "".join(src)
        elif not isinstance(src, str):
            raise SubmissionError("not a valid notebook: a code cell's source is not text")
        if src.lstrip().startswith("%%"):
            continue  # a cell magic (%%time, %%bash...) makes the whole cell non-Python
        lines = [ln for ln in src.splitlines() if not _MAGIC.match(ln)]
        if lines:
            chunks.append("\n".join(lines) + "\n")
    return "\n".join(chunks)


@dataclass
class Submission:
    """Source text of one submission, its display name and its language.

    >>> Submission.from_source("int main() {}", "main.cpp").mode("delaunay")
    'stdio'
    """

    source: str
    filename: str
    language: Language = PYTHON

    @classmethod
    def from_path(cls, path: str | Path, follow_links: bool = False) -> "Submission":
        """Read a ``.py``, ``.ipynb`` or C++ file with :func:`read_submission_bytes`."""
        path = Path(path)
        language = language_of(path)
        if language is None:
            raise SubmissionError(f"{path.name}: a submission must be {accepted_files()}")
        text = read_submission_bytes(path, follow_links=follow_links).decode("utf-8", errors="replace")
        source = notebook_code(text) if language.extraction(path) == "notebook" else text
        return cls(source, "submission.py" if language is PYTHON else f"submission{language.suffixes[0]}", language)

    @classmethod
    def from_source(cls, source: str, filename: str = "submission.py", language: Language | None = None) -> "Submission":
        """A submission from its text; the language is ``language``, else the one of ``filename``'s
        suffix, else Python."""
        return cls(source, filename, language or language_of(filename) or PYTHON)

    @property
    def compiled(self) -> bool:
        """True for a language the judge compiles first (C++)."""
        return bool(self.language.compile)

    def syntax_error(self) -> str | None:
        """A student-facing message when the code does not parse, else None (a compiled language's
        errors come from its compiler, in the compile jail)."""
        if self.language is not PYTHON:
            return None
        try:
            self._tree()
        except SyntaxError as exc:
            return f"SyntaxError: {exc.msg} (line {exc.lineno}): {(exc.text or '').strip()[:80]}"
        except (ValueError, RecursionError, MemoryError) as exc:
            return f"the code cannot be parsed: {type(exc).__name__}"
        return None

    def _tree(self) -> ast.Module:
        if "_tree_cache" not in self.__dict__:
            self.__dict__["_tree_cache"] = ast.parse(self.source)
        return self.__dict__["_tree_cache"]

    def top_level_names(self) -> set[str]:
        names: set[str] = set()
        for node in self._tree().body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                names.add(node.name)
            elif isinstance(node, (ast.Assign, ast.AnnAssign)):
                targets = node.targets if isinstance(node, ast.Assign) else [node.target]
                names.update(t.id for t in targets if isinstance(t, ast.Name))
            elif isinstance(node, (ast.Import, ast.ImportFrom)):
                names.update((a.asname or a.name).split(".")[0] for a in node.names)
        return names

    def reads_stdin(self) -> bool:
        for node in ast.walk(self._tree()):
            if isinstance(node, ast.Name) and node.id in _STDIN_NAMES:
                return True
            if isinstance(node, ast.Attribute) and node.attr in ("stdin", "buffer") :
                return True
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "open" \
                    and node.args and isinstance(node.args[0], ast.Constant) and node.args[0].value == 0:
                return True
        return False

    def mode(self, entry: str) -> str:
        """'function' if ``entry`` is defined at top level, 'stdio' if the code reads stdin, else 'missing'
        (a language without function mode: always 'stdio')."""
        if "function" not in self.language.modes:
            return "stdio"
        if entry in self.top_level_names():
            return "function"
        return "stdio" if self.reads_stdin() else "missing"

    def missing_entry_message(self, entry: str) -> str:
        defined = sorted(n for n in self.top_level_names() if not n.startswith("_"))
        close = [n for n in defined if entry.lower() in n.lower()] or difflib.get_close_matches(entry, defined, n=1,
                                                                                               cutoff=0.5)
        hint = f" Did you mean to name '{close[0]}' '{entry}'?" if close else ""
        return (f"no function '{entry}(...)' is defined and the program does not read standard input."
                f"{hint}")
