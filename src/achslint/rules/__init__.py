"""The rule registry: every rule module, listed explicitly and in code order.

A rule is a module with `CODE`, `NAME`, `SEVERITY`, `FIX` ("none", "safe",
"unsafe" or "sometimes"), `SUMMARY`, a docstring with the sections
What / Why / Example / Use instead / Reference, and one check function for
each scope it takes part in; the function's name says the scope and what it
is given:

    check(ctx)                          LIST: one axis list (`context.Context`)
    check_machine(members, startups)    MACHINE: the summaries of a machine's axis
                                        lists and its start-up lists (LIS5xx)
    check_program(program, machine)     PROGRAM: a homing program read against a
                                        machine (LIS6xx)
    check_after(suppressions, enabled)  AFTER: what the `noqa` directives of a list
                                        or a program suppressed (LIS009)

Every check is a generator of diagnostics and runs in the one lint engine
(`lintengine.run`), which also selects the rules, applies the suppressions and
the severity overrides. `achslint rule CODE` prints the docstring.
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from enum import Enum
from functools import cached_property, lru_cache
from types import ModuleType

from ..core.diagnostics import Diagnostic, Severity


class Scope(Enum):
    """What a check looks at; the value is the name of the rule module's function for it."""

    LIST = "check"
    MACHINE = "check_machine"
    PROGRAM = "check_program"
    AFTER = "check_after"


# A rule's check for one scope, called with that scope's subject (see the module docstring). Program
# rules (LIS6xx) import the machine and program modules inside check_program: a lint of lists imports every
# rule module, and should not pay for what only NC programs need.
Check = Callable[..., Iterable[Diagnostic]]

RULE_MODULES = (
    "lis001_syntax_error",
    "lis002_missing_end_marker",
    "lis003_content_after_end",
    "lis004_misspelt_end_marker",
    "lis005_duplicate_parameter",
    "lis006_byte_order_mark",
    "lis007_text_after_string",
    "lis008_mixed_style",
    "lis009_unused_noqa",
    "lis101_unknown_parameter",
    "lis102_old_syntax",
    "lis103_alias_conflict",
    "lis104_index_out_of_bounds",
    "lis105_not_effective_for_drive",
    "lis201_wrong_type",
    "lis202_out_of_range",
    "lis203_unknown_symbol",
    "lis204_achs_mode_bits",
    "lis205_bad_reference",
    "lis206_string_too_long",
    "lis301_cam_free_needs_one_phase",
    "lis302_reflow_above_refmax",
    "lis303_refmax_above_limits",
    "lis304_torq_distances",
    "lis305_homing_type_vs_drive",
    "lis306_torq_drive_type",
    "lis307_ignore_abs_pos_incremental",
    "lis308_disabled_incremental",
    "lis309_homing_max_movement_dist",
    "lis310_reference_check",
    "lis311_encoder_overflow",
    "lis312_sercos_drive_latch",
    "lis313_refpkt_outside_limits",
    "lis314_spindle_homing",
    "lis315_fixed_stop_setup",
    "lis316_gantry_slave_no_homing",
    "lis317_homing_ends_outside_limits",
    "lis318_no_reference_signal",
    "lis319_spindle_homing_direction",
    "lis320_spindle_homing_with_reversal",
    "lis321_cam_direct_access",
    "lis322_sercos_zero_pulse_without_latch",
    "lis323_reference_cam_input",
    "lis324_absolute_flag_drive_type",
    "lis325_homing_acceleration_above_max",
    "lis326_homing_ramp_time_below_min",
    "lis327_spindle_not_modulo",
    "lis328_fixed_stop_torque_not_limited",
    "lis401_parameter_without_effect",
    "lis402_one_phase_with_cam",
    "lis403_cam_edge_repeatability",
    "lis404_homing_acceleration_fallback",
    "lis405_zero_pulse_near_cam_edge",
    "lis501_duplicate_axis_number",
    "lis502_duplicate_axis_name",
    "lis503_gantry_master_missing",
    "lis504_missing_list",
    "lis505_xml_axis_definition",
    "lis506_default_list_axis_number",
    "lis507_gantry_master_chain",
    "lis508_axis_named_twice_in_channel",
    "lis510_gantry_homing_type_mismatch",
    "lis511_gantry_drive_controlled_homing",
    "lis601_program_text",
    "lis602_unknown_axis",
    "lis603_axis_twice_in_g74",
    "lis604_disabled_axis_homed",
    "lis605_gantry_slave_alone",
    "lis606_move_before_homing",
    "lis607_ignored_axis_beside_moving_axes",
)

SECTIONS = ("What", "Why", "Example", "Use instead", "Reference")


@dataclass(frozen=True)
class Rule:
    code: str
    name: str
    severity: Severity
    fix: str
    summary: str
    doc: str
    module: ModuleType
    checks: tuple[tuple[Scope, Check], ...] = ()  # one check per scope the rule takes part in
    parameters: tuple[str, ...] = ()  # catalogue paths (with [i]) a cross-parameter rule reads
    produced_by: str = "lint"  # "dry-run" for findings only the homing simulation can make (LIS405)

    @property
    def scopes(self) -> tuple[Scope, ...]:
        return tuple(scope for scope, _ in self.checks)

    def checker(self, scope: Scope) -> Check | None:
        """The rule's check for `scope`, or None when the rule does not look at that scope."""
        return next((check for own, check in self.checks if own is scope), None)

    @property
    def needs_whole_axis(self) -> bool:
        """Whether the rule judges parameters together, as the CNC resolves a whole axis: such a rule has
        nothing to judge in a default list on its own."""
        return bool(self.parameters)

    def section(self, title: str) -> str:
        """The text of one docstring section (one of SECTIONS: "What", "Why", ...); empty when missing."""
        return self._sections.get(title, "")

    @cached_property
    def _sections(self) -> dict[str, str]:  # read once: SARIF and the editor show every rule's sections
        texts = {}
        for title in SECTIONS:
            match = re.search(rf"^{re.escape(title)}\n-+\n(.*?)(?=^\S[^\n]*\n-+\n|\Z)", self.doc, re.M | re.S)
            texts[title] = match.group(1).strip() if match else ""
        return texts


@lru_cache(maxsize=1)
def registry() -> dict[str, Rule]:
    rules: dict[str, Rule] = {}
    for module_name in RULE_MODULES:
        module = importlib.import_module(f"{__name__}.{module_name}")
        rules[module.CODE] = Rule(
            code=module.CODE,
            name=module.NAME,
            severity=Severity(module.SEVERITY),
            fix=module.FIX,
            summary=module.SUMMARY,
            doc=(module.__doc__ or "").strip(),
            module=module,
            checks=tuple(
                (scope, getattr(module, scope.value)) for scope in Scope if hasattr(module, scope.value)
            ),
            parameters=tuple(getattr(module, "PARAMETERS", ())),
            produced_by=getattr(module, "PRODUCED_BY", "lint"),
        )
    return rules


def known_codes() -> tuple[str, ...]:
    """Every rule code, from the module names (no rule module is imported)."""
    return tuple(name[:6].upper() for name in RULE_MODULES)


def selector_problem(selector: str) -> str | None:
    """Why a rule code or prefix picks no rule (with the closest codes), or None when it picks some."""
    code = selector.strip().upper()
    if _picks_some(code):
        return None
    return f"{selector.strip()!r} is not a rule code or a prefix of one; {_closest(code)}"


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
