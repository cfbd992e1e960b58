"""Code carried as data in a Python submission: found, decoded and marked for the similarity check.

A copy can hide from a token-based comparison by travelling as data: a classmate's solution
base64-encoded in one string and ``exec``'d behind a one-line wrapper is, to copydetect, one
string token. :func:`unpack` reads a submission's syntax tree (``ast``) and never runs any of
it. It evaluates only constant expressions built from a small whitelist of pure decoding
functions (:mod:`grader.classroom.data_decoders`: ``base64`` b64/b32/b16/b85/a85 and urlsafe, ``zlib``/``gzip``/``bz2``/``lzma``
decompression capped at :data:`MAX_OUTPUT` bytes, ``codecs.decode`` with rot13/hex/base64/zlib/bz2,
``bytes.fromhex``, ``binascii``, concatenation and ``join`` of literals, ``bytes([...])`` of ints,
``chr`` over int lists, slices such as ``[::-1]``, ``str.decode``/``encode``) on constant arguments
and on variables assigned such values. Every string or bytes value found that way (and every
plain literal), when it decodes, possibly through a few automatic steps (base64, base32, base85,
hex, rot13, reversal, decompression), to Python with at least :data:`MIN_STATEMENTS` statements, is
returned as code to fingerprint next to the submission; decoded code is unpacked again, up to
:data:`MAX_LEVELS` levels. Everything stops at :data:`SECONDS` of work per submission.

It also *marks* a submission that runs code from data, decoded or not: ``exec``/``eval``/``compile``
(also reached indirectly: ``f = exec``, ``getattr(builtins, "exec")``), ``marshal`` (bytecode: it
cannot be decompiled safely, so it is marked, never compared), ``pickle``, modules imported by a
computed name or loaded from a spec, ``runpy``, functions built from code objects, and Python code
held encoded in a literal. Each mark is one short reason with a line number.

Only Python is read; other languages get nothing (see :func:`unpack`'s ``language``).

Example:
    >>> import base64
    >>> blob = base64.b64encode(b"def f(a):\\n    b = a + 1\\n    return b * 2\\n").decode()
    >>> found = unpack(f"import base64\\nexec(base64.b64decode('{blob}'))\\n")
    >>> found.marks
    ['runs code decoded from base64 at line 2']
    >>> "return b * 2" in found.code
    True
"""

from __future__ import annotations

import ast
import re
import time
from dataclasses import dataclass, field

from .data_decoders import (BUILTINS, CODECS, DECODERS, MAX_OUTPUT, METHODS, MIN_CANDIDATE, NoValue, TooLarge,
                            as_list, binop, call_decoder, cap, is_marshal, join_via, method, next_steps, to_chr)

MAX_APPENDIX = 4 << 20   #: characters of decoded code returned per submission
MAX_LEVELS = 4           #: code that decodes code that decodes code: levels followed
MAX_CHAIN = 4            #: automatic decoding steps tried on one value
MAX_DEPTH = 80           #: nesting of one evaluated expression
MAX_STEPS = 2_000_000    #: evaluation steps per submission
MAX_MARKS = 20
MIN_STATEMENTS = 3       #: decoded text counts as code from this many statements
SECONDS = 2.0            #: work per submission (all levels)

_SINKS = {"exec": "runs", "eval": "runs", "compile": "compiles"}
_BYTECODE = {"marshal.loads", "marshal.load"}
_PICKLE = {"pickle.loads", "pickle.load", "pickle.Unpickler", "_pickle.loads", "dill.loads", "cloudpickle.loads"}
_IMPORTERS = {"__import__", "importlib.import_module", "importlib.__import__", "builtins.__import__"}
_LOADERS = {"importlib.util.spec_from_file_location", "importlib.util.spec_from_loader",
            "importlib.util.module_from_spec", "importlib.machinery.SourceFileLoader",
            "importlib.machinery.SourcelessFileLoader", "runpy.run_path", "runpy.run_module", "zipimport.zipimporter",
            "types.FunctionType", "types.CodeType", "types.LambdaType"}
