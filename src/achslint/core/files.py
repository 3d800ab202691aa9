"""Lists on disk: which files achslint may read and write, and how it writes them.

Reading: only regular files, and only up to a size limit per kind of file (a list,
an NC program, a TOML file). FIFOs, devices, sockets and the kernel's own file
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
* a rewrite in place keeps the old bytes: when the file system stops it part-way
  (disk full, quota, file-size limit), or a signal (Ctrl-C) ends the run in the
  middle of it, they are written back and the file cut to its old length, and
  the error says so;
* nothing is written when the file changed on disk since it was read.
"""

from __future__ import annotations

import codecs
import errno
import functools
import os
import stat
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar
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


def shown_path(path: Path) -> str:
    """A path as reports show it: relative to the working directory when it lies below it."""
    try:
        return str(path.relative_to(Path.cwd()))
    except ValueError:
        return str(path)


def real_path(path: Path) -> Path:
    """`path` with every symbolic link resolved; as far as possible when a link loops or is broken."""
    resolved = _RESOLVED.get()
    if resolved is None:
        return _resolve_links(path)
    known = resolved.get(path)
    if known is None:
        known = _resolve_held(path, resolved)
    return known


def _resolve_links(path: Path) -> Path:
    try:
        return Path(os.path.realpath(path))
    except (OSError, RuntimeError, ValueError):
        return Path(os.path.abspath(path))


def _resolve_held(path: Path, resolved: dict[Path, Path]) -> Path:
    """`real_path` while `links_held` is in force: a path is its folder's resolution (found once, and kept
    for the other files of that folder) and its own name, unless that name is a link itself, so a file
    costs one `lstat` instead of one per part of its path. The same answer as `os.path.realpath`, which
    resolves part by part from the left and keeps a part that is no link as it is."""
    if os.name != "posix":  # only POSIX resolves a path part by part (Windows asks the file system)
        resolved[path] = real = _resolve_links(path)
        return real
    chain: list[Path] = []
    current = path
    while current not in resolved:
        name, parent = current.name, current.parent
        if not name or name == ".." or parent == current:  # a root, `.`, or a step up: resolved whole
            resolved[current] = _resolve_links(current)
            break
        chain.append(current)
        current = parent
    real = resolved[current]
    for step in reversed(chain):
        real = resolved[step] = _one_more_part(real, step)
    return real


def _one_more_part(folder: Path, path: Path) -> Path:
    """`path` resolved, given its folder resolved (`folder`)."""
    candidate = folder / path.name
    try:
        link = stat.S_ISLNK(os.lstat(candidate).st_mode)
    except OSError:  # missing, a loop on the way, not allowed: realpath keeps the name as it is too
        link = False
    except ValueError:  # a NUL in the name: what `_resolve_links` gives for it
        return Path(os.path.abspath(path))
    return _resolve_links(path) if link else candidate


# The links resolved while `links_held` is in force, by the path asked about.
_RESOLVED: ContextVar[dict[Path, Path] | None] = ContextVar("resolved", default=None)


@contextmanager
def links_held() -> Iterator[None]:
    """Resolve each path's links once while this lasts: for the discovery of one run, which asks the same
    few hundred paths thousands of times whether they lie inside a folder (one `lstat` per part each time)
    and for which the files do not move under it."""
    token = _RESOLVED.set({})
    try:
        yield
    finally:
        _RESOLVED.reset(token)


def inside(path: Path, root: Path) -> bool:
    """Whether `path`, links resolved, is `root` or lies below it."""
    return _at_or_below(real_path(path), real_path(root))


def _at_or_below(target: Path, root: Path) -> bool:
    """`target == root or root in target.parents` for two resolved paths, compared as strings (building the
    parents as paths cost discovery a third of its time)."""
    one, other = os.path.normcase(target), os.path.normcase(root)
    return one == other or one.startswith(other if other.endswith(os.sep) else other + os.sep)


def same_file(first: Path, second: Path) -> bool:
    """Whether two paths name one file (links followed; hard links compared by device and inode). False
    when either cannot be looked at (a report file that does not exist yet is no input)."""
    try:
        one, other = os.stat(first), os.stat(second)
    except (OSError, ValueError):
        return False
    return (one.st_dev, one.st_ino) == (other.st_dev, other.st_ino)


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


