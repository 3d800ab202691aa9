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
    text = json.dumps(document, ensure_ascii=False, indent=2)
    if _SURROGATE.search(text):  # rare: only names that are not UTF-8 carry them, so clean only then
        text = json.dumps(_unicode_document(document), ensure_ascii=False, indent=2)
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
