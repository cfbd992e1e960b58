"""The whitelist of pure decoding functions :mod:`grader.classroom.code_from_data` may evaluate, and nothing else.

Every function here takes constant ``str``/``bytes``/``int``/``list`` values already read from a
submission's syntax tree and returns a new value, or raises :class:`NoValue`; none calls anything a
submission defines, touches files or imports. Outputs are capped: a step that would produce more
than :data:`MAX_OUTPUT` bytes raises :class:`TooLarge` (decompression goes through ``max_length``,
so a bomb is never inflated past the cap).

    >>> import zlib
    >>> inflate(zlib.compress(b"x = 1\\n"), "zlib")
    b'x = 1\\n'
    >>> inflate(zlib.compress(bytes(MAX_OUTPUT + 1)), "zlib")
    Traceback (most recent call last):
    grader.classroom.data_decoders.TooLarge: decompresses to more than MAX_OUTPUT
"""

from __future__ import annotations

import ast
import base64
import binascii
import bz2
import codecs
import lzma
import re
import zlib
from collections.abc import Callable

MAX_OUTPUT = 2 << 20     #: bytes any one decoding step may produce (a decompression bomb stops here)
MIN_CANDIDATE = 24       #: shorter values are not searched for encoded code
_B64 = re.compile(rb"[A-Za-z0-9+/\-_\s]+=*\s*")
_B32 = re.compile(rb"[A-Z2-7\s]+=*\s*")
_HEX = re.compile(rb"(?:[0-9a-fA-F]{2}\s*)+")


class NoValue(Exception):
    """The expression has no value known without running the program."""


class TooLarge(NoValue):
    """A decoding step would produce more than :data:`MAX_OUTPUT`."""


def _capped(data: bytes) -> bytes:
    if len(data) > MAX_OUTPUT:
        raise TooLarge("too large")
    return data


def inflate(data: bytes, kind: str, wbits: int | None = None) -> bytes:
    """Decompress at most :data:`MAX_OUTPUT` bytes; a larger output has no value (bomb-safe)."""
    data = _as_bytes(data)
    if kind in ("zlib", "gzip"):
        d = zlib.decompressobj(wbits if wbits is not None else 47)  # 47: zlib or gzip header
        out = d.decompress(data, MAX_OUTPUT)
        if d.unconsumed_tail:
            raise TooLarge("decompresses to more than MAX_OUTPUT")
        return out
    d = bz2.BZ2Decompressor() if kind == "bz2" else lzma.LZMADecompressor()
    out = d.decompress(data, max_length=MAX_OUTPUT)
    if not d.eof and not d.needs_input:
        raise TooLarge("decompresses to more than MAX_OUTPUT")
    return out


def _as_bytes(v: object) -> bytes:
    if isinstance(v, (bytes, bytearray)):
        return bytes(v)
    if isinstance(v, str):
        return v.encode("latin-1")  # decoders accept ASCII text; anything else fails below
    raise NoValue(type(v).__name__)


def _rot13(v: object) -> str:
    if not isinstance(v, str):
        raise NoValue("rot13 of bytes")
    return codecs.decode(v, "rot13")


def _b64(v: object, altchars: object = None) -> bytes:
    data = _as_bytes(v)
    if altchars is not None:
        data = data.translate(bytes.maketrans(_as_bytes(altchars), b"+/"))
    return base64.b64decode(data.translate(bytes.maketrans(b"-_", b"+/")) + b"==")


