"""What a homing strategy is: its identity, when it applies, its phases and the
parameters it reads, as data. One module in `homing/strategies/` defines one
strategy; `homing/registry.py` lists them in classification order."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..engine import Simulator, Trace
    from ..resolved import ResolvedAxis
    from .setup import HomingSetup

    # simulate(simulator, trace, start position, cam shift) -> trace: the engine sequence of a strategy
    Simulate = Callable[[Simulator, Trace, float, float], Trace]

POSITIVE, NEGATIVE = "positive", "negative"


@dataclass(frozen=True)
class Use:
    """Why a parameter matters for a strategy; `when` narrows it to some axes (with `otherwise` as the reason)."""

    reason: str
    when: Callable[[ResolvedAxis], bool] | None = None
    otherwise: str = ""

    def applies(self, axis: ResolvedAxis) -> tuple[bool, str]:
        if self.when is None or self.when(axis):
            return True, self.reason
        return False, self.otherwise


@dataclass
class Phase:
    name: str
    direction: str | None
    velocity_parameter: str | None  # canonical path of the speed used
    velocity: float | None  # in list units (µm/s or 0.001°/s), after the CNC's caps
    ends_when: str
    note: str = ""


@dataclass(frozen=True)
class StrategyDef:
    """A homing strategy as registered: one per module in `homing/strategies/`."""

    id: str
    title: str
    controlled_by: str  # "cnc", "drive" or "none"
    matches: Callable[[ResolvedAxis], bool]
    describe: Callable[[ResolvedAxis], str]
    parameters: Mapping[str, Use]  # generic paths (`getriebe[i].vb_reflow`) this strategy reads
    example: str  # a list snippet that selects it
    phases: Callable[[HomingSetup], list[Phase]] = lambda setup: []
    manual_type: str | None = None  # I, II, III, IV of the effectiveness table (§3.5)
    unused: str = ""  # why the other homing parameters do not matter here
    with_cam: bool = False
    with_zero_pulse: bool = False
    one_phase: bool = False
    reference_speed: str | None = None  # getriebe member of the speed at which the reference is taken
    ends_with_braking: bool = (
        True  # the axis brakes beyond the reference (not for retraction / flying homing)
    )
    variants: Callable[[HomingSetup], list[str]] = lambda setup: []
    # which engine sequence runs this strategy
    simulate: Simulate = lambda sim, trace, x, cam_shift: sim.stand_still(trace, "skipped")


@dataclass
class HomingStrategy:
    """A registered strategy applied to one axis and gear stage: what `explain`, the rules and the engine read."""

    definition: StrategyDef
    setup: HomingSetup
    description: str
    phases: list[Phase] = field(default_factory=list)
    variants: list[str] = field(default_factory=list)

    @property
    def id(self) -> str:
        return self.definition.id

    @property
    def title(self) -> str:
        return self.definition.title

    @property
    def controlled_by(self) -> str:
        return self.definition.controlled_by

    @property
    def manual_type(self) -> str | None:
        return self.definition.manual_type

    @property
    def gear(self) -> int:
        return self.setup.gear

    @property
    def with_cam(self) -> bool:
        return self.definition.with_cam

    @property
    def with_zero_pulse(self) -> bool:
        return self.definition.with_zero_pulse

    @property
    def one_phase(self) -> bool:
        return self.definition.one_phase

    @property
    def falling_edge(self) -> bool:
        return self.setup.falling_edge and self.with_cam

    @property
    def moves(self) -> bool:
        return bool(self.phases)


def opposite(direction: str) -> str:
    return NEGATIVE if direction == POSITIVE else POSITIVE
