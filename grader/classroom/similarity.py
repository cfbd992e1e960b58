"""Similarity of a class's submissions: who shares code with whom, and with the tutorial.

Built on `copydetect <https://github.com/blingenf/copydetect>`_ (winnowed k-gram fingerprints of
the token stream, MOSS's method): names become ``V``/``F``, strings ``S``, comments and
whitespace vanish, so renamed variables, changed comments and reordered functions do not hide a
copy. Every student's code is compared with every other student's, and with a reference
corpus: the tutorial's code (``reference_impl/teaching/tutorial_bugs.py`` reproduces it) and any
folder the instructor names. Fingerprints of the starter code (the problem's source notebook
with its solution removed, as nbgrader releases it) and of the statement's code snippets are
boilerplate: they count for nobody.

Code carried as data is compared too (:mod:`grader.classroom.code_from_data`): in a Python file, string
literals that decode (base64, hex, rot13, zlib, ... through a whitelist of pure decoders evaluated on
constants, nothing executed) to Python, or that reach ``exec``/``eval``/``compile``, are appended to
the code that is fingerprinted; a submission that runs code from data is *marked* with a short reason
(``Document.marks``), decoded or not.

Submissions are found as ``grade`` finds them (``SUBMISSIONS/<student>/<file>``, read with
:func:`grader.judging.submissions.read_submission_bytes`: no links followed, size capped) or in
nbgrader's collected layout ``submitted/<student>/<problem>/<problem>.ipynb``; both may be mixed.
Of a notebook only the solution cells count (nbgrader ``solution: true``; every code cell when
the notebook has none). Nothing is executed and no test of the problem is read.

The score of a pair is the larger of the two shares "fraction of this side's fingerprinted code
that also appears in the other" (for a pair with a reference, the student's share), from 0 to 1;
a pair at or above ``threshold`` (default 0.5) with at least ``MIN_TOKENS`` shared tokens is
flagged. See ``grader/README.md`` for what the test class scores.

Run:
    python -m grader similarity delaunay class/ --reports sim/ [--reference DIR] [--threshold 0.5]
    (``grader.classroom.similarity_report.run``: this analysis, then the report)
    python -m grader grade delaunay class/ --similarity --reports reports/

Example:
    >>> a = Document("ada", "student", "ada/x.py", "def f(a, b):\\n    return [a * b + i for i in range(a)]\\n" * 3)
    >>> b = Document("bo", "student", "bo/y.py", "def g(x, y):  # mine\\n    return [x * y + j for j in range(x)]\\n" * 3)
    >>> pair = compare(fingerprint(a), fingerprint(b))
    >>> round(pair.score, 2)
    1.0
"""

from __future__ import annotations

import hashlib
import itertools
import json
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .classgrade import choose_submission, _student_dirs
from .code_from_data import unpack
from ..problems import load_problem, problems_root
from ..judging.languages import SUFFIXES, language_of
from ..judging.submissions import CODE_STUB, SubmissionError, notebook_code, read_submission_bytes
from ..judging.text import clean

REPO = Path(__file__).resolve().parent.parent.parent
TUTORIAL = REPO / "reference_impl" / "teaching" / "tutorial_bugs.py"
#: copydetect's defaults: k-grams of 25 filtered characters, every k-gram of 30 guaranteed seen.
NOISE_T = 25
GUARANTEE_T = 30
THRESHOLD = 0.5
MIN_TOKENS = 100  #: shared filtered characters below which a pair is never flagged (tiny files)
MAX_REFERENCE_FILES = 2000
_NB_STUB = CODE_STUB + "\n"   # the solution region and its closing newline become the stub
_SOLUTION = re.compile(r"### BEGIN SOLUTION.*?### END SOLUTION\n?", re.S)
_FENCED = re.compile(r"^(```|~~~)[^\n]*\n(.*?)^\1", re.S | re.M)
_INLINE = re.compile(r"`([^`\n]+)`")


@dataclass
class Document:
    """One piece of code to compare: a student's submission or a reference file."""

    name: str  #: student folder name (cleaned) or ``reference: <label>``
    kind: str  #: "student" or "reference"
    path: str  #: where it came from, for display
    code: str
    note: str = ""  #: why it could not be read, or which file was chosen
    fp: object = field(default=None, repr=False)
    decoded: str = field(default="", repr=False)  #: code found in its data (see :mod:`grader.classroom.code_from_data`)
    marks: list[str] = field(default_factory=list)  #: how it runs code from data, one reason each

    @property
    def compared(self) -> str:
        """The text that is fingerprinted and shown: the code, then the code decoded from its data."""
        return self.code + ("\n" + self.decoded if self.decoded else "")