#: decoding functions by qualified name: (step name shown in a mark, function of the arguments)
DECODERS = {
    **{n: ("base64", _b64) for n in ("base64.b64decode", "base64.standard_b64decode", "base64.urlsafe_b64decode",
                                      "base64.decodebytes", "base64.decodestring", "binascii.a2b_base64")},
    **{n: ("base32", lambda v, *a: base64.b32decode(_as_bytes(v), True)) for n in ("base64.b32decode",)},
    "base64.b32hexdecode": ("base32", lambda v, *a: base64.b32hexdecode(_as_bytes(v), True)),
    "base64.b85decode": ("base85", lambda v: base64.b85decode(_as_bytes(v))),
    "base64.a85decode": ("ascii85", lambda v, *a: base64.a85decode(_as_bytes(v), adobe=_as_bytes(v).startswith(b"<~"))),
    **{n: ("hex", lambda v, *a: binascii.unhexlify(re.sub(rb"\s", b"", _as_bytes(v))))
       for n in ("base64.b16decode", "binascii.unhexlify", "binascii.a2b_hex", "bytes.fromhex", "bytearray.fromhex")},
    "zlib.decompress": ("zlib", lambda v, w=None, *a: inflate(v, "zlib", w if isinstance(w, int) else 15)),
    "gzip.decompress": ("gzip", lambda v: inflate(v, "gzip")),
    "bz2.decompress": ("bz2", lambda v: inflate(v, "bz2")),
    "lzma.decompress": ("lzma", lambda v, *a: inflate(v, "lzma")),
}
#: ``codecs.decode``/``encode`` encodings understood: (step name, function)
CODECS = {"rot13": ("rot13", _rot13), "rot_13": ("rot13", _rot13), "hex": ("hex", lambda v: binascii.unhexlify(_as_bytes(v))),
           "hex_codec": ("hex", lambda v: binascii.unhexlify(_as_bytes(v))), "base64": ("base64", _b64),
           "base_64": ("base64", _b64), "base64_codec": ("base64", _b64), "zlib": ("zlib", lambda v: inflate(v, "zlib")),
           "zip": ("zlib", lambda v: inflate(v, "zlib")), "zlib_codec": ("zlib", lambda v: inflate(v, "zlib")),
           "bz2": ("bz2", lambda v: inflate(v, "bz2")), "bz2_codec": ("bz2", lambda v: inflate(v, "bz2"))}
_TEXT_ENCODINGS = {"utf-8", "utf8", "utf_8", "ascii", "latin-1", "latin1", "iso-8859-1", "unicode_escape"}


def join_via(*vias: tuple) -> tuple:
    """The decoding steps of several values, in order, a step repeated at once kept once."""
    out: list[str] = []
    for via in vias:
        for step in via:
            if not out or out[-1] != step:
                out.append(step)
    return tuple(out)


METHODS = {"decode", "encode", "join", "replace", "strip"}
BUILTINS = {"map", "codecs.decode", "codecs.encode", "bytes", "bytearray", "chr", "str", "list", "reversed"}


def cap(v: object) -> object:
    """``v`` if it is no longer than :data:`MAX_OUTPUT`, else :class:`TooLarge`."""
    if isinstance(v, (str, bytes, list)) and len(v) > MAX_OUTPUT:
        raise NoValue("too large")
    return v


def as_list(v: object) -> list:
    """The items of a str, bytes or list value (ints of bytes)."""
    if isinstance(v, (bytes, list, str)):
        return list(v)
    raise NoValue("not a sequence")


def to_chr(c: object) -> str:
    """``chr(c)`` for a valid code point, else :class:`NoValue`."""
    if not isinstance(c, int) or not 0 <= c < 0x110000:
        raise NoValue("chr")
    return chr(c)


def binop(op: ast.operator, a: object, b: object) -> object:
    """``a op b`` for concatenation, repetition (capped) and small-int arithmetic; else :class:`NoValue`."""
    same = type(a) is type(b) or (isinstance(a, (bytes, bytearray)) and isinstance(b, (bytes, bytearray)))
    if isinstance(op, ast.Add) and same and isinstance(a, (str, bytes, list, int)):
        if isinstance(a, int) and max(abs(a), abs(b)) > 1 << 64:
            raise NoValue("large int")
        return cap(a + b)
    if isinstance(a, int) and isinstance(b, int) and max(abs(a), abs(b)) < 1 << 64:
        ops = {ast.Sub: lambda: a - b, ast.BitXor: lambda: a ^ b, ast.Mod: lambda: a % b if b else None,
               ast.FloorDiv: lambda: a // b if b else None, ast.Mult: lambda: a * b, ast.BitAnd: lambda: a & b,
               ast.BitOr: lambda: a | b}
        out = ops.get(type(op), lambda: None)()
        if out is not None:
            return out
    if isinstance(op, ast.Mult) and isinstance(a, (str, bytes, list)) and isinstance(b, int):
        if len(a) * max(b, 0) > MAX_OUTPUT:
            raise NoValue("too large")
        return a * b
    raise NoValue("operator")


