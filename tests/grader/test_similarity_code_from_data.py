"""``similarity`` sees code carried as data (grader/classroom/code_from_data.py): an accepted solution hidden in
a string (base64, zlib + base64, hex, rot13, base64 split into concatenated chunks, and a wrapper
inside a wrapper) and exec'd is decoded statically and flagged with the original; submissions that
run code from data are marked with a reason, decoded or not; decoding is bomb-, depth- and
time-safe and never runs the submission; the innocent solutions are neither marked nor flagged.

Run: .venv/bin/python -m pytest tests/grader/test_similarity_code_from_data.py -q -n 0
"""
from __future__ import annotations

import ast
import base64
import codecs
import csv
import shutil
import time
import zlib
from pathlib import Path

import pytest

from grader.classroom import code_from_data as cfd
from grader.classroom import similarity as sim
from .conftest import REPO

ORIGINAL = REPO / "solutions" / "delaunay" / "accepted_walk.py"
INNOCENT = {"ada": "delaunay-3d/accepted_bw3d.py", "bo": "edge-flip/accepted_lawson.py",
            "cy": "closest-pair/accepted_sweep.py"}


def _b64(data: bytes) -> str:
    return base64.b64encode(data).decode()


#: the wrapper's first line: the judge sees a program that reads its input (stdio mode)
READS = "import sys; sys.stdin\n"


def disguises(code: str) -> dict[str, tuple[str, str]]:
    """The attack: ``code`` as data behind a short wrapper; student -> (wrapper, expected mark)."""
    raw = code.encode()
    chunks = [_b64(raw)[i:i + 400] for i in range(0, len(_b64(raw)), 400)]
    inner = f"import zlib, base64; exec(zlib.decompress(base64.b64decode({_b64(zlib.compress(raw))!r})))\n"
    return {
        "b64": (f"{READS}import base64\nexec(base64.b64decode('{_b64(raw)}'))\n",
                "runs code decoded from base64 at line 3"),
        "zlib": (f"{READS}import base64 as b, zlib as z\nexec(z.decompress(b.b64decode('{_b64(zlib.compress(raw, 9))}')))\n",
                 "runs code decoded from base64 + zlib at line 3"),
        "hex": (f"{READS}exec(bytes.fromhex('{raw.hex()}').decode())\n", "runs code decoded from hex at line 2"),
        "rot13": (f"{READS}import codecs\nexec(codecs.decode({codecs.encode(code, 'rot13')!r}, 'rot13'))\n",
                  "runs code decoded from rot13 at line 3"),
        "chunks": (f"{READS}from base64 import b64decode\ns = ''\n" + "".join(f"s += {c!r}\n" for c in chunks)
                   + "run = exec\nrun(b64decode(s))\n", "refers to exec without calling it at line"),
        "nested": (f"{READS}import base64\nexec(base64.b64decode('{_b64(inner.encode())}'))\n",
                   "runs code decoded from base64 + zlib at line 1 (in the code found at line 3)"),
    }


@pytest.fixture(scope="module")
def attacked(tmp_path_factory) -> tuple[Path, sim.Analysis]:
    root = tmp_path_factory.mktemp("class")
    (root / "orig").mkdir()
    shutil.copy(ORIGINAL, root / "orig" / "delaunay.py")
    for student, src in INNOCENT.items():
        (root / student).mkdir()
        shutil.copy(REPO / "solutions" / src, root / student / "delaunay.py")
    for student, (wrapper, _) in disguises(ORIGINAL.read_text()).items():
        (root / student).mkdir()
        (root / student / "delaunay.py").write_text(wrapper)
    return root, sim.analyse("delaunay", root)


def pair(analysis: sim.Analysis, a: str, b: str) -> sim.Pair:
    return next(p for p in analysis.pairs if {p.a.name, p.b.name} == {a, b})


@pytest.mark.parametrize("student", list(disguises("x = 1\n")))
def test_an_encoded_copy_is_flagged_with_the_original(attacked, student):
    _, analysis = attacked
    p = pair(analysis, "orig", student)
    assert p.flagged and p.score > max(analysis.threshold, 0.9), (student, p.score)
    assert len([d for d in analysis.students if d.name == student][0].code) < 12_000  # the copy: one blob