@dataclass
class Pair:
    """A compared pair; ``share_a``/``share_b``: fraction of each side's code found in the other."""

    a: Document
    b: Document
    share_a: float
    share_b: float
    tokens: int
    slices_a: np.ndarray = field(repr=False)
    slices_b: np.ndarray = field(repr=False)
    flagged: bool = False

    @property
    def score(self) -> float:
        if self.b.kind == "reference":
            return self.share_a
        return max(self.share_a, self.share_b)


def solution_code(text: str) -> str:
    """The code of a notebook's solution cells (nbgrader ``solution: true``), magics dropped; every
    code cell when no cell is marked. Raises :class:`SubmissionError` for a broken notebook.

    >>> cells = [{"cell_type": "code", "source": "x = 1", "metadata": {"nbgrader": {"solution": True}}},
    ...          {"cell_type": "code", "source": "check()", "metadata": {}}]
    >>> solution_code(json.dumps({"cells": cells}))
    'x = 1\\n'
    """
    everything = notebook_code(text)  # validates the notebook (JSON, cells, sources are text)
    cells = json.loads(text)["cells"]

    def is_solution(c: object) -> bool:
        meta = c.get("metadata") if isinstance(c, dict) else None
        nbg = meta.get("nbgrader") if isinstance(meta, dict) else None
        return isinstance(nbg, dict) and nbg.get("solution") is True

    marked = [c for c in cells if is_solution(c)]
    return notebook_code(json.dumps({"cells": marked})) if marked else everything


def read_code(path: Path) -> str:
    """The code of a ``.py`` file or of a notebook's solution cells, read safely (no links)."""
    text = read_submission_bytes(path).decode("utf-8", errors="replace")
    return solution_code(text) if path.suffix == ".ipynb" else text


def _nbgrader_file(student_dir: Path, problem: str) -> Path | None:
    f = student_dir / problem / f"{problem}.ipynb"
    return f if f.is_file() or f.is_symlink() else None


def collect_class(problem: str, root: str | Path) -> list[Document]:
    """One document per student folder with a submission (``grade``'s choice of file, or the
    nbgrader-collected notebook); unreadable files become empty documents with a note."""
    docs = []
    for d in _student_dirs(root):
        name = clean(d.name, 200)
        f, why = (_nbgrader_file(d, problem), "") if _nbgrader_file(d, problem) else choose_submission(d, problem)
        if f is None:
            continue
        try:
            if d.is_symlink():
                raise SubmissionError(f"the folder of {f.name} is a symbolic link: links are not followed")
            code, note = read_code(f), clean(why, 500)
        except SubmissionError as exc:
            code, note = "", clean(f"not compared: {exc}", 500)
        docs.append(Document(name, "student", clean(str(f.relative_to(root)), 300), code, note))
    return docs


def _under_problem_package(path: Path) -> bool:
    """Is ``path`` inside a problem package (tests, generators, checkers)? Those are never read."""
    root = problems_root().resolve()
    try:
        rel = path.resolve().relative_to(root)
    except ValueError:
        return False
    return bool(rel.parts) and (root / rel.parts[0] / "problem.yaml").is_file()


def collect_references(folders: list[str | Path] = ()) -> list[Document]:
    """The tutorial's code, then every ``.py``/``.ipynb`` under each named folder (recursively;
    links and files inside problem packages skipped)."""
    docs = [Document("reference: tutorial", "reference", "reference_impl/teaching/tutorial_bugs.py",
                     TUTORIAL.read_text())]
    for folder in folders:
        folder = Path(folder)
        if not folder.is_dir():
            raise ValueError(f"reference folder {folder} does not exist")
        files = sorted(p for p in folder.rglob("*") if p.suffix in SUFFIXES and not p.is_symlink()
                       and p.is_file() and not _under_problem_package(p))
        if len(files) > MAX_REFERENCE_FILES:
            raise ValueError(f"reference folder {folder} holds {len(files)} files (at most {MAX_REFERENCE_FILES})")
        for p in files:
            try:
                code = read_code(p)
            except SubmissionError:
                continue
            label = clean(f"{folder.name}/{p.relative_to(folder)}", 300)
            docs.append(Document(f"reference: {label}", "reference", label, code))
    return docs


