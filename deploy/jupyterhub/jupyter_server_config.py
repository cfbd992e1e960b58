"""The course's Jupyter server configuration: saves that replace a file whole (SPEC §2, §7).

Every single-user server on the hub reads this file: ``deploy.sh install`` copies it to
``$HUB_VENV/etc/jupyter/jupyter_server_config.py`` (the shared venv's own config folder, which
every account's server reads and no student can write). ``make lab`` and ``make instructor`` pass
it with ``--config``, and so can any server: ``jupyter server --config <this file>``.

Why. jupyter_server 2.21's "atomic" save copies the notebook to ``.~<name>``, writes the new
version *in place*, then removes the copy. A contents read that meets the half-written file while
the copy exists takes the save for failed, renames the notebook to ``<name>.invalid`` and moves
the copy back: the save in flight answers 404, or 200 while the disk holds an older save. Readers
outside the server (the kernel's ``%check_samples``, nbgrader's Submit) read half-written files.

What this file changes (``CourseContentsManager``, a subclass of the default
``AsyncLargeFileManager``; nothing else of the server is touched):

* A save writes the new version to a temporary file on the notebook's file system (in the
  server root's hidden ``.ipynb_checkpoints/``, outside every assignment folder: nbgrader's
  Submit lists an assignment's files, then copies them, and fails on one that vanished in
  between, as jupyter_server's ``.~<name>`` backups do), flushes and fsyncs it, gives it the old
  file's permission bits (and owner, when the server may), and ``os.replace``-s it over the
  notebook. Any reader, in the server or outside it, opens either
  the previous version or the new one, always whole. A save that fails or dies midway leaves the
  previous version untouched (a failed save removes its temporary file; a killed server leaves it
  aside, hidden: ``<root>/.ipynb_checkpoints/.~<name>.<random>.tmp``).
* A read never "recovers" a notebook it cannot parse (no rename to ``.invalid``, no backup moved
  back): with saves that replace, a half-written notebook is never on the disk, so an unreadable
  one is reported as such (400) and left alone.
* Saves of one path run one after the other, in the order they arrived (an asyncio lock per path,
  held through the save's answer), so two tabs' saves never interleave.
* Checkpoints are written and restored the same way (``CourseFileCheckpoints``).

In a folder the server may not write (but the file is writable), a save writes in place, as
jupyter_server does: there is no room for a temporary file.

The file defines its classes itself and imports nothing of the course: the same file works in the
hub's venv, in the checkout's and with any jupyter_server 2.x, and no move of the course's
modules can break a deployed configuration.
"""
from __future__ import annotations

import asyncio
import contextlib
import os
import secrets
import shutil
from collections.abc import Iterator
from functools import partial
from typing import IO, Any

import nbformat
from anyio.to_thread import run_sync
from jupyter_server.services.contents.filecheckpoints import AsyncFileCheckpoints
from jupyter_server.services.contents.largefilemanager import AsyncLargeFileManager
from tornado.web import HTTPError
from traitlets import default

TEMP_DIR = ".ipynb_checkpoints"   # beside the file: same file system; hidden; nbgrader ignores it


@contextlib.contextmanager
def replacing(path: str, text: bool = True, encoding: str = "utf-8", root: str | None = None,
              **kwargs: Any) -> Iterator[IO]:
    """Open a temporary file for the new contents of ``path``; on a clean exit, fsync it and
    ``os.replace`` it over ``path`` (a symlink's target is replaced, the link kept).

    The temporary file is written in ``root``'s ``.ipynb_checkpoints/`` (the server's root: outside
    every assignment folder, whose files nbgrader's Submit lists and copies one by one) when ``root``
    is on the same file system as ``path`` and writable, else in ``path``'s folder's one.

    The new file keeps the old one's permission bits (a new file gets ``0o666`` less the umask)
    and, when the process may, its owner and group. On any exception the temporary file is
    removed and ``path`` is left as it was. A folder that cannot hold the temporary file but whose
    ``path`` is writable gets an in-place write (what jupyter_server's ``atomic_writing`` does).
    """
    path = os.path.realpath(path) if os.path.islink(path) else path
    folder = os.path.dirname(path) or os.getcwd()
    try:
        old = os.stat(path)
    except FileNotFoundError:
        old = None
    if old is not None and not os.access(folder, os.W_OK) and os.access(path, os.W_OK):
        mode = "w" if text else "wb"
        opts = dict(kwargs, encoding=encoding, newline=kwargs.get("newline", "\n")) if text else kwargs
        with open(path, mode, **opts) as f:
            yield f
        return
    temp_dir = os.path.join(folder, TEMP_DIR)
    if root and os.stat(root).st_dev == os.stat(folder).st_dev:
        with contextlib.suppress(OSError):
            os.makedirs(os.path.join(root, TEMP_DIR), exist_ok=True)
            temp_dir = os.path.join(root, TEMP_DIR)
    os.makedirs(temp_dir, exist_ok=True)
    tmp = os.path.join(temp_dir, f".~{os.path.basename(path)}.{secrets.token_hex(6)}.tmp")
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666 if old is None else old.st_mode & 0o777)
    try:
        if old is not None:
            os.fchmod(fd, old.st_mode & 0o7777)        # the umask does not cut the old bits
            if (old.st_uid, old.st_gid) != (os.geteuid(), os.getegid()):
                with contextlib.suppress(OSError):
                    os.fchown(fd, old.st_uid, old.st_gid)
        if text:
            f = open(fd, "w", encoding=encoding, newline=kwargs.pop("newline", "\n"), **kwargs)  # noqa: SIM115
        else:
            f = open(fd, "wb", **kwargs)  # noqa: SIM115
        fd = -1                                        # the file object owns it now
        with f:
            yield f
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        if fd >= 0:
            os.close(fd)
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise
    with contextlib.suppress(OSError):                 # the rename itself survives a power cut
        dfd = os.open(folder, os.O_RDONLY)
        try:
            os.fsync(dfd)
        finally:
            os.close(dfd)


