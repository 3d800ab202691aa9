"""The machine scenario: one TOML file for the dry-run of a whole machine.

Machine-wide defaults at the top (any key of the single-axis scenario, see scenario.py), then one table per
programmed axis name with the same keys; a key of an axis table wins over the machine-wide one, a `[drive]`
table as a whole:

    cycle_time_ms = 1.0             # machine-wide only: the CNC has one cycle
    hardware_latch = true           # a default for every axis

    [axes.Z]
    start_position = -20.0
    cam = [-120.0, -100.0]
    limit_switches = [-400.0, 50.0]

    [axes.X]
    start_position = 300.0

Every table is validated like a single-axis scenario (finite numbers, known keys named at their level), and
every message names the file and the table. Axis names are matched without regard to case; a name the
machine does not have is an error with the closest names the machine does have.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..core.tomlfile import read_toml
from ..homing.scenario import ScenarioError, parse_input

MACHINE_WIDE = ("cycle_time_ms",)  # keys that only make sense for the whole machine


def scenario_keys() -> list[str]:
    """The keys a single-axis scenario (and so every table of a machine scenario) may hold."""
    from ..homing.scenario_input import ScenarioInput

    return list(ScenarioInput.model_fields)


@dataclass
class MachineScenario:
    """Validated machine-wide defaults and per-axis tables (raw TOML values, names upper case)."""

    where: str = "machine scenario"  # the file (or "command line"), for messages
    defaults: dict[str, Any] = field(default_factory=dict)
    axes: dict[str, dict[str, Any]] = field(default_factory=dict)
    # [names]: programmed name -> logical axis number, for a machine without a channel list
    names: dict[str, int] = field(default_factory=dict)
    _parsed: dict[str, Any] = field(default_factory=dict, repr=False)

    @property
    def cycle_time_ms(self) -> float | None:
        value = self.defaults.get("cycle_time_ms")
        return float(value) if value is not None else None

    def table(self, name: str) -> str:
        """How messages name the table of an axis: `machine.toml: [axes.X]`."""
        return f"{self.where}: [axes.{name}]"

    def given(self, name: str) -> Any:
        """The ScenarioInput of an axis: the machine-wide keys, then its own table (validated, cached)."""
        key = name.upper()
        if key not in self._parsed:
            merged = {**self.defaults, **self.axes.get(key, {})}
            where = self.table(key) if key in self.axes else self.where
            self._parsed[key] = parse_input(merged, where) if merged else None
        return self._parsed[key]

    def check_names(self, names: Iterable[str]) -> None:
        """Every `[axes.NAME]` must name an axis of the machine; otherwise a ScenarioError with a did-you-mean."""
        known = sorted({n.upper() for n in names})
        for name in self.axes:
            if name in known:
                continue
            close = difflib.get_close_matches(name, known, n=3, cutoff=0.5)
            hint = f"; did you mean {', '.join(f'[axes.{c}]' for c in close)}?" if close else ""
            raise ScenarioError(
                f"{self.table(name)}: the machine has no axis {name} "
                f"(its axes: {', '.join(known) or 'none'}){hint}"
            )


def parse_machine_scenario(
    data: Mapping[str, Any], where: str, base: Mapping[str, Any] | None = None
) -> MachineScenario:
    """A MachineScenario from parsed TOML; `base` holds machine-wide defaults from elsewhere (configuration)
    that the file's own keys override. Any problem is a ScenarioError naming `where` and the table."""
    if not isinstance(data, Mapping):
        raise ScenarioError(f"{where}: a machine scenario is a table of keys, not {type(data).__name__}")
    known = scenario_keys()
    unknown = [key for key in data if key not in known and key not in ("axes", "names")]
    if unknown:
        raise ScenarioError(
            f"{where}: unknown key `{unknown[0]}` (known: {', '.join(known)}, [names] and [axes.NAME] tables)"
        )
    names = _names(data.get("names", {}), where)
    defaults = {**(base or {}), **{k: v for k, v in data.items() if k not in ("axes", "names")}}
    if defaults:
        parse_input(defaults, where)
    tables = data.get("axes", {})
    if not isinstance(tables, Mapping):
        raise ScenarioError(
            f"{where}: `axes` holds one table per axis name ([axes.X], [axes.Z1]), not {type(tables).__name__}"
        )
    axes: dict[str, dict[str, Any]] = {}
    for name, table in tables.items():
        key = str(name).upper()
        label = f"{where}: [axes.{name}]"
        if not isinstance(table, Mapping):
            raise ScenarioError(
                f"{label}: an axis entry is a table of scenario keys, not {type(table).__name__}"
            )
        if key in axes:
            raise ScenarioError(
                f"{label}: axis {key} has two tables (names are not case-sensitive); merge them"
            )
        for wide in MACHINE_WIDE:
            if wide in table:
                raise ScenarioError(
                    f"{label}: `{wide}` is the same for the whole machine; set it at the top of the file"
                )
        parse_input(dict(table), label)
        axes[key] = dict(table)
    scenario = MachineScenario(where, defaults, axes, names)
    for name in axes:
        scenario.given(name)  # the merged table must be valid too (e.g. cam_jitter against the period)
    return scenario


AXIS_NAME = re.compile(r"[A-Z][A-Z0-9_]*")


def _names(table: object, where: str) -> dict[str, int]:
    """The [names] table: `X = 1` gives the axis with logical number 1 the programmed name X."""
    if not isinstance(table, Mapping):
        raise ScenarioError(
            f"{where}: `names` maps programmed axis names to logical axis numbers ([names] X = 1), "
            f"not {type(table).__name__}"
        )
    names: dict[str, int] = {}
    for raw, number in table.items():
        name = str(raw).upper()
        if not AXIS_NAME.fullmatch(name):
            raise ScenarioError(
                f"{where}: [names] `{raw}` is not an axis name (a letter, then letters or digits)"
            )
        if isinstance(number, bool) or not isinstance(number, int) or number < 1:
            raise ScenarioError(
                f"{where}: [names] {raw} = {number!r}: give the logical axis number (1, 2, ...)"
            )
        if name in names:
            raise ScenarioError(f"{where}: [names] names {name} twice (names are not case-sensitive)")
        if number in names.values():
            other = next(n for n, v in names.items() if v == number)
            raise ScenarioError(f"{where}: [names] gives logical axis {number} two names, {other} and {name}")
        names[name] = number
    return names


def read_machine_scenario(path: Path, base: Mapping[str, Any] | None = None) -> MachineScenario:
    return parse_machine_scenario(read_toml(path, "machine scenario", ScenarioError), str(path), base)


def machine_scenario_input(
    startup: Path, scenario: Path | None, config: Path | None = None
) -> tuple[MachineScenario, int, Path | None]:
    """The machine scenario, the CNC cycle (µs) and the configured `cnc-root` for a dry-run of a start-up
    list: the configuration's `scenario` table (found next to the start-up list, or `config`) as machine-wide
    defaults, then the file."""
    from ..linting.config import ConfigError, discover, load_file

    try:
        resolved = load_file(config) if config else discover(startup)
    except ConfigError as exc:
        raise ScenarioError(str(exc)) from None
    base = dict(resolved.settings.scenario)
    if base:
        parse_input(base, f"{resolved.path}: [scenario]")
    cycle, root = resolved.settings.cycle_time_us, resolved.cnc_root()
    if scenario is None:
        return MachineScenario(f"{resolved.path}: [scenario]" if base else "scenario", base, {}), cycle, root
    return read_machine_scenario(scenario, base), cycle, root