def test_the_wrappers_are_programs_the_judge_runs():
    """Each wrapper is judged in stdio mode (measured: ``python -m grader judge delaunay`` on each is
    AC 100/100 in the jail; not repeated here, it takes 10-40 s per file on a loaded machine)."""
    from grader.judging.submissions import Submission

    for wrapper, _ in disguises(ORIGINAL.read_text()).values():
        assert Submission.from_source(wrapper).mode("delaunay") == "stdio"


@pytest.mark.parametrize("student", list(disguises("x = 1\n")))
def test_an_encoded_copy_is_marked_with_its_reason(attacked, student):
    _, analysis = attacked
    doc = next(d for d in analysis.students if d.name == student)
    reason = disguises("x = 1\n")[student][1]
    assert any(m.startswith(reason) for m in doc.marks), doc.marks
    assert "def delaunay(points)" in doc.decoded and "def delaunay(points)" not in doc.code


def test_innocent_solutions_are_neither_marked_nor_flagged(attacked):
    _, analysis = attacked
    innocent = {"orig", *INNOCENT}
    assert {d.name for d in analysis.marked} == set(disguises("x = 1\n"))
    assert not [p for p in analysis.flagged if {p.a.name, p.b.name} <= innocent]
    assert [(p.a.name, p.b.name) for p in analysis.flagged if innocent & {p.a.name, p.b.name} - {"orig"}] == []
    # functions of one's own named like builtins, and re.compile, are not exec/eval/compile
    own = ("import re\nfrom re import compile\nP = re.compile(input())\nQ = compile('a+')\n"
           "def eval(x):\n    return x\nprint(eval(3))\nclass A:\n    def exec(self, q):\n        return q\n")
    assert cfd.unpack(own) == cfd.Unpacked()
    # no accepted solution of any problem runs code from data
    for f in sorted(REPO.glob("solutions/*/accepted_*.py")):
        if not f.is_symlink():
            assert cfd.unpack(f.read_text()) == cfd.Unpacked(), f


def test_marks_reach_the_summary_the_csv_and_the_html(attacked, tmp_path):
    from grader.classroom.similarity_report import run

    root, _ = attacked
    analysis = run("delaunay", root, tmp_path)
    lines = sim.summary_lines(analysis)
    assert "marked  b64: runs code decoded from base64 at line 3" in lines
    assert lines[-1].endswith(f"{len(disguises('x = 1'))} marked (run code from data)")
    rows = {(r["a"], r["b"]): r for r in csv.DictReader(open(tmp_path / "similarity.csv"))}
    row = rows.get(("orig", "hex")) or rows[("hex", "orig")]
    assert row["flagged"] == "yes" and "runs code decoded from hex at line 2" in row["a_marks"] + row["b_marks"]
    index = (tmp_path / "similarity.html").read_text()
    assert "Submissions that run code from data" in index and "runs code decoded from base64 + zlib at line 3" in index
    pages = "".join(p.read_text() for p in (tmp_path / "similarity").glob("pair-*.html"))
    assert "Runs code from data: runs code decoded from rot13" in pages
    assert "# ---- found at line 3, decoded from base64 ----" in pages  # the decoded code is shown


@pytest.mark.parametrize("code, reason", [
    ("import sys\nexec(sys.stdin.read())\n", "runs code computed at run time (exec of a non-literal) at line 2"),
    ("import marshal\nf = marshal.loads(open('x', 'rb').read())\n", "loads compiled bytecode (marshal) at line 2"),
    ("import builtins\ngetattr(builtins, 'ex' + 'ec')('x = 1')\n", "reaches exec through getattr at line 2"),
    ("m = input()\nmod = __import__(m)\n", "imports a module named at run time at line 2"),
    ("import importlib\nimportlib.import_module('x' * 2)\nimportlib.import_module(input())\n",
     "imports a module named at run time at line 3"),
    ("import pickle\npickle.loads(b'')\n", "unpickles data at line 2"),
    ("import types\nm = types.ModuleType('m')\nexec(compile(SRC, 'm', 'exec'), m.__dict__)\n",
     "compiles code computed at run time (compile of a non-literal) at line 3"),
    ("r = eval\nr('1 + 1')\n", "refers to eval without calling it at line 1"),
    ("x = __builtins__['exec']\n", "looks up exec by name at line 1"),
])
def test_running_code_from_data_is_marked_even_when_nothing_decodes(code, reason):
    assert any(m.startswith(reason) for m in cfd.unpack(code).marks), cfd.unpack(code).marks


