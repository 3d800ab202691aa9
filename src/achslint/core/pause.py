"""Points where long work on one thread may give way: the language server's worker lints on its own thread
and, at these points, lets the editor's requests be answered first (or stops a lint whose text changed
meanwhile, by raising). Set per thread (`set_hook`); the command line sets none, and then a pause costs
one attribute lookup."""

from __future__ import annotations

import threading
from collections.abc import Callable

_here = threading.local()


def set_hook(hook: Callable[[], None] | None) -> None:
    """Call `hook` at every pause point on this thread (None: never)."""
    _here.pause = hook


def hook() -> Callable[[], None] | None:
    """This thread's hook, if it has one."""
    return getattr(_here, "pause", None)


def pause() -> None:
    """Give way, if this thread has a hook."""
    found = getattr(_here, "pause", None)
    if found is not None:
        found()
