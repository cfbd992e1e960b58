"""Child side of the judge: runs INSIDE the sandbox, as ``python -IS -c LOADER CONFIG``.

The grader compiles this file once and sends the code object (``marshal``) first on the control
pipe; ``LOADER`` (:data:`grader.judging.runner.LOADER`) only reads and runs it. Run by hand,
``python -I child_bootstrap.py CONFIG`` does the same work.

Standard library only, and never imported by the grader itself. Its start-up imports only what
the interpreter has loaded already and the C half of ``json`` (``_json``): the ``json`` package,
``traceback`` and ``linecache`` all import ``re``, which alone cost more CPU than the bare
interpreter's start; they are imported when an error or a violation needs them. It

1. installs an audit hook (PEP 578) that reports forbidden imports and operations (creating
   processes, signalling other processes, sockets, reading or listing files outside the Python
   installation and the working directory, writing outside the working directory) to the parent
   on the control pipe *before* refusing them, so catching the exception does not hide it.
   Compiled engines of forbidden libraries (``matplotlib._qhull``: ``ENGINES`` in the config)
   are violations whoever imports them; a forbidden wrapper that allowed libraries import
   themselves (``matplotlib.tri``, imported by ``matplotlib.pyplot``) is a violation only when
   the student's code imports it. Messages name the student's line that led there;
2. reads the submission source from the control pipe and runs it (as module ``submission`` in
   function mode, as ``__main__`` in stdio mode); in ``exec`` mode (a compiled program) it only
   sets the program's stack limit, closes the control pipes and replaces itself with the binary;
3. function mode: serves calls of the entry function, one JSON line per request/response.
   Results are converted to JSON-native values with exact type checks (numpy arrays and scalars
   become lists and numbers); anything else is reported as a wrong type, never passed on.

Protocol (one JSON object per line), parent -> child on fd ``ctl_in``:
    (before it, for the loader: this program's length in 12 digits, then its marshalled code)
    {"source": str, "filename": str}             first line
    {"id": int, "args": [...]}                   function mode, one per test
child -> parent on fd ``ctl_out``:
    {"loaded": true} | {"load_error": {...}}     after running the module body
    {"id": int, "ok": value} | {"id": int, "error": {...}} | {"id": int, "bad_type": str}
    {"id": int, "frame": {...}}                  instead of "ok" for a long list of float rows,
                                                 when the config says "frames" (frames.py)
    {"violation": str}                           at any time
    {"exit": int}                                stdio mode, the program ended normally; the child
                                                 then waits (2 s at most) until the parent, having
                                                 measured the jail's tmpfs, closes ``ctl_in``

Example (what the parent runs, LOADER reading this program from fd 5 first):
    python -IS -c LOADER '{"mode": "function", "entry": "delaunay", "ctl_in": 5, ...}'
"""

import _json
import os
import select
import sys
import types


class _ScanContext:
    """What ``_json.make_scanner`` reads: ``json.loads``'s defaults (NaN and the infinities accepted)."""

    strict = True
    object_hook = None
    object_pairs_hook = None
    parse_float = float
    parse_int = int
    parse_constant = {"NaN": float("nan"), "Infinity": float("inf"), "-Infinity": float("-inf")}.__getitem__
    memo: dict = {}


_SCAN = _json.make_scanner(_ScanContext())


def _json_type_error(obj):
    raise TypeError(f"Object of type {type(obj).__name__} is not JSON serializable")


#: json.dumps(obj, allow_nan=True, separators=(",", ":")), from the same C encoder it uses
_ENCODER = _json.make_encoder({}, _json_type_error, _json.encode_basestring_ascii, None, ":", ",", False, False, True)


def _loads(text):
    """``json.loads`` of one protocol line (the parent's: str or UTF-8 bytes)."""
    if isinstance(text, (bytes, bytearray)):
        text = text.decode("utf-8", "surrogatepass")
    text = text.strip(" \t\n\r")
    try:
        obj, end = _SCAN(text, 0)
    except StopIteration as exc:
        raise ValueError(f"not JSON (at character {exc.value})") from None
    if end != len(text):
        raise ValueError(f"not JSON (extra data at character {end})")
    return obj


