"""The C launcher of compiled programs (grader/jail/launcher.c, grader/jail/launcher.py).

* a compiled program started by the launcher sees exactly what the Python bootstrap gave it
  (limits, ignored signals, open descriptors, pid, environment, seccomp, capabilities, working
  directory): one probe program, run by both, prints all of it;
* a launcher that is stale, altered, group-writable or a symbolic link is built again, never used;
  an untrusted cache folder is never written to (the account's own is used);
* without a launcher (``GRADER_LAUNCHER=python``, no C compiler) the Python bootstrap starts the
  program; the doctor says which one is used.

As root, :func:`test_as_an_ordinary_account` runs this file again as an ordinary account.

Run: .venv/bin/python -m pytest tests/grader/test_launcher.py -q -p no:cacheprovider
"""
from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path

import pytest

from grader.jail import Limits, Sandbox, doctor, launcher
from grader.jail.sandbox import jail_kind
from grader.judging.program_server import run_compiled

from . import ordinary_user
from .cpp_probe import compiled_probe

needs_gcc = pytest.mark.skipif(launcher.compiler() is None or shutil.which("g++") is None,
                               reason="needs gcc and g++")
needs_jail = pytest.mark.skipif(jail_kind() != "bwrap", reason="compiled programs run in the bubblewrap jail")

#: Prints what the program was started with; the lines that legitimately differ between two runs
#: (none expected) would show in the comparison.
PROBE = r"""
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>
#include <sys/resource.h>
#include <sys/stat.h>
extern char** environ;
int main(int argc, char** argv) {
    int which[] = {RLIMIT_STACK, RLIMIT_NPROC, RLIMIT_AS, RLIMIT_CPU, RLIMIT_FSIZE, RLIMIT_NOFILE, RLIMIT_CORE};
    for (int r : which) {
        struct rlimit l; getrlimit(r, &l);
        std::printf("rlimit %d %llu %llu\n", r, (unsigned long long)l.rlim_cur, (unsigned long long)l.rlim_max);
    }
    FILE* f = std::fopen("/proc/self/status", "r");
    char line[512];
    while (f && std::fgets(line, sizeof line, f))
        if (!std::strncmp(line, "Sig", 3) || !std::strncmp(line, "Cap", 3) || !std::strncmp(line, "NoNewPrivs", 10)
            || !std::strncmp(line, "Seccomp", 7) || !std::strncmp(line, "Uid", 3) || !std::strncmp(line, "Gid", 3))
            if (std::strncmp(line, "SigQ", 4)) std::fputs(line, stdout);
    if (f) std::fclose(f);
    for (int fd = 0; fd < 256; ++fd)
        if (fcntl(fd, F_GETFD) != -1) std::printf("fd %d open\n", fd);
    std::printf("pid %d argc %d argv0 %s\n", (int)getpid(), argc, argv[0]);
    for (char** e = environ; *e; ++e) std::printf("env %s\n", *e);
    char cwd[256]; std::printf("cwd %s umask %o\n", getcwd(cwd, sizeof cwd), umask(0));
    return 0;
}
"""


@pytest.fixture(scope="module")
def probe(tmp_path_factory) -> str:
    return compiled_probe(PROBE, tmp_path_factory)


def _started(binary: str, monkeypatch, starter: str) -> tuple[str, str | None]:
    monkeypatch.setenv(launcher.LAUNCHER_ENV, starter)
    with Sandbox(Limits(cpu_s=2, memory_mb=256), program=binary) as box:
        out = run_compiled(box, "", 2.0)
        assert out.status == "ok", (out.status, out.message)
        return out.value, box.launcher


@needs_gcc
@needs_jail
def test_the_launcher_starts_a_program_exactly_as_the_bootstrap_did(probe, monkeypatch):
    by_launcher, used = _started(probe, monkeypatch, "per-test")
    by_python, none = _started(probe, monkeypatch, "python")
    assert used and none is None, (used, none)
    assert "fd 3 open" not in by_launcher and "SigIgn:\t0000000000000000" not in by_launcher, by_launcher
    assert "pid 1 " in by_launcher and "argv0 /submission/program" in by_launcher, by_launcher
    assert by_launcher.splitlines() == by_python.splitlines()


@needs_gcc
@needs_jail
def test_the_launchers_server_starts_each_test_as_the_per_test_jail_did(probe, monkeypatch):
    """One jail per submission: the same limits, signals, descriptors, environment, directory and
    filter; only the pid differs (the server is pid 1) and the filter is stacked on the jail's own."""
    served, _ = _started(probe, monkeypatch, "serve")
    per_test, _ = _started(probe, monkeypatch, "per-test")
    differ = {"Seccomp_filters:\t1": "Seccomp_filters:\t2", "pid 1 argc": "pid 2 argc"}
    expected = []
    for line in per_test.splitlines():
        expected.append(next((line.replace(a, b) for a, b in differ.items() if line.startswith(a)), line))
    assert served.splitlines() == expected


