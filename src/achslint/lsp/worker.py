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
the loop has work (`Gate`: bytes from the editor not read yet, a message read and not yet handled,
or the loop not waiting in its selector) and for a moment after each answer (the editor's turn to
read it), and a lint whose text was edited meanwhile ends there (`Superseded`): the newer text is
linted next. The processors count as much as the interpreter: on a machine with two of them and
other work, a thread woken to read a request or an answer waited milliseconds for one while the
lint ran; hence the wait for unread bytes, the editor's turn, and a worker that runs as batch work
(`background`). This module does not import pygls.
"""

from __future__ import annotations

import contextlib
import os
import select
import selectors
import threading
import time
from collections import deque
from collections.abc import Callable, Iterator
from concurrent.futures import Future
from typing import Any, BinaryIO, Generic, TypeVar

from ..linting import engine

_T = TypeVar("_T")
_Item = TypeVar("_Item")


PAUSE_LIMIT = 0.05  # seconds one pause waits at most
UNREAD_LOOK = 0.0002  # seconds between two looks at the editor's input from the pause points
UNREAD_CHECK = 0.0005  # seconds between two looks while the worker waits for bytes there to be read
ANSWER_TURN = 0.002  # seconds the worker waits after an answer, the editor reading it (`Gate.answered`)
JOB_PAUSES = 1.0  # seconds one job gives way at most: a loop kept busy (a flood of messages) never starves it


class Superseded(BaseException):
    """A job's result is no longer wanted (its text was edited again): raised at a pause point.

    Not an `Exception`: no handler in the lint on the way up may take it for a failure."""


class Gate:
    """Whether the message loop has work to do: bytes from the editor not read yet (`watch`), messages read and
    not yet handled, or the loop busy (not waiting in its selector: `WatchedSelector` tells); and, for
    `ANSWER_TURN` after an answer, the editor reading it."""

    def __init__(self) -> None:
        self._changed = threading.Condition()
        self._frames = 0
        self._loop_busy = False
        self._turn_ends = 0.0  # (time.monotonic) the editor's turn to read an answer lasts until then
        self._input: Any = None  # a select.poll on the editor's input, when it can be watched
        self._next_look = 0.0  # (time.monotonic) when `busy` looks at the input again
        self._last_look = False  # what it saw the last time

    @property
    def busy(self) -> bool:
        if self._frames > 0 or self._loop_busy:
            return True
        now = time.monotonic()
        return now < self._turn_ends or self._unread(now)

    def watch(self, stream: BinaryIO | None) -> None:
        """Count bytes waiting in `stream` (the editor's input; None: no longer) as the loop's work. The reader
        thread, woken by them, may wait for a processor while the worker holds one; the worker gives way as soon
        as they arrive, not only once the reader has read them."""
        self._input, self._next_look, self._last_look = None, 0.0, False
        poll = getattr(select, "poll", None)  # (not on Windows: nothing is watched there)
        if stream is None or poll is None:
            return
        try:
            fd = stream.fileno()
            poller = poll()
            poller.register(fd, select.POLLIN)
        except (AttributeError, OSError, ValueError):  # not a file (tests), or closed
            return
        self._input = poller

    def _unread(self, now: float | None = None) -> bool:
        """Whether bytes wait in the editor's input; with `now`, looked at once per `UNREAD_LOOK` at most (a
        lint of 50,000 lines passes 50,000 pause points: a system call at each would slow it down), the last
        look's answer meanwhile."""
        poller = self._input
        if poller is None:
            return False
        if now is not None:
            if now < self._next_look:
                return self._last_look
            self._next_look = now + UNREAD_LOOK
        try:
            found = any(events & select.POLLIN for _, events in poller.poll(0))
        except (OSError, ValueError, RuntimeError):  # (RuntimeError: polled on two threads at once)
            found = False
        self._last_look = found
        return found

    def answered(self) -> None:
        """An answer went out (the loop): the worker keeps off the processor for a moment, which the editor
        needs to read it. Resumed at once, the lint left the editor (on a machine with two processors and
        some other work) waiting milliseconds for one."""
        self._turn_ends = time.monotonic() + ANSWER_TURN

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
            if not busy and not self._frames:  # (during the editor's turn too: the worker waits for its end)
                self._changed.notify_all()

    def wait(self) -> float:
        """Wait (at most `PAUSE_LIMIT` seconds) until the loop has nothing to do; the seconds waited."""
        if not self.busy:
            return 0.0
        started = time.monotonic()
        limit = started + PAUSE_LIMIT
        with self._changed:
            while True:
                now = time.monotonic()
                if now >= limit:
                    break
                if self._frames > 0 or self._loop_busy:
                    self._changed.wait(limit - now)
                elif self._unread():  # (the reader has yet to take them: looked at again shortly)
                    self._changed.wait(min(UNREAD_CHECK, limit - now))
                elif now < self._turn_ends:
                    self._changed.wait(min(self._turn_ends, limit) - now)
                else:
                    break
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


def background() -> None:
    """Tell the system that the calling thread does batch work (Linux: SCHED_BATCH; elsewhere nothing changes).

    Its share of the processor stays the same; only, waking up, it no longer takes the processor from a thread
    that runs: the message loop about to answer, or the editor reading the answer. On a busy machine each such
    take-over cost that thread milliseconds."""
    policy = getattr(os, "SCHED_BATCH", None)
    if policy is None or not hasattr(os, "sched_setscheduler"):
        return
    with contextlib.suppress(OSError):  # (a system that refuses: the thread stays as it was)
        os.sched_setscheduler(0, policy, os.sched_param(0))


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
        if self._stopping:  # the server is going away: the running job ends here, not after its pauses
            raise Superseded
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
        """Cancel the jobs not started and wait (up to `timeout`) for the running one to end: at its next pause
        point, with `Superseded` (a lint held there while the loop shut down waited out its pauses: 1 s)."""
        with self._ready:
            self._stopping = True
            while self._jobs:
                self._jobs.popleft()[0].cancel()
            self._ready.notify()
        if threading.current_thread() is not self._thread:
            self._thread.join(timeout)

    def _run(self) -> None:
        background()
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
                try:
                    self._pause()  # the message loop first: a request read with the edit is answered before its lint
                except Superseded:  # stopped meanwhile
                    future.cancel()
                    continue
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