CONFIG = _loads(sys.argv[1])
if CONFIG.get("site_paths") is not None:  # started with -S: the parent named the site-packages directories
    sys.path.extend(p for p in CONFIG["site_paths"] if p not in sys.path)
    import site  # with -S importing it adds no path; it gives the builtins that site would (exit, quit, help)

    site.setquit()
    site.setcopyright()
    site.sethelper()
CTL_IN, CTL_OUT = CONFIG["ctl_in"], CONFIG["ctl_out"]
FORBIDDEN = tuple(CONFIG["forbidden"])
#: compiled engine module -> engine name ("matplotlib._qhull" -> "Qhull"): forbidden whoever imports it
ENGINES = dict(CONFIG.get("engines", {}))
#: forbidden modules that allowed libraries import themselves (pyplot imports matplotlib.tri)
LIBRARY_IMPORTS = tuple(CONFIG.get("library_imports", ()))
ENGINE_API = {k: tuple(v) for k, v in CONFIG.get("engine_api", {}).items()}
#: shared-library name prefixes of the engines ("libqhull"): loading one by path is a violation
ENGINE_LIBS = tuple(CONFIG.get("engine_libs", ()))
READ_ROOTS = tuple(CONFIG["read_roots"]) + (f"/proc/{os.getpid()}",)
WRITE_ROOTS = tuple(CONFIG["write_roots"])
SUBMISSION_FILE = CONFIG["filename"]
#: float answers go as a binary frame (grader/judging/frames.py) when the parent asks for them
FRAMES = bool(CONFIG.get("frames"))
if FRAMES:
    import binascii
    from array import array
    from itertools import chain


class SandboxViolation(BaseException):
    """Raised in student code for a forbidden operation (BaseException: ``except Exception`` misses it)."""


def _encode(obj):
    return "".join(_ENCODER(obj, 0))


def _send(obj, text=None):
    """Send ``obj`` as one JSON line (``text``: the same, already encoded by :func:`_encode`)."""
    try:  # what the submission printed so far reaches its file before the reply (shown for failing tests)
        sys.stdout.flush()
    except BaseException:  # noqa: BLE001 - a flood (EFBIG) is judged by the parent
        pass
    data = ((_encode(obj) if text is None else text) + "\n").encode()
    view = memoryview(data)
    while view:
        n = os.write(CTL_OUT, view)
        view = view[n:]


_reported = False


def _violation(message):
    global _reported
    if not _reported:
        _reported = True
        try:
            _send({"violation": message})
        except OSError:
            pass
    raise SandboxViolation(message)


def _matches(name, prefixes):
    return any(name == f or name.startswith(f + ".") for f in prefixes)


def _forbidden_module(name):
    return _matches(name, FORBIDDEN)


_G = globals()


def _frames():
    """Frames from the innermost outward, without this bootstrap's own."""
    f = sys._getframe(1)
    while f is not None:
        if f.f_globals is not _G:
            yield f
        f = f.f_back


def _is_machinery(f):
    name = f.f_globals.get("__name__", "")
    return f.f_code.co_filename.startswith("<frozen ") or name == "importlib" or name.startswith("importlib.")


def _is_library(f):
    path = f.f_code.co_filename
    return f.f_code.co_filename != SUBMISSION_FILE and path.startswith("/") and _under(path, READ_ROOTS) \
        and not _under(path, WRITE_ROOTS)


