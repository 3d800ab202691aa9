"""Reading LSP messages from a byte stream, tolerant as the base protocol allows and deaf to nothing.

A message is a header block (`Name: value` lines, each ended by CRLF, then an empty line)
and a body of exactly `Content-Length` bytes. This reader accepts what clients send in
practice and what the specification permits: header names in any case, blanks around the
value, a `Content-Type` header (or any other, ignored), and lines ended by LF alone. What it
cannot use it skips, and it says so in one line, then looks for the next header block:

- a block without a valid `Content-Length` (missing, not a number): skipped;
- a `Content-Length` over the limit (64 MB): refused before anything is allocated for it;
  its body is not trusted to be that long, the reader looks for the next header instead;
- bytes that are not a header line (the rest of a body whose length was wrong, noise): skipped
  up to the next `Content-Length` header, even when that header starts mid-line.

Memory stays bounded whatever arrives: a line without an end is kept only up to `MAX_LINE`.
This module does not import pygls: it is tested on its own.
"""

from __future__ import annotations

import re
import sys
from collections.abc import Callable
from dataclasses import dataclass
from typing import BinaryIO

MAX_CONTENT_LENGTH = 64 * 1024 * 1024  # bytes; an axis list is a few hundred kilobytes
MAX_LINE = 8192  # bytes kept of a header line that has not ended yet
_CHUNK = 65536
_KEEP = 64  # bytes kept when a long line is dropped: a header may start in them

# The last `Content-Length: N` of a line, wherever it starts (what comes before it is noise).
_LENGTH = re.compile(rb"content-length[ \t]*:[ \t]*([^ \t]*)[ \t]*$", re.IGNORECASE)
_HEADER = re.compile(rb"[!#-'*+.0-9A-Z^-z|~-]+[ \t]*:")  # an RFC 7230 token, then the colon


@dataclass(frozen=True)
class Skipped:
    """Input the reader passed over, and why (one line, for the log)."""

    reason: str
    refused: bool = False  # a message over the size limit was among it (the user may want to know)


class FrameReader:
    """Reads message bodies from a binary stream (buffered, or raw as `open(fd, "rb", buffering=0)`): `next()`
    gives bytes, a `Skipped`, or None at the end. `waiting` is called whenever the reader is about to read from
    the stream (and may wait for it): the messages given before it are all that had arrived.

    Problems in a row are told together, in one `Skipped` before the next message (or at the end), so
    a stream of noise costs one log line, not one per byte."""

    def __init__(
        self, stream: BinaryIO, limit: int = MAX_CONTENT_LENGTH, waiting: Callable[[], None] | None = None
    ) -> None:
        self._stream = stream
        self._limit = limit
        self._waiting = waiting  # called before each read: what was read so far is all there is
        self._buffer = bytearray()
        self._ended = False
        self._pending: bytes | None = None  # a body that waits while the problems before it are told
        self._noise = 0  # bytes skipped since the last report
        self._bad_blocks = 0  # header blocks without a usable Content-Length since the last report
        self._first_bad = ""  # what was wrong with the first of them

    # -- reading -------------------------------------------------------------------------------
    def _fill(self) -> bool:
        """Read what is available (at least one byte); False at the end of the stream."""
        if self._ended:
            return False
        if self._waiting is not None:
            self._waiting()
        read1 = getattr(self._stream, "read1", None)  # buffered: what is there; raw streams' read does that
        chunk = read1(_CHUNK) if read1 is not None else self._stream.read(_CHUNK)
        if not chunk:
            self._ended = True
            return False
        self._buffer += chunk
        return True

    def _line(self) -> tuple[bytes, int] | None:
        """The next line without its line break, and how many bytes before it were dropped (a line too long
        to keep); None at the end of the stream."""
        dropped = 0
        while True:
            end = self._buffer.find(b"\n")
            if end >= 0:
                line = bytes(self._buffer[:end])
                del self._buffer[: end + 1]
                return (line[:-1] if line.endswith(b"\r") else line), dropped
            if len(self._buffer) > MAX_LINE:
                dropped += len(self._buffer) - _KEEP
                del self._buffer[:-_KEEP]
            if not self._fill():
                self._noise += dropped + len(self._buffer)  # a last line without a break: noise
                self._buffer.clear()
                return None

    def _body(self, length: int) -> bytes | None:
        while len(self._buffer) < length:
            if not self._fill():
                self._noise += len(self._buffer)  # the stream ended inside the body
                self._buffer.clear()
                return None
        body = bytes(self._buffer[:length])
        del self._buffer[:length]
        return body

    # -- messages ------------------------------------------------------------------------------
    def _report(self, refused: str | None = None) -> Skipped | None:
        parts = []
        if self._bad_blocks:
            blocks = "a header block" if self._bad_blocks == 1 else f"{self._bad_blocks} header blocks"
            parts.append(f"skipped {blocks} with {self._first_bad}")
        if self._noise:
            parts.append(f"skipped {self._noise} bytes that were not an LSP header")
        if refused:
            parts.append(refused)
        self._noise, self._bad_blocks, self._first_bad = 0, 0, ""
        return Skipped("; ".join(parts), refused=refused is not None) if parts else None

    def next(self) -> bytes | Skipped | None:
        """The next message body, or a `Skipped` for input that was passed over, or None at the end."""
        if self._pending is not None:
            waiting, self._pending = self._pending, None
            return waiting
        length: int | None = None
        bad_length: bytes | None = None
        headers = 0
        block_bytes = 0  # the header lines read so far: noise if the block turns out not to be one
        while True:
            read = self._line()
            if read is None:
                return self._report()  # None when nothing was skipped
            line, dropped = read
            if dropped:
                self._noise += dropped + block_bytes
                length, bad_length, headers, block_bytes = None, None, 0, 0
            if not line:
                if not headers:
                    continue  # blank lines between messages
                if length is None:
                    self._bad_blocks += 1
                    if self._bad_blocks == 1:
                        self._first_bad = (
                            f"Content-Length {_shown(bad_length)}, not a number"
                            if bad_length is not None
                            else "no Content-Length"
                        )
                    length, bad_length, headers, block_bytes = None, None, 0, 0
                    continue
                if length > self._limit:
                    return self._report(
                        f"refused a message of {length} bytes (over the {_size(self._limit)} limit)"
                    )
                body = self._body(length)
                if body is None:
                    return self._report()
                problems = self._report()
                if problems is None:
                    return body
                self._pending = body
                return problems
            found = _LENGTH.search(line)
            if found is not None:
                if found.start() > 0:  # noise, then a header: the block starts again at the header
                    self._noise += block_bytes + found.start()
                    headers, block_bytes = 0, 0
                value = found.group(1)
                length, bad_length = (
                    # 20 digits and more are over any limit (and Python will not convert 4,300 of them)
                    (int(value) if len(value) < 20 else sys.maxsize, None)
                    if value.isdigit() and value.isascii()
                    else (None, value)
                )
            elif not _HEADER.match(line):
                self._noise += block_bytes + len(line) + 1
                length, bad_length, headers, block_bytes = None, None, 0, 0
                continue
            headers += 1
            block_bytes += len(line) + 1


def _size(count: int) -> str:
    megabytes, rest = divmod(count, 1024 * 1024)
    return f"{megabytes} MB" if megabytes and not rest else f"{count} bytes"


def _shown(value: bytes | None) -> str:
    text = (value or b"")[:40].decode("ascii", "replace")
    return repr(text + ("..." if value is not None and len(value) > 40 else ""))
