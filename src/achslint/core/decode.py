"""Bytes to text: the first stage of the pipeline.

Real axis lists are Latin-1 (µ and ° appear in comments), newer ones may be
UTF-8. Decoding picks the first codec that reads the bytes exactly and
remembers it, so that writing the text back reproduces the original bytes.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from .files import read_list, reason

UTF8_BOM = b"\xef\xbb\xbf"
_WIDE_BOMS = {
    b"\xff\xfe\x00\x00": "UTF-32",
    b"\x00\x00\xfe\xff": "UTF-32",
    b"\xff\xfe": "UTF-16",
    b"\xfe\xff": "UTF-16",
}


class UnreadableInput(Exception):
    """The input cannot be read as a parameter list at all (exit code 2)."""


@dataclass(frozen=True, slots=True)
class SourceText:
    """Decoded text plus what is needed to turn it back into the same bytes."""

    text: str
    encoding: str
    bom: bool = False

    def encode(self, text: str | None = None) -> bytes:
        body = (self.text if text is None else text).encode(self.encoding)
        return UTF8_BOM + body if self.bom else body


def text_bytes(text: str) -> bytes:
    """Text from an editor or a caller as UTF-8 bytes. A lone surrogate (JSON can carry one: "\\ud800") has
    no UTF-8 form: it becomes `?`, one character as it was, so positions stay where they were."""
    return text.encode("utf-8", "replace")


def decode(data: bytes) -> SourceText:
    """Decode list bytes: UTF-8 (with or without BOM), else cp1252, else Latin-1.

    Latin-1 maps every byte, so any byte string decodes; only UTF-16/32 files
    and binary files (a NUL byte, which no text list holds) are refused, because
    reading them byte-wise would turn every line into noise (hundreds of syntax
    errors for a program file) instead of one useful message.
    """
    for mark, name in _WIDE_BOMS.items():
        if data.startswith(mark):
            raise UnreadableInput(
                f"the file is {name} encoded; the CNC reads ASCII/Latin-1 lists, save it as ANSI/Latin-1"
            )
    if b"\x00" in data:
        raise UnreadableInput("a binary file (it holds NUL bytes), not an axis list; nothing of it is shown")
    bom = data.startswith(UTF8_BOM)
    body = data[len(UTF8_BOM) :] if bom else data
    for codec in ("utf-8", "cp1252", "latin-1"):
        try:
            return SourceText(body.decode(codec), codec, bom)
        except UnicodeDecodeError:
            continue
    raise AssertionError("latin-1 decodes every byte string")  # pragma: no cover


def unreadable(path: Path) -> str | None:
    """Why a file cannot be read as list text (an error reading it, UTF-16, binary), or None when it can."""
    try:
        decode(read_list(path))
    except OSError as exc:
        return str(exc) if exc.errno is None else reason(exc)
    except UnreadableInput as exc:
        return str(exc)
    return None
