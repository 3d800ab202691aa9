"""The rule codes: every rule module in code order with the severity of its findings, the scopes a rule
can take part in, and the selectors that pick rules by code or prefix.

A leaf of the rules: what a rule sees (`context`) and the engine read codes and severities here without
importing a single rule module; the registry (`rules/__init__.py`) imports the modules named here.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from enum import Enum

from ..core.diagnostics import Diagnostic, Severity


class Scope(Enum):
    """What a check looks at; the value is the name of the rule module's function for it."""

    LIST = "check"
    MACHINE = "check_machine"
    PROGRAM = "check_program"
    AFTER = "check_after"


# A rule's check for one scope, called with that scope's subject (see `rules/__init__.py`). Program rules
# (LIS6xx) import the machine and program modules inside check_program: a lint of lists imports every rule
# module, and should not pay for what only NC programs need.
Check = Callable[..., Iterable[Diagnostic]]

ERROR, WARNING, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO

# The list kinds (`catalogue.kinds` ids) a rule's LIST check runs for: its module's `KINDS`. A rule that
# declares none judges axis lists (an axis, its homing, its drive); the LIS0/1/2 families check any list
# with a catalogue against that kind's own catalogue and declare ALL_KINDS.
AXIS_KINDS: tuple[str, ...] = ("axis", "default_axis")
ALL_KINDS: tuple[str, ...] = ("*",)


def applies_to(kinds: tuple[str, ...], kind: str) -> bool:
    """Whether a rule declaring `kinds` runs for a list of `kind`."""
    return kinds == ALL_KINDS or kind in kinds


# Every rule module (`rules/<name>.py`, the code in front) and the severity its findings have unless the
# configuration's `[severity]` table says otherwise.
RULE_MODULES: dict[str, Severity] = {
    "lis001_syntax_error": ERROR,
    "lis002_missing_end_marker": WARNING,
    "lis003_content_after_end": WARNING,
    "lis004_misspelt_end_marker": WARNING,
    "lis005_duplicate_parameter": WARNING,
    "lis006_byte_order_mark": ERROR,
    "lis007_text_after_string": WARNING,
    "lis008_mixed_style": INFO,
    "lis009_unused_noqa": WARNING,
    "lis101_unknown_parameter": WARNING,
    "lis102_old_syntax": INFO,
    "lis103_alias_conflict": ERROR,
    "lis104_index_out_of_bounds": ERROR,
    "lis105_not_effective_for_drive": INFO,
    "lis201_wrong_type": ERROR,
    "lis202_out_of_range": ERROR,
    "lis203_unknown_symbol": ERROR,
    "lis204_achs_mode_bits": ERROR,
    "lis205_bad_reference": ERROR,
    "lis206_string_too_long": ERROR,
    "lis301_cam_free_needs_one_phase": ERROR,
    "lis302_reflow_above_refmax": ERROR,
    "lis303_refmax_above_limits": ERROR,
    "lis304_torq_distances": ERROR,
    "lis305_homing_type_vs_drive": ERROR,
    "lis306_torq_drive_type": ERROR,
    "lis307_ignore_abs_pos_incremental": ERROR,
    "lis308_disabled_incremental": WARNING,
    "lis309_homing_max_movement_dist": ERROR,
    "lis310_reference_check": ERROR,
    "lis311_encoder_overflow": ERROR,
    "lis312_sercos_drive_latch": ERROR,
    "lis313_refpkt_outside_limits": ERROR,
    "lis314_spindle_homing": ERROR,
    "lis315_fixed_stop_setup": ERROR,
    "lis316_gantry_slave_no_homing": ERROR,
    "lis317_homing_ends_outside_limits": WARNING,
    "lis318_no_reference_signal": ERROR,
    "lis319_spindle_homing_direction": ERROR,
    "lis320_spindle_homing_with_reversal": WARNING,
    "lis321_cam_direct_access": WARNING,
    "lis322_sercos_zero_pulse_without_latch": ERROR,
    "lis323_reference_cam_input": ERROR,
    "lis324_absolute_flag_drive_type": WARNING,
    "lis325_homing_acceleration_above_max": ERROR,
    "lis326_homing_ramp_time_below_min": ERROR,
    "lis327_spindle_not_modulo": ERROR,
    "lis328_fixed_stop_torque_not_limited": WARNING,
    "lis401_parameter_without_effect": INFO,
    "lis402_one_phase_with_cam": WARNING,
    "lis403_cam_edge_repeatability": WARNING,
    "lis404_homing_acceleration_fallback": INFO,
    "lis405_zero_pulse_near_cam_edge": WARNING,
    "lis501_duplicate_axis_number": WARNING,
    "lis502_duplicate_axis_name": WARNING,
    "lis503_gantry_master_missing": WARNING,
    "lis504_missing_list": ERROR,
    "lis505_xml_axis_definition": WARNING,
    "lis506_default_list_axis_number": ERROR,
    "lis507_gantry_master_chain": ERROR,
    "lis508_axis_named_twice_in_channel": WARNING,
    "lis510_gantry_homing_type_mismatch": ERROR,
    "lis511_gantry_drive_controlled_homing": ERROR,
    "lis512_channel_axis_without_list": ERROR,
    "lis513_channel_axis_type_mismatch": ERROR,
    "lis514_gantry_slave_in_channel": ERROR,
    "lis515_coupled_pair_vs_gantry": WARNING,
    "lis516_entry_beyond_count": WARNING,
    "lis517_count_without_entry": ERROR,
    "lis518_list_named_twice": ERROR,
    "lis519_compensation_for_missing_axis": WARNING,
    "lis520_compensation_axis_number_mismatch": ERROR,
    "lis521_offset_for_missing_channel_axis": WARNING,
    "lis522_channel_count_vs_lists": WARNING,
    "lis601_program_text": ERROR,
    "lis602_unknown_axis": ERROR,
    "lis603_axis_twice_in_g74": ERROR,
    "lis604_disabled_axis_homed": ERROR,
    "lis605_gantry_slave_alone": WARNING,
    "lis606_move_before_homing": WARNING,
    "lis607_ignored_axis_beside_moving_axes": WARNING,
    "lis701_path_axis_also_spindle": ERROR,
    "lis702_channel_name_twice": ERROR,
    "lis703_channel_count_vs_entries": WARNING,
    "lis704_compensation_table_vs_count": WARNING,
    "lis705_compensation_table_above_max_points": ERROR,
    "lis706_coupled_pair_conflict": WARNING,
}
_SEVERITY = {name[:6].upper(): severity for name, severity in RULE_MODULES.items()}


