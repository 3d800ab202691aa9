"""Review of what `achslint explain` says about parameters: the card's checked range against what LIS202
really refuses, the homing strategies a card says a parameter matters for against the parameter's axis
types, the CNC messages a card names, and the message ids the explanation of a list cites."""

from __future__ import annotations

import pytest

import achslint
from achslint.catalogue import catalogue
from achslint.explanation import explain_list, parameter_card, range_words


def card(query: str) -> dict[str, object]:
    parameter = catalogue().find(query)
    assert parameter is not None, query
    return dict(parameter_card(parameter))


def lint_codes(*lines: str) -> list[tuple[int, str]]:
    text = "\n".join([*lines, "Ende", ""]).encode()
    return [(d.line, d.code) for d in achslint.lint(text, name="achsmds1.lis")]


# --- checked range ------------------------------------------------------------------------------


@pytest.mark.parametrize("pid", ["P-AXIS-00751", "P-AXIS-00756", "P-AXIS-00850"])
def test_a_positive_real_with_a_negative_default_is_checked_as_above_zero(pid: str) -> None:
    # "0.0 < x" with the default -1 ("not set"): LIS202 refuses -0.5 and 0 (must be greater than 0) and
    # accepts only -1 itself; the card said "-1 .. 1" (or "-1 .. 500"), as if -0.5 and 0 were fine.
    found = card(pid)
    checked = found["checked_range"]
    assert isinstance(checked, dict)
    assert checked["min"] == 0 and checked.get("min_exclusive") is True
    assert range_words(checked).startswith("above 0")  # type: ignore[arg-type]
    path = str(found["path"]).replace("[i]", "[0]")
    assert (2, "LIS202") in lint_codes("kenngr.antr_typ 1", f"{path} -0.5")
    assert (2, "LIS202") in lint_codes("kenngr.antr_typ 1", f"{path} 0")
    assert not [c for c in lint_codes("kenngr.antr_typ 1", f"{path} -1") if c[1] == "LIS202"]


def test_the_text_card_says_the_default_outside_the_checked_range_is_accepted(cli) -> None:  # type: ignore[no-untyped-def]
    lines = cli("explain", "P-AXIS-00850").stdout.decode().splitlines()
    checked = next(line for line in lines if line.startswith("  checked range"))
    assert checked.startswith("  checked range    above 0, at most 1") and "default -1" in checked


def test_an_integer_parameter_has_integer_bounds() -> None:
    # P-AXIS-00302 "0 ... 1E+7" (UNS32): the card printed "0 .. 10000000.0", a bound no UNS32 writes.
    checked = card("P-AXIS-00302")["checked_range"]
    assert isinstance(checked, dict)
    assert checked["max"] == 10000000 and isinstance(checked["max"], int)
    assert range_words(checked) == "0 .. 10000000"  # type: ignore[arg-type]


def test_lis202_refuses_a_value_between_the_default_and_the_manual_bound() -> None:
    """`Parameter.limits` widened a bound to an out-of-range default, so LIS202 accepted every value between
    the default and the manual's bound; now the default itself is accepted, and nothing between."""
    path = "lr_param.improved_position_control.stage[0].filter.q_factor"  # P-AXIS-00752: 1.0 <= x <= 10.0
    assert (2, "LIS202") in lint_codes("kenngr.antr_typ 1", f"{path} 0.5")
    assert (2, "LIS202") not in lint_codes("kenngr.antr_typ 1", f"{path} -1")  # its default: not set
    assert (2, "LIS202") not in lint_codes("kenngr.antr_typ 1", f"{path} 1.0")


# --- homing strategies on the card -----------------------------------------------------------------


@pytest.mark.parametrize(
    "query",
    [
        "lr_hw[0].cam_direct_access",
        "getriebe[0].a_ref",
        "getriebe[0].tr_ref",
        "kenngr.gantry_slave_no_homing",
    ],
)
def test_a_parameter_of_linear_and_rotary_axes_does_not_matter_for_spindle_homing(query: str) -> None:
    # These parameters apply to linear and rotary axes only (their pages' axis types), so under the flying
    # homing of a spindle `explain LIST` always marks them "no: only for linear, rotary axes"; the card
    # still listed both spindle strategies among those they matter for.
    found = card(query)
    strategies = found["strategies"]
    assert isinstance(strategies, list) and strategies
    ids = {s["id"] for s in strategies}
    assert not ids & {"spindle_flying_cam", "spindle_flying_zero_pulse"}
    for definition in strategies:
        report = explain_list((definition["example"] + "Ende\n").encode(), "achsmds1.lis")
        if report["axis"]["axis_type"] != "spindle":
            continue
        row = next(r for r in report["parameters"] if r["p_axis"] == found["p_axis"])
        assert row["effective"] or row["reason"] != "only for linear, rotary axes"


def test_the_spindle_strategies_still_matter_for_parameters_of_every_axis_type() -> None:
    ids = {s["id"] for s in card("getriebe[0].vb_reflow")["strategies"]}  # type: ignore[union-attr]
    assert {"spindle_flying_cam", "spindle_flying_zero_pulse", "cam_zero_pulse", "simulation"} <= ids
    ids = {s["id"] for s in card("kenngr.homing_max_movement_dist")["strategies"]}  # type: ignore[union-attr]
    assert "spindle_flying_cam" in ids  # rotary axes and spindles


# --- CNC messages ---------------------------------------------------------------------------------


def test_the_card_names_the_cnc_messages_of_the_parameter(cli) -> None:  # type: ignore[no-untyped-def]
    assert card("getriebe[0].vb_reflow")["errors"] == ["P-ERR-110148", "P-ERR-110422"]
    assert card("kenngr.homing_max_movement_dist")["errors"] == ["P-ERR-110545", "P-ERR-70394"]
    assert card("kenngr.fast_from_cam")["errors"] is None
    lines = cli("explain", "vb_reflow").stdout.decode().splitlines()
    assert "  CNC messages     P-ERR-110148, P-ERR-110422" in lines


def test_explain_of_a_disabled_axis_cites_the_homing_disabled_message() -> None:
    """The P-AXIS-00299 page cites P-ERR-50685, which the SDK's message file gives to a synchronisation
    error; its "homing disabled" message is P-ERR-50686 (inconsistency D.40: real files win; LIS308 cites
    50686 too)."""
    text = b"kenngr.antr_typ 2\nkenngr.abs_pos_gueltig 1\nkenngr.homing.homing_type DISABLED\nEnde\n"
    report = explain_list(text, "achsmds1.lis")
    assert report["strategy"]["id"] == "disabled"
    assert "P-ERR-50686" in report["strategy"]["description"]
    assert "P-ERR-50685" not in report["strategy"]["description"]