@functools.cache
def _kernel_prefixes() -> tuple[tuple[str, ...], tuple[str, ...]]:
    """`_kernel_file_systems` as `_at_or_below` compares them: each root itself, and the start of a path
    below it (asked for every list a run looks at)."""
    roots = tuple(os.path.normcase(root) for root in _kernel_file_systems())
    return roots, tuple(root if root.endswith(os.sep) else root + os.sep for root in roots)


def _of_the_system(target: Path) -> bool:
    """Whether a resolved path is, or lies below, one of the kernel's file systems."""
    roots, below = _kernel_prefixes()
    one = os.path.normcase(target)
    return one in roots or one.startswith(below)


# What `not_a_list_file` says when there is no file to read at all (as opposed to one that is refused).
MISSING = (
    "no such file or directory",
    "a part of the path is not a folder",
    "a name too long for the file system",
    "a symbolic link to a file that does not exist",
)


def not_a_list_file(path: Path, *, limit: int | None = None, what: str = "a list") -> str | None:
    """Why `path` cannot be read as a list (missing, a loop, a FIFO, larger than `limit`, ...); None when it
    is a regular file achslint reads. `what` names the kind of file in the messages."""
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
    limit = LIST_LIMIT if limit is None else limit
    if info.st_size > limit:
        return f"a file larger than the {_megabytes(limit)} achslint reads for {what}"
    if _of_the_system(real_path(path)):
        return f"a file of the operating system (/proc, /sys, /dev), not {'an axis list' if what == 'a list' else what}"
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


MIB = 1 << 20
LIST_LIMIT = 64 * MIB  # an axis list is kilobytes; the largest real exports are a few megabytes
PROGRAM_LIMIT = 16 * MIB  # an NC homing program
SETTINGS_LIMIT = 4 * MIB  # a configuration file or a dry-run scenario (TOML)


def _megabytes(size: int) -> str:
    return f"{size // MIB:,} MB" if size % MIB == 0 else f"{size / MIB:,.1f} MB"


def read_list(path: Path, size: int = -1, *, limit: int = LIST_LIMIT, what: str = "a list") -> bytes:
    """The bytes of a regular file (the first `size` of them, when given); `Refused` for anything else,
    without ever blocking on a FIFO, and for a file larger than `limit` bytes (`what` names the kind of
    file in that message). At most `limit` + 1 bytes are ever read, so a file that grows while it is
    read, or one that reports no size (`/proc`), cannot make a run take unbounded memory."""
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    with os.fdopen(fd, "rb") as stream:
        info = os.fstat(stream.fileno())
        kind = _kind(info.st_mode)
        if kind is not None:
            raise Refused(f"{path} is {kind}, not a regular file; not read")
        if size >= 0:
            return stream.read(min(size, limit))
        if info.st_size > limit:
            raise _too_large(path, info.st_size, limit, what)
        data = stream.read(limit + 1)
        if len(data) > limit:
            raise _too_large(path, len(data), limit, what)
        return data


def read_program_file(path: Path) -> bytes:
    """The bytes of an NC program: `read_list`'s checks, with the size limit of a program."""
    return read_list(path, limit=PROGRAM_LIMIT, what="an NC program")


def _too_large(path: Path, size: int, limit: int, what: str) -> Refused:
    return Refused(
        f"{path} is {_megabytes(size)}, more than the {_megabytes(limit)} achslint reads for {what}; not read"
    )


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
        return any(_at_or_below(target, root) for root in self.roots)


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
        try:
            with os.fdopen(handle, "wb", buffering=0) as stream:
                _write_all(stream.fileno(), data)
                os.fsync(stream.fileno())
        except OSError as exc:  # the list itself was never touched
            raise WriteFailed(path, exc, UNCHANGED) from None
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


