"""Float answers as a binary frame: the parent's decoder of what the jailed child sends instead
of a long JSON list of floats, for a problem whose checker asks for it (``from_arrays``).

Parsing a JSON float costs the parent about 0.6 microseconds (``strtod`` and a Python float
each); a ``voronoi`` answer holds about 1 200 of them per 100 points, its 200 tests 180 000.
When the judge starts a worker with ``frames=True`` (:class:`grader.judging.runner.FunctionWorker`),
the child sends a well-formed answer of floats (a list of rows of ``w`` floats, or a list of
groups of such rows) as one JSON line whose numbers are a base64 string of little-endian float64
(and, for groups, of int64 row counts) instead of decimal text::

    {"id": 7, "frame": {"w": 2, "counts": "<base64 int64>", "rows": "<base64 float64>"}}

Still plain data, never pickle: :func:`decode` checks every part (the keys and their types, the
width, that the buffers are whole numbers of items, every count between 0 and the number of rows
and their sum equal to it) and raises :class:`ValueError` naming the fault, which the runner
turns into a ``PE`` verdict. The decoded :class:`FloatRows` is exactly the value the JSON line
would have carried (:meth:`FloatRows.tolist`; float64 round-trips exactly, ``-0.0``, NaN and the
infinities included: a checker judges them as it judges them in JSON). A child that sends a
frame where none was asked for has written on the judge's channel (the runner's rule for any
unexpected line).

Run: ``python -m pytest tests/grader/test_frames.py``. Example:

    >>> cells = [[[0.5, 1.0], [2.0, 3.0]], [], [[4.0, 5.0]]] * 50
    >>> rows = decode(frame_of(cells))
    >>> rows.counts.tolist()[:3], rows.rows.shape, rows.tolist() == cells
    ([2, 0, 1], (150, 2), True)
"""

from __future__ import annotations

import binascii
import sys
from array import array
from itertools import chain
from typing import Any

#: widest row a frame may carry (a point in the plane is 2, in space 3)
MAX_WIDTH = 16
#: the child sends a frame only for an answer of at least this many floats (smaller ones: JSON)
MIN_FLOATS = 256
_STRICT = {"strict_mode": True} if sys.version_info >= (3, 11) else {}


class FloatRows:
    """A decoded frame: ``rows`` (m, w) float64 and, for a list of groups, ``counts`` (n,) int64
    (rows per group, in order). Both arrays are read-only views of the received bytes."""

    __slots__ = ("rows", "counts")

    def __init__(self, rows, counts=None):
        self.rows = rows
        self.counts = counts

    def __len__(self) -> int:
        """The number of items of the answer: groups, or rows when there are no groups."""
        return len(self.rows) if self.counts is None else len(self.counts)

    def tolist(self) -> list:
        """The answer as the JSON-native value the child would have sent as JSON text."""
        flat = self.rows.tolist()
        if self.counts is None:
            return flat
        out, at = [], 0
        for k in self.counts.tolist():
            out.append(flat[at:at + k])
            at += k
        return out


def _b64(text: Any, what: str) -> bytes:
    if not isinstance(text, str):
        raise ValueError(f"{what} should be a base64 string, got {type(text).__name__}")
    try:
        return binascii.a2b_base64(text, **_STRICT)
    except (binascii.Error, ValueError) as exc:
        raise ValueError(f"{what}: not valid base64 ({exc})") from None


def decode(frame: Any) -> FloatRows:
    """The :class:`FloatRows` a child's ``"frame"`` object holds; ValueError naming the fault.

    >>> decode({"w": 2, "counts": None, "rows": "AAAAAAAA8D8AAAAAAAAAQA=="}).tolist()
    [[1.0, 2.0]]
    >>> decode({"w": 3, "counts": None, "rows": "AAAAAAAA8D8AAAAAAAAAQA=="})
    Traceback (most recent call last):
    ...
    ValueError: the rows hold 16 bytes, not a whole number of rows of 3 float64 (24 bytes each)
    """
    import numpy as np

    if not isinstance(frame, dict) or set(frame) != {"w", "counts", "rows"}:
        keys = sorted(map(str, frame))[:5] if isinstance(frame, dict) else type(frame).__name__
        raise ValueError(f"a frame is an object with the keys counts, rows and w, got {keys}")
    w = frame["w"]
    if type(w) is not int or not 1 <= w <= MAX_WIDTH:
        raise ValueError(f"the row width w should be an integer from 1 to {MAX_WIDTH}, got {str(w)[:20]}")
    data = _b64(frame["rows"], "the rows")
    if len(data) % (8 * w):
        raise ValueError(f"the rows hold {len(data)} bytes, not a whole number of rows of {w} float64 "
                         f"({8 * w} bytes each)")
    rows = np.frombuffer(data, "<f8").reshape(-1, w)
    if frame["counts"] is None:
        return FloatRows(rows)
    raw = _b64(frame["counts"], "the counts")
    if len(raw) % 8:
        raise ValueError(f"the counts hold {len(raw)} bytes, not a whole number of int64 (8 bytes each)")
    counts = np.frombuffer(raw, "<i8")
    m = len(rows)
    if len(counts) and (int(counts.min()) < 0 or int(counts.max()) > m):
        bad = int(counts.min()) if int(counts.min()) < 0 else int(counts.max())
        raise ValueError(f"a group's row count is {bad}, outside 0..{m} (the rows sent)")
    total = int(counts.sum())  # each count <= m < 2^28 and fewer than 2^28 counts: no overflow
    if total != m:
        raise ValueError(f"the groups' row counts add up to {total}, but {m} rows were sent")
    return FloatRows(rows, counts)


def frame_of(value: Any) -> dict | None:
    """The frame of ``value`` when it is a list of at least :data:`MIN_FLOATS` floats in rows of
    one width (a list of rows, or a list of groups of rows), else None (it goes as JSON). The
    child's copy of this function (:mod:`grader.jail.child_bootstrap`, which imports nothing of
    the grader) builds what it sends; this one builds frames for tests and benchmarks.

    >>> frame_of([[1.0, 2.0]] * 128)["counts"] is None, frame_of([[1.0, 2.0]]) is None
    (True, True)
    """
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
    if len(widths) != 1 or not 1 <= min(widths) <= MAX_WIDTH:
        return None
    flat = list(chain.from_iterable(rows)) if groups else inner
    if len(flat) < MIN_FLOATS or not set(map(type, flat)) <= {float}:
        return None
    data = array("d", flat)
    counts = array("q", map(len, value)) if groups else None
    if sys.byteorder == "big":
        data.byteswap()
        counts is not None and counts.byteswap()
    return {"w": min(widths), "rows": binascii.b2a_base64(data.tobytes(), newline=False).decode(),
            "counts": None if counts is None else binascii.b2a_base64(counts.tobytes(), newline=False).decode()}
