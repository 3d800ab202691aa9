"""The settings a rule reads, and their defaults.

Rules see the configuration through `RuleOptions`: the few keys that change what a rule finds. The
configuration's `Settings` (`linting.config`) has these keys among all the others and takes its defaults for
them from `DEFAULT_OPTIONS`, so a rule run without a configuration (a test, the dry-run, the model) judges
exactly as a run with an empty one.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, Protocol

UnknownParameters = Literal["warn", "error", "ignore"]


class RuleOptions(Protocol):
    """What a rule may read of the settings that apply to the list it checks."""

    @property
    def unknown_parameters(self) -> UnknownParameters: ...  # LIS101: how an unknown parameter is reported

    @property
    def cycle_time_us(self) -> int: ...  # the CNC cycle (LIS317's probe, LIS403's repeatability)

    @property
    def repeatability_tolerance_um(self) -> float: ...  # LIS403 on linear axes

    @property
    def repeatability_tolerance_deg(self) -> float: ...  # LIS403 on rotary axes and spindles


@dataclass(frozen=True)
class DefaultOptions:
    """The defaults of every `RuleOptions` key."""

    unknown_parameters: UnknownParameters = "warn"
    cycle_time_us: int = 1000
    repeatability_tolerance_um: float = 20.0
    repeatability_tolerance_deg: float = 0.01


DEFAULT_OPTIONS = DefaultOptions()