def _fresh(tmp_path: Path, monkeypatch) -> Path:
    """An empty shared cache of our own and an empty home: the launcher is built there."""
    monkeypatch.setenv("GRADER_CACHE", str(tmp_path / "cache"))
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    monkeypatch.delenv(launcher.LAUNCHER_ENV, raising=False)
    return tmp_path / "cache" / "launcher"


@needs_gcc
def test_a_stale_altered_or_writable_launcher_is_built_again(tmp_path, monkeypatch):
    folder = _fresh(tmp_path, monkeypatch)
    first = launcher.ensure()
    assert first is not None and first.parent == folder and os.stat(first).st_mode & 0o777 == 0o755
    assert launcher.ensure() == first  # found, not built again
    good = first.read_bytes()
    first.write_bytes(good[:-1] + bytes([good[-1] ^ 1]))  # altered by someone who could write it: refused, rebuilt
    assert launcher.check(folder)[0] is None
    assert launcher.ensure() == first and first.read_bytes() == good
    os.chmod(first, 0o775)  # group-writable: refused
    assert "writable by group" in launcher.check(folder)[1]
    assert launcher.ensure() == first and os.stat(first).st_mode & 0o777 == 0o755
    target = tmp_path / "elsewhere"
    shutil.copy(first, target)
    first.unlink()
    first.symlink_to(target)  # a symbolic link: refused, replaced by a file
    assert "symbolic link" in launcher.check(folder)[1]
    assert launcher.ensure() == first and not first.is_symlink()
    for stale in folder.glob("grader-launcher-*"):  # built from another source: another name
        stale.rename(stale.with_name(stale.name.replace("grader-launcher-", "grader-launcher-0")))
    assert launcher.check(folder)[0] is None and launcher.ensure() == first


@needs_gcc
def test_an_untrusted_cache_folder_is_not_written_to(tmp_path, monkeypatch):
    folder = _fresh(tmp_path, monkeypatch)
    folder.parent.mkdir()
    os.chmod(folder.parent, 0o777)  # anyone could swap what is built there
    found = launcher.ensure()
    assert found is not None and found.parent == tmp_path / "home" / ".cache" / "grader" / "launcher"
    assert not folder.exists()


def test_without_a_compiler_the_bootstrap_starts_programs(tmp_path, monkeypatch):
    _fresh(tmp_path, monkeypatch)
    monkeypatch.setattr(launcher, "compiler", lambda: None)
    assert launcher.ensure() is None
    assert "Python bootstrap (no C compiler" in doctor.report().splitlines()[-1]
    monkeypatch.setenv(launcher.LAUNCHER_ENV, "python")
    assert "GRADER_LAUNCHER=python" in launcher.status()


def test_an_install_without_the_source_falls_back_to_the_bootstrap(tmp_path, monkeypatch, capsys):
    """A venv installed without the package's data files (no launcher.c): ``grader warm`` and every
    sandbox go on with the Python bootstrap and say why, instead of failing (the hub's install did)."""
    _fresh(tmp_path, monkeypatch)
    monkeypatch.setattr(launcher, "SOURCE", tmp_path / "missing" / "launcher.c")
    assert launcher.ensure() is None and launcher.host_path() is None
    assert "launcher.c is missing" in capsys.readouterr().err
    assert "source" in launcher.status() and "Python bootstrap" in launcher.status()


def test_the_source_is_package_data():
    """The launcher's source ships with the package (a non-editable install, as the hub makes)."""
    import tomllib
    data = tomllib.loads((Path(launcher.__file__).parents[2] / "pyproject.toml").read_text())
    assert "*.c" in data["tool"]["setuptools"]["package-data"]["grader.jail"]


@needs_gcc
@needs_jail
def test_a_program_that_cannot_start_is_exit_127_with_both_starters(tmp_path, monkeypatch):
    bad = tmp_path / "program"
    bad.write_bytes(b"\x7fELF not really")
    bad.chmod(0o755)
    for starter in ("c", "python"):
        monkeypatch.setenv(launcher.LAUNCHER_ENV, starter)
        with Sandbox(Limits(cpu_s=2, memory_mb=256), program=str(bad)) as box:
            out = run_compiled(box, "", 2.0)
        assert "exited with code 127" in out.message, (starter, out.status, out.message)


@pytest.mark.slow
def test_as_an_ordinary_account():
    """This file again as an ordinary account (bubblewrap without root: RLIMIT_NPROC set by the starter)."""
    why = ordinary_user.can_run()
    if why:
        pytest.skip(why)
    r = ordinary_user.run_as_user([sys.executable, "-m", "pytest", "tests/grader/test_launcher.py", "-q", "-n", "0",
                                   "-p", "no:cacheprovider", "-k", "not ordinary_account"], timeout=600)
    tail = (r.stdout + r.stderr)[-6000:]
    assert r.returncode == 0, tail
    last = r.stdout.splitlines()[-1]
    assert "passed" in last and "failed" not in last and "skipped" not in last, tail  # the account ran every test