def _context():
    """Where the student's code did it: ' (at line N of your code: ...)', or ' (in LIBRARY,
    called from line N of your code: ...)' when a library acted on the student's behalf."""
    lib = None
    for f in _frames():
        if f.f_code.co_filename == SUBMISSION_FILE:
            src = _source_line(f.f_lineno)[:120]
            where = f"line {f.f_lineno} of your code: {src}"
            return f" (in {lib}, called from {where})" if lib else f" (at {where})"
        if lib is None and not _is_machinery(f):
            lib = str(f.f_globals.get("__name__", f.f_code.co_filename))
    return f" (in {lib})" if lib else ""


def _by_library():
    importer = next((f for f in _frames() if not _is_machinery(f)), None)
    return importer is not None and _is_library(importer)


def _engine_of(name):
    return next((ENGINES[m] for m in ENGINES if name == m or name.startswith(m + ".")), None)


def _check_import(name):
    """Violation for an engine module imported by the student's code (a library gets a stand-in,
    see :class:`_EngineStandIn`) or a forbidden module (unless it is one that allowed libraries
    import themselves, and a library imports it)."""
    engine = _engine_of(name)
    if engine is not None:
        if not _by_library():
            _violation(f"the {engine} library ('{name}') is forbidden in this problem{_context()}")
        return
    if _forbidden_module(name):
        if _matches(name, LIBRARY_IMPORTS) and _by_library():
            return
        _violation(f"import of forbidden module '{name}'{_context()}")


def _engine_file(path):
    """The engine a file is a copy of, by its name ('.../spatial/_qhull.cpython-311-...so'), or None."""
    path = os.fsdecode(path) if isinstance(path, bytes) else str(path)
    base = os.path.basename(path)
    parent, stem = os.path.basename(os.path.dirname(path)), base.split(".", 1)[0]
    for module, engine in ENGINES.items():
        parts = module.split(".")
        if stem == parts[-1] and (len(parts) < 2 or parent == parts[-2]) and "." in base:
            return engine
    if ENGINE_LIBS and base.startswith(ENGINE_LIBS):
        return "a forbidden"
    return None


def _guard_extension_loading():
    """Loading an engine's compiled file by path (``ExtensionFileLoader``, any copy, any name)
    goes through ``_imp.create_dynamic``: refuse it there."""
    import _imp
    real = _imp.create_dynamic

    def create_dynamic(spec, *rest):
        origin = getattr(spec, "origin", None) or ""
        engine = _engine_file(origin)
        if engine is not None:
            _violation(f"loading '{origin}' (the {engine} library) is forbidden in this problem{_context()}")
        return real(spec, *rest)

    _imp.create_dynamic = create_dynamic


class _EngineStandIn(types.ModuleType):
    """What a library gets for a forbidden engine (``from ._qhull import *`` in scipy.spatial):
    every name is a class whose use (call, instantiation) is a violation naming the student's line."""

    def __init__(self, name):
        super().__init__(name)
        self.__all__ = list(ENGINE_API.get(name, ()))
        for attr in self.__all__:
            setattr(self, attr, self._stub(attr))

    def _stub(self, attr):
        module, engine = self.__name__, _engine_of(self.__name__)

        def refuse(*args, **kwargs):
            _violation(f"the {engine} library ({module}.{attr}) is forbidden in this problem{_context()}")

        if attr.endswith("Error"):
            return type(attr, (RuntimeError,), {"__module__": module})
        return type(attr, (), {"__module__": module, "__new__": refuse})

    def __getattr__(self, attr):
        if attr.startswith("__pyx") or not attr.startswith("__"):  # Cython's C-level import too
            _violation(f"the {_engine_of(self.__name__)} library ({self.__name__}.{attr}) is forbidden in "
                       f"this problem{_context()}")
        raise AttributeError(attr)


class _StandInLoader:
    @staticmethod
    def create_module(spec):
        return _EngineStandIn(spec.name)

    @staticmethod
    def exec_module(module):
        pass


def _under(path, roots):
    return any(path == r or path.startswith(r.rstrip("/") + "/") for r in roots)


def _norm(path):
    if isinstance(path, bytes):
        path = os.fsdecode(path)
    if isinstance(path, int):
        return None
    return os.path.normpath(os.path.join(os.getcwd(), str(path)))


