"""Which homing strategy an axis is configured for, its phases, and which
homing parameters matter under it.

The classification follows the TF5200 homing manual:

* absolute axes (P-AXIS-00014 = 1) need no homing move (§2, effectiveness
  type IV); `DISABLED` and `IGNORE_ABS_POS` are for such axes (P-AXIS-00299);
* the homing type is P-AXIS-00299, or the drive type's default when it is not
  set or `DRIVE_DEFAULT` (P-AXIS-00299 table: SERCOS drive-controlled, all
  others CNC-controlled);
* drive-controlled homing runs the drive's own sequence (§3.1.1.2);
* `TORQ` moves to a fixed stop (§2.3.3.4);
* simulated drives home in one phase over P-AXIS-00161 (§3.4);
* CNC-controlled homing of a spindle with P-AXIS-00157 = 1 is flying homing,
  with or without cam (§2.3.2);
* otherwise the manual's types I (cam only), II (zero pulse only) and III
  (cam and zero pulse), in three phases or — with P-AXIS-00157 = 1 — one phase
  (§2.3.1, §2.3.3), optionally on the falling cam edge (inverted P-AXIS-00038
  and P-AXIS-00158, §2.3.3.1), with delayed zero-pulse activation
  (P-AXIS-00494, §2.6) or on the encoder overflow (P-AXIS-00294, §3.1.1.2).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .effective import SIMULATION, AxisValues
from .units import describe

POSITIVE, NEGATIVE = "positive", "negative"


@dataclass
class Phase:
    name: str
    direction: str | None
    velocity_parameter: str | None  # canonical path of the speed used
    velocity: float | None  # in list units (µm/s or 0.001°/s)
    ends_when: str
    note: str = ""


@dataclass
class HomingStrategy:
    id: str
    title: str
    description: str
    controlled_by: str  # "cnc", "drive", "none"
    manual_type: str | None = None  # I, II, III, IV of the effectiveness table (§3.5)
    phases: list[Phase] = field(default_factory=list)
    variants: list[str] = field(default_factory=list)
    gear: int = 0
    with_cam: bool = False
    with_zero_pulse: bool = False
    one_phase: bool = False
    falling_edge: bool = False

    @property
    def moves(self) -> bool:
        return bool(self.phases)


def _opposite(direction: str) -> str:
    return NEGATIVE if direction == POSITIVE else POSITIVE


def classify(values: AxisValues, gear: int = 0) -> HomingStrategy:
    """The homing strategy of the axis (gear stage `gear` for speeds)."""
    homing_type = values.homing_type
    absolute = bool(values.get("kenngr.abs_pos_gueltig"))
    if homing_type == "DISABLED":
        return HomingStrategy(
            "disabled", "homing disabled",
            "Homing is disabled: G74 for this axis is refused with an error. Meant for axes with an absolute "
            "measuring system." + ("" if absolute else " This axis has an incremental one, so it can never be homed."),
            "none", "IV" if absolute else None, gear=gear,
        )
    if homing_type == "IGNORE_ABS_POS":
        return HomingStrategy(
            "ignore_abs_pos", "homing skipped (IGNORE_ABS_POS)",
            "The axis is skipped by G74 without an error; it relies on its absolute encoder."
            + ("" if absolute else " Without an absolute encoder (abs_pos_gueltig = 0) the CNC warns (P-ERR-110584)."),
            "none", "IV" if absolute else None, gear=gear,
        )
    if absolute:
        return HomingStrategy(
            "absolute", "no homing move (absolute measuring system)",
            "The axis has an absolute measuring system (abs_pos_gueltig = 1): its position is known at power-up, "
            "so no homing move is needed.",
            "none", "IV", gear=gear,
        )
    if homing_type == "DRIVE_CONTROLLED":
        return HomingStrategy(
            "drive_controlled", "drive-controlled homing",
            f"The drive ({values.drive_name()}) runs its own homing sequence (SERCOS command S-0-148 or the "
            "CANopen homing mode); the cam must be wired to the drive and the CNC's sequence parameters are not used.",
            "drive", gear=gear,
        )
    if homing_type == "TORQ":
        return _fixed_stop(values, gear)
    if homing_type == "NONE":
        return HomingStrategy(
            "none", "reference position adopted (compatibility mode NONE)",
            "When homing is commanded, pos_refpkt is taken over as the axis position; a simulated axis moves a "
            "short distance first, a DSE axis does not move.",
            "cnc", gear=gear,
        )
    if values.drive_type == SIMULATION:
        return _simulation(values, gear)
    if values.axis_type == "S" and values.get("kenngr.ref_ohne_rev"):
        return _flying_spindle(values, gear)
    return _cnc(values, gear)


def _speed(values: AxisValues, gear: int, member: str) -> tuple[str, float]:
    path = f"getriebe[{gear}].{member}"
    return path, values.get(path)


def _direction(values: AxisValues) -> str:
    return POSITIVE if values.get("kenngr.ref_richt") else NEGATIVE


def _simulation(values: AxisValues, gear: int) -> HomingStrategy:
    direction = _direction(values)
    path, speed = _speed(values, gear, "vb_reflow")
    distance = values.get("antr.simu.rpf_weg_bis_nip")
    unit = values.parameter("antr.simu.rpf_weg_bis_nip").unit(values.axis_type)
    return HomingStrategy(
        "simulation", "simulated drive: single phase",
        "The drive is simulated: homing runs in one phase without a cam and sets the reference after the "
        "simulated distance to the zero pulse (rpf_weg_bis_nip); the other homing parameters are not used.",
        "cnc", phases=[Phase("to the simulated zero pulse", direction, path, speed,
                             f"the simulated zero pulse after rpf_weg_bis_nip = {describe(distance, unit)}",
                             "the manual does not name the speed of this phase; vb_reflow is assumed")],
        gear=gear, with_zero_pulse=True, one_phase=True,
    )


def _flying_spindle(values: AxisValues, gear: int) -> HomingStrategy:
    direction = _direction(values)
    with_cam = not values.get("kenngr.ref_ohne_nocken")
    path, speed = _speed(values, gear, "vb_reflow")
    if with_cam:
        ends = "the cam is left (its edge from operated to not operated) and the next zero pulse arrives"
        title = "flying homing of a spindle with cam"
    else:
        ends = "the zero pulse arrives (one pulse per spindle revolution)"
        title = "flying homing of a spindle without cam"
    return HomingStrategy(
        "spindle_flying_cam" if with_cam else "spindle_flying_zero_pulse", title,
        "The spindle references while it turns, without stopping or reversing: it runs at vb_reflow in the "
        "homing direction (also from endless rotation) and takes the reference on the fly.",
        "cnc", phases=[Phase("reference on the fly", direction, path, speed, ends)],
        gear=gear, with_cam=with_cam, with_zero_pulse=True, one_phase=True,
    )


def _fixed_stop(values: AxisValues, gear: int) -> HomingStrategy:
    direction = POSITIVE if values.get("kenngr.homing.torq_homing_dir") else NEGATIVE
    path, speed = _speed(values, gear, "homing.torq_move_velocity")
    retraction = values.get("kenngr.homing.torq_retraction_distance")
    unit = values.parameter("kenngr.homing.torq_retraction_distance").unit(values.axis_type)
    return HomingStrategy(
        "fixed_stop", "homing to a fixed stop (TORQ)",
        "The axis moves with limited torque towards a mechanical stop; when the stop is detected, the position "
        "torq_homing_position is set and the axis backs off by the retraction distance.",
        "cnc",
        phases=[
            Phase("to the fixed stop", direction, path, speed,
                  "the stop is detected (after torq_min_distance; abort after torq_max_distance)"),
            Phase("retract from the stop", _opposite(direction), path, speed,
                  f"torq_retraction_distance = {describe(retraction, unit)} is travelled"),
        ],
        gear=gear,
    )


def _cnc(values: AxisValues, gear: int) -> HomingStrategy:
    direction = _direction(values)
    with_cam = not values.get("kenngr.ref_ohne_nocken")
    overflow = bool(values.get("kenngr.homing_overflow_evaluation"))
    zero_pulse = not values.get("kenngr.homing_without_zero_pulse")
    one_phase = bool(values.get("kenngr.ref_ohne_rev"))
    falling = with_cam and not values.get("lr_hw[0].cam_level")
    fast_path, fast = _speed(values, gear, "vb_refmax")
    slow_path, slow = _speed(values, gear, "vb_reflow")
    event = "the encoder overflow" if overflow else ("the next zero pulse" if zero_pulse else "the cam edge")
    variants = []
    if overflow:
        variants.append("reference on the encoder overflow instead of the zero pulse (P-AXIS-00294)")
    if falling:
        variants.append("cam active at a 0-signal (cam_level = 0): referencing on the falling edge, moving off the cam")
    shift = values.get("kenngr.shift_offset_zero_pulse_activation")
    if zero_pulse and with_cam and shift:
        variants.append(f"zero-pulse detection switched on only {shift} after the cam edge (P-AXIS-00494)")

    if not with_cam:
        manual_type = "II"
        strategy_id, title = "zero_pulse_only", "zero pulse without reference cam (type II)"
        description = "There is no reference cam: the axis moves at vb_reflow in the homing direction and takes the first zero pulse as the reference."
        phases = [Phase("to the zero pulse", direction, slow_path, slow, f"{event} is detected")]
    else:
        manual_type = "III" if zero_pulse or overflow else "I"
        what = "on the cam and the zero pulse (type III)" if manual_type == "III" else "on the cam only, without zero pulse (type I)"
        if one_phase:
            strategy_id = "one_phase_cam_zero_pulse" if manual_type == "III" else "one_phase_cam"
            title = f"one-phase homing {what}"
            description = (
                "Homing in a single phase without reversal: the axis moves in the homing direction until the cam "
                f"and then references on {event}. It must not start on the cam (the PLC has to check this)."
            )
            phases = [Phase("to the cam and reference", direction, slow_path, slow,
                            f"the cam is reached and {event} is detected",
                            "the manual does not name the speed of the single phase; vb_reflow is assumed")]
        else:
            strategy_id = "cam_zero_pulse" if manual_type == "III" else "cam_only"
            title = f"three-phase homing {what}"
            description = (
                "Default homing in three phases: to the reference cam at the fast speed, back off the cam, and "
                f"slowly onto the cam again, referencing on {event}."
            )
            off_path, off_speed = (fast_path, fast) if values.get("kenngr.fast_from_cam") else (slow_path, slow)
            phases = [
                Phase("to the reference cam", direction, fast_path, fast, "the cam is reached (skipped when starting on the cam)"),
                Phase("off the reference cam", _opposite(direction), off_path, off_speed, "the cam is left"),
                Phase("onto the cam and reference", direction, slow_path, slow, f"the cam is reached and {event} is detected"),
            ]
    return HomingStrategy(
        strategy_id, title, description, "cnc", manual_type, phases, variants, gear,
        with_cam=with_cam, with_zero_pulse=zero_pulse or overflow, one_phase=one_phase or not with_cam,
        falling_edge=falling,
    )


# --- which homing parameters matter ------------------------------------------------------------

# The homing parameters explain shows, in the manual's order (system, then sequence parameters).
HOMING_PARAMETERS = [
    "kenngr.homing.homing_type", "kenngr.abs_pos_gueltig", "kenngr.antr_typ", "kenngr.achs_typ",
    "kenngr.ref_ohne_nocken", "kenngr.homing_without_zero_pulse", "lr_hw[0].cam_direct_access",
    "lr_hw[0].cam_level", "kenngr.ref_ohne_rev", "kenngr.ref_richt", "kenngr.fast_from_cam",
    "getriebe[i].vb_refmax", "getriebe[i].vb_reflow", "getriebe[i].a_ref", "getriebe[i].tr_ref",
    "getriebe[i].pos_refpkt", "kenngr.shift_offset_zero_pulse_activation", "antr.simu.rpf_weg_bis_nip",
    "kenngr.homing_overflow_evaluation", "antr.encoder_bit_range", "antr.encoder_overflow_offset",
    "antr.sercos.drive_supports_cnc_homing", "antr.sercos.cnc_homing_rt_bit_layout", "antr.cnc_homing_encoder",
    "antr.reference_cam_signal", "lr_hw[0].zero_pulse_search_max_dist", "lr_hw[0].move_from_cam_max_dist",
    "kenngr.homing_max_movement_dist", "kenngr.set_refpos_mode", "kenngr.set_refpos_offset",
    "getriebe[i].vb_not_referenced", "kenngr.write_reference_position_to_drive",
    "kenngr.homing.torq_homing_dir", "getriebe[i].homing.torq_move_velocity",
    "getriebe[i].homing.torq_move_acceleration", "getriebe[i].homing.torq_move_torque_limit",
    "kenngr.homing.torq_min_distance", "kenngr.homing.torq_max_distance", "kenngr.homing.torq_detect_time",
    "kenngr.homing.torq_detect_velocity_limit", "kenngr.homing.torq_detect_pos_lag_limit",
    "kenngr.homing.torq_detect_torque_limit", "kenngr.homing.torq_retraction_distance",
    "kenngr.homing.torq_homing_position", "kenngr.homing.torq_distance_to_block",
    "kenngr.gantry_slave_no_homing", "antr.reference_check.element_name", "antr.reference_check.bit_nr",
]

_TORQ = {p for p in HOMING_PARAMETERS if ".torq_" in p}
_CAM = {"lr_hw[0].cam_direct_access", "lr_hw[0].cam_level", "lr_hw[0].move_from_cam_max_dist", "antr.reference_cam_signal"}
_OVERFLOW = {"antr.encoder_bit_range", "antr.encoder_overflow_offset"}
_SERCOS_LATCH = {"antr.sercos.drive_supports_cnc_homing", "antr.sercos.cnc_homing_rt_bit_layout", "antr.cnc_homing_encoder"}
_NO_MOVE = {
    "absolute": "an axis with an absolute measuring system does not move to home",
    "disabled": "homing is disabled for this axis",
    "ignore_abs_pos": "G74 skips this axis (IGNORE_ABS_POS)",
}
_ALWAYS = {"kenngr.homing.homing_type", "kenngr.abs_pos_gueltig", "kenngr.antr_typ", "kenngr.achs_typ"}


def homing_parameter_paths(gear: int = 0) -> list[str]:
    return [p.replace("[i]", f"[{gear}]") for p in HOMING_PARAMETERS]


def effectiveness(strategy: HomingStrategy, values: AxisValues, path: str) -> tuple[bool, str]:
    """Whether a homing parameter (canonical path) takes effect under the strategy, and why."""
    generic = path.replace(f"getriebe[{strategy.gear}]", "getriebe[i]").replace("lr_hw[1]", "lr_hw[0]")
    if generic in _ALWAYS:
        return True, "selects the homing strategy"
    if generic == "kenngr.gantry_slave_no_homing":
        return (values.get("kenngr.gantry_ax_nr") != 0,
                "only on a gantry slave axis (kenngr.gantry_ax_nr set)")
    if generic.startswith("antr.reference_check."):
        return True, "reference monitoring after homing, independent of the strategy"
    if generic in ("kenngr.set_refpos_mode", "kenngr.set_refpos_offset"):
        return strategy.controlled_by != "drive", "decides how the reference position is applied"
    if strategy.id in _NO_MOVE:
        return False, _NO_MOVE[strategy.id]
    if generic == "getriebe[i].vb_not_referenced":
        return True, "caps every move of the axis while it is not homed (also the homing speeds)"
    if strategy.controlled_by == "drive":
        if generic == "getriebe[i].pos_refpkt":
            return bool(values.get("kenngr.write_reference_position_to_drive")), "sent to the drive only with write_reference_position_to_drive = 1"
        if generic == "kenngr.write_reference_position_to_drive":
            return True, "sends pos_refpkt to the drive for its homing"
        return False, "drive-controlled homing: the drive's own parameters define the sequence"
    if strategy.id == "fixed_stop":
        if generic in _TORQ:
            if generic == "kenngr.homing.torq_distance_to_block":
                return values.drive_type == SIMULATION, "distance to the simulated stop, simulated drives only"
            return True, "parameter of homing to a fixed stop"
        if generic in ("getriebe[i].a_ref", "getriebe[i].tr_ref"):
            return False, "fixed-stop homing uses its own speed and acceleration"
        return False, "fixed-stop homing uses only the torq_* parameters"
    if generic in _TORQ:
        return False, "only used by fixed-stop homing (TORQ)"
    if strategy.id == "simulation":
        if generic in ("antr.simu.rpf_weg_bis_nip", "getriebe[i].pos_refpkt"):
            return True, "simulated homing: distance to the zero pulse and reference position"
        if generic in ("kenngr.ref_richt", "getriebe[i].vb_reflow"):
            return True, "direction / speed of the simulated move (assumed: the manual names only rpf_weg_bis_nip)"
        return False, "simulated drives home in one phase over rpf_weg_bis_nip; other homing parameters are ignored (§3.4)"
    if generic == "antr.simu.rpf_weg_bis_nip":
        return False, "only used by simulated drives"
    if strategy.id == "none":
        return generic == "getriebe[i].pos_refpkt", "compatibility mode NONE only adopts pos_refpkt"
    # CNC-controlled sequences (types I, II, III and flying spindle homing).
    overflow = bool(values.get("kenngr.homing_overflow_evaluation"))
    if generic in _OVERFLOW:
        return overflow, "only with encoder-overflow homing (homing_overflow_evaluation = 1)"
    if generic in _SERCOS_LATCH:
        if values.drive_type != 2:
            return False, "SERCOS drives only"
        if generic == "antr.sercos.drive_supports_cnc_homing":
            return True, "lets the SERCOS drive latch the zero pulse (S-0-146)"
        return bool(values.get("antr.sercos.drive_supports_cnc_homing")), "only with drive_supports_cnc_homing = 1"
    if generic in _CAM:
        return strategy.with_cam, "only with a reference cam" if not strategy.with_cam else "reads the reference cam"
    if generic == "kenngr.ref_ohne_nocken":
        return True, "selects cam or no cam"
    if generic == "kenngr.homing_without_zero_pulse":
        return True, "selects zero pulse or cam edge for the reference"
    if generic == "kenngr.ref_ohne_rev":
        if not strategy.with_cam:
            return True, "must be 1 without a reference cam (one phase)"
        return True, "selects one or three phases"
    if generic == "kenngr.fast_from_cam":
        multi = strategy.with_cam and not strategy.one_phase
        return multi, "speed of phase 2 (off the cam)" if multi else "no phase 2: the sequence does not reverse at the cam"
    if generic == "getriebe[i].vb_refmax":
        multi = strategy.with_cam and not strategy.one_phase
        return multi, "speed of phase 1 (to the cam)" if multi else "no fast search phase in this sequence (effectiveness table §3.5)"
    if generic == "kenngr.shift_offset_zero_pulse_activation":
        used = strategy.with_cam and strategy.with_zero_pulse
        return used, "delays zero-pulse detection after the cam edge" if used else "needs a cam and a zero pulse"
    if generic == "lr_hw[0].zero_pulse_search_max_dist":
        return strategy.with_zero_pulse, "bounds the zero-pulse search" if strategy.with_zero_pulse else "no zero-pulse search"
    if generic == "kenngr.homing_max_movement_dist":
        return values.axis_type in ("R", "S"), "path monitoring works for rotary axes and spindles only"
    if generic == "kenngr.write_reference_position_to_drive":
        return False, "only for drive-controlled homing"
    return True, "used by the CNC-controlled sequence"
