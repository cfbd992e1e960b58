"""The one shared loader of checkers: binds the library modules a checker names, and runs it as a
Kattis output validator.

A checker (``assignments/<id>/output_validator/checker.py``) is plain stdlib-only Python. When it
needs exact helpers from the library it names them in a module-level literal::

    LIBRARY = ("verify",)      # stdlib-only modules of reference_impl, by file name

and uses ``verify.check_delaunay(...)`` as a global: :func:`load_checker` binds ``verify`` (loaded
by path from ``reference_impl/exact/verify.py``, without importing the ``reference_impl`` package, which
would pull in numpy and numba) before the checker's code runs. ``python -m grader export-kattis``
appends this file's source and the named modules' sources to the exported checker, so the copy runs
on its own (``python3 checker.py input answer feedback_dir < team_output``, exit 42/43) through
:func:`kattis_main`. This file is stdlib-only for that reason, and has no ``__future__`` import.

Example:
    >>> from grader.problems import REPO
    >>> chk = load_checker(REPO / "assignments/delaunay/output_validator/checker.py", "_chk_doc")
    >>> chk.verify.check_delaunay([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]])
    (True, 'ok')
"""

import ast
import sys
import types
from pathlib import Path

#: where library modules live in the checkout (unused in an exported copy, which embeds them)
LIBRARY_DIR = Path(globals().get("__file__", ".")).resolve().parent.parent.parent / "reference_impl"


def library_file(name: str, library_dir=None) -> Path:
    """The one file ``<name>.py`` in the library's tree (``verify`` is ``reference_impl/exact/verify.py``).

    Raises ValueError when there is none or more than one.

    >>> library_file("verify").relative_to(LIBRARY_DIR).as_posix()
    'exact/verify.py'
    """
    lib = Path(library_dir) if library_dir else LIBRARY_DIR
    found = sorted(f for f in lib.rglob(f"{name}.py") if "__pycache__" not in f.parts)
    if len(found) != 1:
        where = "does not exist" if not found else "is ambiguous: " + ", ".join(str(f) for f in found)
        raise ValueError(f"{lib / '**' / (name + '.py')} {where}")
    return found[0]


def library_names(source: str, filename: str = "checker.py") -> tuple:
    """The names in the checker's module-level ``LIBRARY = (...)`` literal (``()`` without one).

    >>> library_names('LIBRARY = ("verify",)\\n')
    ('verify',)
    """
    node = _library_node(source, filename)
    if node is None:
        return ()
    value = ast.literal_eval(node.value)
    if not isinstance(value, (tuple, list)) or not all(isinstance(v, str) and v.isidentifier() for v in value):
        raise ValueError(f"{filename}: LIBRARY must be a tuple of module names, got {value!r}")
    return tuple(value)


def _library_node(source: str, filename: str = "checker.py"):
    """The module-level ``LIBRARY = ...`` statement, or ``None``."""
    return next((node for node in ast.parse(source, filename).body if isinstance(node, ast.Assign)
                 and any(isinstance(t, ast.Name) and t.id == "LIBRARY" for t in node.targets)), None)


def bind_library(namespace: dict, sources: dict, standalone: bool = False) -> None:
    """Execute each library module's source (name -> text) as a module and bind it in ``namespace``.

    Each module sees ``STANDALONE``: True in an exported Kattis validator (:func:`embed`), where it
    must not import anything from the checkout even when an installed copy could be found."""
    for name, source in sources.items():
        module = types.ModuleType(f"checker_library_{name}")
        module.__file__ = f"{name}.py"
        module.STANDALONE = standalone
        sys.modules[module.__name__] = module  # dataclasses and pickling look modules up here
        exec(compile(source, f"{name}.py", "exec"), module.__dict__)
        namespace[name] = module


