"""The resolved axis: what the CNC ends up running for one axis.

The CNC fills an axis the same way each time, and so does this module:

1. its built-in default,
2. the default axis list (`default_achs_mds` of the start-up list), if any,
3. the axis list itself, where the later of two assignments wins,
4. parameter references (`P-AXIS-00212.0`) resolved to the referenced value,
5. the CNC's own load-time corrections (a homing type the drive cannot run,
   speeds above the limit for unreferenced axes, ...), each recorded as a
   `Correction` with the value written, the value used and the CNC message.

Values the CNC would reject (wrong type, out of range) do not count. Every
command reads this one object: the rules, `explain`, `dry-run`, `diff`, the
typed model and the editor. `written(path)` gives the value before the
corrections, `get(path)` the value the CNC uses.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TypedDict

from ..catalogue import AXIS_TYPE_CODES, Catalogue, Parameter, Value, catalogue, fill_indices
from ..syntax.parser import parse_bytes, path_pattern
from .analysis import Analysis, Reference, Setting, analyse
from .corrections import apply
from .drives import default_homing_type


@dataclass(frozen=True, slots=True)
class Origin:
    """Where a value came from: an assignment (in the list or the default list) or the default."""

    kind: str  # "list", "default list" or "default"
    setting: Setting | None = None
    file: str | None = None

    def __str__(self) -> str:
        if self.setting is None:
            return "default"
        where = f"line {self.setting.line.number}"
        return where if self.kind == "list" else f"{self.file} {where} (default list)"


DEFAULT_ORIGIN = Origin("default")


class CorrectionData(TypedDict):
    """A correction as JSON (`explain --format json`, `dry-run --format json`)."""

    parameter: str
    written: int | float | str | None
    used: int | float | str | None
    error: str
    reason: str
    source: str
    line: int | None


@dataclass(frozen=True, slots=True)
class Correction:
    """A value the CNC replaces while it loads the list, and the message it gives."""

    parameter: str  # canonical path
    written: Value | None  # the value of the layers (references resolved)
    used: Value  # the value the CNC runs with
    error: str  # the CNC message id, e.g. P-ERR-110421
    reason: str  # why, in our words
    origin: Origin = DEFAULT_ORIGIN

    def as_dict(self) -> CorrectionData:
        setting = self.origin.setting
        return {
            "parameter": self.parameter,
            "written": plain(self.written),
            "used": plain(self.used),
            "error": self.error,
            "reason": self.reason,
            "source": self.origin.kind,
            "line": setting.line.number if setting else None,
        }


def plain(value: Value | None) -> int | float | str | None:
    """A value for JSON and tables: booleans as 0 and 1, as lists write them."""
    return int(value) if isinstance(value, bool) else value


def numeric(value: Value | None, path: str) -> float:
    """A numeric parameter's value as stored (int, float, or a bool as 0/1); TypeError for anything else.

    Every numeric parameter has a number: a converted value or its catalogue default. A parameter without
    one (no default, or a symbol without a code) is a catalogue error, not a list error.
    """
    if isinstance(value, (int, float)):
        return value
    raise TypeError(f"{path} has no numeric value ({value!r})")


class ResolvedAxis:
    """Typed values of one axis by canonical concrete path, after layering, references and corrections."""

    def __init__(
        self, analysis: Analysis, defaults: Analysis | None = None, cat: Catalogue | None = None
    ) -> None:
        self.catalogue = cat or catalogue()
        self.analysis = analysis
        self._values: dict[str, Value | Reference] = {}
        # The assignment that won per path, and those of the default list. An `Origin` is made when first
        # asked for (few are): making one per assignment was most of the cost of building the axis.
        self._assigned: dict[str, Setting] = {}
        self._from_defaults: dict[str, Setting] = {}
        self._default_name = defaults.file.name if defaults else None
        self._list_name = analysis.file.name
        self._origins: dict[str, Origin] = {}
        self._stages: dict[str, set[int]] | None = None
        self._corrected: dict[str, Correction] = {}
        # Answers of `get` and `written` per path, and the axis, drive and homing type: the rules and the
        # homing strategies ask the same few values over and over. A correction changes what they answer,
        # so `correct` forgets them all.
        self._used: dict[str, Value | None] = {}
        self._written: dict[str, Value | None] = {}
        self._axis_type: str | None = None
        self._drive_type: int | None = None
        self._homing_type: str | None = None
        values, assigned = self._values, self._assigned
        if defaults:
            for setting in defaults.settings:
                path = setting.canonical  # not None for known settings
                if path is not None and not setting.problems and setting.value is not None:
                    values[path] = setting.value
                    assigned[path] = setting
            self._from_defaults = dict(assigned)
        for setting in analysis.settings:
            path = setting.canonical
            if path is not None and not setting.problems and setting.value is not None:
                values[path] = setting.value
                assigned[path] = setting
        apply(self)

    # -- lookups ---------------------------------------------------------------------------
    def parameter(self, path: str) -> Parameter:
        resolved = self.catalogue.resolve(path)
        if resolved is None:
            pattern, _ = path_pattern(path)
            raise KeyError(f"not a catalogue parameter: {path} ({pattern})")
        return resolved.parameter

    def get(self, path: str) -> Value | None:
        """The value the CNC uses (typed): corrected, references followed, the default when unset."""
        used = self._used
        if path in used:
            return used[path]
        correction = self._corrected.get(path)
        value = used[path] = correction.used if correction is not None else self.written(path)
        return value

    def number(self, path: str) -> float:
        """The value the CNC uses of a numeric parameter (see `numeric`)."""
        return numeric(self.get(path), path)

    def written_number(self, path: str) -> float:
        """The value of a numeric parameter before the CNC's corrections (see `numeric`)."""
        return numeric(self.written(path), path)

    def written(self, path: str, _depth: int = 0) -> Value | None:
        """The value before the CNC's corrections (references followed, the default when unset)."""
        if _depth:  # a step along a chain of references: its answer depends on the depth (cycles)
            return self._written_now(path, _depth)
        written = self._written
        if path in written:
            return written[path]
        value = written[path] = self._written_now(path, 0)
        return value

    def _written_now(self, path: str, depth: int) -> Value | None:
        value = self._values.get(path)
        if value is None:
            return self.parameter(path).typed_default
        if isinstance(value, Reference):
            return self._follow(path, value, depth)
        return value

    def referenced(self, path: str, reference: Reference) -> str:
        """The canonical concrete path a reference written at `path` points to (`P-AXIS-00212.0`)."""
        target = self.catalogue.by_id[reference.target]
        count = target.path.count("[i]")
        if count:
            _, own = path_pattern(path)
            indices = (
                ((reference.index,) + (0,) * (count - 1))
                if reference.index is not None
                else (own + (0,) * count)[:count]
            )
        else:
            indices = ()
        return fill_indices(target.path, indices)

    def _follow(self, path: str, reference: Reference, depth: int) -> Value | None:
        if depth > 8:  # a reference cycle; LIS205 reports self-references
            return self.parameter(path).typed_default
        concrete = self.referenced(path, reference)
        correction = self._corrected.get(concrete)
        return correction.used if correction is not None else self.written(concrete, depth + 1)

    def origin(self, path: str) -> Origin:
        made = self._origins.get(path)
        if made is None:
            setting = self._assigned.get(path)
            if setting is None:
                return DEFAULT_ORIGIN
            if self._from_defaults.get(path) is setting:
                made = Origin("default list", setting, self._default_name)
            else:
                made = Origin("list", setting, self._list_name)
            self._origins[path] = made
        return made

    def setting(self, path: str) -> Setting | None:
        """The assignment that produced the value, if it was set in a list."""
        return self._assigned.get(path)

    def is_set(self, path: str) -> bool:
        return path in self._assigned

    def in_list(self, path: str) -> Setting | None:
        """The assignment in the axis list itself (not the default list), if any."""
        setting = self._assigned.get(path)
        return None if setting is None or self._from_defaults.get(path) is setting else setting

    def set_paths(self) -> list[str]:
        """Canonical paths assigned in the list or the default list."""
        return list(self._assigned)

    def gear_stages_set(self, *members: str) -> list[int]:
        """Gear stages (0..5) in which any of the given `getriebe[i].…` members is set."""
        if self._stages is None:
            self._stages = {}
            for path in self._assigned:
                if not path.startswith("getriebe["):  # the pattern below begins with it: cheap to skip
                    continue
                pattern, indices = path_pattern(path)
                if pattern.startswith("getriebe[i].") and indices:
                    self._stages.setdefault(pattern[len("getriebe[i].") :], set()).add(indices[0])
        stages: set[int] = set()
        for member in members:
            stages |= self._stages.get(member, set())
        return sorted(stages)

    # -- corrections ---------------------------------------------------------------------------
    def correct(self, path: str, used: Value, error: str, reason: str) -> None:
        """Record a load-time correction of the CNC (called by `corrections.apply`)."""
        self._corrected[path] = Correction(path, self.written(path), used, error, reason, self.origin(path))
        self._used.clear()  # what was worked out before may have read the value corrected now
        self._written.clear()
        self._axis_type = self._drive_type = self._homing_type = None

    @property
    def corrections(self) -> list[Correction]:
        return list(self._corrected.values())

    def correction(self, path: str) -> Correction | None:
        return self._corrected.get(path)

    # -- the axis as a whole -----------------------------------------------------------------
    @property
    def axis_type(self) -> str:
        """ "T" (linear), "R" (rotary) or "S" (spindle); the CNC assumes linear when unset."""
        known = self._axis_type
        if known is None:
            value = self.get("kenngr.achs_typ")  # a symbol (ACHSTYP_ROTATOR)
            code = (
                self.parameter("kenngr.achs_typ").symbol_codes.get(value) if isinstance(value, str) else value
            )
            known = self._axis_type = AXIS_TYPE_CODES.get(code, "T") if isinstance(code, int) else "T"
        return known

    @property
    def drive_type(self) -> int:
        known = self._drive_type
        if known is None:
            known = self._drive_type = int(self.number("kenngr.antr_typ"))
        return known

    @property
    def drive_type_known(self) -> bool:
        return self.is_set("kenngr.antr_typ")

    def drive_name(self, code: int | None = None) -> str:
        code = self.drive_type if code is None else code
        return self.catalogue.drive_type_names.get(code, f"drive type {code}")

    @property
    def homing_type(self) -> str:
        """The homing type in force: as set (after corrections), or the drive type's default (P-AXIS-00299 table)."""
        known = self._homing_type
        if known is None:
            value = self.get("kenngr.homing.homing_type")
            if value is None or value == "DRIVE_DEFAULT":
                known = default_homing_type(self.drive_type)
            else:
                known = str(value)  # a symbol
            self._homing_type = known
        return known

    @property
    def homing_type_is_default(self) -> bool:
        return (
            not self.is_set("kenngr.homing.homing_type")
            or self.written("kenngr.homing.homing_type") == "DRIVE_DEFAULT"
        )


def resolve_bytes(
    data: bytes, name: str, defaults: bytes | None = None, defaults_name: str = "default list"
) -> ResolvedAxis:
    """The resolved axis of a list's bytes, with an optional default list (named `defaults_name` where a value
    comes from it) underneath."""
    default_analysis = analyse(parse_bytes(defaults, defaults_name)) if defaults is not None else None
    return ResolvedAxis(analyse(parse_bytes(data, name)), default_analysis)
