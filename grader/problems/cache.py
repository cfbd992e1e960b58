"""The cache of generated tests and of parsed YAML: where it is, whom it trusts, how it is filled.

A problem's hidden tests are generated once (the generator's inputs, the answer key's answers)
into ``<cache>/<id>/<digest>/`` (``<cache>``: ``$GRADER_CACHE``, else ``<checkout>/.cache/grader``;
``<digest>``: :meth:`grader.problems.Problem.digest`, a hash of the package and the code its tests
come from). Each such folder holds a ``MANIFEST.json`` saying what it was made for: the problem,
the digest, the cache's format and a hash of the answer key (``reference_impl``'s sources). A
folder is used only when

* its manifest matches (a folder made by an older grader or for another answer key is made again);
* the cache folder, the problem's folder, that folder and every file in it are owned by root, by
  the account running the grader or by the checkout's owner, are not symbolic links, and are not
  writable by group or others (anyone who can write the tests can change every verdict).

Otherwise the tests are generated again: into the same cache when this account may replace what
is there, else into the account's own ``~/.cache/grader`` (a warning on stderr says why and how
to fix the shared cache). A cache folder that is itself unsafe is never written to.

The same trusted cache keeps each parsed ``course.yaml``/``problem.yaml`` as JSON under
``<cache>/yaml/`` (keyed by a hash of the text), so that listing every problem does not parse
230 KB of YAML on each command; YAML is read with libyaml's ``CSafeLoader`` where it is
installed (the same data as ``yaml.safe_load``: tested on every problem), else the pure-Python one.

Run (fills the cache for every problem, or the ones named; ``make warm`` does it):
    python -m grader warm [PROBLEM...]     (grader.problems.package.warm)

Example:
    >>> unsafe_reason(Path("/tmp"))
    '/tmp is writable by group and others (mode 1777)'
    >>> load_yaml_text("a: [1, 2.5, x]")
    {'a': [1, 2.5, 'x']}
"""

from __future__ import annotations

import hashlib
import importlib.util
import json
import os
import shutil
import sys
import tempfile
from pathlib import Path
from typing import Any, Callable

from ..jail.trust import unsafe_reason

REPO = Path(__file__).resolve().parent.parent.parent
CACHE_FORMAT = 1
MANIFEST = "MANIFEST.json"
_warned: set[str] = set()


# -- where, and whom it trusts ----------------------------------------------------------------------
def cache_root() -> Path:
    """Where generated tests are cached: ``$GRADER_CACHE`` or ``<checkout>/.cache/grader``."""
    return Path(os.environ.get("GRADER_CACHE", REPO / ".cache" / "grader"))


def private_root() -> Path:
    """The account's own cache, used when the configured one cannot be trusted or written."""
    return Path.home() / ".cache" / "grader"


def tree_reason(folder: Path) -> str | None:
    """The first reason not to trust ``folder`` or anything below it (None: all of it is safe)."""
    reason = unsafe_reason(folder)
    if reason:
        return reason
    for dirpath, dirnames, filenames in os.walk(folder):  # never follows a link (each is checked)
        for name in (*dirnames, *filenames):
            reason = unsafe_reason(Path(dirpath) / name)
            if reason:
                return reason
    return None


def _make_private(folder: Path, mode: int) -> None:
    """``mkdir -p folder``; a folder made here gets ``mode`` whatever the umask (a group-writable
    one would be refused)."""
    if not folder.is_dir():
        folder.mkdir(parents=True, exist_ok=True)
        if folder.stat().st_uid == os.geteuid():
            os.chmod(folder, mode)


def _warn(message: str) -> None:
    if message not in _warned:
        _warned.add(message)
        print(f"warning: {message}", file=sys.stderr)


def _usable_root(root: Path) -> bool:
    """True when ``root`` exists (made here if missing) and may be trusted; a warning when not."""
    try:
        _make_private(root, 0o755)
        reason = unsafe_reason(root)
    except PermissionError:
        return False
    if reason:
        _warn(f"the test cache {root} is not trusted: {reason}; anyone who can write it could change "
              f"every verdict. Make it yours alone (chown, chmod go-w) or remove it, then run "
              f"`python -m grader warm`")
        return False
    return True


# -- the answer key and the manifest ----------------------------------------------------------------
def answer_key_digest() -> str:
    """A hash of ``reference_impl``'s sources: the answers in the cache come from them."""
    if "key" not in _memo:
        spec = importlib.util.find_spec("reference_impl")  # its location only: nothing is imported
        if spec is None or not spec.submodule_search_locations:
            raise ValueError("the answer key (reference_impl) is not installed: the tests cannot be generated")
        h = hashlib.sha256()
        pkg = Path(list(spec.submodule_search_locations)[0]).resolve()
        for f in sorted(pkg.rglob("*.py")):
            h.update(str(f.relative_to(pkg)).encode())
            h.update(f.read_bytes())
        _memo["key"] = h.hexdigest()[:16]
    return _memo["key"]


_memo: dict[str, str] = {}


def manifest_for(problem_id: str, digest: str) -> dict[str, Any]:
    """What a tests folder of ``problem_id`` at ``digest`` must say it was made for."""
    return {"format": CACHE_FORMAT, "problem": problem_id, "digest": digest, "answer_key": answer_key_digest()}