def write_output(path: Path, data: bytes) -> None:
    """Write a file a command makes (a report, a plot) at `path`, which the user named.

    A regular file (or a new one) gets its new content through a temporary file beside it that is renamed
    over it, so a full disk or a signal leaves the earlier file, never half of a new one (a link is
    followed; the link stays). A device or FIFO (a pipe), a name in /dev or /proc (`/dev/stdout`) is
    written as it is, and so is a file with several names or in a folder that cannot take a temporary
    file. Raises `OSError`.
    """
    try:
        info: os.stat_result | None = os.stat(path)
    except FileNotFoundError:
        info = None
        # A new file: its folder must exist as the system walks the path. `real_path` drops `missing/..` by
        # the letters, so `-o missing/../achsmds1.lis` would have replaced the input that `same_file` (which
        # asks the system) did not recognise: refused here as the shell's `>` refuses it.
        os.stat(os.path.dirname(path) or os.curdir)
    # `/dev/stdout` stands for what the shell opened, maybe a file `>>` appends to: appended to, never cut
    if any(_at_or_below(Path(os.path.abspath(path)), Path(root)) for root in KERNEL_FILE_SYSTEMS):
        _write_plainly(path, data, "ab")
        return
    if info is not None and (not stat.S_ISREG(info.st_mode) or info.st_nlink > 1):
        _write_plainly(path, data)
        return
    target = real_path(path)
    temporary = target.parent / f".{target.name}.{os.getpid()}.{os.urandom(4).hex()}.achslint"
    try:  # created as `open` would create the file (mode 0o666 less the umask), never over another file
        handle = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0), 0o666)
    except PermissionError:  # a folder we may not write: the file itself may still be writable
        _write_plainly(target, data)
        return
    try:
        with os.fdopen(handle, "wb", buffering=0) as stream:
            _write_all(stream.fileno(), data)
        if info is not None:
            os.chmod(temporary, stat.S_IMODE(info.st_mode))
        os.replace(temporary, target)
    except BaseException:  # also Ctrl-C and the exit signals: never leave the temporary file
        temporary.unlink(missing_ok=True)
        raise


def _write_plainly(target: Path, data: bytes, mode: str = "wb") -> None:
    with open(target, mode) as stream:
        stream.write(data)


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
    """Overwrite the file's own content (same inode: hard links, owner and mode stay as they are).

    The old bytes are kept in memory: when the write fails part-way (disk full, quota, file-size
    limit), they are written back over the blocks they had and the file is cut to its old length, so it
    is never left truncated or half new; `WriteFailed` then says whether that worked.
    """
    with open(target, "r+b", buffering=0) as stream:  # unbuffered: every failure surfaces here, not at close
        old = stream.readall()
        if expected is not None and old != expected:
            raise ChangedOnDisk(
                f"{shown} changed while achslint was working on it; nothing written, run again"
            )
        fd = stream.fileno()
        progress = [0]
        try:
            _write_all(fd, data, progress)
            os.ftruncate(fd, len(data))
            progress[0] = max(progress[0], len(old))  # a shorter text has cut the old tail off too
            os.fsync(fd)
        except OSError as exc:
            restored = _restore(fd, old, progress[0])
            raise WriteFailed(shown, exc, RESTORED if restored else DAMAGED) from None
        except BaseException:  # Ctrl-C or an exit signal part-way: the old bytes go back before the run ends
            # all of them: the signal may have come after a write returned and before `progress` counted it
            _restore(fd, old, max(progress[0], len(data), len(old)))
            raise


def _write_all(fd: int, data: bytes, progress: list[int] | None = None) -> None:
    """Write all of `data` from the start of the file (a short write is continued, an error raised);
    `progress[0]` says how many bytes are written when it stops."""
    view, offset = memoryview(data), 0
    while offset < len(view):
        offset += os.pwrite(fd, view[offset:], offset)
        if progress is not None:
            progress[0] = offset


def _restore(fd: int, old: bytes, written: int) -> bool:
    """Put `old` back as the whole content of an open file of which the first `written` bytes were
    overwritten (or cut off); whether that worked. Only those bytes are written again — a file-size limit
    inside the old content is not crossed again — and the file is cut back to its old length."""
    try:
        _write_all(fd, old[:written])
        os.ftruncate(fd, len(old))
        os.fsync(fd)
    except OSError:
        return False
    return True


UNCHANGED = "the list is unchanged"
RESTORED = "the list is unchanged (its old content was put back)"
DAMAGED = "its old content could not be put back either: restore it from version control or a backup"


class WriteFailed(OSError):
    """A rewrite the file system stopped (disk full, quota, file-size limit); the message says what state
    the file was left in."""

    def __init__(self, shown: Path, cause: OSError, outcome: str) -> None:
        super().__init__(cause.errno, f"cannot write {shown}: {reason(cause)}; {outcome}")
        self.outcome = outcome

    def __str__(self) -> str:
        return str(self.strerror)
