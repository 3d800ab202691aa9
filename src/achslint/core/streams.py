"""Standard output that reports a write it could not finish.

Python's own standard output loses the rest of a write the system took only in part: on a full disk, or
above a file-size limit (`ulimit -f`), `achslint explain x.lis > out` ended with exit 0 and a report cut
at the limit, without a word. The command line (`cli.run`) therefore writes its standard output through
`WholeWrites`, which writes until every byte is out or the system says why not; that reason ends the run
as `StandardOutputFailed` (one line, exit 2). A closed pipe (`achslint lint | head`) stays what it was.
"""

from __future__ import annotations

import errno
import io
import os
import sys
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from _typeshed import ReadableBuffer


class StandardOutputFailed(OSError):
    """Standard output could not take what the command wrote (full disk, file-size limit ...)."""


class WholeWrites(io.RawIOBase):
    """A file descriptor written to until every byte of each write is out. After a failure, which it raises
    once, it takes what is still written without writing it: the run ends with that failure, and the
    interpreter's last flush must not report it again."""

    def __init__(self, fd: int) -> None:
        super().__init__()
        self._fd = fd
        self._failed = False

    def writable(self) -> bool:
        return True

    def fileno(self) -> int:
        return self._fd

    def isatty(self) -> bool:
        return os.isatty(self._fd)

    def write(self, data: ReadableBuffer) -> int:
        view = memoryview(data).cast("B")
        done = 0
        while done < len(view) and not self._failed:
            try:
                done += os.write(self._fd, view[done:])
            except InterruptedError:
                continue
            except OSError as exc:
                if exc.errno == errno.EPIPE:
                    raise
                self._failed = True
                failed = StandardOutputFailed(f"cannot write standard output: {os.strerror(exc.errno or 0)}")
                failed.errno = exc.errno
                raise failed from None
        return len(view)


def install() -> None:
    """Standard output written through `WholeWrites`, with the encoding, error handling and buffering it had;
    left as it is when it is no file (a test's capture, a closed descriptor)."""
    stream = sys.stdout
    try:
        fd = stream.fileno()
    except (AttributeError, OSError, ValueError):
        return
    stream.flush()
    buffered = io.BufferedWriter(WholeWrites(fd))
    sys.stdout = io.TextIOWrapper(
        buffered,
        encoding=stream.encoding,
        errors=stream.errors,
        newline=None,
        line_buffering=bool(stream.line_buffering),
        write_through=getattr(stream, "write_through", False),
    )