_PROCESS_EVENTS = {"os.system", "os.fork", "os.forkpty", "os.exec", "os.posix_spawn", "os.spawn",
                   "subprocess.Popen", "os.kill", "os.killpg", "signal.pthread_kill", "pty.spawn",
                   "os.setuid", "os.setgid", "os.chroot"}
_NET_EVENTS = {"socket.connect", "socket.bind", "socket.sendto", "socket.getaddrinfo", "socket.gethostbyname",
               "urllib.Request", "http.client.connect", "ftplib.connect", "smtplib.connect"}
_WRITE_FLAGS = os.O_WRONLY | os.O_RDWR | os.O_APPEND | os.O_CREAT | os.O_TRUNC


def _audit(event, args):
    if event == "import":
        if isinstance(args[0], str):
            _check_import(args[0])
    elif event == "open":
        path = _norm(args[0])
        if path is None:
            return
        mode, flags = args[1], args[2]
        writing = (isinstance(mode, str) and any(c in mode for c in "wax+")) or (flags & _WRITE_FLAGS)
        if writing:
            if not _under(path, WRITE_ROOTS) and path != "/dev/null":
                _violation(f"writing '{path}' (outside the working directory) is not allowed{_context()}")
        elif not _under(path, READ_ROOTS):
            _violation(f"reading '{path}' (outside the working directory) is not allowed{_context()}")
    elif event in ("os.listdir", "os.scandir"):
        path = _norm(args[0] if args and args[0] is not None else ".")
        if path is not None and not _under(path, READ_ROOTS):
            _violation(f"listing '{path}' (outside the working directory) is not allowed{_context()}")
    elif event == "ctypes.dlopen":
        engine = _engine_file(args[0]) if args and args[0] else None
        if engine is not None:
            _violation(f"loading '{args[0]}' (the {engine} library) is forbidden in this problem{_context()}")
    elif event in _PROCESS_EVENTS:
        _violation(f"operation '{event}' is not allowed (no processes, signals or environment changes){_context()}")
    elif event in _NET_EVENTS:
        _violation(f"network operation '{event}' is not allowed{_context()}")
    elif event in ("os.remove", "os.rename", "os.rmdir", "os.mkdir", "os.chmod", "os.chown", "os.symlink",
                   "os.link", "os.truncate", "shutil.rmtree", "os.utime"):
        path = _norm(args[0]) if args else None
        if path is not None and not _under(path, WRITE_ROOTS):
            _violation(f"operation '{event}' on '{path}' is not allowed{_context()}")


class _ImportGuard:
    """Meta-path finder: catches forbidden imports that bypass the ``import`` audit event
    (``importlib.import_module`` goes through pure-Python importlib)."""

    @staticmethod
    def find_spec(name, path=None, target=None):
        _check_import(name)
        if _engine_of(name) is not None:  # a library's import: the stand-in, never the engine
            import importlib.machinery
            return importlib.machinery.ModuleSpec(name, _StandInLoader)
        return None

    @staticmethod
    def invalidate_caches():
        pass


#: the submission's source lines (set when it is loaded)
_SOURCE_LINES = []


def _source_line(lineno):
    """Line ``lineno`` of the submission, stripped ('' when there is none)."""
    return _SOURCE_LINES[lineno - 1].strip() if lineno and 0 < lineno <= len(_SOURCE_LINES) else ""


def _line_of(filename, lineno):
    """A frame's source line: the submission's from its source, a library's through ``linecache``."""
    if filename == SUBMISSION_FILE:
        return _source_line(lineno)
    try:
        import linecache

        return linecache.getline(filename, lineno or 0).strip()
    except BaseException:  # noqa: BLE001 - the student may have broken imports: no line then
        return ""


