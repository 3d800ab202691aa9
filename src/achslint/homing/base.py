"""What a homing strategy is: its identity, when it applies, its phases and the
parameters it reads, as data. One module in `homing/strategies/` defines one
strategy; `homing/registry.py` lists them in classification order."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from ..axis.drives import SERCOS
from .scenario import (
    DEFAULT_STOP_DISTANCE,
    Scenario,
    ScenarioError,
    complete,
    fitted_cams,
    fixed_stop_distance,
)

if TYPE_CHECKING:
    from ..axis.resolved import ResolvedAxis
    from .motion import Simulator, Trace
    from .scenario_input import ScenarioInput
    from .setup import Acceleration, HomingSetup

    # simulate(simulator, trace, start position, cam shift) -> trace: the sequence a strategy runs
    # (one of homing/sequences/)
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
    # How the axis comes to rest after the reference event. By default it brakes and stands beyond the
    # reference by its braking distance; `retracts`: it backs off from a fixed stop by a set distance;
    # `flying`: a spindle that references on the fly and keeps turning (§2.3.2.1).
    retracts: bool = False
    flying: bool = False
    # The parameter whose value the reference event gets (generic path).
    reference_parameter: str = "getriebe[i].pos_refpkt"
    # Where the zero-pulse logic is armed: where the cam is reached (§2.6), or, for flying homing of a
    # spindle with cam, where the cam changes from operated to not operated (§2.3.2.1).
    arms_on_cam_exit: bool = False
    # The zero pulse is the only reference signal (no cam to fall back on): without one nothing marks
    # the reference (LIS318).
    needs_zero_pulse: bool = False
    # What a G74 that names the axis does. `power_up_only`: the strategy describes only the axis at power-up
    # (an absolute encoder, §3.5 type IV); a G74 naming it runs the next strategy that matches
    # (P-AXIS-00299 remark). `refuses_g74`: the G74 ends with an error (P-ERR-50686). `skipped_by_g74`: the
    # G74 leaves the axis standing while the other axes of its group move.
    power_up_only: bool = False
    refuses_g74: bool = False
    skipped_by_g74: bool = False
    # Homed together with its gantry master, never on its own (P-AXIS-00074).
    homed_with_master: bool = False
    # The CNC takes the axis's position as valid from power-up on: an absolute encoder supplies it (§3.5 type
    # IV), or G74 never homes the axis (IGNORE_ABS_POS, DISABLED: both settings for absolute encoders).
    referenced_at_power_up: bool = False
    # The direction of the homing moves (+1 / -1) and their acceleration (None: the drive's own).
    direction: Callable[[HomingSetup], int] = lambda setup: setup.direction
    acceleration: Callable[[HomingSetup], Acceleration | None] = lambda setup: setup.acceleration
    variants: Callable[[HomingSetup], list[str]] = lambda setup: []
    # the sequence (homing/sequences/) that simulates this strategy
    simulate: Simulate = lambda sim, trace, x, cam_shift: sim.stand_still(trace, "skipped")

    @property
    def ends_with_braking(self) -> bool:
        """The axis brakes after the reference event and stands beyond it (not after retraction or on the fly)."""
        return not (self.retracts or self.flying)

    @property
    def reverses(self) -> bool:
        """Three-phase homing: on the cam the axis reverses to leave it, then approaches it again (§2.3.1)."""
        return self.with_cam and not self.one_phase


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
    def direction(self) -> int:
        """+1 or -1: the direction of the homing moves (towards the cam, the zero pulse or the fixed stop)."""
        return self.definition.direction(self.setup)

    @property
    def acceleration(self) -> Acceleration | None:
        """The acceleration of the homing moves and where it comes from; None when the drive uses its own."""
        return self.definition.acceleration(self.setup)

    @property
    def retracts(self) -> bool:
        return self.definition.retracts

    @property
    def flying(self) -> bool:
        """Flying homing of a spindle (§2.3.2.1): from standstill or from endless rotation, without stopping."""
        return self.definition.flying

    @property
    def falling_edge(self) -> bool:
        return self.setup.falling_edge and self.with_cam

    @property
    def unlatched_zero_pulse(self) -> bool:
        """CNC-controlled homing of a SERCOS drive on its zero pulse with nothing to capture the pulse: the CNC
        does not search a SERCOS zero pulse itself (TF5200 §2.2), it needs the drive's latch (S-0-146,
        P-AXIS-00386), the AX5000 latch (P-AXIS-00060) or the encoder overflow (P-AXIS-00294, §3.1.1.2). Without
        one the pulse is never found (LIS322), and the dry-run does not home the axis either."""
        setup = self.setup
        if setup.axis.drive_type != SERCOS or self.controlled_by != "cnc" or not self.with_zero_pulse:
            return False
        if setup.overflow or setup.simulated or self.flying:
            return False
        axis = setup.axis
        return not (axis.get("antr.sercos.drive_supports_cnc_homing") or axis.get("kenngr.echtzeit_bit_nr"))

    @property
    def moves(self) -> bool:
        return bool(self.phases)

    @property
    def referenced_from_start(self) -> bool:
        """Whether a homing program may count the axis as homed before any G74: its strategy says so, or its
        absolute encoder gives the position (also when a gantry master references it)."""
        return self.definition.referenced_at_power_up or self.setup.absolute

    def simulate(self, simulator: Simulator, trace: Trace, start: float, cam_shift: float) -> Trace:
        """Run the strategy's sequence from `start`, with the cam moved by `cam_shift` (its jitter)."""
        return self.definition.simulate(simulator, trace, start, cam_shift)

    def default_scenario(
        self, given: ScenarioInput | None = None, cycle_time_us: int = 1000, *, name: str = "the axis"
    ) -> Scenario:
        """The scenario `given` (or none) completed with the documented default geometry (scenario.py) for this
        strategy's axis `name`: the cam in its homing direction, zero pulses where the logic is armed, its
        limits. A `[drive]` table, which describes drive-controlled homing, is a ScenarioError on another axis."""
        setup = self.setup
        if given is not None and given.drive is not None and self.controlled_by != "drive":
            raise ScenarioError(
                f"scenario: the [drive] table describes drive-controlled homing, but {name} homes "
                f"{self.title} (homing type {setup.homing_type}): remove the [drive] table"
            )
        braking = setup.fast * setup.fast / (2 * (setup.acceleration.value or 1.0))
        turning = given.start_velocity if given is not None and setup.spindle else None
        direction = (1 if turning > 0 else -1) if turning else self.direction  # endless rotation: its way

        needs = self.geometry(given)
        stop_distance = DEFAULT_STOP_DISTANCE
        if "fixed_stop" in needs:
            from .motion import POSITION

            stop_distance = fixed_stop_distance(
                setup.axis.number("kenngr.homing.torq_min_distance") * POSITION,
                setup.axis.number("kenngr.homing.torq_max_distance") * POSITION,
            )

        def build(cam_place: tuple[float, float] | None = None) -> Scenario:
            return complete(
                given,
                direction=direction,
                rotary=setup.rotary,
                soft_limits=setup.soft_limits,
                cycle_time=cycle_time_us / 1e6,
                zero_pulse=self.with_zero_pulse,
                braking=braking,
                modulo=setup.modulo,
                spindle=setup.spindle,
                armed_on_exit=self.definition.arms_on_cam_exit,
                cam_place=cam_place,
                needs=needs,
                stop_distance=stop_distance,
            )

        scenario = build()
        if not self.cam_may_move(scenario) or not geometry_failure(self.trial(scenario).failure):
            return scenario
        for place in fitted_cams(scenario.start_position, direction, setup.soft_limits, braking):
            fitted = build(place)
            if self.trial(fitted).reference is not None:
                return fitted
        return scenario  # nothing fits: the default stays, and the run says where it stops

    def geometry(self, given: ScenarioInput | None = None) -> frozenset[str]:
        """What this strategy's run reads of the scenario (names of scenario.GEOMETRY_NEEDS): the cam only with
        a cam, the zero pulses and the latch only with a zero pulse, the fixed stop only for TORQ on a real
        drive (a simulated drive's stop lies torq_distance_to_block away), the limit switches and the cycle
        only when the axis moves, a start velocity only on a moving spindle. Drive-controlled homing reads what
        the scenario's [drive] table searches for; without one it does not move."""
        if self.controlled_by == "drive":
            drive = given.drive if given is not None else None
            if drive is None:
                return frozenset()
            needs = {"limit_switches", "cycle_time"}
            if drive.method == "nc":
                needs.add("cam")
                if drive.reference_mode in ("hardware-sync", "software-sync"):
                    needs.add("zero_pulse")
            for search in (drive.first_search, drive.second_search):
                if search is not None and drive.method == "standard":
                    needs.add({"limit_switch": "limit_switches"}.get(search.trigger, search.trigger))
            return frozenset(needs)
        if not self.moves or self.unlatched_zero_pulse:  # the latter fails before it moves (LIS322)
            return frozenset()
        needs = {"limit_switches", "cycle_time"}
        if self.with_cam:
            needs.add("cam")
        if self.with_zero_pulse and not self.setup.simulated:  # a simulated drive's pulse: rpf_weg_bis_nip
            needs |= {"zero_pulse", "hardware_latch"}
        if self.retracts and not self.setup.simulated:
            needs.add("fixed_stop")
        if self.setup.spindle:
            needs.add("start_velocity")
        return frozenset(needs)

    def cam_may_move(self, scenario: Scenario) -> bool:
        """The cam is assumed and may be moved to fit the axis: CNC-controlled homing on a cam of a linear or
        non-modulo axis (a modulo axis meets its cam every revolution)."""
        return (
            "cam" in scenario.assumed
            and self.definition.with_cam
            and self.controlled_by == "cnc"
            and self.moves
            and scenario.modulo is None
        )

    def trial(self, scenario: Scenario) -> Trace:
        """Homing simulated with this geometry, to see whether it fits the axis."""
        from .motion import Simulator

        return Simulator(self.setup.axis, self, scenario).run()


def geometry_failure(failure: str | None) -> bool:
    """A failed run that ran out of travel (limit switch, homing_max_movement_dist) before its event."""
    return failure is not None and ("limit switch" in failure or "homing_max_movement_dist" in failure)


def opposite(direction: str) -> str:
    return NEGATIVE if direction == POSITIVE else POSITIVE
