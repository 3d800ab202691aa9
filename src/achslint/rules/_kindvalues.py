"""What the kind rules (LIS7xx) and the machine rules about lists of other kinds (LIS519–LIS521) read from a
list: the value of each parameter as the CNC takes it (the last usable assignment), the axis slots of a
channel list, and the numbered entries of a table. A value the list family reports (wrong type, out of
range, a reference) is not read: that list's own finding says what is wrong with it."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..axis.analysis import analyse
from ..catalogue.kinds import STARTUP
from ..core.decode import UnreadableInput
from ..core.diagnostics import Diagnostic, Related, Severity
from ..core.files import shown_path
from ..machine.startup import entry_index
from ..syntax.parser import parse_bytes, path_pattern
from ._common import known_settings

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from ..catalogue import Catalogue
    from ..catalogue.kinds import Kind
    from ..machine.resolved import Machine
    from ..machine.startup import StartupEntry

Values = dict[str, "Setting"]  # canonical concrete path -> the assignment the CNC takes


def written(settings: Iterable[Setting]) -> Values:
    """The usable assignments by canonical path, the later one winning as in the CNC (LIS005 reports the
    repeat): typed without a problem and not a reference to another parameter."""
    found: Values = {}
    for setting, _, path in known_settings(settings):
        if isinstance(setting.value, (int, str)) and not setting.problems:
            found[path] = setting
    return found


def unusable(settings: Iterable[Setting]) -> set[str]:
    """The canonical paths whose last assignment `written` does not read (a wrong type, out of range, a
    reference): a rule that would take such a parameter's default instead stays silent."""
    last: dict[str, Setting] = {}
    for setting, _, path in known_settings(settings):
        last[path] = setting
    usable = written(last.values())
    return {path for path in last if path not in usable}


def read_settings(data: bytes, name: str, cat: Catalogue) -> list[Setting]:
    """The assignments of a list read from bytes (a list a start-up list names, for the machine rules).

    Raises `decode.UnreadableInput` when the bytes are not a text list."""
    return analyse(parse_bytes(data, name), cat).settings


def whole(setting: Setting | None) -> int | None:
    """A setting's value as a whole number (a BOOLEAN is none), or None."""
    value = setting.value if setting is not None else None
    return value if isinstance(value, int) and not isinstance(value, bool) else None


def entries(values: Values, pattern: str) -> dict[tuple[int, ...], Values]:
    """The assignments whose path pattern starts with `pattern` (`kw.ssfk.table[i].`), by their indices."""
    found: dict[tuple[int, ...], Values] = {}
    for path, setting in values.items():
        shape, indices = path_pattern(path)
        if shape.startswith(pattern):
            found.setdefault(indices[: pattern.count("[i]")], {})[shape[len(pattern) :]] = setting
    return found


@dataclass(frozen=True)
class Slot:
    """An axis slot of a channel list: `gruppe[0].achse[2]` (a path axis) or `spindel[1]` (a spindle)."""

    path: str
    spindle: bool
    index: int  # the channel-internal axis index (the slot's last index)
    number: Setting | None  # its log_achs_nr (P-CHAN-00035 / P-CHAN-00036)
    name: Setting | None  # its bezeichnung (P-CHAN-00006 / P-CHAN-00007)

    @property
    def logical_number(self) -> int | None:
        """The logical axis number the slot gives; None when it gives none (0 leaves a path-axis slot empty)."""
        number = whole(self.number)
        return number if number else None

    @property
    def label(self) -> str:
        """`gruppe[0].achse[2] (Z, logical axis 3)`, for messages."""
        words = [f"`{self.name.value}`"] if self.name is not None else []
        if self.logical_number is not None:
            words.append(f"logical axis {self.logical_number}")
        return f"{self.path} ({', '.join(words)})" if words else self.path


_SLOTS = {"gruppe[i].achse[i].": False, "spindel[i].": True}


def slots(values: Values) -> list[Slot]:
    """The axis slots a channel list writes a logical axis number or a name for, path axes first, each in
    index order."""
    found: list[Slot] = []
    for pattern, spindle in _SLOTS.items():
        for indices, members in sorted(entries(values, pattern).items()):
            number, name = members.get("log_achs_nr"), members.get("bezeichnung")
            if number is None and name is None:
                continue
            path = pattern[:-1].replace("[i]", "[{}]").format(*indices)
            found.append(Slot(path, spindle, indices[-1], number, name))
    return found


