"""Languages as data: which files the judge accepts and how each becomes something to run.

One frozen :class:`Language` per language, in :data:`LANGUAGES`; nothing else in the grader lists
file suffixes (submissions, class grading and the similarity corpus ask :func:`language_of` and
:data:`SUFFIXES`). Two languages are judged: Python (a ``.py`` file or the code cells of an
``.ipynb`` notebook) and C++ (``.cpp``, ``.cc``, ``.cxx``). A compiled language is one entry with
its compile command (after DOMjudge's one compile and one run script per language): the judging
loop compiles once per submission in the compile jail (:mod:`grader.judging.compile`; a compile
error is ``CE``) and runs the binary in the run jail per test; the time-limit rule says how a
problem's limits apply to it. Suffixes are matched as written (``.PY`` and ``.CPP`` are not
accepted), by :func:`language_of` and :meth:`Language.extraction` alike.

Imports: the standard library only (the bottom of the judging room).

    >>> language_of("ada/delaunay.ipynb").name, PYTHON.extraction("ada/delaunay.ipynb")
    ('python', 'notebook')
    >>> language_of("main.cpp").name, language_of("main.CPP"), SUFFIXES
    ('cpp', None, ('.py', '.ipynb', '.cpp', '.cc', '.cxx'))
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import PurePath


@dataclass(frozen=True)
class Language:
    """One language the judge runs.

    ``suffixes`` and ``notebook_suffixes`` map a file to it; :meth:`extraction` says how the file's
    text becomes source code (``"source"``: as it is; ``"notebook"``: the code cells, magics
    dropped, see :func:`grader.judging.submissions.notebook_code`); ``compile`` is the command that makes a
    program of the source (empty: nothing to compile), ``run`` how the program runs in the jail
    (placeholders ``{source}``, ``{binary}``); ``modes`` the judging modes it supports
    (``function``: the entry function is called per test; ``stdio``: a program per test);
    ``time_limit`` the rule for the problem's limits (``"problem"``: as written in the package;
    ``"per-language"``: the problem's limit for this language,
    :meth:`grader.problems.package.Problem.time_limit_for`).
    """

    name: str
    suffixes: tuple[str, ...]
    notebook_suffixes: tuple[str, ...] = ()
    compile: tuple[str, ...] = ()
    run: tuple[str, ...] = ()
    modes: tuple[str, ...] = ("stdio",)
    time_limit: str = "problem"

    def extraction(self, path: str | PurePath) -> str:
        """``"notebook"`` for one of the language's notebook suffixes, else ``"source"``.

        >>> PYTHON.extraction("x.ipynb"), PYTHON.extraction("x.py")
        ('notebook', 'source')
        """
        return "notebook" if PurePath(path).suffix in self.notebook_suffixes else "source"

    def compile_command(self, source: str = "{source}", binary: str = "{binary}") -> tuple[str, ...]:
        """The compile command with its placeholders filled (empty when nothing is compiled).

        >>> " ".join(CPP.compile_command("main.cpp", "main"))
        'g++ -std=gnu++17 -O2 -pipe -static -s -o main main.cpp'
        """
        return tuple(a.replace("{source}", source).replace("{binary}", binary) for a in self.compile)

    @property
    def all_suffixes(self) -> tuple[str, ...]:
        """Every suffix of the language: source files, then notebooks."""
        return self.suffixes + self.notebook_suffixes


#: Python: nothing to compile; the sandbox's interpreter runs it (function mode through the jail's
#: bootstrap, stdio mode as a script); the problem's time and memory limits apply as written.
PYTHON = Language(name="python", suffixes=(".py",), notebook_suffixes=(".ipynb",), compile=(),
                  run=("{python}", "{source}"), modes=("function", "stdio"), time_limit="problem")

#: C++: Debian's g++ with the flags of Kattis, DOMjudge and CMS (GNU C++17, optimised, static, so
#: that the run jail needs no shared libraries); stdio mode only (the problem's text format on
#: stdin and stdout); the time limit is the problem's C++ limit (course.yaml ``time_limits: {cpp: ..}``,
#: set from the accepted C++ solution's slowest test, see ``benchmarks/bench_cpp_solutions.py``).
CPP = Language(name="cpp", suffixes=(".cpp", ".cc", ".cxx"),
               compile=("g++", "-std=gnu++17", "-O2", "-pipe", "-static", "-s", "-o", "{binary}", "{source}"),
               run=("{binary}",), modes=("stdio",), time_limit="per-language")

#: Every language the judge accepts, in order of preference.
LANGUAGES: tuple[Language, ...] = (PYTHON, CPP)

#: Every accepted file suffix (a class folder's candidates, the similarity corpus).
SUFFIXES: tuple[str, ...] = tuple(s for lang in LANGUAGES for s in lang.all_suffixes)


def language_of(path: str | PurePath) -> Language | None:
    """The language of a file by its suffix (case as written: ``.PY`` is not accepted), or None.

    >>> language_of("a/b.cc").name, language_of("b.py").name, language_of("b.txt")
    ('cpp', 'python', None)
    """
    suffix = PurePath(path).suffix
    return next((lang for lang in LANGUAGES if suffix in lang.all_suffixes), None)


def accepted_files() -> str:
    """The accepted files in words, for messages (written out: a new language adds its words here).

    >>> accepted_files()
    'a .py file, an .ipynb notebook or a C++ file (.cpp, .cc, .cxx)'
    """
    return "a .py file, an .ipynb notebook or a C++ file (.cpp, .cc, .cxx)"