def _error_info(exc):
    tb, frames = exc.__traceback__, []
    while tb is not None:  # what traceback.extract_tb lists: (file, line, function), outermost first
        frames.append((tb.tb_frame.f_code.co_filename, tb.tb_lineno, tb.tb_frame.f_code.co_name))
        tb = tb.tb_next
    frames = [f for f in frames if f[0] == SUBMISSION_FILE] or frames[-1:]
    lines = [f"line {n}, in {name}: {_line_of(file, n)}" for file, n, name in frames[-4:]]
    text = f"{type(exc).__name__}: {exc}"
    return {"type": type(exc).__name__, "message": text[:2000], "where": lines}


def _to_json(value, depth=0):
    """Exact-type conversion to JSON-native data; raises TypeError naming the first bad type."""
    t = type(value)
    if t is int and abs(value) >= 1 << 64:
        raise TypeError("int too large (over 64 bits)")
    if t in (int, float, str, bool) or value is None:
        return value
    if depth > 20:
        raise TypeError("nested too deeply")
    if t in (list, tuple):
        return [_to_json(v, depth + 1) for v in value]
    np = sys.modules.get("numpy")
    if np is not None:
        if t is np.ndarray:
            if value.dtype.kind not in "biuf":
                raise TypeError(f"numpy array of dtype {value.dtype}")
            return value.tolist()
        if isinstance(value, np.generic) and t.__module__ == "numpy" and value.dtype.kind in "biuf":
            return value.item()
        if t is np.ndarray and value.dtype.kind == "O":
            raise TypeError("numpy array of Python objects")
    raise TypeError(f"{t.__module__}.{t.__qualname__}".removeprefix("builtins."))


def _frame_of(value):
    """grader.judging.frames.frame_of's copy (this program imports nothing of the grader): a list
    of at least 256 floats in rows of one width (rows, or groups of rows) as base64 float64 and
    int64 counts, little-endian; None for anything else (it goes as JSON)."""
    if type(value) is not list or not value or not set(map(type, value)) <= {list}:
        return None
    inner = list(chain.from_iterable(value))
    kinds = set(map(type, inner))
    if inner and kinds <= {list}:
        rows, groups = inner, True
    elif inner and kinds <= {float}:
        rows, groups = value, False
    else:
        return None
    widths = set(map(len, rows))
    if len(widths) != 1 or not 1 <= min(widths) <= 16:
        return None
    flat = list(chain.from_iterable(rows)) if groups else inner
    if len(flat) < 256 or not set(map(type, flat)) <= {float}:
        return None
    data = array("d", flat)
    counts = array("q", map(len, value)) if groups else None
    if sys.byteorder == "big":
        data.byteswap()
        counts is not None and counts.byteswap()
    return {"w": min(widths), "rows": binascii.b2a_base64(data.tobytes(), newline=False).decode(),
            "counts": None if counts is None else binascii.b2a_base64(counts.tobytes(), newline=False).decode()}


class _SourceLoader:
    """The submission's ``__loader__``: ``linecache`` asks it for the source of the module's frames."""

    def __init__(self, source):
        self._source = source

    def get_source(self, name):
        return self._source


def _load(source, as_main):
    name = "__main__" if as_main else "submission"
    module = types.ModuleType(name)
    module.__file__ = SUBMISSION_FILE
    module.__builtins__ = __builtins__
    sys.modules[name] = module
    _SOURCE_LINES[:] = source.splitlines()
    module.__loader__ = _SourceLoader(source)  # tracebacks the student prints find its lines (linecache)
    code = compile(source, SUBMISSION_FILE, "exec")  # SyntaxError is reported by the caller
    exec(code, module.__dict__)
    return module


def _read_lines(fd):
    buf = b""
    while True:
        chunk = os.read(fd, 1 << 20)
        if not chunk:
            if buf:
                yield buf
            return
        buf += chunk
        while b"\n" in buf:
            line, buf = buf.split(b"\n", 1)
            yield line


