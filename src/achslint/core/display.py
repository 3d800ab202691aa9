"""Text from lists and file names, made safe to show and to embed in reports.

A list or a file name can hold any character. Printed as they are, control
characters and escape sequences (`ESC [ 2 J`, a carriage return, a bidi
override) would drive the terminal or CI log that shows them, a bare line
break would forge an extra line of output, and a name that is not UTF-8
(Python keeps its bytes as lone surrogates) cannot be written to a UTF-8
stream or a JSON or XML document at all.

* `printable` is for everything people read (the concise, full and github
  formats, JUnit, messages on stderr): each such character becomes a visible
  escape, `\\x1b`, `\\u202e`; a byte of a non-UTF-8 name becomes `\\xff`.
* `unicode_text` is for JSON documents, which escape control characters
  themselves: only the lone surrogates are replaced, so the text stays valid
  Unicode and the document strict JSON.
"""

from __future__ import annotations

import functools
import json
import re
from json.encoder import INFINITY as _INFINITY
from json.encoder import encode_basestring as _encode_string  # the C one where there is one

# C0 and C1 controls, DEL, line/paragraph separators, bidi embeddings / overrides / isolates,
# lone surrogates and the two non-characters XML forbids.
_UNSAFE = "[\x00-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069\ud800-\udfff\ufffe\uffff]"
_SURROGATE = re.compile("[\ud800-\udfff]")


def _escape(match: re.Match[str]) -> str:
    code = ord(match.group(0))
    if 0xDC80 <= code <= 0xDCFF:  # a byte that was not UTF-8, kept by the file system decoding
        return f"\\x{code - 0xDC00:02x}"
    return f"\\x{code:02x}" if code <= 0xFF else f"\\u{code:04x}"


def printable(text: str) -> str:
    """`text` with every character that could act on a terminal or break a line shown as an escape."""
    if text.isascii() and text.isprintable():  # none of them (most texts): no pattern to compile
        return text
    return _unsafe().sub(_escape, text)


@functools.cache
def _unsafe() -> re.Pattern[str]:
    return re.compile(_UNSAFE)  # 0.6 ms: compiled only for a text that may need it


def unicode_text(text: str) -> str:
    """`text` without lone surrogates (the undecodable bytes of a file name), for JSON documents."""
    return _SURROGATE.sub(_escape, text)


def json_text(document: object) -> str:
    """A JSON document as strict JSON text (UTF-8 friendly, no lone surrogates), indented."""
    text = indented_json(document)
    if _SURROGATE.search(text):  # rare: only names that are not UTF-8 carry them, so clean only then
        text = indented_json(_unicode_document(document))
    return text


def indented_json(document: object, *, allow_nan: bool = True) -> str:
    """`json.dumps(document, ensure_ascii=False, indent=2, allow_nan=allow_nan)`, character for character,
    in a fraction of its time.

    With an indent, the standard library leaves its C encoder aside and hands every piece of text up through
    one Python generator per level of nesting; a lint report of a few hundred findings took tens of
    milliseconds that way. This writer walks the document once and collects the pieces in one list; only
    strings go through the library's own (C) string encoder. Whatever it does not take as it is (a type
    JSON has no form for, a reference cycle, a NaN when `allow_nan` is false) is left to `json.dumps`, which
    answers, or raises, as it always did.
    """
    try:
        return _IndentedWriter(allow_nan).text(document)
    except Exception:
        return json.dumps(document, ensure_ascii=False, indent=2, allow_nan=allow_nan)


class _NotPlain(Exception):
    """Raised by the writer for anything it leaves to `json.dumps`."""


_INDENT = "  "  # json.dumps(indent=2)


