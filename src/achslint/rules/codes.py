"""The rule codes: every rule module in code order with the severity of its findings, the scopes it takes
part in and the list kinds it checks, and the selectors that pick rules by code or prefix.

A leaf of the rules: what a rule sees (`context`) and the engine read codes, severities, scopes and kinds
here without importing a single rule module, so that a run imports only the rule modules it runs (a lint of
axis lists loads no program rule and no rule of channel lists); the registry (`rules/__init__.py`) imports
the modules named here.
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

# The list kinds (`catalogue.kinds` ids) a rule's LIST check runs for. Most rules judge axis lists (an axis,
# its homing, its drive); the LIS0/1/2 families check any list with a catalogue against that kind's own
# catalogue (ALL_KINDS).
AXIS_KINDS: tuple[str, ...] = ("axis", "default_axis")
ALL_KINDS: tuple[str, ...] = ("*",)

# The scopes a rule takes part in: its module has the check function of each (`Scope` values) and no other.
LIST, MACHINE, PROGRAM, AFTER = (Scope.LIST,), (Scope.MACHINE,), (Scope.PROGRAM,), (Scope.AFTER,)
LIST_MACHINE = (Scope.LIST, Scope.MACHINE)
NO_CHECK: tuple[Scope, ...] = ()  # findings only another product makes (LIS405: the dry-run)


def applies_to(kinds: tuple[str, ...], kind: str) -> bool:
    """Whether a rule declaring `kinds` runs for a list of `kind`."""
    return kinds == ALL_KINDS or kind in kinds


# Every rule module (`rules/<name>.py`, the code in front): the severity its findings have unless the
# configuration's `[severity]` table says otherwise, its scopes, and the list kinds its LIST check runs for.
RULE_MODULES: dict[str, tuple[Severity, tuple[Scope, ...], tuple[str, ...]]] = {
    "lis001_syntax_error": (ERROR, LIST, ALL_KINDS),
    "lis002_missing_end_marker": (WARNING, LIST, ALL_KINDS),
    "lis003_content_after_end": (WARNING, LIST, ALL_KINDS),
    "lis004_misspelt_end_marker": (WARNING, LIST, ALL_KINDS),
    "lis005_duplicate_parameter": (WARNING, LIST, ALL_KINDS),
    "lis006_byte_order_mark": (ERROR, LIST, ALL_KINDS),
    "lis007_text_after_string": (WARNING, LIST, ALL_KINDS),
    "lis008_mixed_style": (INFO, LIST, ALL_KINDS),
    "lis009_unused_noqa": (WARNING, AFTER, ALL_KINDS),
    "lis101_unknown_parameter": (WARNING, LIST, ALL_KINDS),
    "lis102_old_syntax": (INFO, LIST, ALL_KINDS),
    "lis103_alias_conflict": (ERROR, LIST, ALL_KINDS),
    "lis104_index_out_of_bounds": (ERROR, LIST, ALL_KINDS),
    "lis105_not_effective_for_drive": (INFO, LIST, AXIS_KINDS),
    "lis201_wrong_type": (ERROR, LIST, ALL_KINDS),
    "lis202_out_of_range": (ERROR, LIST, ALL_KINDS),
    "lis203_unknown_symbol": (ERROR, LIST, ALL_KINDS),
    "lis204_achs_mode_bits": (ERROR, LIST, AXIS_KINDS),
    "lis205_bad_reference": (ERROR, LIST, ALL_KINDS),
    "lis206_string_too_long": (ERROR, LIST, ALL_KINDS),
    "lis301_cam_free_needs_one_phase": (ERROR, LIST, AXIS_KINDS),
    "lis302_reflow_above_refmax": (ERROR, LIST, AXIS_KINDS),
    "lis303_refmax_above_limits": (ERROR, LIST, AXIS_KINDS),
    "lis304_torq_distances": (ERROR, LIST, AXIS_KINDS),
    "lis305_homing_type_vs_drive": (ERROR, LIST, AXIS_KINDS),
    "lis306_torq_drive_type": (ERROR, LIST, AXIS_KINDS),
    "lis307_ignore_abs_pos_incremental": (ERROR, LIST, AXIS_KINDS),
    "lis308_disabled_incremental": (WARNING, LIST, AXIS_KINDS),
    "lis309_homing_max_movement_dist": (ERROR, LIST, AXIS_KINDS),
    "lis310_reference_check": (ERROR, LIST, AXIS_KINDS),
    "lis311_encoder_overflow": (ERROR, LIST, AXIS_KINDS),
    "lis312_sercos_drive_latch": (ERROR, LIST, AXIS_KINDS),
    "lis313_refpkt_outside_limits": (ERROR, LIST, AXIS_KINDS),
    "lis314_spindle_homing": (ERROR, LIST, AXIS_KINDS),
    "lis315_fixed_stop_setup": (ERROR, LIST, AXIS_KINDS),
    "lis316_gantry_slave_no_homing": (ERROR, LIST_MACHINE, AXIS_KINDS),
    "lis317_homing_ends_outside_limits": (WARNING, LIST, AXIS_KINDS),
    "lis318_no_reference_signal": (ERROR, LIST, AXIS_KINDS),
    "lis319_spindle_homing_direction": (ERROR, LIST, AXIS_KINDS),
    "lis320_spindle_homing_with_reversal": (WARNING, LIST, AXIS_KINDS),
    "lis321_cam_direct_access": (WARNING, LIST, AXIS_KINDS),
    "lis322_sercos_zero_pulse_without_latch": (ERROR, LIST, AXIS_KINDS),
    "lis323_reference_cam_input": (ERROR, LIST, AXIS_KINDS),
    "lis324_absolute_flag_drive_type": (WARNING, LIST, AXIS_KINDS),
    "lis325_homing_acceleration_above_max": (ERROR, LIST, AXIS_KINDS),
    "lis326_homing_ramp_time_below_min": (ERROR, LIST, AXIS_KINDS),
    "lis327_spindle_not_modulo": (ERROR, LIST, AXIS_KINDS),
    "lis328_fixed_stop_torque_not_limited": (ERROR, LIST, AXIS_KINDS),
    "lis401_parameter_without_effect": (INFO, LIST, AXIS_KINDS),
    "lis402_one_phase_with_cam": (WARNING, LIST, AXIS_KINDS),
    "lis403_cam_edge_repeatability": (WARNING, LIST, AXIS_KINDS),
    "lis404_homing_acceleration_fallback": (INFO, LIST, AXIS_KINDS),
    "lis405_zero_pulse_near_cam_edge": (WARNING, NO_CHECK, AXIS_KINDS),
    "lis501_duplicate_axis_number": (WARNING, MACHINE, AXIS_KINDS),
    "lis502_duplicate_axis_name": (WARNING, MACHINE, AXIS_KINDS),
    "lis503_gantry_master_missing": (WARNING, MACHINE, AXIS_KINDS),
    "lis504_missing_list": (ERROR, MACHINE, AXIS_KINDS),
    "lis505_xml_axis_definition": (WARNING, LIST, AXIS_KINDS),
    "lis506_default_list_axis_number": (ERROR, LIST, AXIS_KINDS),
    "lis507_gantry_master_chain": (ERROR, MACHINE, AXIS_KINDS),
    "lis508_axis_named_twice_in_channel": (WARNING, MACHINE, AXIS_KINDS),
    "lis510_gantry_homing_type_mismatch": (ERROR, MACHINE, AXIS_KINDS),
    "lis511_gantry_drive_controlled_homing": (ERROR, MACHINE, AXIS_KINDS),
    "lis512_channel_axis_without_list": (ERROR, MACHINE, AXIS_KINDS),
    "lis513_channel_axis_type_mismatch": (ERROR, MACHINE, AXIS_KINDS),
    "lis514_gantry_slave_in_channel": (ERROR, MACHINE, AXIS_KINDS),
    "lis515_coupled_pair_vs_gantry": (WARNING, MACHINE, AXIS_KINDS),
    "lis516_entry_beyond_count": (WARNING, MACHINE, AXIS_KINDS),
    "lis517_count_without_entry": (ERROR, MACHINE, AXIS_KINDS),
    "lis518_list_named_twice": (ERROR, MACHINE, AXIS_KINDS),
    "lis519_compensation_for_missing_axis": (WARNING, MACHINE, AXIS_KINDS),
    "lis520_compensation_axis_number_mismatch": (ERROR, MACHINE, AXIS_KINDS),
    "lis521_offset_for_missing_channel_axis": (WARNING, MACHINE, AXIS_KINDS),
    "lis522_channel_count_vs_lists": (WARNING, MACHINE, AXIS_KINDS),
    "lis523_entry_names_list_of_other_kind": (WARNING, MACHINE, AXIS_KINDS),
    "lis601_program_text": (ERROR, PROGRAM, AXIS_KINDS),
    "lis602_unknown_axis": (ERROR, PROGRAM, AXIS_KINDS),
    "lis603_axis_twice_in_g74": (ERROR, PROGRAM, AXIS_KINDS),
    "lis604_disabled_axis_homed": (ERROR, PROGRAM, AXIS_KINDS),
    "lis605_gantry_slave_alone": (WARNING, PROGRAM, AXIS_KINDS),
    "lis606_move_before_homing": (WARNING, PROGRAM, AXIS_KINDS),
    "lis607_ignored_axis_beside_moving_axes": (WARNING, PROGRAM, AXIS_KINDS),
    "lis701_path_axis_also_spindle": (ERROR, LIST, ("channel",)),
    "lis702_channel_name_twice": (ERROR, LIST, ("channel",)),
    "lis703_channel_count_vs_entries": (WARNING, LIST, ("channel",)),
    "lis704_compensation_table_vs_count": (WARNING, LIST, ("compensation",)),
    "lis705_compensation_table_above_max_points": (ERROR, LIST, ("compensation",)),
    "lis706_coupled_pair_conflict": (WARNING, LIST, ("channel",)),
}
_BY_CODE = {name[:6].upper(): (name, *declared) for name, declared in RULE_MODULES.items()}


def known_codes() -> tuple[str, ...]:
    """Every rule code, in code order."""
    return tuple(_BY_CODE)


def module_name(code: str) -> str:
    """The name of the rule's module in `rules/` (`lis202_out_of_range`)."""
    return _BY_CODE[code][0]


def severity(code: str) -> Severity:
    """The severity of a rule's findings before the configuration's `[severity]` overrides."""
    return _BY_CODE[code][1]


def scopes(code: str) -> tuple[Scope, ...]:
    """The scopes a rule's checks take part in."""
    return _BY_CODE[code][2]


def kinds(code: str) -> tuple[str, ...]:
    """The list kinds a rule's LIST check runs for."""
    return _BY_CODE[code][3]


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