_INDIRECT = set(_SINKS) | {"__import__"}


class _Stop(Exception):
    """The time or step budget of a submission is spent."""


@dataclass
class Unpacked:
    """What :func:`unpack` found: decoded code to fingerprint, and why the submission is marked."""

    code: str = ""  #: decoded code, each piece under a comment naming its line and decoding
    marks: list[str] = field(default_factory=list)  #: short reasons, e.g. "runs code decoded from base64 at line 3"

    def mark(self, reason: str) -> None:
        """Add ``reason`` once (at most :data:`MAX_MARKS` reasons)."""
        if reason not in self.marks and len(self.marks) < MAX_MARKS:
            self.marks.append(reason)


class _Evaluator:
    """Values of constant expressions of one module, with the whitelist of decoders (nothing else runs)."""

    def __init__(self, nodes: list[ast.AST], deadline: float) -> None:
        self.deadline, self.steps = deadline, 0
        self.aliases: dict[str, str] = {}           # local name -> module or function it stands for
        self.assigns: dict[str, list[ast.AST]] = {}  # variable -> Assign/AugAssign nodes, in source order
        self.busy: set[str] = set()
        # names the module binds itself (def, class, parameters, loop targets...): never a builtin
        self.defined: set[str] = set()
        self.cache: dict[int, tuple | NoValue] = {}  # id(node) -> value of a node outside comprehensions
        for node in nodes:
            if isinstance(node, ast.Name):
                if not isinstance(node.ctx, ast.Load):
                    self.defined.add(node.id)
            elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                self.defined.add(node.name)
            elif isinstance(node, ast.arg):
                self.defined.add(node.arg)
            elif isinstance(node, ast.Import):
                for a in node.names:
                    self.aliases[a.asname or a.name.split(".")[0]] = a.name if a.asname else a.name.split(".")[0]
            elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
                for a in node.names:
                    self.aliases[a.asname or a.name] = f"{node.module}.{a.name}"
            elif isinstance(node, (ast.Assign, ast.AugAssign, ast.AnnAssign)):
                targets = node.targets if isinstance(node, ast.Assign) else [node.target]
                for t in targets:
                    if isinstance(t, ast.Name):
                        self.assigns.setdefault(t.id, []).append(node)
        for nodes in self.assigns.values():
            nodes.sort(key=lambda n: (n.lineno, n.col_offset))

    def tick(self) -> None:
        """Count one step; :class:`_Stop` past :data:`MAX_STEPS` or the deadline."""
        self.steps += 1
        if self.steps > MAX_STEPS or (self.steps % 512 == 0 and time.monotonic() > self.deadline):
            raise _Stop

    def qualname(self, node: ast.AST) -> str | None:
        """``base64.b64decode`` for ``b64.b64decode`` after ``import base64 as b64``, and so on."""
        if isinstance(node, ast.Name):
            if node.id in self.aliases:
                return self.aliases[node.id]
            nodes = self.assigns.get(node.id, [])
            if len(nodes) == 1 and isinstance(nodes[0], ast.Assign) and node.id not in self.busy:
                self.busy.add(node.id)
                try:
                    return self.qualname(nodes[0].value)  # m = __import__("zlib"); d = base64.b64decode
                finally:
                    self.busy.discard(node.id)
            return None if nodes or node.id in self.defined else node.id
        if isinstance(node, ast.Attribute):
            base = self.qualname(node.value)
            return f"{base}.{node.attr}" if base else None
        if isinstance(node, ast.Call) and self.qualname(node.func) in _IMPORTERS and node.args:
            try:
                name = self.value(node.args[0])[0]
            except NoValue:
                return None
            return name if isinstance(name, str) else None
        return None

    def value(self, node: ast.AST, depth: int = 0, bound: dict | None = None) -> tuple[object, tuple]:
        """``(value, decoding steps)`` of a constant expression; raises :class:`NoValue`."""
        if bound:
            return self._value(node, depth, bound)
        if id(node) not in self.cache:
            try:
                self.cache[id(node)] = self._value(node, depth, {})
            except NoValue as exc:
                self.cache[id(node)] = exc
        got = self.cache[id(node)]
        if isinstance(got, NoValue):
            raise got
        return got

    def _value(self, node: ast.AST, depth: int, bound: dict) -> tuple[object, tuple]:
        self.tick()
        if depth > MAX_DEPTH:
            raise NoValue("too deep")
        d = depth + 1
        if isinstance(node, ast.Constant) and isinstance(node.value, (str, bytes, int)) and not isinstance(node.value, bool):
            return node.value, ()
        if isinstance(node, ast.Name):
            return self._name(node.id, d, bound)
        if isinstance(node, (ast.List, ast.Tuple)):
            items = [self.value(e, d, bound) for e in node.elts]
            return [v for v, _ in items], join_via(*(w for _, w in items))
        if isinstance(node, ast.JoinedStr):
            parts = [self.value(p.value if isinstance(p, ast.FormattedValue) else p, d, bound) for p in node.values
                     if not (isinstance(p, ast.FormattedValue) and (p.format_spec or p.conversion != -1))]
            if len(parts) != len(node.values) or not all(isinstance(v, (str, int)) for v, _ in parts):
                raise NoValue("f-string")
            return cap("".join(str(v) for v, _ in parts)), join_via(*(w for _, w in parts))
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.Invert, ast.UAdd)):
            v, via = self.value(node.operand, d, bound)
            if not isinstance(v, int):
                raise NoValue("unary operator")
            return {ast.USub: -v, ast.Invert: ~v, ast.UAdd: v}[type(node.op)], via
        if isinstance(node, ast.BinOp):
            chain = [node]  # a + b + c + ... (chunks): a left-leaning chain, folded without recursion
            while isinstance(chain[-1].left, ast.BinOp) and type(chain[-1].left.op) is type(node.op):
                chain.append(chain[-1].left)
            value, via = self.value(chain[-1].left, d, bound)
            for link in reversed(chain):
                b, vb = self.value(link.right, d, bound)
                value, via = binop(link.op, value, b), join_via(via, vb)
            return value, via
        if isinstance(node, ast.Subscript):
            return self._subscript(node, d, bound)
        if isinstance(node, (ast.ListComp, ast.GeneratorExp)):
            return self._comprehension(node, d, bound)
        if isinstance(node, ast.Call) and not any(isinstance(a, ast.Starred) for a in node.args):
            return self._call(node, d, bound)
        raise NoValue(type(node).__name__)

    def _name(self, name: str, depth: int, bound: dict) -> tuple[object, tuple]:
        if name in bound:
            return bound[name], ()
        nodes = self.assigns.get(name)
        if not nodes or name in self.busy:
            raise NoValue(name)
        self.busy.add(name)
        try:
            value, via = None, ()
            for n in nodes:  # s = "..."; s += "..." (chunks): folded in source order
                if n.value is None:
                    raise NoValue(name)
                v, w = self.value(n.value, depth, {**bound, name: value} if value is not None else bound)
                if isinstance(n, ast.AugAssign):
                    v = binop(n.op, value, v)
                value, via = v, join_via(via, w)
            return value, via
        finally:
            self.busy.discard(name)

    def _subscript(self, node: ast.Subscript, depth: int, bound: dict) -> tuple[object, tuple]:
        seq, via = self.value(node.value, depth, bound)
        if not isinstance(seq, (str, bytes, list)):
            raise NoValue("subscript")
        s = node.slice
        if isinstance(s, ast.Slice):
            ends = [None if e is None else self.value(e, depth, bound)[0] for e in (s.lower, s.upper, s.step)]
            if not all(e is None or isinstance(e, int) for e in ends) or ends[2] == 0:
                raise NoValue("slice")
            out = seq[ends[0]:ends[1]:ends[2]]
            return out, join_via(via, ("reversal",) if ends[2] is not None and ends[2] < 0 else ())
        i = self.value(s, depth, bound)[0]
        if not isinstance(i, int) or not -len(seq) <= i < len(seq):
            raise NoValue("index")
        return seq[i], via

    def _comprehension(self, node: ast.ListComp | ast.GeneratorExp, depth: int, bound: dict) -> tuple[object, tuple]:
        if len(node.generators) != 1 or node.generators[0].ifs or not isinstance(node.generators[0].target, ast.Name):
            raise NoValue("comprehension")
        gen = node.generators[0]
        seq, via = self.value(gen.iter, depth, bound)
        if not isinstance(seq, (str, bytes, list)):
            raise NoValue("comprehension over a non-sequence")
        out = []
        for item in seq:
            v, w = self.value(node.elt, depth, {**bound, gen.target.id: item})
            out.append(v)
            via = join_via(via, w)
        return out, via

    def _call(self, node: ast.Call, depth: int, bound: dict) -> tuple[object, tuple]:
        func = node.func
        kwargs = {k.arg: self.value(k.value, depth, bound)[0] for k in node.keywords if k.arg}
        if len(kwargs) != len(node.keywords):
            raise NoValue("**kwargs")
        if isinstance(func, ast.Attribute) and func.attr in METHODS and self.qualname(func) is None:
            obj, via = self.value(func.value, depth, bound)
            args = [self.value(a, depth, bound) for a in node.args]
            step, out = method(obj, func.attr, [a for a, _ in args], kwargs)
            return out, join_via(via, *(w for _, w in args), (step,) if step else ())
        name = self.qualname(func)
        if name not in DECODERS and name not in BUILTINS:
            raise NoValue(f"call of {name}")
        if name == "map" and len(node.args) == 2 and self.qualname(node.args[0]) == "chr":
            seq, via = self.value(node.args[1], depth, bound)
            return [to_chr(c) for c in as_list(seq)], join_via(via, ("character codes",))
        args = [self.value(a, depth, bound) for a in node.args]
        values, via = [a for a, _ in args], join_via(*(w for _, w in args))
        if name in DECODERS:
            step, fn = DECODERS[name]
            return call_decoder(fn, values, {}), join_via(via, (step,))
        if name in ("codecs.decode", "codecs.encode") and values:
            enc = (values[1] if len(values) > 1 else kwargs.get("encoding", "utf-8"))
            enc = enc.lower().replace("-", "_") if isinstance(enc, str) else None
            if enc in CODECS:
                step, fn = CODECS[enc]
                return call_decoder(fn, values[:1], {}), join_via(via, (step,))
            return method(values[0], "decode" if name == "codecs.decode" else "encode", [enc], {})[1], via
        if name in ("bytes", "bytearray") and len(values) <= 2:
            if len(values) == 2 or (values and isinstance(values[0], str)):
                return method(values[0], "encode", values[1:], kwargs)[1], via
            return call_decoder(bytes, [as_list(values[0])], {}) if values else b"", join_via(via, ("byte values",))
        if name == "chr" and len(values) == 1:
            return to_chr(values[0]), join_via(via, ("character codes",))
        if name in ("str", "list") and len(values) == 1 and not kwargs:
            if name == "list":
                return list(as_list(values[0])), via
            if isinstance(values[0], (str, int)):
                return str(values[0]), via
        if name == "reversed" and len(values) == 1:
            return list(as_list(values[0]))[::-1], join_via(via, ("reversal",))
        raise NoValue(f"call of {name}")


