"""Compiling a submission of a compiled language (C++) in the compile jail, once per judging.

The compiler is as untrusted as the program it builds: it runs in the sandbox's compile profile
(:mod:`grader.jail.profiles`: only the system trees, the source and a writable folder; no network;
new processes allowed for ``g++ -> cc1plus, as, collect2, ld``) under :data:`COMPILE_LIMITS` and a
wall-clock cap. Its messages are read from a pipe: the first :data:`SHOWN_BYTES` are kept (made
safe with :func:`grader.judging.text.clean`), the rest is read and dropped, and more than
:data:`MESSAGE_LIMIT_BYTES` in all stops the compiler. The binary is taken out of the jail's folder
without following links (it must be a regular file within the size limit) and copied to a file
of the grader's own, which the run jail then shows read-only.

Every way a compile can fail (errors, a file it may not include, too long, too much memory, too
many messages, no binary) is a :class:`CompileResult` with ``ok=False`` and a message for the
student: the judge gives ``CE``.

Example:
    >>> from grader.judging.languages import CPP
    >>> r = compile_source("int main() { return 0; }", CPP, "/tmp/x")   # doctest: +SKIP
    >>> r.ok, os.path.basename(r.binary)                                  # doctest: +SKIP
    (True, 'program')
"""

from __future__ import annotations

import os
import select
import shutil
import stat
import tempfile
import time
from dataclasses import dataclass
from typing import Sequence

from ..jail import Limits, Sandbox
from ..jail.cgroups import ProcTree
from .languages import Language
from .text import clean

#: The compile step's limits: 30 s of CPU, 1 GiB of memory, processes for the compiler's chain,
#: a binary of at most 64 MiB (RLIMIT_FSIZE: also each temporary file), a 128 MiB /tmp.
COMPILE_LIMITS = Limits(cpu_s=30.0, memory_mb=1024, output_mb=64, open_files=128, processes=16, disk_mb=128, shm_mb=1)
#: Wall-clock cap of one compile (seconds).
COMPILE_WALL_S = 60.0
#: Bytes of the compiler's messages shown to the student.
SHOWN_BYTES = 3000
#: More messages than this stops the compiler (a flood of errors).
MESSAGE_LIMIT_BYTES = 4 << 20
SOURCE_NAME, BINARY_NAME = "submission", "program"


@dataclass
class CompileResult:
    """How a compile ended: ``ok`` with ``binary`` (a host path, in the caller's folder) or a
    message for the student; ``time_s`` the wall time it took."""

    ok: bool
    binary: str = ""
    message: str = ""
    time_s: float = 0.0


def _sandbox_cpu(box: Sandbox) -> float:
    try:
        return box.group.cpu_seconds() if box.group is not None else 0.0
    except (OSError, ValueError):
        return 0.0


def compile_source(source: str, language: Language, dest_dir: str, hide: Sequence[str | os.PathLike] = (),
                   trusted: bool | None = None, limits: Limits = COMPILE_LIMITS,
                   wall_s: float = COMPILE_WALL_S) -> CompileResult:
    """Compile ``source`` with ``language``'s command in the compile jail; on success the binary is
    ``dest_dir/program`` (mode 0755). ``hide``: more host paths the compiler must not see (they are
    not in its view anyway unless they lie under ``/usr``). Raises
    :class:`grader.jail.JailUnavailable` where no compile jail can be built."""
    if not language.compile:
        raise ValueError(f"the language {language.name!r} has no compile step")
    t0 = time.monotonic()
    src_name = SOURCE_NAME + language.suffixes[0]
    with Sandbox(limits, hide=hide, trusted=trusted, profile="compile") as box:
        src_path = os.path.join(box.scratch, src_name)
        with open(src_path, "w", encoding="utf-8", errors="surrogateescape") as f:
            f.write(source)
        os.chmod(src_path, 0o644)
        argv = list(language.compile_command(src_name, BINARY_NAME))
        nproc = box.inner_nproc()
        if nproc is not None:  # an ordinary account: the limit is set inside the jail's user namespace
            argv = ["/usr/bin/prlimit", f"--nproc={nproc}", "--", *argv]
        code, shown, why = _run(box, argv, limits, wall_s)
        text = clean(shown[:SHOWN_BYTES].decode("utf-8", "replace"), SHOWN_BYTES + 200, newlines=True)
        if len(shown) > SHOWN_BYTES:
            text += "\n... (more compiler messages not shown)"
        if why:
            return CompileResult(False, message=f"{why}\n{text}".rstrip(), time_s=time.monotonic() - t0)
        if code != 0:
            head = f"compilation failed (exit code {code})" if code > 0 else f"the compiler was killed (signal {-code})"
            return CompileResult(False, message=f"{head}:\n{text}".rstrip(), time_s=time.monotonic() - t0)
        try:
            binary = _take_binary(box.scratch, dest_dir, limits.output_mb << 20)
        except OSError as exc:
            return CompileResult(False, message=f"the compiler made no usable program: {exc.strerror or exc}",
                                 time_s=time.monotonic() - t0)
        return CompileResult(True, binary=binary, message=text, time_s=time.monotonic() - t0)


