"""The homing value object: everything a homing strategy needs from the resolved
axis, in mm (degrees on rotary axes and spindles) and seconds, after the CNC's
corrections — the one place where list units are turned into physics."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

from ..axis.corrections import encoder_revolution
from ..axis.drives import SIMULATION
from ..axis.resolved import ResolvedAxis

POSITION = 1e-4  # 0.1 µm or 0.0001° per list unit
VELOCITY = 1e-3  # µm/s -> mm/s, 0.001°/s -> °/s


# Where an acceleration of the homing moves comes from, in words (the dry-run's header and JSON).
_SOURCES = {
    "a_ref": "getriebe[i].a_ref (P-AXIS-00285)",
    "fallback": "a_ref is 0: min(lslope_profil.a_grenz_stufe_1, a_grenz_stufe_2) (P-AXIS-00005/00006, §3.2.4)",
    "default ramps": "spindle default ramps: min(lslope_profil.a_grenz_stufe_1, a_grenz_stufe_2) "
    "(P-AXIS-00005/00006; a_ref is for axis types T and R, §2.3.2.1)",
    "torq_move_acceleration": "getriebe[i].homing.torq_move_acceleration (P-AXIS-00334)",
}


@dataclass(frozen=True)
class Acceleration:
    value: float  # mm/s² or °/s²
    # "a_ref", "fallback" (min of the linear slope's rapid accelerations), "default ramps" (spindles) or
    # "torq_move_acceleration" (homing to a fixed stop)
    source: str

    @property
    def fallback(self) -> bool:
        """The homing acceleration is not a_ref of its own but the CNC's stand-in (LIS404)."""
        return self.source in ("fallback", "default ramps")

    @property
    def words(self) -> str:
        return _SOURCES[self.source]

    @property
    def ramp(self) -> float:
        """What the simulated moves use. A homing acceleration of 0 (a_ref and both slopes unset) is taken as
        1 unit/s² so the axis still moves; fixed-stop homing reports a torq_move_acceleration of 0 itself."""
        if self.value or self.source == "torq_move_acceleration":
            return self.value
        return 1.0


