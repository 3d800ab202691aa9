"""The pydantic models that validate scenario input (a scenario file, `[scenario]` of the configuration,
command-line options, the Python API).

Every number must be finite (`nan` and `inf` are refused) and plausible; the bounds are in `bounds.py`.
`scenario.py` imports this module on first use: linting never needs pydantic.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from .bounds import ANY_POSITION, CYCLE_MS, MAX_RATE, MIN_PERIOD

Position = Annotated[float, Field(ge=-ANY_POSITION, le=ANY_POSITION)]
Rate = Annotated[float, Field(gt=0, le=MAX_RATE)]
_STRICT = ConfigDict(extra="forbid", allow_inf_nan=False)


class SearchInput(BaseModel):
    """One search move of the drive's "Standard" method (Triamec FirstSearchMove / SecondSearchMove)."""

    model_config = _STRICT

    trigger: Literal["cam", "zero_pulse", "fixed_stop", "limit_switch"] = "cam"
    signed_max_distance: Position
    active_low: bool = False
    dynamic_reduction: float = Field(1.0, gt=0, le=1)

    @model_validator(mode="after")
    def _moves(self) -> SearchInput:
        if self.signed_max_distance == 0:
            raise ValueError("signed_max_distance must not be 0: its sign gives the search direction")
        return self


class DriveInput(BaseModel):
    """The drive's own homing method, for drive-controlled homing (Triamec drive homing)."""

    model_config = _STRICT

    method: Literal["standard", "immediate", "at-position", "absolute-encoder", "nc"]
    velocity: Rate = 10.0
    acceleration: Rate = 100.0
    reference_position: Position | None = None
    home_position: Position | None = None
    encoder_offset: Position = 0.0
    first_search: SearchInput | None = None
    relocate_distance: Position = 0.0
    second_search: SearchInput | None = None
    # method "nc": TwinCAT NC / AX5000 reference modes
    reference_mode: Literal[
        "plc-cam", "hardware-sync", "software-sync", "hardware-latch-pos", "hardware-latch-neg"
    ] = "plc-cam"
    invert_cam_search: bool = False
    invert_sync_search: bool = False
    velocity_sync: Rate | None = None
    reference_mask_period: float | None = Field(None, ge=MIN_PERIOD, le=ANY_POSITION)
    latch_position: Position | None = None

    @model_validator(mode="after")
    def _searches(self) -> DriveInput:
        if self.method == "standard" and (self.first_search is None or self.second_search is None):
            raise ValueError("the standard method needs [drive.first_search] and [drive.second_search]")
        return self


class ScenarioInput(BaseModel):
    """What a scenario file may contain. Every key is optional."""

    model_config = _STRICT

    start_position: Position | None = None
    # A spindle turning endlessly when homing starts (°/s, signed: its rotation direction); 0 is standstill.
    start_velocity: float | None = Field(None, ge=-MAX_RATE, le=MAX_RATE)
    cam: tuple[Position, Position] | None = None
    zero_pulse_period: float | None = Field(None, ge=MIN_PERIOD, le=ANY_POSITION)
    zero_pulse_phase: Position | None = None
    hardware_latch: bool | None = None
    cycle_time_ms: float | None = Field(None, ge=CYCLE_MS[0], le=CYCLE_MS[1])
    limit_switches: tuple[Position, Position] | None = None
    fixed_stop: Position | None = None
    cam_jitter: float | None = Field(None, ge=0, le=ANY_POSITION)
    drive: DriveInput | None = None

    @model_validator(mode="after")
    def _ordered(self) -> ScenarioInput:
        for name in ("cam", "limit_switches"):
            pair = getattr(self, name)
            if pair is not None and pair[0] >= pair[1]:
                raise ValueError(f"{name} must be [low, high] with low < high, got {list(pair)}")
        if (
            self.cam_jitter is not None
            and self.zero_pulse_period is not None
            and self.cam_jitter >= self.zero_pulse_period
        ):
            raise ValueError(
                f"cam_jitter ({self.cam_jitter:g}) must be smaller than zero_pulse_period "
                f"({self.zero_pulse_period:g})"
            )
        return self