def copy_replacing(src: str, dest: str, root: str | None = None) -> None:
    """Copy ``src`` over ``dest`` through :func:`replacing`, then its times (as ``shutil.copy2``)."""
    with open(src, "rb") as s, replacing(dest, text=False, root=root) as d:
        shutil.copyfileobj(s, d)
    with contextlib.suppress(OSError):
        shutil.copystat(src, dest)


class CourseFileCheckpoints(AsyncFileCheckpoints):
    """Checkpoints created and restored by replacing files whole (never written in place)."""

    async def _copy(self, src: str, dest: str) -> None:
        """Copy ``src`` to ``dest``; a reader of ``dest`` sees the old file or the new one."""
        with self.perm_to_403(dest):
            await run_sync(copy_replacing, src, dest, self.root_dir)


class CourseContentsManager(AsyncLargeFileManager):
    """jupyter_server's default contents manager with saves that replace files whole, reads that
    never move files, and the saves of one path in arrival order (see the module's docstring)."""

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._save_locks: dict[str, tuple[asyncio.Lock, int]] = {}

    @default("checkpoints_class")
    def _checkpoints_class_default(self) -> type:
        return CourseFileCheckpoints

    @contextlib.contextmanager
    def atomic_writing(self, os_path: str, *args: Any, **kwargs: Any) -> Iterator[IO]:
        """The file to write ``os_path``'s new contents to (permission errors become 403)."""
        kwargs.pop("log", None)
        with self.perm_to_403(os_path), replacing(os_path, *args, root=self.root_dir, **kwargs) as f:
            yield f

    async def _read_notebook(self, os_path: str, as_version: int = 4,
                             capture_validation_error: dict | None = None, raw: bool = False) -> Any:
        """Read and parse a notebook; an unreadable one is a 400, and no file is moved."""
        answer = await self._read_file(os_path, "text", raw)
        try:
            nb = await run_sync(partial(nbformat.reads, as_version=as_version,
                                        capture_validation_error=capture_validation_error), answer[0])
        except Exception as e:
            raise HTTPError(400, f"Unreadable Notebook: {os_path} {e!r}") from e
        return (nb, answer[2]) if raw else nb

    @contextlib.asynccontextmanager
    async def _path_lock(self, path: str):
        """Hold the lock of ``path`` (one per path while anyone waits for it; FIFO)."""
        key = self._get_os_path(path.strip("/"))
        lock, users = self._save_locks.get(key, (asyncio.Lock(), 0))
        self._save_locks[key] = (lock, users + 1)
        try:
            async with lock:
                yield
        finally:
            lock, users = self._save_locks[key]
            if users == 1:
                del self._save_locks[key]
            else:
                self._save_locks[key] = (lock, users - 1)

    async def save(self, model: dict, path: str = "") -> dict:
        """Save ``model`` at ``path`` after every earlier save of that path has answered."""
        async with self._path_lock(path):
            return await super().save(model, path)


if "get_config" in globals():                     # loaded as a Jupyter config file
    c = get_config()  # noqa: F821 - provided by traitlets when it loads this file
    c.ServerApp.contents_manager_class = CourseContentsManager