def looks_like_code(text: str, minimum: int = MIN_STATEMENTS) -> bool:
    """Is ``text`` Python with at least ``minimum`` statements, not all of them bare expressions
    (a few words on lines of their own parse as names)?

    >>> looks_like_code("def f(x):\\n    y = x\\n    return y\\n"), looks_like_code("Hello\\nWorld\\nagain")
    (True, False)
    """
    if len(text) < 8 or "\x00" in text or (minimum > 1 and "\n" not in text and ";" not in text):
        return False
    try:
        tree = ast.parse(text)
    except (SyntaxError, ValueError, RecursionError, MemoryError, OverflowError):
        return False
    stmts = [n for n in ast.walk(tree) if isinstance(n, ast.stmt)]
    return len(stmts) >= minimum and any(not isinstance(n, ast.Expr) for n in stmts)


def _find_code(v: object, via: tuple, ev: _Evaluator, minimum: int, depth: int = 0) -> tuple[str, str | None, tuple]:
    """Search a few automatic decoding steps from ``v`` for Python code (``minimum`` statements)
    or a marshal blob: ``(kind, text, steps)``, kind ``"code"``, ``"bytecode"`` or ``""`` (none)."""
    ev.tick()
    if time.monotonic() > ev.deadline:  # each call may parse up to MAX_OUTPUT of text: checked every time
        raise _Stop
    if isinstance(v, bytearray):
        v = bytes(v)
    if not isinstance(v, (str, bytes)) or len(v) < 8:
        return "", None, via
    if isinstance(v, bytes) and is_marshal(v):
        return "bytecode", None, via
    try:
        text = v if isinstance(v, str) else v.decode("utf-8")
    except UnicodeDecodeError:
        text = None
    if text is not None and looks_like_code(text, minimum if depth == 0 else MIN_STATEMENTS):
        return "code", text, via
    if depth >= MAX_CHAIN:
        return "", None, via
    for step, fn in next_steps(v, via):
        try:
            out = call_decoder(fn, [], {})
        except NoValue:
            continue
        if out == v:
            continue
        found = _find_code(out, via + (step,), ev, minimum, depth + 1)
        if found[0]:
            return found
    return "", None, via


