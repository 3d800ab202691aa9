"""The machine geometry a dry run assumes: where the axis starts, where the cam,
the zero pulses, the limit switches and the fixed stop are.

A scenario is written in human units (mm for linear axes, degrees for rotary
axes and spindles; seconds) in TOML, or given as command-line options. What is
not given is filled from a documented default geometry, and every filled-in
value is listed as "assumed" in the output:

* the axis starts at 0;
* the reference cam begins 100 (mm or °) away from the start in the homing
  direction and is 20 wide, or three braking distances at the fast homing speed
  when that is wider (so the axis can stop on it);
* zero pulses repeat every 5 mm (10° on rotary axes) and the first one after
  the cam edge lies half a period behind it (the manual's recommendation);
* a hardware latch is available when the strategy references on a zero pulse;
* the cycle time is the configured CNC cycle (default 1 ms);
* limit switches sit 10 beyond the software limits;
* a fixed stop (TORQ) sits 100 away from the start in the homing direction.

Drive-controlled homing is simulated when the scenario describes the drive's
method in a `[drive]` table (Triamec drive homing: "standard" with two
searches, a relocation and a move to the home position; "immediate";
"at-position"; "absolute-encoder"; "nc" for the TwinCAT NC / AX5000 reference
modes PLC cam, hardware sync, software sync with reference mask and hardware
latch).
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from functools import lru_cache
from pathlib import Path
from typing import Literal

from .tomlfile import read_toml


class ScenarioError(Exception):
    """A scenario that cannot be used (exit code 2)."""


@lru_cache(maxsize=1)
def _models() -> dict:
    """The pydantic models that validate scenario input (built on first use: lint does not need them)."""
    from pydantic import BaseModel, ConfigDict, Field, model_validator

    class SearchInput(BaseModel):
        """One search move of the drive's "Standard" method (Triamec FirstSearchMove / SecondSearchMove)."""

        model_config = ConfigDict(extra="forbid")

        trigger: Literal["cam", "zero_pulse", "fixed_stop", "limit_switch"] = "cam"
        signed_max_distance: float
        active_low: bool = False
        dynamic_reduction: float = Field(1.0, gt=0, le=1)

    class DriveInput(BaseModel):
        """The drive's own homing method, for drive-controlled homing (Triamec drive homing)."""

        model_config = ConfigDict(extra="forbid")

        method: Literal["standard", "immediate", "at-position", "absolute-encoder", "nc"]
        velocity: float = Field(10.0, gt=0)
        acceleration: float = Field(100.0, gt=0)
        reference_position: float | None = None
        home_position: float | None = None
        encoder_offset: float = 0.0
        first_search: SearchInput | None = None
        relocate_distance: float = 0.0
        second_search: SearchInput | None = None
        # method "nc": TwinCAT NC / AX5000 reference modes
        reference_mode: Literal["plc-cam", "hardware-sync", "software-sync", "hardware-latch-pos",
                                "hardware-latch-neg"] = "plc-cam"
        invert_cam_search: bool = False
        invert_sync_search: bool = False
        velocity_sync: float | None = Field(None, gt=0)
        reference_mask_period: float | None = Field(None, gt=0)
        latch_position: float | None = None

        @model_validator(mode="after")
        def _searches(self):
            if self.method == "standard" and (self.first_search is None or self.second_search is None):
                raise ValueError("the standard method needs [drive.first_search] and [drive.second_search]")
            return self

    class ScenarioInput(BaseModel):
        """What a scenario file may contain. Every key is optional."""

        model_config = ConfigDict(extra="forbid")

        start_position: float | None = None
        cam: tuple[float, float] | None = None
        zero_pulse_period: float | None = Field(None, gt=0)
        zero_pulse_phase: float | None = None
        hardware_latch: bool | None = None
        cycle_time_ms: float | None = Field(None, gt=0)
        limit_switches: tuple[float, float] | None = None
        fixed_stop: float | None = None
        cam_jitter: float | None = Field(None, ge=0)
        drive: DriveInput | None = None

        @model_validator(mode="after")
        def _ordered(self):
            for name in ("cam", "limit_switches"):
                pair = getattr(self, name)
                if pair is not None and pair[0] >= pair[1]:
                    raise ValueError(f"{name} must be [low, high] with low < high, got {list(pair)}")
            return self

    return {"SearchInput": SearchInput, "DriveInput": DriveInput, "ScenarioInput": ScenarioInput}


