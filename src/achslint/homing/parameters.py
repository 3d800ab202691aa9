"""The homing parameters `explain` shows and the reasons shared by several strategies."""

from __future__ import annotations

from ..axis.drives import DriveType
from ..axis.resolved import ResolvedAxis
from .base import Use

# In the manual's order: system parameters, then sequence parameters (§3.1, §3.2), then the special methods.
HOMING_PARAMETERS = (
    "kenngr.homing.homing_type",
    "kenngr.abs_pos_gueltig",
    "kenngr.antr_typ",
    "kenngr.achs_typ",
    "kenngr.ref_ohne_nocken",
    "kenngr.homing_without_zero_pulse",
    "lr_hw[0].cam_direct_access",
    "lr_hw[0].cam_level",
    "kenngr.ref_ohne_rev",
    "kenngr.ref_richt",
    "kenngr.fast_from_cam",
    "getriebe[i].vb_refmax",
    "getriebe[i].vb_reflow",
    "getriebe[i].a_ref",
    "getriebe[i].tr_ref",
    "getriebe[i].pos_refpkt",
    "kenngr.shift_offset_zero_pulse_activation",
    "antr.simu.rpf_weg_bis_nip",
    "kenngr.homing_overflow_evaluation",
    "antr.encoder_bit_range",
    "antr.encoder_overflow_offset",
    "antr.sercos.drive_supports_cnc_homing",
    "antr.sercos.cnc_homing_rt_bit_layout",
    "antr.cnc_homing_encoder",
    "antr.reference_cam_signal",
    "lr_hw[0].zero_pulse_search_max_dist",
    "lr_hw[0].move_from_cam_max_dist",
    "kenngr.homing_max_movement_dist",
    "kenngr.set_refpos_mode",
    "kenngr.set_refpos_offset",
    "getriebe[i].vb_not_referenced",
    "kenngr.write_reference_position_to_drive",
    "kenngr.homing.torq_homing_dir",
    "getriebe[i].homing.torq_move_velocity",
    "getriebe[i].homing.torq_move_acceleration",
    "getriebe[i].homing.torq_move_torque_limit",
    "kenngr.homing.torq_min_distance",
    "kenngr.homing.torq_max_distance",
    "kenngr.homing.torq_detect_time",
    "kenngr.homing.torq_detect_velocity_limit",
    "kenngr.homing.torq_detect_pos_lag_limit",
    "kenngr.homing.torq_detect_torque_limit",
    "kenngr.homing.torq_retraction_distance",
    "kenngr.homing.torq_homing_position",
    "kenngr.homing.torq_distance_to_block",
    "kenngr.gantry_slave_no_homing",
    "antr.reference_check.element_name",
    "antr.reference_check.bit_nr",
)

# Parameters that decide which strategy runs: they always matter.
SELECTORS = frozenset(
    {"kenngr.homing.homing_type", "kenngr.abs_pos_gueltig", "kenngr.antr_typ", "kenngr.achs_typ"}
)


def _gantry_slave(axis: ResolvedAxis) -> bool:
    return bool(axis.get("kenngr.gantry_ax_nr"))


def _sercos(axis: ResolvedAxis) -> bool:
    return axis.drive_type == DriveType.SERCOS


def _latch_on(axis: ResolvedAxis) -> bool:
    return axis.drive_type == DriveType.SERCOS and bool(axis.get("antr.sercos.drive_supports_cnc_homing"))


def _non_linear_slope(axis: ResolvedAxis) -> bool:
    return axis.get("getriebe[0].slope_type") != 0


def _overflow(axis: ResolvedAxis) -> bool:
    return bool(axis.get("kenngr.homing_overflow_evaluation"))


# Read under every strategy (monitoring and gantry coupling are independent of the homing sequence).
EVERYWHERE = {
    "antr.reference_check.element_name": Use(
        "reference monitoring after homing, independent of the strategy"
    ),
    "antr.reference_check.bit_nr": Use("reference monitoring after homing, independent of the strategy"),
    "kenngr.gantry_slave_no_homing": Use(
        "suppresses this gantry slave's own homing (P-AXIS-00074)",
        when=_gantry_slave,
        otherwise="only on a gantry slave (kenngr.gantry_ax_nr set)",
    ),
}