def test_more_decoders_and_code_written_to_a_module():
    src = ORIGINAL.read_text()
    raw = src.encode()
    cases = {
        "''.join(chr(c) for c in %r)" % [ord(c) for c in src]: "character codes",
        "bytes(%r).decode()" % list(raw): "byte values",
        f"{src[::-1]!r}[::-1]": "reversal",
        f"base64.b32decode({base64.b32encode(raw).decode()!r})": "base32",
        f"base64.b85decode({base64.b85encode(raw).decode()!r})": "base85",
        f"base64.urlsafe_b64decode({base64.urlsafe_b64encode(raw).decode()!r})": "base64",
        f"codecs.decode({raw.hex()!r}, 'hex')": "hex",
        f"binascii.unhexlify({raw.hex()!r})": "hex",
        f"gzip.decompress(base64.a85decode({base64.a85encode(__import__('gzip').compress(raw)).decode()!r}))":
            "ascii85 + gzip",
        f"lzma.decompress(base64.b64decode({_b64(__import__('lzma').compress(raw))!r}))": "base64 + lzma",
        f"bz2.decompress(base64.b64decode({_b64(__import__('bz2').compress(raw))!r}))": "base64 + bz2",
        f"' '.join({src.split(' ')!r})": "",
    }
    for expr, steps in cases.items():
        code = f"import base64, binascii, bz2, codecs, gzip, lzma\nexec({expr})\n"
        found = cfd.unpack(code)
        assert "def delaunay(points)" in found.code, expr[:60]
        assert found.marks == [f"runs code decoded from {steps} at line 2" if steps else "runs code from a string at line 2"]
    # written to a module and imported: not exec'd, but the encoded code is found and marked
    code = (f"import base64, importlib\nopen('sol.py', 'wb').write(base64.b64decode({_b64(raw)!r}))\n"
            "sol = importlib.import_module('sol')\n")
    found = cfd.unpack(code)
    assert "def delaunay(points)" in found.code and found.marks == ["holds Python code encoded as base64 at line 2"]
    # chunks in a list, joined where they are written out
    chunks = [_b64(raw)[i:i + 300] for i in range(0, len(_b64(raw)), 300)]
    found = cfd.unpack(f"import base64\nPARTS = {chunks!r}\n\n\nopen('s.py', 'wb').write(base64.b64decode(''.join(PARTS)))\n")
    assert "def delaunay(points)" in found.code and found.marks == ["holds Python code encoded as base64 at line 5"]
    # 1881 chunks of 4 characters in one a + b + ... chain (deeper than the evaluator's nesting limit)
    tiny = " + ".join(repr(_b64(raw)[i:i + 4]) for i in range(0, len(_b64(raw)), 4))
    for code, mark in ((f"import base64\nexec(base64.b64decode({tiny}))\n", "runs code decoded from base64 at line 2"),
                       (f"import base64\nS = {tiny}\nopen('s.py', 'wb').write(base64.b64decode(S))\n",
                        "holds Python code encoded as base64 at line 2")):
        start = time.process_time()
        found = cfd.unpack(code)
        assert "def delaunay(points)" in found.code and found.marks == [mark] and time.process_time() - start < 1
    # a blob that is only data, decoded automatically (no decoder called in the file)
    found = cfd.unpack(f"BLOB = {base64.b85encode(zlib.compress(raw)).decode()!r}\n")
    assert "def delaunay(points)" in found.code and found.marks == ["holds Python code encoded as base85 + zlib at line 1"]