def _docstrings(nodes: list[ast.AST]) -> set[int]:
    out = set()
    for node in nodes:
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                out.add(id(first.value))
    return out


#: a source with none of these words runs no code from data (the marks' pass is skipped)
_RUNNERS = re.compile(r"exec|eval|compile|marshal|pickle|__import__|import_module|runpy|spec_from|FunctionType|CodeType"
                      r"|LambdaType|getattr|builtins|Unpickler|zipimport|SourceFileLoader|SourcelessFileLoader")


#: nodes climbed through without a value of their own (``"".join``, f-string parts, ``for c in``, keywords)
_PASSED = (ast.Name, ast.Attribute, ast.FormattedValue, ast.comprehension, ast.keyword, ast.Starred)


def _data_like(node: ast.AST) -> bool:
    """Could ``node`` hold encoded code: a long string or bytes literal, or a long list (of codes)?"""
    if isinstance(node, ast.Constant):
        return isinstance(node.value, (str, bytes)) and len(node.value) >= MIN_CANDIDATE // 2
    return isinstance(node, (ast.List, ast.Tuple)) and len(node.elts) >= MIN_CANDIDATE // 2


def _steps(via: tuple) -> str:
    return " + ".join(via)


class _Reader:
    """One level of :func:`unpack`: marks and decoded pieces of one module."""

    def __init__(self, tree: ast.Module, deadline: float, out: Unpacked) -> None:
        self.tree, self.nodes, self.out = tree, [tree], out
        self.parents: dict[int, ast.AST] = {}
        for node in self.nodes:  # ast.walk's order, keeping each node's parent
            for child in ast.iter_child_nodes(node):
                self.parents[id(child)] = node
                self.nodes.append(child)
        self.ev = _Evaluator(self.nodes, deadline)
        self.pieces: list[tuple[int, tuple, str]] = []   # (line, decoding steps, code)
        self.seen: set[str] = set()
        self.sink_args: set[int] = set()
        self.stmt_of: dict[int, ast.AST | None] = {}

    def examine(self, v: object, via: tuple, line: int, sink: bool) -> tuple[str, tuple]:
        """Look for code in ``v`` (found at ``line``, reached ``exec`` if ``sink``): keep it, mark it."""
        kind, text, steps = _find_code(v, via, self.ev, 1 if sink else MIN_STATEMENTS)
        if kind == "bytecode" and not sink:
            self.out.mark(f"holds compiled bytecode (marshal) at line {line}: it cannot be compared")
        elif kind == "code" and text not in self.seen:
            self.seen.add(text)
            self.pieces.append((line, steps, text))
            if steps and not sink:
                self.out.mark(f"holds Python code encoded as {_steps(steps)} at line {line}")
        return kind, steps

    def calls(self) -> None:
        """Marks: every way of running code from data, and what each runs when it is a constant."""
        funcs = {id(n.func) for n in self.nodes if isinstance(n, ast.Call)}
        for node in self.nodes:
            if not isinstance(node, (ast.Name, ast.Attribute, ast.Subscript, ast.Call)):
                continue
            self.ev.tick()
            line = getattr(node, "lineno", 0)
            if isinstance(node, (ast.Name, ast.Attribute)) and id(node) not in funcs:
                name = self.ev.qualname(node) if isinstance(node.ctx, ast.Load) else None
                name = name.removeprefix("builtins.") if name else None
                if name in _INDIRECT:
                    self.out.mark(f"refers to {name} without calling it at line {line} (an indirect call)")
                continue
            if isinstance(node, ast.Subscript) and isinstance(node.slice, ast.Constant) and node.slice.value in _INDIRECT:
                self.out.mark(f"looks up {node.slice.value} by name at line {line}")
                continue
            if not isinstance(node, ast.Call):
                continue
            try:
                name = self.ev.qualname(node.func)
            except NoValue:
                name = None
            name = name.removeprefix("builtins.") if name else None
            first = node.args[0] if node.args else None
            if name in _SINKS and first is not None:
                self.sink_args.add(id(first))
                inner = self.ev.qualname(first.func) if isinstance(first, ast.Call) else None
                if inner in _BYTECODE or inner in ("compile", "builtins.compile"):
                    continue  # marked where the bytecode is loaded or compiled
                verb = _SINKS[name]
                try:
                    v, via = self.ev.value(first)
                except TooLarge:
                    self.out.mark(f"{verb} data that decodes to more than {MAX_OUTPUT >> 20} MiB at line {line} "
                                  "(not examined)")
                    continue
                except NoValue:
                    self.out.mark(f"{verb} code computed at run time ({name} of a non-literal) at line {line}")
                    continue
                kind, _ = self.examine(v, via, line, sink=True)
                where = f"decoded from {_steps(via)}" if via else "from a string"
                self.out.mark(f"{verb} code {where} at line {line}"
                              + ("" if kind == "code" or not via else " (not Python once decoded)"))
            elif name in _BYTECODE:
                self.out.mark(f"loads compiled bytecode (marshal) at line {line}: it cannot be compared")
                if first is not None:
                    self.sink_args.add(id(first))
            elif name in _PICKLE:
                self.out.mark(f"unpickles data at line {line} (unpickling can run code)")
            elif name in _IMPORTERS and first is not None:
                try:
                    fixed = isinstance(self.ev.value(first)[0], str)
                except NoValue:
                    fixed = False
                if not fixed:
                    self.out.mark(f"imports a module named at run time at line {line}")
            elif name in _LOADERS:
                self.out.mark(f"loads code through {name} at line {line}")
            elif name == "getattr" and len(node.args) >= 2:
                try:
                    attr = self.ev.value(node.args[1])[0]
                except NoValue:
                    continue
                if attr in _INDIRECT or attr in ("loads", "exec_module"):
                    self.out.mark(f"reaches {attr} through getattr at line {line}")

    def data(self, docstrings: set[int]) -> None:
        """From each long literal up to the largest expression around it that has a constant text
        value (the literal itself, or a whitelisted decoding of it): that value, examined once."""
        done: set[int] = set()
        leaves = [n for n in self.nodes if id(n) not in docstrings and self.data_like(n)]
        names = set()  # variables assigned from long literals: their uses are leaves too ("".join(parts))
        for leaf in leaves:
            node = self.statement(leaf)
            if isinstance(node, (ast.Assign, ast.AugAssign, ast.AnnAssign)):
                targets = node.targets if isinstance(node, ast.Assign) else [node.target]
                names |= {t.id for t in targets if isinstance(t, ast.Name)}
        leaves += [n for n in self.nodes if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load) and n.id in names]
        above: dict[int, tuple | None] = {}  # node climbed through -> the value found at or above it
        for leaf in leaves:
            best, node, path = None, leaf, []
            while isinstance(node, (ast.expr, ast.comprehension, ast.keyword)):
                self.ev.tick()
                if id(node) in above:  # climbed before from another leaf: the rest of the way is known
                    best = above[id(node)] or best
                    break
                path.append((node, best))
                parent = self.parents.get(id(node))
                inner = (isinstance(node, ast.BinOp) and isinstance(parent, ast.BinOp) and parent.left is node
                         and type(parent.op) is type(node.op))  # only the whole chain a + b + c is evaluated
                if node is leaf or not (inner or isinstance(node, _PASSED)):
                    try:
                        v, via = self.ev.value(node)
                    except NoValue:
                        break
                    if isinstance(v, (str, bytes, bytearray)):
                        best = (node, v, via)
                node = parent
            for n, below in path:
                above[id(n)] = best if best is not below else None
            if best and id(best[0]) not in done and len(best[1]) >= MIN_CANDIDATE // 2:
                done.add(id(best[0]))
                self.examine(best[1], best[2], getattr(best[0], "lineno", 0), id(best[0]) in self.sink_args)

    def data_like(self, node: ast.AST) -> bool:
        """A long literal, a long list (of codes), or a literal chunk of a concatenation ``a + b``."""
        return _data_like(node) or (isinstance(node, ast.Constant) and isinstance(node.value, (str, bytes))
                                    and isinstance(self.parents.get(id(node)), ast.BinOp))

    def statement(self, node: ast.AST) -> ast.AST | None:
        """The statement ``node`` is part of (remembered on the way up: long chains stay linear)."""
        path = []
        while node is not None and not isinstance(node, ast.stmt) and id(node) not in self.stmt_of:
            path.append(node)
            node = self.parents.get(id(node))
        found = self.stmt_of.get(id(node), node) if node is not None else None
        for n in path:
            self.stmt_of[id(n)] = found
        return found