# Read by every strategy that moves the axis under the CNC's control.
CNC_MOVES = {
    **EVERYWHERE,
    "getriebe[i].vb_not_referenced": Use(
        "caps every move while the axis is not homed, the homing moves included"
    ),
    "kenngr.set_refpos_mode": Use("decides how the reference position is applied"),
    "kenngr.set_refpos_offset": Use("decides how the reference position is applied"),
    "getriebe[i].pos_refpkt": Use("the position the axis takes at the reference event"),
    "kenngr.homing_max_movement_dist": Use(
        "aborts homing when the reference is not found within this distance of the start (P-AXIS-00412)"
    ),
}

# The CNC-controlled sequences of §2.3 (types I, II, III, flying spindle homing).
SEQUENCE = {
    **CNC_MOVES,
    "kenngr.ref_ohne_nocken": Use("selects homing with or without reference cam"),
    "kenngr.ref_ohne_rev": Use("selects one phase or several phases"),
    "kenngr.ref_richt": Use("direction of the homing moves"),
    "getriebe[i].vb_reflow": Use("speed at which the reference is searched"),
    "getriebe[i].a_ref": Use("acceleration of the homing moves (0: min of a_grenz_stufe_1/2)"),
    "getriebe[i].tr_ref": Use(
        "ramp time of the homing moves",
        when=_non_linear_slope,
        otherwise="only with a non-linear slope (getriebe[i].slope_type other than 0)",
    ),
}

CAM = {
    "lr_hw[0].cam_direct_access": Use("how the cam signal is read (§3.1.2.3)"),
    "lr_hw[0].cam_level": Use("signal level of the operated cam"),
    "lr_hw[0].move_from_cam_max_dist": Use("bounds the move off the cam"),
    "antr.reference_cam_signal": Use("input the cam signal is read from (P-AXIS-00321)"),
}

ZERO_PULSE = {
    "kenngr.homing_without_zero_pulse": Use("selects zero pulse or cam edge for the reference"),
    "lr_hw[0].zero_pulse_search_max_dist": Use(
        "bounds the zero-pulse search, counted from where the zero-pulse logic is armed (the cam edge plus shift_offset_zero_pulse_activation; the manual does not say, this is the tool's reading)"
    ),
    "kenngr.homing_overflow_evaluation": Use("references on the encoder overflow instead of the zero pulse"),
    "antr.encoder_bit_range": Use(
        "encoder bits whose overflow marks the reference",
        when=_overflow,
        otherwise="only with encoder-overflow homing (homing_overflow_evaluation = 1)",
    ),
    "antr.encoder_overflow_offset": Use(
        "shifts the overflow within one encoder revolution",
        when=_overflow,
        otherwise="only with encoder-overflow homing (homing_overflow_evaluation = 1)",
    ),
    "antr.sercos.drive_supports_cnc_homing": Use(
        "lets the SERCOS drive latch the zero pulse (S-0-146)", when=_sercos, otherwise="SERCOS drives only"
    ),
    "antr.sercos.cnc_homing_rt_bit_layout": Use(
        "handshake bits of the drive's zero-pulse latch",
        when=_latch_on,
        otherwise="only with drive_supports_cnc_homing = 1 on a SERCOS drive",
    ),
    "antr.cnc_homing_encoder": Use(
        "encoder the drive latches the zero pulse of",
        when=_latch_on,
        otherwise="only with drive_supports_cnc_homing = 1 on a SERCOS drive",
    ),
}

CAM_AND_ZERO_PULSE = {
    "kenngr.shift_offset_zero_pulse_activation": Use(
        "delays the zero-pulse detection after the cam edge (§2.6)"
    ),
}

CAM_EDGE = {
    # Types I: the cam edge is the reference, there is no zero pulse to search.
    "kenngr.homing_without_zero_pulse": Use("selects the cam edge as the reference"),
}