def call_decoder(fn: Callable[..., object], args: list, kwargs: dict) -> object:
    """``fn(*args, **kwargs)`` for a whitelisted decoder: its errors become :class:`NoValue`, its output is capped."""
    try:
        return _capped(fn(*args, **kwargs))
    except NoValue:
        raise
    except (ValueError, TypeError, binascii.Error, zlib.error, lzma.LZMAError, OSError, EOFError, OverflowError) as exc:
        raise NoValue(str(exc)) from None


def method(obj: object, name: str, args: list, kwargs: dict) -> tuple[str, object]:
    """A whitelisted method of a str/bytes value: (decoding step or "", result)."""
    if name == "decode" and isinstance(obj, (bytes, bytearray)):
        enc = (args[0] if args else kwargs.get("encoding", "utf-8"))
        if not isinstance(enc, str) or enc.lower() not in _TEXT_ENCODINGS:
            raise NoValue("encoding")
        return "", call_decoder(lambda: bytes(obj).decode(enc.lower(), "strict"), [], {})
    if name == "encode" and isinstance(obj, str):
        enc = (args[0] if args else kwargs.get("encoding", "utf-8"))
        if not isinstance(enc, str) or enc.lower() not in _TEXT_ENCODINGS - {"unicode_escape"}:
            raise NoValue("encoding")
        return "", call_decoder(lambda: obj.encode(enc.lower(), "strict"), [], {})
    if name == "join" and isinstance(obj, (str, bytes)) and len(args) == 1:
        items = as_list(args[0])
        if not all(isinstance(i, type(obj)) for i in items):
            raise NoValue("join")
        return "", cap(obj.join(items))
    if name == "replace" and isinstance(obj, (str, bytes)) and len(args) == 2 and all(type(a) is type(obj) for a in args):
        if args[0] and len(obj) // len(args[0]) * len(args[1]) > MAX_OUTPUT:
            raise NoValue("too large")
        return "", obj.replace(*args)
    if name == "strip" and isinstance(obj, (str, bytes)) and not args:
        return "", obj.strip()
    raise NoValue(f"method {name}")


def is_marshal(b: bytes) -> bool:
    """A marshalled code object: type byte 'c' (with or without the ref flag), then argcount,
    posonlyargcount and kwonlyargcount as small little-endian ints (9 zero bytes by chance: 2^-72)."""
    return len(b) >= 64 and b[0] in (0x63, 0xE3) and all(b[i + 1:i + 4] == b"\0\0\0" for i in (1, 5, 9))


def next_steps(v: str | bytes, via: tuple) -> list[tuple[str, object]]:
    """The automatic decoding steps worth trying on ``v`` (by its alphabet or magic bytes)."""
    try:
        b = v if isinstance(v, bytes) else v.encode("ascii")
    except UnicodeEncodeError:
        b = None
    steps: list[tuple[str, object]] = []
    if b is not None:
        s = b.strip()
        if s[:1] == b"\x78" and len(s) > 2 and int.from_bytes(s[:2], "big") % 31 == 0:
            steps.append(("zlib", lambda: inflate(s, "zlib", 15)))
        if s[:2] == b"\x1f\x8b":
            steps.append(("gzip", lambda: inflate(s, "gzip")))
        if s[:3] == b"BZh":
            steps.append(("bz2", lambda: inflate(s, "bz2")))
        if s[:6] == b"\xfd7zXZ\x00" or s[:3] == b"\x5d\x00\x00":
            steps.append(("lzma", lambda: inflate(s, "lzma")))
        if len(s) >= MIN_CANDIDATE:
            if _HEX.fullmatch(s):
                steps.append(("hex", lambda: binascii.unhexlify(re.sub(rb"\s", b"", s))))
            if _B32.fullmatch(s):
                steps.append(("base32", lambda: base64.b32decode(re.sub(rb"\s", b"", s))))
            if _B64.fullmatch(s):
                steps.append(("base64", lambda: _b64(s)))
            if s.startswith(b"<~"):
                steps.append(("ascii85", lambda: base64.a85decode(s, adobe=True)))
            elif not re.search(rb"[\s\"',./:\[\]\\]", s):
                steps.append(("base85", lambda: base64.b85decode(s)))
    if isinstance(v, str) and len(v) >= MIN_CANDIDATE:
        if "rot13" not in via:
            steps.append(("rot13", lambda: codecs.decode(v, "rot13")))
        if "reversal" not in via:
            steps.append(("reversal", lambda: v[::-1]))
    return steps