class HomingSetup:
    """The homing-relevant values of one axis for one gear stage."""

    def __init__(self, axis: ResolvedAxis, gear: int = 0) -> None:
        self.axis = axis
        self.gear = gear
        self.axis_type = axis.axis_type
        self.rotary = self.axis_type in ("R", "S")
        self.spindle = self.axis_type == "S"
        self.unit = "deg" if self.rotary else "mm"

    def stage(self, member: str) -> str:
        """`vb_reflow` -> `getriebe[<gear>].vb_reflow`."""
        return f"getriebe[{self.gear}].{member}"

    def speed(self, member: str) -> float:
        """A speed of this gear stage in list units, after the CNC's caps."""
        return self.axis.number(self.stage(member))

    # -- what selects the sequence ---------------------------------------------------------------
    @cached_property
    def homing_type(self) -> str:
        return self.axis.homing_type

    @cached_property
    def absolute(self) -> bool:
        return bool(self.axis.get("kenngr.abs_pos_gueltig"))

    @cached_property
    def simulated(self) -> bool:
        return self.axis.drive_type == SIMULATION

    @cached_property
    def with_cam(self) -> bool:
        return not self.axis.get("kenngr.ref_ohne_nocken")

    @cached_property
    def overflow(self) -> bool:
        return bool(self.axis.get("kenngr.homing_overflow_evaluation"))

    @cached_property
    def zero_pulse(self) -> bool:
        """References on a zero pulse (or the encoder overflow that replaces it); spindles always do (P-AXIS-00084 is for T, R)."""
        return self.overflow or self.spindle or not self.axis.get("kenngr.homing_without_zero_pulse")

    @cached_property
    def one_phase(self) -> bool:
        return bool(self.axis.get("kenngr.ref_ohne_rev"))

    @cached_property
    def direction(self) -> int:
        return 1 if self.axis.get("kenngr.ref_richt") else -1

    @cached_property
    def torq_direction(self) -> int:
        return 1 if self.axis.get("kenngr.homing.torq_homing_dir") else -1

    @cached_property
    def cam_level(self) -> bool:
        return bool(self.axis.get("lr_hw[0].cam_level"))

    @cached_property
    def falling_edge(self) -> bool:
        """Cam signal inverted (cam_level 0): with a 1-active switch the reference is the falling edge (§2.3.3.1)."""
        return self.with_cam and not self.cam_level

    # -- physics -----------------------------------------------------------------------------------
    @cached_property
    def fast(self) -> float:
        return self.speed("vb_refmax") * VELOCITY

    @cached_property
    def slow(self) -> float:
        return self.speed("vb_reflow") * VELOCITY

    @cached_property
    def fast_from_cam(self) -> bool:
        return bool(self.axis.get("kenngr.fast_from_cam"))

    @cached_property
    def unreferenced_limit(self) -> float:
        """vb_not_referenced in mm/s (°/s); infinite when 0 (no limit)."""
        cap = self.speed("vb_not_referenced") * VELOCITY
        return cap if cap > 0 else float("inf")

    @cached_property
    def acceleration(self) -> Acceleration:
        """P-AXIS-00285, or min(P-AXIS-00005, P-AXIS-00006) when 0 (§3.2.4); spindles use their default ramps (§2.3.2.1)."""
        fallback = min(
            self.axis.number(self.stage("lslope_profil.a_grenz_stufe_1")),
            self.axis.number(self.stage("lslope_profil.a_grenz_stufe_2")),
        )
        if self.spindle:
            return Acceleration(float(fallback), "default ramps")
        own = self.axis.number(self.stage("a_ref"))
        if own:
            return Acceleration(float(own), "a_ref")
        return Acceleration(float(fallback), "fallback")

    @cached_property
    def modulo(self) -> tuple[float, float] | None:
        """The modulo range [modulou, moduloo) of this gear stage in degrees, or None when positions do not wrap.

        Spindles always count modulo; a rotary axis does with the MODULO bit (0x4) of kenngr.achs_mode
        (P-AXIS-00015), and not with LINEAR (a rotary axis with a restricted range). Linear axes never do here
        (MODULO_LINEAR conveyors are not simulated modulo)."""
        if not self.rotary:
            return None
        if not self.spindle and not int(self.axis.number("kenngr.achs_mode")) & 0x4:
            return None
        low = self.axis.number(self.stage("modulou")) * POSITION
        high = self.axis.number(self.stage("moduloo")) * POSITION
        return (low, high) if high > low else None

    @cached_property
    def shift(self) -> float:
        return self.axis.number("kenngr.shift_offset_zero_pulse_activation") * POSITION

    @cached_property
    def zero_pulse_search_max(self) -> float:
        return self.axis.number("lr_hw[0].zero_pulse_search_max_dist") * POSITION

    @cached_property
    def path_limit(self) -> float:
        """homing_max_movement_dist (0 = off; the CNC sets it to 0 on linear axes)."""
        return self.axis.number("kenngr.homing_max_movement_dist") * POSITION

    @cached_property
    def reference_position(self) -> float:
        return self.axis.number(self.stage("pos_refpkt")) * POSITION

    @cached_property
    def soft_limits(self) -> tuple[float, float]:
        return self.axis.number("kenngr.swe_neg") * POSITION, self.axis.number("kenngr.swe_pos") * POSITION

    @cached_property
    def overflow_period(self) -> float | None:
        """One encoder revolution of this gear stage (the overflow lattice), if encoder_bit_range and the resolution say."""
        revolution = encoder_revolution(self.axis, self.gear)
        return revolution * POSITION if revolution else None

    @cached_property
    def overflow_offset(self) -> float:
        return self.axis.number("antr.encoder_overflow_offset") * POSITION

    @cached_property
    def simulated_distance(self) -> float:
        return abs(self.axis.number("antr.simu.rpf_weg_bis_nip")) * POSITION

    # -- fixed stop (TORQ) ---------------------------------------------------------------------------
    @cached_property
    def torq_speed(self) -> float:
        return self.speed("homing.torq_move_velocity") * VELOCITY

    @cached_property
    def torq_acceleration(self) -> float:
        return float(self.speed("homing.torq_move_acceleration"))

    @cached_property
    def torq_ramp(self) -> Acceleration:
        """The acceleration of the moves to and from the fixed stop (P-AXIS-00334)."""
        return Acceleration(self.torq_acceleration, "torq_move_acceleration")

    def distance(self, path: str) -> float:
        """A length parameter in mm (degrees)."""
        return self.axis.number(path) * POSITION