def statement_snippets(markdown: str) -> str:
    """The code in a statement: fenced and indented blocks, and inline code spans.

    >>> statement_snippets("Call `delaunay(points)`.\\n\\n    4\\n    1 1\\n\\n```python\\nx = 1\\n```\\n")
    'x = 1\\n\\n4\\n1 1\\n\\ndelaunay(points)'
    """
    blocks = [m.group(2) for m in _FENCED.finditer(markdown)]
    rest = _FENCED.sub("", markdown)
    indented, current = [], []
    for line in rest.splitlines():
        if line.startswith("    ") or (current and not line.strip()):
            current.append(line[4:])
        elif current:
            indented.append("\n".join(current).strip() + "\n")
            current = []
    if current:
        indented.append("\n".join(current).strip() + "\n")
    inline = [m.group(1) for m in _INLINE.finditer(rest)]
    return "\n".join([*blocks, *indented, "\n".join(inline)])


def boilerplate(problem: str, extra: list[str | Path] = ()) -> list[str]:
    """Code everyone is given: the released starter notebook (the source notebook with each
    solution replaced by nbgrader's stub), the statement's snippets, and files of ``extra`` folders."""
    p = load_problem(problem)
    out = []
    nb = problems_root() / "source" / problem / f"{problem}.ipynb"
    if nb.is_file():
        cells = json.loads(nb.read_text()).get("cells", [])
        for c in cells:
            if c.get("cell_type") == "code":
                src = c.get("source", "")
                out.append(_SOLUTION.sub(_NB_STUB, "".join(src) if isinstance(src, list) else src))
    statement = p.path / "statement" / "problem.en.md"
    if statement.is_file():
        out.append(statement_snippets(statement.read_text()))
    for folder in extra:
        if not Path(folder).is_dir():
            raise ValueError(f"boilerplate folder {folder} does not exist")
        out += [d.code for d in collect_references([folder])[1:]]
    return out


@dataclass
class Fingerprint:
    """What copydetect's ``compare_files`` reads of a ``CodeFingerprint``, built here with a
    deterministic k-gram hash (copydetect hashes with Python's ``hash()``, which changes from run
    to run, and so would the winnowed fingerprints and the scores)."""

    filename: str
    k: int
    filtered_code: str
    offsets: np.ndarray
    hashes: set
    hash_idx: dict
    token_coverage: float


def _kgram_hashes(text: str, k: int) -> np.ndarray:
    data = text.encode("utf-8", errors="surrogatepass")
    if len(text) == len(data):  # ASCII (the filtered code almost always is): slice bytes
        grams = (data[i:i + k] for i in range(len(data) - k + 1))
    else:
        grams = (text[i:i + k].encode("utf-8", errors="surrogatepass") for i in range(len(text) - k + 1))
    return np.array([int.from_bytes(hashlib.blake2b(g, digest_size=8).digest(), "little", signed=True)
                     for g in grams], dtype=np.int64)


def _fingerprint(name: str, code: str, win: int, boiler: np.ndarray | None = None, lang: str = "python") -> Fingerprint:
    """Tokenise and filter ``code`` (copydetect's ``filter_code`` with Pygments' lexer of ``lang``:
    names -> V/F, strings -> S, no comments or whitespace), hash its k-grams, winnow, drop
    boilerplate hashes."""
    from copydetect.utils import filter_code, get_token_coverage, winnow

    filtered, offsets = filter_code(code, name, lang)
    hashes, idx = winnow(_kgram_hashes(filtered, NOISE_T), win, remove_duplicates=False)
    if boiler is not None and len(boiler) and len(hashes):
        keep = ~np.isin(hashes, boiler)
        hashes, idx = hashes[keep], idx[keep]
    hash_idx: dict = {}
    for h, i in zip(hashes.tolist(), idx.tolist()):
        hash_idx.setdefault(h, []).append(i)
    return Fingerprint(name, NOISE_T, filtered, offsets, set(hash_idx), hash_idx,
                       get_token_coverage(hash_idx, NOISE_T, len(filtered)))


def boilerplate_hashes(codes: list[str]) -> np.ndarray:
    """Every k-gram hash of the boilerplate (window 1: no winnowing, nothing slips through)."""
    hashes: set = set()
    for code in codes:
        hashes |= _fingerprint("boilerplate.py", code, 1).hashes
    return np.array(sorted(hashes), dtype=np.int64)