def _run(box: Sandbox, argv: list[str], limits: Limits, wall_s: float) -> tuple[int, bytes, str]:
    """Run the compiler; (exit code, first messages, why it was stopped or '')."""
    r, w = os.pipe()
    null = os.open(os.devnull, os.O_RDONLY)
    try:
        proc = box.spawn(argv, null, w, w, cpu_s=limits.cpu_s)
    finally:
        os.close(w)
        os.close(null)
    pidfd = os.pidfd_open(proc.pid)
    os.set_blocking(r, False)
    shown, total, why = bytearray(), 0, ""
    cpu0 = _sandbox_cpu(box)
    deadline = time.monotonic() + wall_s
    status = None
    try:
        while True:
            ready = select.select([r, pidfd] if r >= 0 else [pidfd], [], [], 0.2)[0]
            if r in ready:
                try:
                    chunk = os.read(r, 1 << 16)
                except BlockingIOError:
                    chunk = None
                if chunk == b"":
                    os.close(r)
                    r = -1
                elif chunk:
                    total += len(chunk)
                    if len(shown) < SHOWN_BYTES + 1:
                        shown += chunk[:SHOWN_BYTES + 1 - len(shown)]
                    if total > MESSAGE_LIMIT_BYTES:
                        why = f"compilation stopped: more than {MESSAGE_LIMIT_BYTES >> 20} MiB of compiler messages"
            if status is None and pidfd in ready:
                status = os.waitpid(proc.pid, 0)[1]
            if status is not None and r < 0:
                break
            if status is not None:  # the compiler ended; its helpers may hold the pipe a moment
                deadline = min(deadline, time.monotonic() + 1.0)
            if not why and time.monotonic() > deadline and status is None:
                why = f"compilation took more than {wall_s:g} s of wall time (stopped)"
            if not why and not isinstance(box.group, ProcTree) and _sandbox_cpu(box) - cpu0 > limits.cpu_s:
                why = f"compilation used more than {limits.cpu_s:g} s of CPU time (stopped)"
            if why or (status is not None and time.monotonic() > deadline):
                if status is None:
                    box.terminate(proc.pid)
                    status = os.waitpid(proc.pid, 0)[1]
                break
    finally:
        os.close(pidfd)
        if r >= 0:
            os.close(r)
        box.kill_all()
    code = box.decode_exit(os.waitstatus_to_exitcode(status))
    if not why and code < 0:
        sig = -code
        why = {24: f"compilation used more than {limits.cpu_s:g} s of CPU time (stopped)",
               25: f"the compiler wrote a file larger than {limits.output_mb} MiB (the program or a temporary file)",
               9: "the compiler was killed (memory limit of the compile step?)"}.get(sig, "")
    if not why and box.group is not None and not isinstance(box.group, ProcTree):
        try:
            if box.group.memory_limit_hit():
                why = f"compilation used more than {limits.memory_mb} MiB of memory (stopped)"
        except (OSError, ValueError):
            pass
    return code, bytes(shown), why


def _take_binary(scratch: str, dest_dir: str, limit: int) -> str:
    """Copy ``scratch/program`` to ``dest_dir/program`` without following a link: it must be a
    regular file of at most ``limit`` bytes (raises OSError otherwise)."""
    dir_fd = os.open(scratch, os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW | os.O_CLOEXEC)
    try:
        fd = os.open(BINARY_NAME, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC, dir_fd=dir_fd)
    except OSError as exc:
        raise OSError(exc.errno, "no program was written" if exc.errno == 2 else exc.strerror) from None
    finally:
        os.close(dir_fd)
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise OSError(0, "the program is not a regular file")
        if st.st_size > limit:
            raise OSError(0, f"the program is larger than {limit >> 20} MiB")
        dest = os.path.join(dest_dir, BINARY_NAME)
        with os.fdopen(os.open(dest, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o755), "wb") as out:
            with os.fdopen(os.dup(fd), "rb") as src:
                shutil.copyfileobj(src, out, 1 << 20)
        os.chmod(dest, 0o755)
        return dest
    finally:
        os.close(fd)


def build_dir() -> str:
    """A fresh folder of the grader's own for one submission's binary (the caller removes it)."""
    return tempfile.mkdtemp(prefix="grader-prog-")