def path_axes(values: Values, group: int = 0) -> dict[int, Slot]:
    """The path axes of a channel list's axis group by channel-internal axis index: the slots with a logical
    axis number other than 0."""
    prefix = f"gruppe[{group}]."
    return {
        slot.index: slot
        for slot in slots(values)
        if not slot.spindle and slot.path.startswith(prefix) and slot.logical_number is not None
    }


def at_setting(
    code: str,
    name: str,
    setting: Setting,
    severity: Severity,
    message: str,
    related: Iterable[Related] = (),
    value: bool = True,
) -> Diagnostic:
    """A machine-rule finding on an assignment of a list (its value, or its path when `value` is False)."""
    line = setting.line
    column = line.value_column if value else line.path_column
    text = (line.value if value else line.path) or ""
    return Diagnostic(
        name,
        line.number,
        column,
        line.number,
        column + max(len(text), 1),
        code,
        severity,
        message,
        parameter=setting.canonical,
        p_axis=setting.parameter.id if setting.parameter else None,
        related=tuple(related),
    )


def related_at(name: str, setting: Setting, note: str) -> Related:
    """A related location: an assignment of a list."""
    return Related(name, setting.line.number, setting.line.path_column, setting.canonical, note)


def shown(numbers: list[str], limit: int = 6) -> str:
    """`a, b, c and 4 more`: a list of names shortened for a message."""
    more = f" and {len(numbers) - limit} more" if len(numbers) > limit else ""
    return ", ".join(numbers[:limit]) + more


def loaded_settings(machine: Machine, entry: StartupEntry, what: str, kind: Kind) -> list[Setting] | None:
    """The assignments of the list a start-up entry names, read once for the machine; None when it cannot be
    read (LIS504 says why) or its kind has no catalogue."""
    loaded = machine.load(entry, what)
    cat = kind.catalogue()
    if loaded.data is None or entry.path is None or cat is None:
        return None
    try:
        return read_settings(loaded.data, shown_path(entry.path), cat)
    except UnreadableInput:
        return None


def startup_settings(machine: Machine) -> list[Setting] | None:
    """The assignments of the machine's start-up list (its entries beyond the lists the machine keeps:
    `achs_kw_log_ax_nr[i]`, `kanal_anzahl` ...), read once per machine through its reader; None when it has
    none or it cannot be read."""
    startup = machine.startup
    if startup is None:
        return None

    def read() -> list[Setting] | None:
        cat = STARTUP.catalogue()
        assert cat is not None
        try:
            return read_settings(startup.reader(startup.path), str(startup.path), cat)
        except (OSError, UnreadableInput):
            return None

    return machine.memo("startup settings", read)


@dataclass(frozen=True)
class Assignment:
    """A compensation list the CNC loads (`achs_kw[i]` below `zahl_kw`, P-STUP-00016/17) and its axis
    assignment (`achs_kw_log_ax_nr[i]`, P-STUP-00036)."""

    entry: StartupEntry
    key: str  # achs_kw_log_ax_nr[i]
    setting: Setting | None  # its usable assignment; None when not written (or not usable)
    unusable: bool  # written, but with a value the start-up list's own finding reports


def compensation_assignments(machine: Machine) -> list[Assignment]:
    """The compensation lists of the machine's start-up list the CNC loads, with their assignments (none when
    the start-up list names none or cannot be read)."""
    startup = machine.startup
    settings = startup_settings(machine) if startup is not None and startup.compensations else None
    if startup is None or settings is None:
        return []
    values, unread = written(settings), unusable(settings)
    found = []
    # The count as written decides, as for LIS504, LIS516 and LIS517: the entries at or above it are never
    # loaded (LIS516 says so), even when the count itself is out of range (the start-up list's own finding).
    for entry in startup.loaded_compensations():
        key = f"achs_kw_log_ax_nr[{entry_index(entry)}]"
        found.append(Assignment(entry, key, values.get(key), key in unread))
    return found