def unpack(source: str, language: str = "python", *, _level: int = 0, _deadline: float | None = None) -> Unpacked:
    """The code ``source`` carries as data, decoded without running anything, and the ways it runs
    code from data (see the module's docstring). ``language`` other than ``"python"``: nothing
    (a C++ submission is compared as it is). A source that does not parse: nothing."""
    out = Unpacked()
    if language != "python" or not source:
        return out
    deadline = _deadline if _deadline is not None else time.monotonic() + SECONDS
    try:
        tree = ast.parse(source)
    except (SyntaxError, ValueError, RecursionError, MemoryError, OverflowError):
        return out
    reader = _Reader(tree, deadline, out)
    try:
        if _RUNNERS.search(source):
            reader.calls()
        if any(reader.data_like(n) for n in reader.nodes):
            reader.data(_docstrings(reader.nodes))
    except _Stop:
        out.mark("stopped decoding at the time limit: some data was not examined")
    except RecursionError:
        out.mark("stopped decoding: the code nests too deeply to examine")
    parts = []
    size = 0
    for line, via, text in reader.pieces:
        if text.strip() == source.strip():
            continue
        header = f"# ---- found at line {line}" + (f", decoded from {_steps(via)}" if via else ", in a string") + " ----\n"
        if size + len(header) + len(text) > MAX_APPENDIX:
            out.mark("decoded code beyond the size limit was left out")
            break
        size += len(header) + len(text)
        parts.append(header + text.rstrip("\n") + "\n")
        if _level + 1 < MAX_LEVELS:
            inner = unpack(text, language, _level=_level + 1, _deadline=deadline)
            for m in inner.marks:
                out.mark(f"{m} (in the code found at line {line})")
            if inner.code:
                parts.append(inner.code)
                size += len(inner.code)
    out.code = "".join(parts)
    return out