def valid_reason(folder: Path, manifest: dict[str, Any]) -> str | None:
    """None when ``folder`` holds trusted tests made for ``manifest``, else why not."""
    reason = tree_reason(folder)
    if reason:
        return reason
    try:
        made_for = json.loads((folder / MANIFEST).read_text())
    except (OSError, ValueError):
        return f"{folder} has no readable {MANIFEST} (made by an older grader)"
    if made_for != manifest:
        diff = ", ".join(k for k in manifest if made_for.get(k) != manifest[k]) if isinstance(made_for, dict) else "all"
        return f"{folder} was made for another {diff}"
    return None


# -- filling ----------------------------------------------------------------------------------------
def tests_folder(problem_id: str, digest: str, generate: Callable[[Path], None]) -> Path:
    """The folder of ``problem_id``'s generated tests at ``digest``: a trusted cached one, else one
    made now by ``generate(folder)`` (it writes ``<group>/<NN>.in`` and ``.ans`` files).

    ``ValueError`` (saying what to do) when neither the configured cache nor the account's own can
    be used."""
    manifest = manifest_for(problem_id, digest)
    roots = [cache_root()]
    if private_root().resolve() != roots[0].resolve():
        roots.append(private_root())
    tried = []
    for root in roots:
        if not _usable_root(root):
            tried.append(f"{root} (not trusted or not writable)")
            continue
        target = root / problem_id / digest
        if os.path.lexists(target):
            why = valid_reason(target, manifest)
            if why is None:
                return target
            if "made by an older grader" not in why and "made for another" not in why:
                _warn(f"refused the cached tests: {why}; generating them again")
        try:
            return _fill(root, target, manifest, generate)
        except PermissionError:
            tried.append(f"{root} (cannot write {target.parent})")
    raise ValueError(f"problem {problem_id!r}: no usable cache for its generated tests: tried {'; '.join(tried)}. "
                     f"Set GRADER_CACHE to a folder of your own (not writable by others)")


def _fill(root: Path, target: Path, manifest: dict[str, Any], generate: Callable[[Path], None]) -> Path:
    """Generate into a private temporary folder, then rename it into place (replacing a refused one)."""
    _make_private(target.parent, 0o755)
    reason = unsafe_reason(target.parent)
    if reason:
        raise PermissionError(reason)
    tmp = Path(tempfile.mkdtemp(dir=target.parent, prefix=".tmp-"))  # 0700: hidden tests stay private
    try:
        generate(tmp)
        (tmp / MANIFEST).write_text(json.dumps(manifest, indent=1) + "\n")
        for dirpath, dirnames, filenames in os.walk(tmp):
            for d in dirnames:
                os.chmod(os.path.join(dirpath, d), 0o700)
            for f in filenames:
                os.chmod(os.path.join(dirpath, f), 0o644)
        if os.path.lexists(target):  # refused: set aside, then removed, unless another process
            if valid_reason(target, manifest) is None:  # has just put a good one there (in use: kept)
                shutil.rmtree(tmp, ignore_errors=True)
                return target
            aside = Path(tempfile.mkdtemp(dir=target.parent, prefix=".stale-"))
            try:
                os.rename(target, aside / "tests")
            except FileNotFoundError:  # another process replaced it first
                pass
            shutil.rmtree(aside, ignore_errors=True)
        try:
            os.rename(tmp, target)
        except OSError:  # another process won the race: its folder is as good
            shutil.rmtree(tmp, ignore_errors=True)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return target


# -- YAML ---------------------------------------------------------------------------------------
def load_yaml_text(text: str) -> Any:
    """``yaml.safe_load(text)`` through libyaml's ``CSafeLoader`` where installed (same data)."""
    import yaml  # noqa: PLC0415 - only when a YAML file is parsed, not on a cache hit

    return yaml.load(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))  # noqa: S506 - a safe loader


def load_yaml(path: Path) -> Any:
    """The data of the YAML file ``path``, from the parsed cache when a trusted copy is there."""
    raw = path.read_bytes()
    key = hashlib.sha256(b"yaml-json-1\0" + raw).hexdigest()[:32]
    folder = _yaml_folder()
    if folder is not None:
        hit = folder / f"{key}.json"
        try:
            if unsafe_reason(hit) is None:
                return json.loads(hit.read_text())
        except (OSError, ValueError):
            pass
    data = load_yaml_text(raw.decode("utf-8"))
    if folder is not None:
        _remember(folder, key, data)
    return data


def _yaml_folder() -> Path | None:
    """``<cache>/yaml`` when the cache is trusted (made if missing); None: parse without a cache."""
    root = cache_root()
    key = f"yaml:{root}"
    if key not in _memo:
        folder = root / "yaml"
        try:
            _make_private(folder, 0o700)
            ok = unsafe_reason(root) is None and unsafe_reason(folder) is None
        except OSError:
            ok = False
        _memo[key] = str(folder) if ok else ""
    return Path(_memo[key]) if _memo[key] else None


def _remember(folder: Path, key: str, data: Any) -> None:
    """Keep ``data`` as JSON when JSON gives back exactly the same (else parse next time, too)."""
    try:
        text = json.dumps(data, allow_nan=False)
        if json.loads(text) != data:
            return
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=".tmp-", suffix=".json")
        with os.fdopen(fd, "w") as f:
            f.write(text)
        os.chmod(tmp, 0o644)
        os.replace(tmp, folder / f"{key}.json")
    except (TypeError, ValueError, OSError):  # not JSON data (dates, ...), or a read-only cache
        pass

