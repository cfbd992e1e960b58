"""Copy the exact predicates into every C++ reference solution, or check that the copies match.

Each C++ submission must be one self-contained file, so the predicates (a floating-point filter
with a proven error bound plus an exact big-integer fallback) live in one master copy,
``solutions/cpp/predicates.hpp``, between the lines ``// BEGIN PREDICATES`` and
``// END PREDICATES``; every ``solutions/<id>/*.cpp`` holding those markers gets that block.

Usage:
    python solutions/cpp/sync_predicates.py          # rewrite the copies that differ
    python solutions/cpp/sync_predicates.py --check  # exit 1 naming each copy that differs

Example:
    $ python solutions/cpp/sync_predicates.py --check
    4 C++ files hold the predicates; all match solutions/cpp/predicates.hpp
"""
from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
MASTER = HERE / "predicates.hpp"
BLOCK = re.compile(r"// BEGIN PREDICATES\n.*?// END PREDICATES\n", re.S)


def master_block(master: Path = MASTER) -> str:
    """The block between the markers in the master copy (markers included)."""
    found = BLOCK.search(master.read_text())
    if found is None:
        raise SystemExit(f"{master}: no '// BEGIN PREDICATES' ... '// END PREDICATES' block")
    return found.group(0)


def copies(solutions: Path = HERE.parent) -> list[Path]:
    """Every C++ solution file that holds the markers."""
    return [f for f in sorted(solutions.glob("*/*.cpp")) if BLOCK.search(f.read_text())]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="only check; exit 1 when a copy differs")
    args = parser.parse_args(argv)
    block = master_block()
    files = copies()
    differ = [f for f in files if BLOCK.search(f.read_text()).group(0) != block]
    rel = [str(f.relative_to(HERE.parent.parent)) for f in differ]
    if args.check:
        if differ:
            print("predicates differ from solutions/cpp/predicates.hpp in: " + ", ".join(rel))
            return 1
        print(f"{len(files)} C++ files hold the predicates; all match solutions/cpp/predicates.hpp")
        return 0
    for f in differ:
        f.write_text(BLOCK.sub(lambda _m: block, f.read_text(), count=1))
    print(f"{len(files)} C++ files hold the predicates; rewrote {len(differ)}" + (": " + ", ".join(rel) if rel else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
