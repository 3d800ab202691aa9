"""Lists on disk: which files achslint may read and write, and how it writes them.

Reading: only regular files. FIFOs, devices, sockets and the kernel's own file
systems (`/proc`, `/sys`, `/dev`) are refused, and a file is opened without
blocking, so a FIFO put in place of a list cannot make a run hang.

Writing (`fmt`, `lint --fix`) keeps the file what it was:

* a symbolic link is followed and its target rewritten; the link stays a link
  (whether the target may be written at all is decided by the caller, from the
  paths the user gave);
* a read-only file (no write permission for us, or no write bit for anyone,
  which is how people mark a file "do not touch") is refused, never replaced;
* a file with several hard links is rewritten in place, so that every name
  still shows the same content;
* otherwise the new content goes to a temporary file next to the target, gets
  the target's mode, owner and group, and is renamed over it, so a crash or a
  signal leaves the old file or the new one, never half of one. When the owner
  cannot be kept (someone else's file in a folder we may write), or the folder
  cannot take a temporary file, the file is rewritten in place instead;
* nothing is written when the file changed on disk since it was read.
"""

from __future__ import annotations

import codecs
import errno
import functools
import os
import stat
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

KERNEL_FILE_SYSTEMS = ("/proc", "/sys", "/dev")
XML_SUFFIXES = (".xml", ".xti", ".tsproj")  # TwinCAT exports and ISG XML lists (xmlinput.py)

_REASONS = {
    errno.ENOENT: "no such file or directory",
    errno.ELOOP: "a loop of symbolic links",
    errno.ENAMETOOLONG: "a name too long for the file system",
    errno.EACCES: "permission denied",
    errno.EPERM: "permission denied",
    errno.ENOTDIR: "a part of the path is not a folder",
    errno.EISDIR: "it is a folder, not a file",
}


class ChangedOnDisk(OSError):
    """The file is no longer what was read: someone edited, replaced or removed it meanwhile."""


class Refused(OSError):
    """achslint will not read or write this file; the message says why and what to do."""


def reason(exc: OSError) -> str:
    """A short phrase for why a file system call failed."""
    found = _REASONS.get(exc.errno) if exc.errno is not None else None
    return found or exc.strerror or str(exc)


def real_path(path: Path) -> Path:
    """`path` with every symbolic link resolved; as far as possible when a link loops or is broken."""
    try:
        return Path(os.path.realpath(path))
    except (OSError, RuntimeError, ValueError):
        return Path(os.path.abspath(path))


def inside(path: Path, root: Path) -> bool:
    """Whether `path`, links resolved, is `root` or lies below it."""
    target, base = real_path(path), real_path(root)
    return target == base or base in target.parents


def _kind(mode: int) -> str | None:
    """What a non-regular file is, in words; None for a regular file."""
    if stat.S_ISREG(mode):
        return None
    if stat.S_ISDIR(mode):
        return "a folder"
    if stat.S_ISFIFO(mode):
        return "a FIFO"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a regular file"


@functools.cache
def _kernel_file_systems() -> tuple[Path, ...]:
    return tuple(real_path(Path(root)) for root in KERNEL_FILE_SYSTEMS)


def not_a_list_file(path: Path) -> str | None:
    """Why `path` cannot be read as a list (missing, a loop, a FIFO, ...); None when it is a regular file."""
    try:
        info = os.stat(path)
    except OSError as exc:
        if exc.errno == errno.ENOENT and os.path.islink(path):
            return "a symbolic link to a file that does not exist"
        return reason(exc)
    except ValueError:  # a NUL byte in the name
        return "a name the file system cannot hold"
    kind = _kind(info.st_mode)
    if kind is not None:
        return f"{kind}, not a regular file"
    target = real_path(path)
    if any(target == root or root in target.parents for root in _kernel_file_systems()):
        return "a file of the operating system (/proc, /sys, /dev), not an axis list"
    return None


def is_xml(name: str) -> bool:
    """Whether a file name is one of the XML forms an axis list comes in (read by `xmlinput`)."""
    return name.lower().endswith(XML_SUFFIXES)


def is_folder(path: Path) -> bool:
    """Whether `path` is a folder (links followed); False for anything that cannot be looked at."""
    try:
        return stat.S_ISDIR(os.stat(path).st_mode)
    except (OSError, ValueError):
        return False


