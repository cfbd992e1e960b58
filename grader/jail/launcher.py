"""The C launcher of compiled submissions: built once per machine and account, kept in a trusted cache.

A compiled program's test used to start ``python -I`` with the jail's bootstrap, which set two
limits, closed the control pipes and ``execv``'d the binary: about 40 ms of interpreter start-up
charged to the student's CPU time on every test. ``launcher.c`` (next to this file) does the same
in a few dozen lines of C (see its header); its ``serve`` mode is pid 1 of one jail per compiled
submission and starts a fresh process per test (:mod:`grader.judging.program_server`). :func:`ensure` builds it with the system's C compiler
(``gcc -std=c99 -O2 -static -s``) into ``<cache>/launcher/`` (``<cache>``: ``$GRADER_CACHE``,
else ``<checkout>/.cache/grader``, as for the tests), named after a hash of its source and the
build command, with a manifest holding the binary's SHA-256. A launcher is used only when

* the cache folder, the ``launcher`` folder, the binary and its manifest belong to root, to the
  account running the grader or to the checkout's owner, are not symbolic links and are not
  writable by group or others (the rule of :mod:`grader.problems.cache`: whoever can replace the
  launcher runs code in every jail), and
* the manifest matches the source's hash and the binary's SHA-256.

Anything else is built again (in place when this account may, else in ``~/.cache/grader/launcher``),
never trusted. Without a C compiler (or a static C library) the Python bootstrap starts compiled
programs, as before; ``python -m grader.jail`` says which one this machine uses.

Run: ``python -m grader warm`` builds it (``make warm``); ``python -m grader.jail`` says which starter is used.

Example:
    >>> path = ensure()                     # doctest: +SKIP
    >>> path is None or path.name.startswith("grader-launcher-")   # doctest: +SKIP
    True
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import stat
import subprocess
import sys
import tempfile
from pathlib import Path

from .trust import unsafe_reason as trust_reason

SOURCE = Path(__file__).with_name("launcher.c")
REPO = Path(__file__).resolve().parent.parent.parent
#: The C compilers tried, in this order (found in the system's directories only).
COMPILERS = ("gcc", "cc")
#: The build flags: a static binary (the jail shows /usr, but nothing must depend on it).
CFLAGS = ("-std=c99", "-D_POSIX_C_SOURCE=200809L", "-O2", "-static", "-s")
#: ``GRADER_LAUNCHER=python`` forces the Python bootstrap, one jail per test (tests of both paths; a
#: broken compiler); ``per-test``: the C launcher, one jail per test (the A/B of :func:`serves`).
LAUNCHER_ENV = "GRADER_LAUNCHER"
_warned: set[str] = set()


def compiler() -> str | None:
    """The system's C compiler (``gcc``, else ``cc``), or None."""
    for name in COMPILERS:
        found = shutil.which(name, path="/usr/bin:/bin:/usr/local/bin")
        if found:
            return found
    return None


def source_digest() -> str:
    """A hash of the launcher's source and build flags: a launcher built from anything else is stale."""
    h = hashlib.sha256(SOURCE.read_bytes())
    h.update("\0".join(CFLAGS).encode())
    return h.hexdigest()[:16]


def roots() -> list[Path]:
    """Where launchers are kept, in order: the shared cache's ``launcher`` folder, then the account's own."""
    cache = Path(os.environ.get("GRADER_CACHE", REPO / ".cache" / "grader"))
    return [cache / "launcher", Path.home() / ".cache" / "grader" / "launcher"]


def unsafe_reason(path: Path) -> str | None:
    """Why ``path`` (itself) cannot be trusted (:func:`grader.jail.trust.unsafe_reason`), or None;
    a path that cannot be read is not trusted."""
    try:
        return trust_reason(path)
    except OSError as exc:
        return f"{path}: {exc.strerror}"


def _names(folder: Path) -> tuple[Path, Path]:
    base = folder / f"grader-launcher-{source_digest()}"
    return base, base.with_suffix(".json")


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def check(folder: Path) -> tuple[Path | None, str]:
    """(the launcher in ``folder``, "") when it exists, is trusted and matches its manifest; else
    (None, why not)."""
    binary, manifest = _names(folder)
    for p in (folder.parent, folder, binary, manifest):
        reason = unsafe_reason(p)
        if reason:
            return None, reason
    st = os.lstat(binary)
    if not stat.S_ISREG(st.st_mode) or not st.st_mode & 0o001:
        return None, f"{binary} is not an executable regular file"
    try:  # hashed on every check (once per sandbox: about a millisecond), never remembered
        meta = json.loads(manifest.read_text())
    except (OSError, ValueError):
        return None, f"{manifest} is unreadable"
    if not isinstance(meta, dict) or meta.get("source") != source_digest() or meta.get("sha256") != _sha256(binary):
        return None, f"{binary} does not match its manifest (stale or altered)"
    return binary, ""


