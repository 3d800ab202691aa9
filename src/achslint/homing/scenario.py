"""The machine geometry a dry run assumes: where the axis starts, where the cam,
the zero pulses, the limit switches and the fixed stop are.

A scenario is written in human units (mm for linear axes, degrees for rotary
axes and spindles; seconds) in TOML, or given as command-line options. What is
not given is filled from a documented default geometry, and every filled-in
value is listed as "assumed" in the output:

* the axis starts at 0, at standstill (a spindle may instead turn endlessly:
  `start_velocity`, signed °/s, §2.3.2.1; only spindles, which list it as
  assumed when it is not given);
* the reference cam begins 100 (mm or °) away from the start in the homing
  direction and is 20 wide, or three braking distances at the fast homing speed
  when that is wider (so the axis can stop on it). On an axis too short for
  that (homing would run into a limit switch before it is referenced) the cam
  moves closer and becomes narrower: the first of a few smaller cams between
  the start and the software limit with which homing completes (`fitted_cams`);
  when none does, the default cam stays and the output says that no assumed
  geometry fits the axis;
* zero pulses repeat every 5 mm (10° on rotary axes, once per revolution on
  spindles) and the first one after
  the cam edge lies half a period behind it (the manual's recommendation);
* a hardware latch is available when the strategy references on a zero pulse;
* the cycle time is the configured CNC cycle (default 1 ms);
* limit switches sit 10 beyond the software limits (none on spindles and
  modulo rotary axes, where the cam and the zero pulses recur every revolution);
* a fixed stop (TORQ) sits 100 away from the start in the homing direction.

Only what the strategy's run reads is filled in and listed as assumed (`HomingStrategy.geometry`): no cam
for zero-pulse homing without cam, flying spindle homing without cam or simulated drives; no cam, zero
pulses, latch or limit switches for axes that do not move (absolute, DISABLED, IGNORE_ABS_POS, gantry
slaves, drive-controlled homing without a `[drive]` table); a fixed stop only for TORQ on a real drive
(or a drive search for one); a start velocity only for moving spindles.

Drive-controlled homing is simulated when the scenario describes the drive's
method in a `[drive]` table (Triamec drive homing: "standard" with two
searches, a relocation and a move to the home position; "immediate";
"at-position"; "absolute-encoder"; "nc" for the TwinCAT NC / AX5000 reference
modes PLC cam, hardware sync, software sync with reference mask and hardware
latch).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypedDict, TypeVar

from ..catalogue.units import unit_label
from .bounds import CYCLE_TIME_US, POSITION_BOUND

if TYPE_CHECKING:
    from pydantic import BaseModel

    from .scenario_input import DriveInput, ScenarioInput, SearchInput

# CYCLE_TIME_US: the command line reads the cycle-time bounds here too (they live in bounds.py)
__all__ = ["CYCLE_TIME_US", "DriveInput", "Scenario", "ScenarioError", "ScenarioInput", "SearchInput"]


class ScenarioError(Exception):
    """A scenario that cannot be used (exit code 2)."""


DEFAULT_CAM_DISTANCE = 100.0  # from the start to the cam's near edge, mm or °

# What a run may read of the scenario besides the start position: the cam (and its jitter), the zero pulses
# (period and phase), the hardware latch, the limit switches, the fixed stop, the cycle time and a spindle's
# start velocity. A strategy names the ones its run reads (HomingStrategy.geometry); only those are filled in
# from the default geometry and listed as assumed.
GEOMETRY_NEEDS = frozenset(
    ("cam", "zero_pulse", "hardware_latch", "limit_switches", "fixed_stop", "cycle_time", "start_velocity")
)


_T = TypeVar("_T")

# The input models live in scenario_input.py, imported on first use (linting never needs pydantic).
_MODELS = ("SearchInput", "DriveInput", "ScenarioInput")


def __getattr__(name: str) -> type[BaseModel]:
    if name in _MODELS:
        from . import scenario_input

        model: type[BaseModel] = getattr(scenario_input, name)
        return model
    raise AttributeError(name)


@dataclass
class Scenario:
    """A complete geometry (human units) plus the names of the values that were assumed."""

    start_position: float
    cam: tuple[float, float] | None
    zero_pulse_period: float
    zero_pulse_phase: float
    hardware_latch: bool
    cycle_time: float  # seconds
    limit_switches: tuple[float, float] | None  # None: none (modulo axes unless the scenario names them)
    fixed_stop: float | None
    cam_jitter: float = 0.0
    drive: DriveInput | None = None
    assumed: list[str] = field(default_factory=list)
    modulo: tuple[float, float] | None = (
        None  # positions recur every revolution (spindles, modulo rotary axes)
    )
    start_velocity: float = 0.0  # a spindle turning endlessly at the start (signed, °/s); 0: standstill
    uses: frozenset[str] = GEOMETRY_NEEDS  # what the strategy's run reads (GEOMETRY_NEEDS)

    def as_dict(self) -> ScenarioData:
        """The scenario as JSON; the zero pulses and the latch are null when the run reads none."""
        pulses = "zero_pulse" in self.uses
        return {
            "start_position": self.start_position,
            "cam": list(self.cam) if self.cam else None,
            "zero_pulse_period": self.zero_pulse_period if pulses else None,
            "zero_pulse_phase": self.zero_pulse_phase if pulses else None,
            "hardware_latch": self.hardware_latch if "hardware_latch" in self.uses else None,
            "limit_switches": list(self.limit_switches) if self.limit_switches else None,
            "fixed_stop": self.fixed_stop,
            "cam_jitter": self.cam_jitter,
            "drive": self.drive.model_dump() if self.drive else None,
            "modulo": list(self.modulo) if self.modulo else None,
            "start_velocity": self.start_velocity,
            "cycle_time_ms": self.cycle_time * 1000,
            "assumed": list(self.assumed),
        }


class ScenarioData(TypedDict):
    """A scenario as JSON (`dry-run --format json`), in the order of the fields, the cycle time in ms."""

    start_position: float
    cam: list[float] | None
    zero_pulse_period: float | None
    zero_pulse_phase: float | None
    hardware_latch: bool | None
    limit_switches: list[float] | None
    fixed_stop: float | None
    cam_jitter: float
    drive: dict[str, Any] | None
    modulo: list[float] | None
    start_velocity: float
    cycle_time_ms: float
    assumed: list[str]


def read_scenario(path: Path) -> ScenarioInput:
    from ..core.tomlfile import read_toml

    return parse_input(read_toml(path, "scenario", ScenarioError), str(path))


def parse_input(data: object, where: str = "scenario") -> ScenarioInput:
    """A validated ScenarioInput; any problem is a ScenarioError naming the key (nested keys in full)."""
    from pydantic import ValidationError

    from .scenario_input import DriveInput, ScenarioInput, SearchInput

    levels: dict[tuple[str, ...], type[BaseModel]] = {
        (): ScenarioInput,
        ("drive",): DriveInput,
        ("drive", "first_search"): SearchInput,
        ("drive", "second_search"): SearchInput,
    }
    if not isinstance(data, dict):
        raise ScenarioError(f"{where}: a scenario is a table of keys, not {type(data).__name__}")
    try:
        return ScenarioInput.model_validate(data)
    except ValidationError as exc:
        problems: list[str] = []
        for item in exc.errors():
            loc = tuple(str(p) for p in item["loc"])
            key = ".".join(loc) or "(scenario)"
            if item["type"] == "extra_forbidden":
                model = levels.get(loc[:-1])
                known = f" (known: {', '.join(model.model_fields)})" if model is not None else ""
                problems.append(f"unknown key `{key}`{known}")
            else:
                message = item["msg"].removeprefix("Value error, ")
                problems.append(f"`{key}`: {message}" if loc else message)
        raise ScenarioError(f"{where}: " + "; ".join(problems).replace("\n", " ")) from None


# Assumed limit switches lie this far beyond the software limits (mm or °), in the frame the software limits
# hold in: the homed one. Until the homing gives that frame, the actual values are taken for it.
SWITCH_MARGIN = 10.0
# The assumed fixed stop lies this far from the start in the homing direction (mm or °), unless the axis
# searches it over a shorter way (`fixed_stop_distance`).
DEFAULT_STOP_DISTANCE = 100.0


def fixed_stop_distance(least: float, most: float) -> float:
    """Where to assume the fixed stop of an axis that arms the stop detection after `least` and gives up after
    `most` (torq_min_distance, torq_max_distance; 0: no limit): DEFAULT_STOP_DISTANCE where that lies between
    them, else halfway between them (beyond `least` when there is no `most`). An assumed stop beyond
    torq_max_distance made the manual's own example list fail on the assumed geometry. Distances that leave
    no room (`most` not beyond `least`, LIS304) keep the default."""
    if least < DEFAULT_STOP_DISTANCE and (most <= 0 or most >= DEFAULT_STOP_DISTANCE):
        return DEFAULT_STOP_DISTANCE
    if most <= 0:
        return least + SWITCH_MARGIN
    return (least + most) / 2 if most > least else DEFAULT_STOP_DISTANCE


def complete(
    given: ScenarioInput | None,
    *,
    direction: int,
    rotary: bool,
    soft_limits: tuple[float, float],
    cycle_time: float,
    zero_pulse: bool,
    braking: float = 0.0,
    modulo: tuple[float, float] | None = None,
    spindle: bool = False,
    armed_on_exit: bool = False,
    cam_place: tuple[float, float] | None = None,
    needs: frozenset[str] = GEOMETRY_NEEDS,
    stop_distance: float = DEFAULT_STOP_DISTANCE,
) -> Scenario:
    """Fill what the scenario (a ScenarioInput, or None) leaves open with the documented default geometry.

    On a modulo axis (spindle, rotary axis with MODULO) positions recur every revolution: there are no limit
    switches unless the scenario names them, a spindle has one zero pulse per revolution, and the cam must be
    narrower than a revolution. `cam_place` (distance from the start to the cam, width) replaces the default
    cam when the scenario names none. Only what the run `needs` (GEOMETRY_NEEDS) is assumed: a cam, limit
    switches or a fixed stop it does not read stay None unless given, and unread numbers are not listed as
    assumed. Raises ScenarioError for values beyond the unit's plausibility bound."""
    unit = "deg" if rotary else "mm"
    _check_bounds(given, unit)
    revolution = modulo[1] - modulo[0] if modulo else 0.0
    assumed: list[str] = []

    def pick(name: str, default: _T, needed: bool = True) -> _T:
        value: _T | None = getattr(given, name, None)
        if value is None:
            if needed:
                assumed.append(name)
            return default
        return value

    start = pick("start_position", 0.0)
    velocity = getattr(given, "start_velocity", None)
    if velocity and not spindle:
        raise ScenarioError(
            f"scenario: `start_velocity` ({velocity:g}) is for a spindle turning endlessly when homing starts "
            "(§2.3.2.1); this axis starts homing at standstill: remove it"
        )
    if velocity is None and spindle and "start_velocity" in needs:
        assumed.append("start_velocity")
    cam = getattr(given, "cam", None)
    if cam is None:
        if "cam" in needs:
            assumed.append("cam")
        distance, width = cam_place or (DEFAULT_CAM_DISTANCE, max(20.0, 3 * braking))
        near = start + direction * distance
        if revolution:
            width = min(width, revolution / 2)
        cam = (near - width, near) if direction < 0 else (near, near + width)
    elif revolution and cam[1] - cam[0] >= revolution:
        raise ScenarioError(
            f"scenario: `cam` [{cam[0]:g}, {cam[1]:g}] is as wide as the modulo range of "
            f"{revolution:g}° or wider: the cam would be operated all the time"
        )
    pulses = "zero_pulse" in needs
    period = pick(
        "zero_pulse_period", revolution if spindle and revolution else (10.0 if rotary else 5.0), pulses
    )
    # Ideal phase: the first pulse half a period after the cam edge that arms the zero-pulse logic (the edge
    # where the cam is reached; for flying spindle homing the edge where it is left).
    edge = cam[1] if (direction < 0) != armed_on_exit else cam[0]
    phase = pick("zero_pulse_phase", edge + direction * period / 2, pulses)
    latch = pick("hardware_latch", zero_pulse, "hardware_latch" in needs)
    cycle_ms = getattr(given, "cycle_time_ms", None)
    cycle = cycle_ms / 1000 if cycle_ms is not None else cycle_time
    if cycle_ms is None and "cycle_time" in needs:
        assumed.append("cycle_time_ms")
    low, high = soft_limits
    if modulo or "limit_switches" not in needs:
        limits = getattr(given, "limit_switches", None)  # none unless the scenario names them
    else:
        limits = pick("limit_switches", (low - SWITCH_MARGIN, high + SWITCH_MARGIN))
    stop = (
        pick("fixed_stop", start + direction * stop_distance)
        if "fixed_stop" in needs
        else getattr(given, "fixed_stop", None)
    )
    jitter = pick("cam_jitter", 0.0, "cam" in needs)
    if jitter and jitter >= period:
        raise ScenarioError(
            f"scenario: `cam_jitter` ({jitter:g}) must be smaller than the zero-pulse period "
            f"({period:g} {unit_label(unit)})"
        )
    if "cam" not in needs and getattr(given, "cam", None) is None:
        cam = None  # the run reads no cam: none is assumed (the default one only placed the pulses)
    return Scenario(
        start,
        tuple(cam) if cam else None,
        period,
        phase,
        latch,
        cycle,
        tuple(limits) if limits else None,
        stop,
        jitter,
        getattr(given, "drive", None),
        assumed,
        modulo,
        velocity or 0.0,
        needs,
    )