def read_list(path: Path, size: int = -1) -> bytes:
    """The bytes of a regular file (the first `size` of them, when given); `Refused` for anything else,
    without ever blocking on a FIFO."""
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    with os.fdopen(fd, "rb") as stream:
        kind = _kind(os.fstat(stream.fileno()).st_mode)
        if kind is not None:
            raise Refused(f"{path} is {kind}, not a regular file; not read")
        return stream.read(size)


def starts_with_bom(path: Path) -> bool:
    """Whether a regular file begins with the UTF-8 byte-order mark (False for anything unreadable)."""
    try:
        return read_list(path, len(codecs.BOM_UTF8)) == codecs.BOM_UTF8
    except (OSError, ValueError):  # Refused is an OSError; ValueError: a NUL byte in the name
        return False


@dataclass(frozen=True)
class Scope:
    """The files and folders the user named, with links resolved: what achslint may rewrite."""

    roots: tuple[Path, ...]

    @classmethod
    def of(cls, paths: Iterable[str | Path]) -> Scope:
        return cls(tuple(real_path(Path(p)) for p in paths if p != "-"))

    def contains(self, path: Path) -> bool:
        target = real_path(path)
        return any(target == root or root in target.parents for root in self.roots)


def write_atomically(path: Path, data: bytes, expected: bytes | None = None) -> None:
    """Replace the content of the list at `path` (see the module docstring for the rules).

    With `expected` (the bytes the new content was made from), nothing is written
    when the file changed or vanished in the meantime (`ChangedOnDisk`); a file
    that may not be written raises `Refused`.
    """
    target = real_path(path)
    try:
        info = os.stat(target)
    except FileNotFoundError:
        raise ChangedOnDisk(f"{path} was removed while achslint was working on it; nothing written") from None
    if not stat.S_ISREG(info.st_mode):
        raise Refused(f"{path} is {_kind(info.st_mode)}, not a regular file; not written")
    if not info.st_mode & 0o222 or not os.access(target, os.W_OK):
        raise Refused(f"{path} is read-only; not rewritten (make it writable if it should change)")
    if info.st_nlink > 1:
        _write_in_place(target, path, data, expected)
        return
    try:
        import tempfile  # only when writing (its imports cost more than linting a small list)

        handle, temporary = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".achslint", dir=target.parent)
    except PermissionError:  # a writable file in a folder we may not write: the file itself can still change
        _write_in_place(target, path, data, expected)
        return
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(data)
            stream.flush()
            os.fsync(stream.fileno())
        os.chmod(temporary, stat.S_IMODE(info.st_mode))
        if not _keep_owner(temporary, info):
            Path(temporary).unlink()
            _write_in_place(target, path, data, expected)
            return
        _check_unchanged(target, path, expected)
        os.replace(temporary, target)
    except BaseException:  # also KeyboardInterrupt and the exit signals: never leave the temporary file
        Path(temporary).unlink(missing_ok=True)
        raise


def _keep_owner(temporary: str, info: os.stat_result) -> bool:
    """Give the temporary file the owner and group of the original; False when that is not allowed."""
    current = os.stat(temporary)
    if (current.st_uid, current.st_gid) == (info.st_uid, info.st_gid) or not hasattr(os, "chown"):
        return True
    try:
        os.chown(temporary, info.st_uid, info.st_gid)
    except PermissionError:
        return False
    return True


def _check_unchanged(target: Path, shown: Path, expected: bytes | None) -> None:
    if expected is None:
        return
    try:
        current = target.read_bytes()
    except FileNotFoundError:
        raise ChangedOnDisk(
            f"{shown} was removed while achslint was working on it; nothing written"
        ) from None
    if current != expected:
        raise ChangedOnDisk(f"{shown} changed while achslint was working on it; nothing written, run again")


def _write_in_place(target: Path, shown: Path, data: bytes, expected: bytes | None) -> None:
    """Overwrite the file's own content (same inode: hard links, owner and mode stay as they are)."""
    with open(target, "r+b") as stream:
        if expected is not None and stream.read() != expected:
            raise ChangedOnDisk(
                f"{shown} changed while achslint was working on it; nothing written, run again"
            )
        stream.seek(0)
        stream.write(data)
        stream.truncate()
        stream.flush()
        os.fsync(stream.fileno())