def known_codes() -> tuple[str, ...]:
    """Every rule code, in code order."""
    return tuple(_SEVERITY)


def severity(code: str) -> Severity:
    """The severity of a rule's findings before the configuration's `[severity]` overrides."""
    return _SEVERITY[code]


def selector_problem(selector: str) -> str | None:
    """Why a rule code or prefix picks no rule (with the closest codes), or None when it picks some."""
    code = selector.strip().upper()
    if _picks_some(code):
        return None
    return f"{selector.strip()!r} is not a rule code or a prefix of one; {_closest(code)}"


def code_hint(code: str) -> str:
    """A did-you-mean for a code that names no rule (`achslint rule LIS3011`): the codes a family prefix
    stands for (`LIS20`), a letter typed for a digit (`LIS3O2`), or the closest codes."""
    wanted = code.strip().upper()
    family = [c for c in known_codes() if c.startswith(wanted)] if re.fullmatch(r"LIS[0-9]+", wanted) else []
    if family:
        shown = ", ".join(family[:8]) + (", ..." if len(family) > 8 else "")
        return f"did you mean one of {shown}? ({wanted} is a prefix; name one rule)"
    return _closest(wanted)


def _picks_some(code: str) -> bool:
    return code == "ALL" or (
        bool(re.fullmatch(r"LIS[0-9]*", code)) and any(c.startswith(code) for c in known_codes())
    )


def _closest(code: str) -> str:
    """A did-you-mean hint: a letter typed for a digit first (`LIS3O2`), then the families or similar codes."""
    import difflib

    known = known_codes()
    if code.startswith("LIS"):
        digits = "LIS" + code[3:].translate(str.maketrans("OQDILZSB", "00011258"))
        if digits != code and _picks_some(digits):
            return f"did you mean {digits}?"
        if re.fullmatch(r"LIS[0-9]{0,2}", code):
            families = sorted({c[:4] for c in known})
            return f"the rule families are {', '.join(families)}"
    close = difflib.get_close_matches(code, known, n=3, cutoff=0.6)
    return f"did you mean {' or '.join(close)}?" if close else "`achslint rules` lists the codes"


def matches(code: str, selectors: Iterable[str]) -> bool:
    """True when a code is picked by any selector: "ALL", a full code or a prefix (LIS1, LIS20)."""
    return any(s == "ALL" or code.startswith(s.upper()) for s in selectors)