def test_decoding_is_safe_nothing_runs_and_bombs_stop(tmp_path, monkeypatch):
    canary = tmp_path / "ran"
    payload = f"open({str(canary)!r}, 'w').write('x')\nimport os\nos.remove({str(tmp_path)!r})\n".encode()
    found = cfd.unpack(f"import base64\nexec(base64.b64decode({_b64(payload)!r}))\n")
    assert not canary.exists() and "import os" in found.code  # decoded and compared, never run
    bomb = _b64(zlib.compress(b"\0" * 300_000_000, 9))  # 300 MB of zeros in 300 kB
    start = time.monotonic()
    found = cfd.unpack(f"import base64, zlib\nexec(zlib.decompress(base64.b64decode({bomb!r})))\nZ = {bomb!r}\n")
    assert time.monotonic() - start < 10
    assert found.marks == ["runs data that decodes to more than 2 MiB at line 2 (not examined)"] and found.code == ""
    for huge in ("exec('x = 1;' * 10**12)", "exec(bytes(10**12))", "exec(chr(65) * 2**60)",
                 "(" * 200 + "1" + ")" * 200, "x = " + " + ".join(["'a'"] * 20000), "x = " + "-" * 3000 + "1"):
        found = cfd.unpack(huge)  # no exception, no memory blow-up
        assert found.code == "" and len(found.marks) <= 1
    # code that decodes code that decodes code: a few levels are followed, then it stops
    layer = ORIGINAL.read_text()
    for _ in range(cfd.MAX_LEVELS + 2):
        layer = f"import base64\nexec(base64.b64decode({_b64(layer.encode())!r}))\n"
    found = cfd.unpack(layer)
    assert "def delaunay" not in found.code and len(found.marks) == cfd.MAX_LEVELS
    monkeypatch.setattr(cfd, "SECONDS", 0.0)  # the time limit: stops with a mark, not an error
    stopped = cfd.unpack(disguises(ORIGINAL.read_text())["b64"][0])
    assert stopped.marks == ["stopped decoding at the time limit: some data was not examined"] and stopped.code == ""
    monkeypatch.setattr(cfd, "SECONDS", 2.0)
    monkeypatch.setattr(cfd, "MAX_STEPS", 50)  # and the step limit
    assert "stopped decoding at the time limit: some data was not examined" in cfd.unpack(
        disguises(ORIGINAL.read_text())["chunks"][0]).marks


def test_decoded_code_is_escaped_in_the_report(tmp_path):
    from grader.classroom.similarity_report import run

    evil = ORIGINAL.read_text() + "\nBANNER = '</pre><script>alert(1)</script>'\n"
    for student, code in (("ann", evil), ("ben", disguises(evil)["zlib"][0])):
        (tmp_path / "class" / student).mkdir(parents=True)
        (tmp_path / "class" / student / "delaunay.py").write_text(code)
    analysis = run("delaunay", tmp_path / "class", tmp_path / "out")
    assert len(analysis.flagged) == 1 and analysis.flagged[0].score > 0.9
    page = (tmp_path / "out" / "similarity" / "pair-1.html").read_text()
    assert "<script>" not in page and page.count("&lt;script&gt;alert(1)&lt;/script&gt;") == 2


def test_only_python_is_unpacked_and_the_import_circle_is_gone():
    wrapper = disguises(ORIGINAL.read_text())["b64"][0]
    assert cfd.unpack(wrapper, "cpp") == cfd.Unpacked() and cfd.unpack("def (", "python") == cfd.Unpacked()
    assert sim.language("bo/main.cpp") == "cpp" and sim.language("a/b.ipynb") == "python"
    doc = sim.fingerprint(sim.Document("x", "student", "x/main.cpp", wrapper))
    assert doc.marks == [] and doc.compared == wrapper
    imports = {n.module for n in ast.walk(ast.parse((REPO / "grader" / "classroom" / "similarity.py").read_text()))
               if isinstance(n, ast.ImportFrom)}
    assert "similarity_report" not in imports  # similarity_report imports similarity, not the reverse