def load_checker(path, module_name: str, library_dir=None) -> types.ModuleType:
    """Import the checker at ``path`` with the library modules it names already bound."""
    path = Path(path)
    source = path.read_text()
    sources = {}
    for name in library_names(source, str(path)):
        try:
            sources[name] = library_file(name, library_dir).read_text()
        except ValueError as exc:
            raise ValueError(f"{path}: LIBRARY names {name!r} but {exc}") from None
    module = types.ModuleType(module_name)
    module.__file__ = str(path)
    sys.modules[module_name] = module
    bind_library(module.__dict__, sources)
    exec(compile(source, str(path), "exec"), module.__dict__)
    return module


def read_answer(checker, text: str, args: list):
    """The reference answer from an ``.ans`` text: the checker's ``read_answer(text, args)`` when
    it has one, else ``read_output(text, args)`` (answers are written in the output format)."""
    reader = getattr(checker, "read_answer", None) if not isinstance(checker, dict) else checker.get("read_answer")
    if reader is None:
        reader = checker["read_output"] if isinstance(checker, dict) else checker.read_output
    return reader(text, args)


def kattis_main(namespace: dict, argv: list) -> int:
    """Kattis output validator: ``checker.py input answer feedback_dir < team_output``.

    Exit 42 accepts, 43 rejects; the reason goes to ``feedback_dir/judgemessage.txt``.
    """
    input_path, answer_path, feedback_dir = argv[1], argv[2], argv[3]
    presentation_error = namespace["PresentationError"]
    try:
        team = sys.stdin.buffer.read().decode("utf-8")
        args = namespace["read_input"](Path(input_path).read_text())
        received = namespace["read_output"](team, args)
        expected = read_answer(namespace, Path(answer_path).read_text(), args)
        ok, message = namespace["check"](args, received, expected)
    except UnicodeDecodeError:
        ok, message = False, "presentation error: the output is not UTF-8 text"
    except presentation_error as exc:
        ok, message = False, f"presentation error: {exc}"
    except namespace.get("WrongAnswer", ()) as exc:  # optional: wrong before any real check
        ok, message = False, str(exc)
    Path(feedback_dir, "judgemessage.txt").write_text(message + "\n")
    return 42 if ok else 43


def embed(checker_source: str, library_dir=None) -> str:
    """The self-contained Kattis copy of a checker: this runtime and the library modules it names
    (as string constants ``EMBEDDED_<NAME>_SOURCE``) inserted right after its ``LIBRARY`` line
    (so module-level code may use them, as in the checkout), and the ``__main__`` entry at the end."""
    names = library_names(checker_source)
    block = ["# ---- inserted by `python -m grader export-kattis`: the shared checker runtime and the",
             "# ---- library modules named in LIBRARY, so that this file runs on its own as a Kattis",
             "# ---- output validator: python3 checker.py input answer feedback_dir < team_output",
             f"EMBEDDED_CHECKER_RUNTIME_SOURCE = {Path(__file__).read_text()!r}"]
    for name in names:
        block.append(f"EMBEDDED_{name.upper()}_SOURCE = {library_file(name, library_dir).read_text()!r}")
    block += ['_checker_runtime = {"__name__": "checker_runtime"}',
              'exec(compile(EMBEDDED_CHECKER_RUNTIME_SOURCE, "checker_runtime.py", "exec"), _checker_runtime)',
              '_checker_runtime["bind_library"](globals(), {'
              + ", ".join(f"{n!r}: EMBEDDED_{n.upper()}_SOURCE" for n in names) + "}, standalone=True)",
              "# ---- end of the inserted block"]
    lines = checker_source.rstrip("\n").split("\n")
    node = _library_node(checker_source)
    at = node.end_lineno if node is not None else len(lines)
    main = ["", "", 'if __name__ == "__main__":',
            '    raise SystemExit(_checker_runtime["kattis_main"](globals(), __import__("sys").argv))', ""]
    return "\n".join(lines[:at] + block + lines[at:] + main)
