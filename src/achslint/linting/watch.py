"""`lint --watch`: wait until a file a run reads changes, by comparing modification times (no file-system
notification library: a poll every half second costs a few stat calls per list).

Watched: the files named and every file below the folders named (hidden folders such as `.git` left out),
the other files in a named file's folder (its machine: start-up list, neighbours, default list), and the
configuration files that apply (with those they extend). A file that appears or goes counts as a change.
"""

from __future__ import annotations

import contextlib
import os
import stat
import time
from collections.abc import Iterator
from pathlib import Path

from ..core.files import is_folder
from .config import ConfigError, discover, load_file

INTERVAL = float(os.environ.get("ACHSLINT_WATCH_INTERVAL", "0.5"))  # seconds between two looks

Stamp = tuple[int, int]  # (modification time in ns, size)


class Watcher:
    def __init__(
        self,
        paths: list[str],
        config_file: str | None = None,
        interval: float = INTERVAL,
        written: list[str] | None = None,
    ) -> None:
        self.paths = [Path(p) for p in paths if p != "-"]
        self.config_file = Path(config_file) if config_file else None
        self.interval = interval
        # What the run itself writes (its --output-file, the file standard output goes to) wakes no run: the
        # report written into the folder watched made it lint again without end.
        self.own: set[tuple[int, int]] = set()
        places: list[str | int] = [*(written or []), 1]
        for where in places:
            with contextlib.suppress(OSError, ValueError):
                info = os.stat(where)
                if stat.S_ISREG(info.st_mode):
                    self.own.add((info.st_dev, info.st_ino))
        self.seen = self.snapshot()

    def files(self) -> Iterator[Path]:
        for path in self.paths:
            if is_folder(path):
                for below, folders, names in os.walk(path):
                    folders[:] = sorted(f for f in folders if not f.startswith("."))
                    yield from (Path(below) / name for name in names)
                yield from self._configs(path)
                continue
            yield path
            folder = path.parent
            with contextlib.suppress(OSError):  # a folder that cannot be read: the file alone
                yield from (entry for entry in folder.iterdir() if not entry.name.startswith("."))
            yield from self._configs(path)

    def _configs(self, path: Path) -> Iterator[Path]:
        try:
            resolved = load_file(self.config_file) if self.config_file else discover(path)
        except ConfigError:  # the run said so; a fixed file counts as a change
            return
        if resolved.path is not None:
            yield resolved.path
        yield from resolved.extends

    def snapshot(self) -> dict[str, Stamp]:
        stamps: dict[str, Stamp] = {}
        for path in self.files():
            try:
                info = os.stat(path)
            except (OSError, ValueError):
                continue
            if (info.st_dev, info.st_ino) in self.own:
                continue
            stamps[str(path)] = (info.st_mtime_ns, info.st_size)
        return stamps

    def changed(self) -> bool:
        now = self.snapshot()
        if now == self.seen:
            return False
        self.seen = now
        return True

    def wait(self) -> None:
        """Return once something changed since the last look."""
        while not self.changed():
            time.sleep(self.interval)