def fitted_cams(
    start: float, direction: int, soft_limits: tuple[float, float], braking: float
) -> list[tuple[float, float]]:
    """Smaller cams for an axis too short for the default one, largest first: (distance from the start to
    the cam, width), each ending at the software limit in the homing direction at the latest. The cam lies
    half, a quarter or a tenth of the room between start and limit away; it is as wide as the default
    (20, or three fast braking distances) where that fits, else it fills the rest of the room or half of it.
    None when the start is not inside the software limits."""
    low, high = soft_limits
    room = high - start if direction > 0 else start - low
    if not low <= start <= high or room <= 0:
        return []
    wide = max(20.0, 3 * braking)
    places: list[tuple[float, float]] = []
    for distance in (room / 2, room / 4, room / 10):
        rest = room - distance
        for width in (min(wide, rest), min(wide, rest / 2)):
            if width > 0 and (distance, width) not in places:
                places.append((distance, width))
    return places


def _check_bounds(given: ScenarioInput | None, unit: str) -> None:
    """Positions and distances within ±1e6 mm (±1e9 °): beyond that the arithmetic loses the micrometre."""
    if given is None:
        return
    bound = POSITION_BOUND[unit]
    data = given.model_dump(exclude_none=True)
    found: list[str] = []

    def walk(prefix: str, value: object) -> None:
        if isinstance(value, dict):
            for key, item in value.items():
                walk(f"{prefix}.{key}" if prefix else key, item)
        elif isinstance(value, (list, tuple)):
            for item in value:
                walk(prefix, item)
        elif (
            isinstance(value, float)
            and not isinstance(value, bool)
            and abs(value) > bound
            and not prefix.endswith(("velocity", "acceleration", "velocity_sync"))
        ):
            found.append(f"`{prefix}` = {value:g} is beyond ±{bound:g} {unit_label(unit)}")

    walk("", data)
    if found:
        raise ScenarioError("scenario: " + "; ".join(found))