class _IndentedWriter:
    """One document written as `json.dumps(..., ensure_ascii=False, indent=2)` writes it (see `indented_json`).

    The order of the type tests is the standard library's (`json.encoder._make_iterencode`): it decides what a
    subclass is written as (a bool is `true`, not 1; an IntEnum is its number; a str Enum its text).
    """

    def __init__(self, allow_nan: bool) -> None:
        self.allow_nan = allow_nan
        self.parts: list[str] = []
        self.breaks = ["\n"]  # a line break and the indent of each nesting level

    def text(self, document: object) -> str:
        if isinstance(document, str):
            return _encode_string(document)
        self.value(document, 0)
        return "".join(self.parts)

    def newline(self, level: int) -> str:
        breaks = self.breaks
        while len(breaks) <= level:
            breaks.append("\n" + _INDENT * len(breaks))
        return breaks[level]

    def number(self, value: float) -> str:
        if value != value or value in (_INFINITY, -_INFINITY):
            if not self.allow_nan:
                raise _NotPlain  # json.dumps raises its ValueError
            return "NaN" if value != value else ("Infinity" if value > 0 else "-Infinity")
        return float.__repr__(value)

    def scalar(self, value: object) -> str | None:
        """The text of a value that is no container, None for a list, tuple or dict (raises for the rest)."""
        if isinstance(value, str):
            return _encode_string(value)
        if value is None:
            return "null"
        if value is True:
            return "true"
        if value is False:
            return "false"
        if isinstance(value, int):
            return int.__repr__(value)
        if isinstance(value, float):
            return self.number(value)
        if isinstance(value, (list, tuple, dict)):
            return None
        raise _NotPlain  # json.dumps calls its `default`, which raises the TypeError

    def value(self, value: object, level: int) -> None:
        kind = type(value)
        if kind is dict:
            self.mapping(value, level)  # type: ignore[arg-type]  # its type is dict
        elif kind is list or kind is tuple:
            self.sequence(value, level)  # type: ignore[arg-type]  # its type is list or tuple
        else:
            text = self.scalar(value)
            if text is not None:
                self.parts.append(text)
            elif isinstance(value, dict):
                self.mapping(value, level)
            else:
                self.sequence(value, level)  # type: ignore[arg-type]  # scalar() let only these through

    def sequence(self, items: list[object] | tuple[object, ...], level: int) -> None:
        if not items:
            self.parts.append("[]")
            return
        add, scalar = self.parts.append, self.scalar
        inner = self.newline(level + 1)
        separator = "," + inner
        lead = "[" + inner
        for item in items:
            kind = type(item)
            if kind is str:
                add(lead + _encode_string(item))  # type: ignore[arg-type]  # its type is str
            elif kind is int:
                add(lead + int.__repr__(item))
            else:
                text = None if kind is dict or kind is list else scalar(item)
                if text is not None:
                    add(lead + text)
                else:
                    add(lead)
                    self.value(item, level + 1)
            lead = separator
        add(self.newline(level) + "]")

    def mapping(self, items: dict[object, object], level: int) -> None:
        if not items:
            self.parts.append("{}")
            return
        add, scalar = self.parts.append, self.scalar
        inner = self.newline(level + 1)
        separator = "," + inner
        lead = "{" + inner
        for key, item in items.items():
            name = _encode_string(key if isinstance(key, str) else self.key(key))
            kind = type(item)
            if kind is str:
                add(lead + name + ": " + _encode_string(item))  # type: ignore[arg-type]  # its type is str
            elif kind is int:
                add(lead + name + ": " + int.__repr__(item))
            else:
                text = None if kind is dict or kind is list else scalar(item)
                if text is not None:
                    add(lead + name + ": " + text)
                else:
                    add(lead + name + ": ")
                    self.value(item, level + 1)
            lead = separator
        add(self.newline(level) + "}")

    def key(self, key: object) -> str:
        """A key that is no string as JSON names it: a number, true, false or null, written as that value is."""
        text = self.scalar(key) if key is None or isinstance(key, (int, float)) else None  # (bool is an int)
        if text is None:
            raise _NotPlain  # json.dumps raises its TypeError
        return text


def _unicode_document(value: object) -> object:
    if isinstance(value, str):
        return unicode_text(value)
    if isinstance(value, dict):
        return {unicode_text(key): _unicode_document(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [_unicode_document(item) for item in value]
    return value


def shortened(text: str, limit: int = 80, keep: int = 60) -> str:
    """`text` as a message shows it: whole up to `limit` characters, else its first `keep` and its length
    (a 5,000-character name or number is not worth repeating)."""
    if len(text) <= limit:
        return text
    return f"{text[:keep]}… ({len(text):,} characters)"