def language(path: str) -> str:
    """The language of a document by its file name (:func:`grader.judging.languages.language_of`;
    ``"python"`` for no name or an unknown suffix).

    >>> language("ada/delaunay.ipynb"), language("bo/main.cpp"), language("cy/main.cc")
    ('python', 'cpp', 'cpp')
    """
    found = language_of(path) if path else None
    return found.name if found is not None else "python"


def fingerprint(doc: Document, boiler: np.ndarray | None = None) -> Document:
    """``doc`` with the code decoded from its data and its marks (Python only), and the winnowed
    fingerprints of both (boilerplate hashes removed)."""
    found = unpack(doc.code, language(doc.path))
    doc.decoded, doc.marks = found.code, found.marks
    doc.fp = _fingerprint(doc.path or "submission.py", doc.compared, GUARANTEE_T - NOISE_T + 1, boiler,
                          language(doc.path))
    return doc


def compare(a: Document, b: Document, threshold: float = THRESHOLD) -> Pair:
    """The shared code of two fingerprinted documents (``b`` may be a reference)."""
    from copydetect import compare_files

    tokens, (sa, sb), (sl_a, sl_b) = compare_files(a.fp, b.fp)
    pair = Pair(a, b, float(sa), float(sb), int(tokens), np.asarray(sl_a, dtype=np.int64).reshape(2, -1),
                np.asarray(sl_b, dtype=np.int64).reshape(2, -1))
    pair.flagged = pair.score >= threshold and pair.tokens >= MIN_TOKENS
    return pair


@dataclass
class Analysis:
    """Everything a report needs: the documents and every compared pair, best score first."""

    problem: str
    students: list[Document]
    references: list[Document]
    pairs: list[Pair]
    threshold: float

    @property
    def flagged(self) -> list[Pair]:
        return [p for p in self.pairs if p.flagged]

    @property
    def marked(self) -> list[Document]:
        """The students whose submission runs code from data (or holds encoded code)."""
        return [d for d in self.students if d.marks]

    def best(self, student: Document) -> Pair | None:
        """The student's highest-scoring pair (with a classmate or a reference)."""
        if "_best" not in self.__dict__:
            best: dict[int, Pair] = {}
            for p in self.pairs:  # best score first
                best.setdefault(id(p.a), p)
                best.setdefault(id(p.b), p)
            self.__dict__["_best"] = best
        return self.__dict__["_best"].get(id(student))


def analyse(problem: str, root: str | Path, references: list[str | Path] = (), extra_boilerplate: list[str | Path] = (),
            threshold: float = THRESHOLD) -> Analysis:
    """Compare every pair of the class and every student with every reference."""
    if not 0 < threshold <= 1:
        raise ValueError(f"--threshold must be in (0, 1], not {threshold}")
    boiler = boilerplate_hashes(boilerplate(problem, list(extra_boilerplate)))  # also: unknown problem -> error
    students = [fingerprint(d, boiler) for d in collect_class(problem, root)]
    refs = [fingerprint(d, boiler) for d in collect_references(list(references))]
    readable = [d for d in students if d.code]
    same = lambda a, b: language(a.path) == language(b.path)  # noqa: E731 - C++ is compared with C++ only
    pairs = [compare(a, b, threshold) for a, b in itertools.combinations(readable, 2) if same(a, b)]
    pairs += [compare(s, r, threshold) for s in readable for r in refs if same(s, r)]
    pairs.sort(key=lambda p: (-p.score, -p.tokens, p.a.name, p.b.name))
    return Analysis(problem, students, refs, pairs, threshold)


def summary_lines(analysis: Analysis) -> list[str]:
    """What the command prints: one line per flagged pair, one per marked submission, then a count."""
    lines = [f"{p.score:5.2f}  {p.a.name}  ~  {p.b.name}  ({p.tokens} shared tokens)" for p in analysis.flagged]
    lines += [f"marked  {d.name}: {'; '.join(d.marks)}" for d in analysis.marked]
    n = len(analysis.students)
    lines.append(f"{analysis.problem}: {n} submissions, {len(analysis.references)} references, "
                 f"{len(analysis.flagged)} flagged pairs (score >= {analysis.threshold:g}), "
                 f"{len(analysis.marked)} marked (run code from data)")
    return lines