def build(folder: Path, cc: str) -> Path:
    """Build the launcher into ``folder`` (made 0755 if missing): compiled in a private temporary
    folder, then moved in under its final name (readers never see half a file). Raises OSError or
    subprocess.CalledProcessError."""
    missing = [d for d in (folder, *folder.parents) if not d.exists()]
    for d in reversed(missing):  # made here: 0755 whatever the umask (a group-writable one is refused)
        d.mkdir(exist_ok=True)
        os.chmod(d, 0o755)
    binary, manifest = _names(folder)
    with tempfile.TemporaryDirectory(prefix="grader-launcher-") as tmp:
        out = Path(tmp) / "launcher"
        subprocess.run([cc, *CFLAGS, "-o", str(out), str(SOURCE)], check=True, timeout=120,
                       stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                       env={"PATH": "/usr/bin:/bin", "LANG": "C"})
        os.chmod(out, 0o755)
        meta = Path(tmp) / "manifest.json"
        meta.write_text(json.dumps({"source": source_digest(), "sha256": _sha256(out), "compiler": cc,
                                    "flags": list(CFLAGS)}) + "\n")
        os.chmod(meta, 0o644)
        part = folder / f".{binary.name}.{os.getpid()}"
        shutil.copyfile(out, part)
        os.chmod(part, 0o755)
        os.replace(part, binary)
        part = folder / f".{manifest.name}.{os.getpid()}"
        shutil.copyfile(meta, part)
        os.chmod(part, 0o644)
        os.replace(part, manifest)
    return binary


def _warn(message: str) -> None:
    if message not in _warned:
        _warned.add(message)
        print(f"warning: {message}", file=sys.stderr)


def ensure(build_missing: bool = True) -> Path | None:
    """The trusted launcher's host path, built first when there is none (``build_missing``), or
    None: the Python bootstrap starts compiled programs (no C compiler, the build failed, or
    ``GRADER_LAUNCHER=python``)."""
    if os.environ.get(LAUNCHER_ENV) == "python":
        return None
    if not SOURCE.is_file():  # an install without the package data: the bootstrap, said once
        _warn(f"the C launcher's source {SOURCE} is missing (an install without the package's data files): "
              "the Python bootstrap starts compiled programs (about 40 ms of CPU more per test)")
        return None
    reasons = []
    for folder in roots():
        found, why = check(folder)
        if found is not None:
            return found
        reasons.append(why)
    cc = compiler()
    if not build_missing or cc is None:
        return None
    for folder in roots():
        try:
            if folder.parent.exists() and unsafe_reason(folder.parent):
                continue  # an untrusted cache is never written to
            build(folder, cc)
        except (OSError, subprocess.SubprocessError) as exc:
            err = getattr(exc, "stderr", b"") or b""
            reasons.append(f"{folder}: {exc} {err.decode(errors='replace').strip()[-300:]}".strip())
            continue
        found, why = check(folder)
        if found is not None:
            return found
        reasons.append(why)
    _warn("the C launcher of compiled programs could not be built or trusted (" + "; ".join(reasons)
          + "): the Python bootstrap starts them (about 40 ms of CPU more per test)")
    return None


def serves() -> bool:
    """True (the default) when a compiled submission gets one jail whose launcher, in its server
    mode, starts a fresh process per test (:mod:`grader.judging.program_server`); False with
    ``GRADER_LAUNCHER=per-test`` or ``python``: one jail per test."""
    return os.environ.get(LAUNCHER_ENV) not in ("python", "per-test")


def host_path() -> str | None:
    """:func:`ensure` as a string (what a sandbox binds), or None."""
    found = ensure()
    return str(found) if found is not None else None


def status() -> str:
    """One line for the doctor: what starts compiled programs in the run jail (nothing is built)."""
    if os.environ.get(LAUNCHER_ENV) == "python":
        return f"compiled programs: started by the Python bootstrap ({LAUNCHER_ENV}=python)"
    if not SOURCE.is_file():
        return f"compiled programs: started by the Python bootstrap (the launcher's source {SOURCE} is missing)"
    found = ensure(build_missing=False)
    if found is not None:
        how = "one jail per submission, a fresh process per test" if serves() else \
            f"one jail per test, {LAUNCHER_ENV}=per-test"
        return f"compiled programs: started by the C launcher {found} ({how})"
    cc = compiler()
    if cc is None:
        return ("compiled programs: started by the Python bootstrap (no C compiler: about 40 ms of CPU more per "
                "test; apt-get install gcc)")
    return (f"compiled programs: the C launcher is not built yet ({cc}; `python -m grader warm` builds it, "
            "else the first compiled submission does)")
