"""Keep the code `dataclasses` compiles for the classes it makes, so that the next run need not compile it.

On Python 3.11 `@dataclass` writes each method it adds (`__init__`, `__repr__`, `__eq__`, `__hash__`,
and `__setattr__` / `__delattr__` for frozen classes) as source text and compiles that text while the class
is made: for the ~70 dataclasses a `lint` of one list loads, that is a fifth of the instructions of its cold
start (valgrind; `benchmarks/run --only cold` times it). Compiled code depends only on the text and on the Python that compiled it,
so the command line (`achslint.cli`) keeps it between runs: keyed by the text itself, in a file named after
the Python version, in the private per-user folder that also holds Lark's grammar cache. A text not found
there is compiled as before, and added to the file when the process ends.

Nothing can go stale (a changed class writes a different text, a different Python a different file), and a
missing, unreadable or damaged file only means compiling again. The file holds code objects, so it is read
only from a folder that belongs to the user and that no one else can write to, as Lark's cache is.
"""

from __future__ import annotations

import atexit
import contextlib
import dataclasses
import marshal
import os
import stat
import sys
from types import CodeType
from typing import Any

# Above this size the file is written anew with only what the run that writes it used: edits to the classes
# leave texts behind that no run asks for any more. Every run reads the whole file (a lint uses ~450 texts,
# 0.4 MB; reading 2 MB was 9 M instructions of its cold start), so it is kept to what the commands use.
MAX_BYTES = 1 << 20

_installed = False


def private_folder() -> str | None:
    """The per-user cache folder (`$XDG_CACHE_HOME/achslint`, else `~/.cache/achslint`), created if missing;
    None when it cannot be made or when anyone but the user could write to it."""
    given = os.environ.get("XDG_CACHE_HOME", "")
    # A relative XDG_CACHE_HOME is to be ignored (XDG base directory spec): it would put the cache in the cwd.
    base = given if os.path.isabs(given) else os.path.join(os.path.expanduser("~"), ".cache")
    folder = os.path.join(base, "achslint")
    try:
        os.makedirs(folder, mode=0o700, exist_ok=True)
        info = os.stat(folder)
    except OSError:
        return None
    if (hasattr(os, "getuid") and info.st_uid != os.getuid()) or info.st_mode & 0o022:
        return None
    return folder


def cache_path(folder: str) -> str:
    """The file for this Python: compiled code and its marshal format belong to one interpreter version."""
    tag = sys.implementation.cache_tag or sys.implementation.name
    return os.path.join(folder, f"dataclass-code-{tag}-{sys.hexversion:x}.marshal")


class CodeCache:
    """Compiled dataclass methods by their source text: those in the file at `path`, and those compiled since.

    The file maps each text to its code in marshal's bytes, and a code object is made from them only when a
    class asks for that text: a run reads the whole file but unpacks only what it uses.
    """

    def __init__(self, path: str) -> None:
        self.path = path
        self.stored = _read(path)
        self.added: dict[str, bytes] = {}
        self.found: set[str] = set()  # texts this run took from the file
        self.made: dict[str, CodeType] = {}  # code this run has made, by text (two classes may share one)
        self.compiled = 0  # texts not found in the file (or found damaged)

    def code(self, source: str) -> CodeType:
        code = self.made.get(source)
        if code is None:
            code = self.made[source] = self._make(source)
        return code

    def _make(self, source: str) -> CodeType:
        stored = self.stored.get(source)
        if type(stored) is bytes:
            with contextlib.suppress(EOFError, ValueError, TypeError):
                code = marshal.loads(stored)
                if type(code) is CodeType:
                    self.found.add(source)
                    return code
        # What exec(source) compiles: file name "<string>", and no __future__ flags from this module.
        code = compile(source, "<string>", "exec", dont_inherit=True)
        self.compiled += 1
        self.added[source] = marshal.dumps(code)
        return code

    def exec(self, source: Any, *args: Any, **kwargs: Any) -> None:
        """`exec` as `dataclasses` calls it, with a text's code taken from the cache."""
        exec(self.code(source) if type(source) is str else source, *args, **kwargs)

    def save(self) -> None:
        """Write the file again when this run compiled something (atomically; failures are ignored)."""
        if not self.compiled:
            return
        data = marshal.dumps({**self.stored, **self.added})
        if len(data) > MAX_BYTES:  # texts of classes since changed pile up: keep only what this run used
            data = marshal.dumps({**{text: self.stored[text] for text in self.found}, **self.added})
        temporary = f"{self.path}.{os.getpid()}.tmp"  # one per process: runs at once do not mix their bytes
        try:
            with open(temporary, "wb") as stream:
                stream.write(data)
            os.replace(temporary, self.path)
        except BaseException as exc:  # a failed write, or Ctrl-C at exit: no temporary file left behind
            with contextlib.suppress(OSError):
                os.unlink(temporary)
            if not isinstance(exc, OSError):
                raise


def _read(path: str) -> dict[str, bytes]:
    """The texts and their code's bytes in the file; empty when it is missing, too large or not what this
    module writes."""
    try:
        # Opened without blocking, and read only when it is a regular file: a FIFO (or a link to a device) put
        # in its place must not make every run hang (or read without end).
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0))
        with os.fdopen(fd, "rb") as stream:
            if not stat.S_ISREG(os.fstat(stream.fileno()).st_mode):
                return {}
            data = stream.read(MAX_BYTES + 1)
        table = marshal.loads(data) if len(data) <= MAX_BYTES else None
    except (OSError, EOFError, ValueError, TypeError):
        return {}
    # Not filtered entry by entry (a tenth of a lint's 450 lookups' cost): only a text (a str key) is ever
    # looked up, and a value that is not marshal's bytes of a code object is compiled again (`_make`).
    return table if isinstance(table, dict) else {}


def install() -> CodeCache | None:
    """Let `dataclasses` take its compiled methods from the cache for the rest of this process, and save
    what it compiled at exit. Does nothing (None) when already done or when there is no private folder."""
    global _installed
    if _installed:
        return None
    folder = private_folder()
    if folder is None:
        return None
    cache = CodeCache(cache_path(folder))
    # `dataclasses` calls `exec` by its global name: a module attribute of that name is found before the
    # built-in. The code run is what compiling the same text gives, so the classes are the same.
    dataclasses.exec = cache.exec  # type: ignore[attr-defined]
    atexit.register(cache.save)
    _installed = True
    return cache
