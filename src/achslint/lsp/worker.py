"""One thread that does the language server's slow work, in the order it was asked for.

Linting a large list takes seconds; on the message loop it would hold back every answer. The
server hands that work (lints, fix-all, formatting, the session's bookkeeping) to this thread
and keeps answering hovers and completions from the last analysis meanwhile. Everything that
touches the `Session` runs here, one job at a time, so the session needs no locks.

Lints are coalesced: asking again for a document whose lint has not started yet replaces the
text to lint, it does not queue a second lint. This module does not import pygls.
"""

from __future__ import annotations

import threading
from collections import deque
from collections.abc import Callable
from concurrent.futures import Future
from typing import Generic, TypeVar

_T = TypeVar("_T")
_Item = TypeVar("_Item")


class Worker:
    def __init__(self, name: str = "achslint-worker") -> None:
        self._jobs: deque[tuple[Future[object], Callable[[], object]]] = deque()
        self._ready = threading.Condition()
        self._stopping = False
        self._running = False
        self._thread = threading.Thread(target=self._run, name=name, daemon=True)
        self._thread.start()

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
        while True:
            with self._ready:
                while not self._jobs and not self._stopping:
                    self._ready.wait()
                if not self._jobs:
                    return
                future, job = self._jobs.popleft()
                self._running = True
            try:
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
