"""Effective values: what the CNC ends up with for every parameter of one axis.

The CNC fills an axis the same way each time: its built-in default, then the
default axis list (if the start-up list names one), then the axis list, where
the last assignment of a parameter wins. Values the CNC would reject (wrong
type, out of range) do not count. Parameter references (`P-AXIS-00212.0`) are
resolved to the referenced parameter's effective value.

`AxisValues` is what the cross-parameter rules, the strategy classification and
`explain` read; it also remembers which assignment produced each value, so
diagnostics can point at every line involved.
"""

from __future__ import annotations

from dataclasses import dataclass

from .analysis import Analysis, Reference, Setting
from .catalogue import AXIS_TYPE_CODES, Catalogue, Parameter, catalogue, fill_indices
from .syntax import path_pattern


@dataclass(frozen=True, slots=True)
class Origin:
    """Where an effective value came from: an assignment (in the list or the default list) or the default."""

    kind: str  # "list", "default list" or "default"
    setting: Setting | None = None
    file: str | None = None

    def __str__(self) -> str:
        if self.setting is None:
            return "default"
        where = f"line {self.setting.line.number}"
        return where if self.kind == "list" else f"{self.file} {where} (default list)"


DEFAULT_ORIGIN = Origin("default")


class AxisValues:
    """Effective, typed values of one axis, by canonical concrete path."""

    def __init__(self, analysis: Analysis, defaults: Analysis | None = None, cat: Catalogue | None = None):
        self.catalogue = cat or catalogue()
        self.analysis = analysis
        self._values: dict[str, object] = {}
        self._origins: dict[str, Origin] = {}
        self._stages: dict[str, set[int]] | None = None
        layers = [(defaults, "default list"), (analysis, "list")] if defaults else [(analysis, "list")]
        for layer, kind in layers:
            for setting in layer.settings:
                if setting.known and not setting.problems and setting.value is not None:
                    self._values[setting.canonical] = setting.value
                    self._origins[setting.canonical] = Origin(kind, setting, layer.file.name)

    # -- lookups ---------------------------------------------------------------------------
    def parameter(self, path: str) -> Parameter:
        pattern, _ = path_pattern(path)
        resolved = self.catalogue.resolve(path)
        if resolved is None:
            raise KeyError(f"not a catalogue parameter: {path} ({pattern})")
        return resolved.parameter

    def get(self, path: str, _depth: int = 0):
        """The effective value (typed), following references; the built-in default when unset."""
        value = self._values.get(path)
        if isinstance(value, Reference):
            return self._follow(path, value, _depth)
        if value is not None:
            return value
        return self.parameter(path).typed_default

    def _follow(self, path: str, reference: Reference, depth: int):
        if depth > 8:  # a reference cycle; LIS205 reports self-references
            return self.parameter(path).typed_default
        target = self.catalogue.by_id[reference.target]
        count = target.path.count("[i]")
        if count:
            _, own = path_pattern(path)
            indices = ((reference.index,) + (0,) * (count - 1)) if reference.index is not None else (own + (0,) * count)[:count]
        else:
            indices = ()
        return self.get(fill_indices(target.path, indices), depth + 1)

    def origin(self, path: str) -> Origin:
        return self._origins.get(path, DEFAULT_ORIGIN)

    def setting(self, path: str) -> Setting | None:
        """The assignment that produced the effective value, if it was set in a list."""
        return self._origins.get(path, DEFAULT_ORIGIN).setting

    def is_set(self, path: str) -> bool:
        return path in self._origins

    def in_list(self, path: str) -> Setting | None:
        """The assignment in the axis list itself (not the default list), if any."""
        origin = self._origins.get(path)
        return origin.setting if origin and origin.kind == "list" else None

    def gear_stages_set(self, *members: str) -> list[int]:
        """Gear stages (0..5) in which any of the given `getriebe[i].…` members is set."""
        if self._stages is None:
            self._stages = {}
            for path in self._origins:
                pattern, indices = path_pattern(path)
                if pattern.startswith("getriebe[i].") and indices:
                    self._stages.setdefault(pattern[len("getriebe[i]."):], set()).add(indices[0])
        stages: set[int] = set()
        for member in members:
            stages |= self._stages.get(member, set())
        return sorted(stages)

    # -- the axis as a whole -----------------------------------------------------------------
    @property
    def axis_type(self) -> str:
        """"T" (linear), "R" (rotary) or "S" (spindle); the CNC assumes linear when unset."""
        value = self.get("kenngr.achs_typ")
        codes = self.parameter("kenngr.achs_typ").symbol_codes
        return AXIS_TYPE_CODES.get(codes.get(value, value), "T")

    @property
    def drive_type(self) -> int:
        return int(self.get("kenngr.antr_typ"))

    @property
    def drive_type_known(self) -> bool:
        return self.is_set("kenngr.antr_typ")

    def drive_name(self, code: int | None = None) -> str:
        code = self.drive_type if code is None else code
        return self.catalogue.drive_type_names.get(code, f"drive type {code}")

    @property
    def homing_type(self) -> str:
        """The homing type in force: as set, or the drive type's default (P-AXIS-00299 table)."""
        value = self.get("kenngr.homing.homing_type")
        if value in (None, "DRIVE_DEFAULT"):
            return default_homing_type(self.drive_type)
        return value

    @property
    def homing_type_is_default(self) -> bool:
        return not self.is_set("kenngr.homing.homing_type") or self.get("kenngr.homing.homing_type") == "DRIVE_DEFAULT"


SERCOS, CANOPEN, SIMULATION = 2, 8, 4


def default_homing_type(drive_type: int) -> str:
    """The homing type a drive type uses when none is configured (P-AXIS-00299 table)."""
    return "DRIVE_CONTROLLED" if drive_type == SERCOS else "CNC_CONTROLLED"
