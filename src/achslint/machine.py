"""Whole machines: several axis lists checked together (LIS501–LIS504).

A machine is the set of axis lists named by a start-up list (`hochlauf.lis`,
entries `achs_mds[i]`, with `default_achs_mds` applied under each of them the
way the CNC loads them), or else the axis lists of one folder. Each linted list
contributes a small summary (logical axis number, axis name, gantry settings,
with their lines); rules with a `check_machine(members, startups)` function
compare the summaries.
"""

from __future__ import annotations

import fnmatch
import re
from dataclasses import dataclass, field
from pathlib import Path

from .diagnostics import Diagnostic, Related, Severity
from .files import Scope, inside, not_a_list_file, read_list

STARTUP_NAMES = ("hochlauf*.lis", "startup*.lis")
_ENTRY = re.compile(r"achs_mds\[[0-9]+\]|default_achs_mds")


@dataclass
class StartupEntry:
    key: str
    raw: str
    line: int
    column: int
    path: Path | None  # resolved file, None when it does not exist or is not read
    refused: str | None = None  # why an existing file is not read (outside the machine's folder, a FIFO, ...)


@dataclass
class Startup:
    path: Path
    default: StartupEntry | None = None
    axes: list[StartupEntry] = field(default_factory=list)


def is_startup_list(path: Path) -> bool:
    return any(fnmatch.fnmatch(path.name.lower(), pattern) for pattern in STARTUP_NAMES)


_MISSING = ("no such file or directory", "a part of the path is not a folder", "a name too long for the file system",
            "a symbolic link to a file that does not exist")


def _resolve(raw: str, startup: Path, scope: Scope | None) -> tuple[Path | None, str | None]:
    """(file, None) for an entry achslint reads, (None, why) for one it refuses, (None, None) when it is missing.

    Relative entries are taken from the start-up list's folder; lists kept as `./listen/x.lis` next to a
    start-up list inside `listen/` (the SDK layout) are found from the parent folder too. Either way the
    file must lie in the start-up list's folder or below it, or under a path the user gave: a start-up
    list cannot make achslint read (and show) `/proc/self/environ` or `../../secret.lis`.
    """
    candidate = Path(raw.strip('"'))
    bases = (Path(),) if candidate.is_absolute() else (startup.parent, startup.parent.parent)
    for base in bases:
        target = base / candidate
        problem = not_a_list_file(target)
        if problem in _MISSING:
            continue
        if problem is not None:
            return None, f"it is {problem}" if problem.startswith("a ") else problem
        if not inside(target, startup.parent) and not (scope and scope.contains(target)):
            return None, f"it lies outside the start-up list's folder {startup.parent}"
        return target, None
    return None, None


def read_startup(path: Path, scope: Scope | None = None) -> Startup:
    """The entries of a start-up list. Raises `OSError` / `decode.UnreadableInput` when it cannot be read."""
    from .syntax import parse_bytes

    startup = Startup(path)
    for line in parse_bytes(read_list(path), str(path)).assignments():
        if not line.path_ok or line.value is None or not _ENTRY.fullmatch(line.path):
            continue
        found, refused = _resolve(line.value, path, scope)
        entry = StartupEntry(line.path, line.value, line.number, line.value_column, found, refused)
        if entry.key == "default_achs_mds":
            startup.default = entry
        else:
            startup.axes.append(entry)
    return startup


def summary(ctx) -> dict:
    """What the machine checks need from one axis list (small and picklable)."""
    values = ctx.values

    def at(path):
        setting = values.in_list(path)
        return (setting.line.number, setting.line.path_column) if setting else None

    return {
        "achs_nr": values.get("kopf.achs_nr"), "achs_nr_at": at("kopf.achs_nr"),
        "name": values.get("kopf.log_achs_name"), "name_at": at("kopf.log_achs_name"),
        "gantry_ax_nr": values.get("kenngr.gantry_ax_nr"), "gantry_at": at("kenngr.gantry_ax_nr"),
        "resettable": values.get("kenngr.gantry_max_diff_resetable"),
        "retraction": values.get("kenngr.homing.torq_retraction_distance"),
        "torq": values.homing_type == "TORQ",
        "axis_type": values.axis_type,
    }


def diagnostic(code: str, member: tuple[str, dict], where: str, message: str, severity: Severity,
               related: list[Related] | None = None) -> Diagnostic:
    """A machine-level diagnostic at a member list's line for `where` (or its first line)."""
    name, info = member
    line, column = info.get(where) or (1, 1)
    return Diagnostic(name, line, column, line, column + 1, code, severity, message, related=tuple(related or ()))


def unset_note(member: tuple[str, dict], where: str) -> str:
    """` (not written in this list: the default)` when the value comes from a default, else nothing."""
    return "" if member[1].get(where) else " (not written in this list, so the default applies)"


def first_uses(members: list[tuple[str, dict]], key: str):
    """(member, first member with the same value) for every repeated value of `key`."""
    first: dict = {}
    for member in members:
        value = member[1][key]
        if value in (None, "", 0):
            continue
        if value in first:
            yield member, first[value]
        else:
            first[value] = member
