"""Ending a run on SIGINT, SIGTERM and SIGHUP the same clean way.

Python turns only SIGINT into an exception; SIGTERM (a CI job cancelled, a
container stopped) and SIGHUP (the terminal closed) would end the process at
once, leaving a temporary file next to a list that was being rewritten. Here
all three raise `Stopped`, so every `finally`/`except BaseException` runs (the
writer removes its temporary file), and the command line ends with one line
and the exit code 128 + signal number, as a shell reports it.
"""

from __future__ import annotations

import contextlib
import signal
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from types import FrameType

# What `signal.signal` returns and accepts: a handler, SIG_DFL / SIG_IGN, or None (set outside Python).
Handler = Callable[[int, FrameType | None], object] | int | signal.Handlers | None

NAMES = {"SIGINT": "interrupted", "SIGTERM": "terminated", "SIGHUP": "hung up"}


class Stopped(BaseException):
    """The run was stopped by a signal. A BaseException, so that no `except Exception` swallows it."""

    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum = signum

    @property
    def exit_code(self) -> int:
        return 128 + self.signum

    @property
    def words(self) -> str:
        return NAMES.get(signal.Signals(self.signum).name, f"stopped by signal {self.signum}")


def _stop(signum: int, _frame: FrameType | None) -> None:
    raise Stopped(signum)


def install() -> dict[int, Handler]:
    """Make SIGINT, SIGTERM and SIGHUP raise `Stopped` in this process; returns the handlers they had."""
    previous: dict[int, Handler] = {}
    for name in NAMES:
        number = getattr(signal, name, None)
        if number is not None:
            # ValueError/OSError: not the main thread, or a platform that forbids it
            with contextlib.suppress(ValueError, OSError):
                previous[number] = signal.signal(number, _stop)
    return previous


@contextmanager
def stopping_on_signals() -> Iterator[None]:
    """`install` for the duration of a block (the command line), then the earlier handlers again."""
    previous = install()
    try:
        yield
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)