def __getattr__(name: str):
    if name in ("SearchInput", "DriveInput", "ScenarioInput"):
        return _models()[name]
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
    limit_switches: tuple[float, float]
    fixed_stop: float | None
    cam_jitter: float = 0.0
    drive: object = None  # DriveInput
    assumed: list[str] = field(default_factory=list)

    def as_dict(self) -> dict:
        data = {f.name: getattr(self, f.name) for f in fields(self) if f.name != "assumed"}
        data["cycle_time_ms"] = data.pop("cycle_time") * 1000
        data["cam"] = list(self.cam) if self.cam else None
        data["limit_switches"] = list(self.limit_switches)
        data["assumed"] = list(self.assumed)
        data["drive"] = self.drive.model_dump() if self.drive else None
        return data


def read_scenario(path: Path):
    return parse_input(read_toml(path, "scenario", ScenarioError), str(path))


def parse_input(data: dict, where: str = "scenario"):
    """A validated ScenarioInput; any problem is a ScenarioError naming the key."""
    from pydantic import ValidationError

    model = _models()["ScenarioInput"]
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        problems = []
        for item in exc.errors():
            key = ".".join(str(p) for p in item["loc"]) or "(scenario)"
            if item["type"] == "extra_forbidden":
                problems.append(f"unknown key `{key}` (known: {', '.join(model.model_fields)})")
            else:
                problems.append(f"`{key}`: {item['msg']}")
        raise ScenarioError(f"{where}: " + "; ".join(problems)) from None


def default_scenario(strategy, given=None, cycle_time_us: int = 1000) -> Scenario:
    """The scenario completed with the documented default geometry for the strategy's axis."""
    setup = strategy.setup
    direction = setup.torq_direction if strategy.id == "fixed_stop" else setup.direction
    braking = setup.fast * setup.fast / (2 * (setup.acceleration.value or 1.0))
    return complete(given, direction=direction, rotary=setup.rotary, soft_limits=setup.soft_limits,
                    cycle_time=cycle_time_us / 1e6, zero_pulse=strategy.with_zero_pulse, braking=braking)


def complete(given, *, direction: int, rotary: bool, soft_limits: tuple[float, float],
             cycle_time: float, zero_pulse: bool, braking: float = 0.0) -> Scenario:
    """Fill what the scenario (a ScenarioInput, or None) leaves open with the documented default geometry."""
    assumed: list[str] = []

    def pick(name, default):
        value = getattr(given, name, None)
        if value is None:
            assumed.append(name)
            return default
        return value

    start = pick("start_position", 0.0)
    cam = getattr(given, "cam", None)
    if cam is None:
        assumed.append("cam")
        near = start + direction * 100.0
        width = max(20.0, 3 * braking)
        cam = (near - width, near) if direction < 0 else (near, near + width)
    period = pick("zero_pulse_period", 10.0 if rotary else 5.0)
    # Ideal phase: the first pulse half a period after the cam edge that starts the search.
    edge = cam[1] if direction < 0 else cam[0]
    phase = pick("zero_pulse_phase", edge + direction * period / 2)
    latch = pick("hardware_latch", zero_pulse)
    cycle_ms = getattr(given, "cycle_time_ms", None)
    cycle = cycle_ms / 1000 if cycle_ms is not None else cycle_time
    if cycle_ms is None:
        assumed.append("cycle_time_ms")
    low, high = soft_limits
    limits = pick("limit_switches", (low - 10.0, high + 10.0))
    stop = pick("fixed_stop", start + direction * 100.0)
    jitter = pick("cam_jitter", 0.0)
    return Scenario(start, tuple(cam), period, phase, latch, cycle, tuple(limits), stop, jitter,
                    getattr(given, "drive", None), assumed)
