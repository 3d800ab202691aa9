"""One thread that does the language server's slow work, in the order it was asked for.

Linting a large list takes seconds; on the message loop it would hold back every answer. The
server hands that work (lints, fix-all, formatting, the session's bookkeeping) to this thread
and keeps answering hovers and completions from the last analysis meanwhile. Everything that
touches the `Session` runs here, one job at a time, so the session needs no locks.

Lints are coalesced: asking again for a document whose lint has not started yet replaces the
text to lint, it does not queue a second lint.

The message loop goes first. Python runs one thread at a time: a lint that runs while the loop
answers a hover takes turns with it, and the hover waits. So the worker stops at its pause points
(before each rule, `engine.pause_between_rules`, and every few thousand lines of a parse) while
the loop has work (`Gate`: a message read and not yet handled, or the loop not waiting in its
selector), and a lint whose text was edited meanwhile ends there (`Superseded`): the newer text is
linted next. This module does not import pygls.
"""

from __future__ import annotations

import contextlib
import selectors
import threading
import time
from collections import deque
from collections.abc import Callable, Iterator
from concurrent.futures import Future
from typing import Any, Generic, TypeVar

from ..linting import engine

_T = TypeVar("_T")
_Item = TypeVar("_Item")


PAUSE_LIMIT = 0.05  # seconds one pause waits at most
JOB_PAUSES = 1.0  # seconds one job gives way at most: a loop kept busy (a flood of messages) never starves it


class Superseded(BaseException):
    """A job's result is no longer wanted (its text was edited again): raised at a pause point.

    Not an `Exception`: no handler in the lint on the way up may take it for a failure."""


class Gate:
    """Whether the message loop has work to do: messages read and not yet handled, or the loop busy
    (not waiting in its selector: `WatchedSelector` tells)."""

    def __init__(self) -> None:
        self._changed = threading.Condition()
        self._frames = 0
        self._loop_busy = False

    @property
    def busy(self) -> bool:
        return self._frames > 0 or self._loop_busy

    def read(self) -> None:
        """A message was read (the reader thread)."""
        with self._changed:
            self._frames += 1

    def taken(self) -> None:
        """The loop took a message read."""
        with self._changed:
            self._frames -= 1

    def loop(self, busy: bool) -> None:
        with self._changed:
            self._loop_busy = busy
            if not self.busy:
                self._changed.notify_all()

    def wait(self) -> float:
        """Wait (at most `PAUSE_LIMIT` seconds) until the loop has nothing to do; the seconds waited."""
        if not self.busy:
            return 0.0
        started = time.monotonic()
        with self._changed:
            self._changed.wait_for(lambda: not self.busy, PAUSE_LIMIT)
        return time.monotonic() - started


class WatchedSelector(selectors.DefaultSelector):
    """The event loop's selector, telling the gate when the loop waits (nothing ready to run) and when it
    runs again."""

    def __init__(self, gate: Gate) -> None:
        super().__init__()
        self._gate = gate

    def select(self, timeout: float | None = None) -> Any:
        # a timeout of 0: callbacks are ready to run, the loop only polls; else it has nothing to do meanwhile
        self._gate.loop(timeout is not None and timeout <= 0)
        try:
            return super().select(timeout)
        finally:
            self._gate.loop(True)


class Worker:
    def __init__(self, name: str = "achslint-worker", gate: Gate | None = None) -> None:
        self._jobs: deque[tuple[Future[object], Callable[[], object]]] = deque()
        self._ready = threading.Condition()
        self._stopping = False
        self._running = False
        self._gate = gate
        self._stale: Callable[[], bool] | None = None
        self._paused = 0.0  # seconds the running job gave way so far
        self._thread = threading.Thread(target=self._run, name=name, daemon=True)
        self._thread.start()

    @contextlib.contextmanager
    def superseded_when(self, stale: Callable[[], bool]) -> Iterator[None]:
        """Within it (on the worker, in a job), a pause point raises `Superseded` once `stale()` is true."""
        self._stale = stale
        try:
            yield
        finally:
            self._stale = None

    def _pause(self) -> None:
        if self._gate is not None and self._paused < JOB_PAUSES:
            self._paused += self._gate.wait()
        stale = self._stale
        if stale is not None and stale():
            raise Superseded

    def submit(self, job: Callable[[], _T]) -> Future[_T]:
        """Run `job` after the jobs before it; its result (or exception) arrives in the future."""
        future: Future[_T] = Future()
        with self._ready:
            if self._stopping:
                future.cancel()
                return future
            self._jobs.append((future, job))  # type: ignore[arg-type]  # a Future[_T] is read as one
            self._ready.notify()
        return future

    @property
    def idle(self) -> bool:
        """Nothing running, nothing queued."""
        return not self._running and not self._jobs

    def stop(self, timeout: float = 1.0) -> None:
        """Cancel the jobs not started and wait (up to `timeout`) for the running one to end."""
        with self._ready:
            self._stopping = True
            while self._jobs:
                self._jobs.popleft()[0].cancel()
            self._ready.notify()
        if threading.current_thread() is not self._thread:
            self._thread.join(timeout)

    def _run(self) -> None:
        engine.pause_between_rules(self._pause)
        while True:
            with self._ready:
                while not self._jobs and not self._stopping:
                    self._ready.wait()
                if not self._jobs:
                    return
                future, job = self._jobs.popleft()
                self._running = True
            self._paused = 0.0
            try:
                self._pause()  # the message loop first: a request read with the edit is answered before its lint
                if not future.set_running_or_notify_cancel():
                    continue
                try:
                    result = job()
                except BaseException as exc:  # handed to whoever waits for the job
                    future.set_exception(exc)
                else:
                    future.set_result(result)
            finally:
                self._running = False


class Latest(Generic[_Item]):
    """The newest item asked for per key, taken once by the job that handles it (lint coalescing)."""

    def __init__(self) -> None:
        self._items: dict[str, _Item] = {}
        self._lock = threading.Lock()

    def put(self, key: str, item: _Item) -> bool:
        """Keep `item` for `key`; True when nothing was waiting for it (a job must be queued)."""
        with self._lock:
            first = key not in self._items
            self._items[key] = item
            return first

    def waiting(self, key: str) -> bool:
        """Whether an item for `key` waits (a newer one, when a job for the key is running)."""
        return key in self._items

    def take(self, key: str) -> _Item | None:
        with self._lock:
            return self._items.pop(key, None)

    def drop(self, key: str) -> None:
        with self._lock:
            self._items.pop(key, None)
