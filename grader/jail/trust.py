"""Whom the grader trusts with a file it will run or read as its own: the one rule, used by the
test cache (:mod:`grader.problems.cache`) and the C launcher's cache (:mod:`grader.jail.launcher`).

A path is trusted when it is not a symbolic link, is owned by root, by this account or by the
checkout's owner, and is not writable by group or others: whoever can replace such a file could
change every verdict (a test's answer) or run code outside the jail (the launcher). Standard
library only, so both the bottom room and the problems room may import it.

Example:
    >>> from pathlib import Path
    >>> unsafe_reason(Path("/tmp"))
    '/tmp is writable by group and others (mode 1777)'
"""
from __future__ import annotations

import os
import stat
from pathlib import Path

__all__ = ["REPO", "trusted_uids", "unsafe_reason"]

REPO = Path(__file__).resolve().parent.parent.parent


def trusted_uids() -> set[int]:
    """Who may own a file the grader trusts: root, this account, the checkout's owner."""
    uids = {0, os.geteuid()}
    try:
        uids.add(REPO.stat().st_uid)
    except OSError:
        pass
    return uids


def unsafe_reason(path: Path) -> str | None:
    """Why ``path`` (itself, not what it holds) cannot be trusted, or None when it can. An
    ``OSError`` of ``lstat`` (no such file, ...) is the caller's to handle."""
    st = os.lstat(path)
    if stat.S_ISLNK(st.st_mode):
        return f"{path} is a symbolic link"
    if st.st_uid not in trusted_uids():
        return f"{path} is owned by uid {st.st_uid}, not by root, you or the checkout's owner"
    if st.st_mode & 0o022:
        who = " and ".join(w for w, bit in (("group", 0o020), ("others", 0o002)) if st.st_mode & bit)
        return f"{path} is writable by {who} (mode {stat.S_IMODE(st.st_mode):o})"
    return None