def main():
    if CONFIG.get("nproc"):  # not root: set here, inside the sandbox's user namespace (see Sandbox.inner_nproc)
        import resource
        resource.setrlimit(resource.RLIMIT_NPROC, (CONFIG["nproc"], CONFIG["nproc"]))
    if CONFIG["mode"] == "exec":
        _exec_program()
    lines = _read_lines(CTL_IN)
    first = _loads(next(lines))
    sys.argv = [SUBMISSION_FILE]
    sys.path[:0] = [os.getcwd()]
    sys.meta_path.insert(0, _ImportGuard)
    _guard_extension_loading()
    sys.addaudithook(_audit)
    sys.setrecursionlimit(CONFIG.get("recursion_limit", 10000))
    mode = CONFIG["mode"]
    try:
        module = _load(first["source"], as_main=(mode == "stdio"))
    except SandboxViolation:
        os._exit(0)
    except SystemExit as exc:
        if mode == "stdio":
            code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
            _flush_and_exit(code)
        _send({"load_error": {"type": "SystemExit", "message": f"sys.exit({exc.code!r}) while loading"}})
        os._exit(0)
    except BaseException as exc:  # noqa: BLE001 - every student failure becomes a verdict
        _send({"load_error": _error_info(exc)})
        if mode == "stdio":
            _flush_and_exit(1)
        os._exit(0)
    if mode == "stdio":
        _flush_and_exit(0)
    entry = getattr(module, CONFIG["entry"], None)
    if not callable(entry):
        _send({"load_error": {"type": "MissingEntry", "message": f"no function '{CONFIG['entry']}' is defined"}})
        os._exit(0)
    _send({"loaded": True})
    for raw in lines:
        request = _loads(raw)
        rid = request["id"]
        try:
            result = entry(*request["args"])
        except SandboxViolation:
            os._exit(0)
        except SystemExit as exc:
            _send({"id": rid, "error": {"type": "SystemExit", "message": f"called sys.exit({exc.code!r})"}})
            continue
        except BaseException as exc:  # noqa: BLE001
            _send({"id": rid, "error": _error_info(exc)})
            continue
        try:  # converted and encoded once: what cannot be encoded is a wrong type
            value = _to_json(result)
            frame = _frame_of(value) if FRAMES else None
            text = _encode({"id": rid, "ok": value} if frame is None else {"id": rid, "frame": frame})
        except (TypeError, ValueError) as exc:
            _send({"id": rid, "bad_type": str(exc)})
            continue
        except RecursionError:
            _send({"id": rid, "bad_type": "nested too deeply"})
            continue
        _send(None, text)
    os._exit(0)


def _exec_program():
    """A compiled program (mode ``exec``): its stack may grow to ``stack_bytes`` (counted in memory
    like the rest), the control pipes are closed (the program cannot write on them), then the
    binary replaces this process (same pid, same limits, same seccomp filter)."""
    import resource
    stack = CONFIG.get("stack_bytes") or 0
    if stack:
        _, hard = resource.getrlimit(resource.RLIMIT_STACK)
        want = stack if hard == resource.RLIM_INFINITY else min(stack, hard)
        try:
            resource.setrlimit(resource.RLIMIT_STACK, (want, want))
        except (ValueError, OSError):
            pass
    os.close(CTL_IN)
    os.close(CTL_OUT)
    program = CONFIG["program"]
    try:
        os.execv(program, [program])
    except OSError as exc:
        os.write(2, f"the program could not be started: {exc.strerror}\n".encode())
        os._exit(127)


def _flush_and_exit(code):
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    except BaseException:  # noqa: BLE001 - EFBIG from a flood is judged by the parent
        pass
    try:
        _send({"exit": code})
        # the jail (its /tmp, /dev/shm) ends with this process: let the parent measure them first
        if select.select([CTL_IN], [], [], 2.0)[0]:
            os.read(CTL_IN, 1)
    except (OSError, ValueError):
        pass
    os._exit(code)


if __name__ == "__main__":
    main()
