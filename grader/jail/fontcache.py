"""A matplotlib font cache for the jail, built once per matplotlib installation.

matplotlib builds its font list on first use and, on Linux, runs ``fc-list`` for it: in the jail
that is a forbidden subprocess, and a fresh jail would rebuild the list for every worker. The
grader builds it once (outside the jail, with the same interpreter), keeps only the fonts the
jail can read (matplotlib's own and those inside the Python installations), stores it under the
checkout's ``.cache/`` and gives it read-only to every child as ``$MPLCONFIGDIR/fontlist-*.json``.

Run ``python -m grader.jail.fontcache`` to build it and print its path.

Example:
    >>> path = matplotlib_fontlist()                     # doctest: +SKIP
    >>> path.endswith(".json")                           # doctest: +SKIP
    True
"""

from __future__ import annotations

import functools
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from .paths import python_roots, under


@functools.lru_cache(maxsize=1)
def matplotlib_fontlist() -> str | None:
    """A font cache for matplotlib, built once per matplotlib installation, listing only fonts
    inside the Python installation (readable in the jail); None without matplotlib.

    Without it, matplotlib rebuilds the cache in every fresh jail and runs ``fc-list``.
    """
    import importlib.util
    spec = importlib.util.find_spec("matplotlib")
    if spec is None or spec.origin is None:
        return None
    origin = os.path.dirname(spec.origin)
    key = f"{os.path.getmtime(origin):.0f}-{hashlib.sha256(origin.encode()).hexdigest()[:12]}"
    # the checkout's cache, else (a checkout this account cannot write, or an older unreadable
    # copy) one in this account's home
    places = [Path(__file__).resolve().parents[2] / ".cache", Path.home() / ".cache" / "grader"]
    caches = [p / f"mpl-fontlist-{key}" for p in places]
    found = _readable(caches)
    if found:
        return found
    tmp = Path(tempfile.mkdtemp(prefix="mpl-fontlist-"))
    env = {"PATH": "/usr/bin:/bin", "MPLCONFIGDIR": str(tmp), "MPLBACKEND": "Agg", "HOME": str(tmp)}
    try:
        subprocess.run([sys.executable, "-I", "-c", "import matplotlib.font_manager"], env=env, timeout=300,
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        built = sorted(tmp.glob("fontlist-v*.json"))
        if not built:
            return None
        data = json.loads(built[-1].read_text())
        roots = python_roots()
        for key_ in ("ttflist", "afmlist"):
            data[key_] = [f for f in data.get(key_, []) if not os.path.isabs(f.get("fname", "/"))  # mpl-data's own
                          or any(under(os.path.realpath(f["fname"]), r) for r in roots)]
        built[-1].write_text(json.dumps(data))
        os.chmod(built[-1], 0o644)
        os.chmod(tmp, 0o755)  # other accounts (a sandbox uid) read it too
        for cache in caches:
            try:
                cache.parent.mkdir(parents=True, exist_ok=True)
                os.rename(tmp, cache)  # atomic: a concurrent builder's copy wins, ours is removed
            except OSError:
                pass
            if _readable([cache]):
                break
    except (OSError, subprocess.SubprocessError, ValueError):
        return None
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return _readable(caches)


def _readable(caches: list[Path]) -> str | None:
    """The newest font list this account can read in the first cache directory holding one."""
    for cache in caches:
        try:
            found = sorted(cache.glob("fontlist-v*.json")) if cache.is_dir() else []
        except OSError:
            found = []
        found = [f for f in found if os.access(f, os.R_OK)]
        if found:
            return str(found[-1])
    return None



def main() -> None:
    """The command ``python -m grader.jail.fontcache``."""
    print(matplotlib_fontlist())


if __name__ == "__main__":
    main()
