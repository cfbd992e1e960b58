"""A matplotlib font cache for the jail, built once per matplotlib installation.

matplotlib builds its font list on first use and, on Linux, runs ``fc-list`` for it: in the jail
that is a forbidden subprocess, and a fresh jail would rebuild the list for every worker. The
grader builds it once (outside the jail, with the same interpreter), keeps only the fonts the
jail can read (matplotlib's own and those inside the Python installations), stores it under the
checkout's ``.cache/`` and gives it read-only to every child as ``$MPLCONFIGDIR/fontlist-*.json``.

Run ``python -m grader.fontcache`` to build it and print its path.

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
    cache = Path(__file__).resolve().parent.parent / ".cache" / f"mpl-fontlist-{key}"
    found = sorted(cache.glob("fontlist-v*.json")) if cache.is_dir() else []
    if found:
        return str(found[-1])
    tmp = Path(tempfile.mkdtemp(prefix="mpl-fontlist-"))
    env = {"PATH": "/usr/bin:/bin", "MPLCONFIGDIR": str(tmp), "MPLBACKEND": "Agg", "HOME": str(tmp)}
    try:
        subprocess.run([sys.executable, "-I", "-c", "import matplotlib.font_manager"], env=env, timeout=300,
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        built = sorted(tmp.glob("fontlist-v*.json"))
        if not built:
            return None
        data = json.loads(built[-1].read_text())
        from .sandbox import _under, python_roots  # late: sandbox imports this module
        roots = python_roots()
        for key_ in ("ttflist", "afmlist"):
            data[key_] = [f for f in data.get(key_, []) if not os.path.isabs(f.get("fname", "/"))  # mpl-data's own
                          or any(_under(os.path.realpath(f["fname"]), r) for r in roots)]
        built[-1].write_text(json.dumps(data))
        os.chmod(built[-1], 0o644)
        cache.parent.mkdir(parents=True, exist_ok=True)
        try:
            os.rename(tmp, cache)  # atomic: a concurrent builder's copy wins, ours is removed
        except OSError:
            pass
    except (OSError, subprocess.SubprocessError, ValueError):
        return None
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    found = sorted(cache.glob("fontlist-v*.json"))
    return str(found[-1]) if found else None



if __name__ == "__main__":
    print(matplotlib_fontlist())
