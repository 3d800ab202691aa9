"""No finding contradicts another finding or `explain`: checked on generated axis lists that reach every
homing strategy, on every fixture and on the bundled lists."""

from __future__ import annotations

from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

import achslint
from achslint.axis.resolved import resolve_bytes
from achslint.core.diagnostics import Severity
from achslint.dryrun import DryRunRefused, dry_run, prepare
from achslint.explanation import explain_list
from achslint.homing import STRATEGY_MODULES, strategies
from achslint.linting.linter import FileSettings, lint_file, list_kind
from achslint.rules import registry
from achslint.rules.context import Context
from achslint.syntax.parser import parse_bytes

from .conftest import FIXTURES, examples

NO_EFFECT = {"LIS105", "LIS401"}

# (parameter, values) the generator picks from: every switch that selects a strategy, and the values that
# the cross rules compare.
CHOICES = [
    ("kenngr.antr_typ", ["1", "2", "4", "5", "6", "8"]),
    ("kenngr.achs_typ", ["1", "2", "4"]),
    (
        "kenngr.homing.homing_type",
        ["CNC_CONTROLLED", "DRIVE_CONTROLLED", "TORQ", "NONE", "DISABLED", "IGNORE_ABS_POS", "DRIVE_DEFAULT"],
    ),
    ("kenngr.abs_pos_gueltig", ["0", "1"]),
    ("kenngr.ref_ohne_nocken", ["0", "1"]),
    ("kenngr.ref_ohne_rev", ["0", "1"]),
    ("kenngr.homing_without_zero_pulse", ["0", "1"]),
    ("kenngr.homing_overflow_evaluation", ["0", "1"]),
    ("antr.encoder_bit_range", ["10", "20"]),
    ("antr.encoder_overflow_offset", ["100", "5000"]),
    ("lr_hw[0].cam_level", ["0", "1"]),
    ("lr_hw[0].cam_direct_access", ["0", "1"]),
    ("kenngr.ref_richt", ["0", "1"]),
    ("kenngr.fast_from_cam", ["0", "1"]),
    ("getriebe[0].vb_refmax", ["20000", "90000", "300000"]),
    ("getriebe[0].vb_reflow", ["5000", "50000"]),
    ("getriebe[0].vb_not_referenced", ["0", "10000"]),
    ("getriebe[0].dynamik.vb_max", ["100000", "200000"]),
    ("getriebe[0].a_ref", ["0", "500"]),
    ("getriebe[0].pos_refpkt", ["0", "-99000000"]),
    ("antr.simu.rpf_weg_bis_nip", ["200"]),
    ("antr.sercos.drive_supports_cnc_homing", ["0", "1"]),
    ("antr.cnc_homing_encoder", ["0", "1"]),
    ("antr.sercos.cnc_homing_rt_bit_layout", ["0", "16"]),
    ("kenngr.echtzeit_bit_nr", ["0", "2"]),
    ("antr.reference_cam_signal", ["PLC", "RT_STATUS_BIT_1", "STATUS_DIG_INPUTS"]),
    ("kenngr.homing_max_movement_dist", ["0", "1800000"]),
    ("kenngr.gantry_ax_nr", ["0", "1"]),
    ("kenngr.gantry_slave_no_homing", ["0", "1"]),
    ("kenngr.homing.torq_min_distance", ["0", "300000"]),
    ("kenngr.homing.torq_max_distance", ["200000"]),
    ("kenngr.homing.torq_detect_time", ["0", "25000"]),
    ("getriebe[0].homing.torq_move_velocity", ["0", "2000", "500000"]),
    ("getriebe[0].homing.torq_move_acceleration", ["0", "50"]),
    ("antr.reference_check.element_name", ["S-0-0135"]),
    ("antr.reference_check.bit_nr", ["6", "40"]),
    ("kenngr.vorz_richtung", ["0", "1"]),
    ("kenngr.beweg_richt", ["0", "1"]),
]

AXIS_LISTS = st.lists(
    st.sampled_from(range(len(CHOICES))).flatmap(
        lambda i: st.sampled_from(CHOICES[i][1]).map(lambda value, i=i: f"{CHOICES[i][0]} {value}")
    ),
    max_size=25,
).map(lambda lines: ("\n".join(lines) + "\nEnde\n").encode())


def assert_consistent(data: bytes) -> str:
    """Every invariant for one list; returns the strategy id."""
    diagnostics = lint_file(data, "t.lis", FileSettings(keep_source=False)).diagnostics
    without_effect = {d.parameter for d in diagnostics if d.code in NO_EFFECT}
    rules = registry()
    for d in diagnostics:
        if d.code != "LIS101":  # the one rule whose level is a setting (unknown-parameters)
            # What is emitted has the severity `achslint rules` and `achslint rule CODE` document.
            assert d.severity in rules[d.code].severities, (d.code, d.severity)
        if d.code[:4] in ("LIS2", "LIS3", "LIS4") and d.code not in NO_EFFECT:
            named = {d.parameter, *(r.parameter for r in d.related)}
            # A parameter without effect gets LIS105/LIS401 and nothing else.
            assert not named & without_effect, (d.code, d.message, named & without_effect)
    # explain, dry-run and the rules see the same strategy and the same effectiveness.
    ctx = Context("t.lis", parse_bytes(data, "t.lis"))
    report = explain_list(data, "t.lis")
    # dry-run refuses exactly when lint says the CNC does not run the homing (LIS306, LIS319, LIS328 as an
    # error), with that text.
    refusing = {d.code for d in diagnostics if d.severity is Severity.ERROR} & {"LIS306", "LIS319", "LIS328"}
    try:
        trace = dry_run(data, "t.lis").trace
        simulated = trace.strategy.id
        assert not refusing, refusing
        shown = report["strategy"]["acceleration"]
        if shown and shown["value"]:
            # explain and dry-run name the same homing acceleration.
            assert trace.acceleration == shown["value"], (trace.acceleration, shown)
    except DryRunRefused as exc:
        assert refusing and any(code in str(exc) for code in refusing), str(exc)
        simulated = prepare(data, "t.lis").strategy.id
    assert report["strategy"]["id"] == ctx.strategy.id == simulated
    rows = {row["parameter"]: row for row in report["parameters"]}
    for d in diagnostics:
        if d.code == "LIS401" and d.parameter in rows:
            assert rows[d.parameter]["effective"] is False, d.parameter
    # The model and the rules see the same value for every parameter the list sets (an axis list's model:
    # `load` refuses a list of another kind, whose values its own model holds).
    if list_kind(parse_bytes(data, "t.lis"), "t.lis").id not in ("axis", "default_axis"):
        return ctx.strategy.id
    axis = resolve_bytes(data, "t.lis")
    model = achslint.load(data)
    for path in axis.set_paths():
        value = axis.get(path)
        if isinstance(value, (bool, int, float, str)):
            assert model.get(path) == value, path
    return ctx.strategy.id


@settings(max_examples=examples(250), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(AXIS_LISTS)
# An absolute axis of homing type TORQ: LIS315 judged its fixed-stop speed, which LIS401 says has no effect.
@example(
    b"kenngr.homing.homing_type TORQ\nkenngr.abs_pos_gueltig 1\ngetriebe[0].homing.torq_move_velocity 500000\nEnde\n"
)
def test_generated_lists_never_contradict_themselves(data):
    assert_consistent(data)


def test_generated_lists_reach_every_strategy():
    """The generator above is able to reach every registered strategy (one hand-picked list each)."""
    picks = {
        "disabled": "kenngr.homing.homing_type DISABLED",
        "ignore_abs_pos": "kenngr.homing.homing_type IGNORE_ABS_POS",
        "gantry_slave": "kenngr.gantry_ax_nr 1\nkenngr.gantry_slave_no_homing 1",
        "absolute": "kenngr.abs_pos_gueltig 1",
        "drive_controlled": "kenngr.antr_typ 2",
        "fixed_stop": "kenngr.homing.homing_type TORQ",
        "none": "kenngr.homing.homing_type NONE",
        "simulation": "kenngr.antr_typ 4",
        "spindle_flying_cam": "kenngr.antr_typ 1\nkenngr.achs_typ 4\nkenngr.ref_ohne_rev 1",
        "spindle_flying_zero_pulse": "kenngr.antr_typ 1\nkenngr.achs_typ 4\nkenngr.ref_ohne_rev 1\nkenngr.ref_ohne_nocken 1",
        "zero_pulse_only": "kenngr.antr_typ 1\nkenngr.ref_ohne_nocken 1\nkenngr.ref_ohne_rev 1",
        "one_phase_cam_zero_pulse": "kenngr.antr_typ 1\nkenngr.ref_ohne_rev 1",
        "one_phase_cam": "kenngr.antr_typ 1\nkenngr.ref_ohne_rev 1\nkenngr.homing_without_zero_pulse 1",
        "cam_zero_pulse": "kenngr.antr_typ 1",
        "cam_only": "kenngr.antr_typ 1\nkenngr.homing_without_zero_pulse 1",
    }
    assert sorted(picks) == sorted(d.id for d in strategies()) and len(picks) == len(STRATEGY_MODULES)
    for strategy_id, body in picks.items():
        for line in body.splitlines():
            name, value = line.split()
            assert value in dict(CHOICES)[name], line
        assert assert_consistent((body + "\nEnde\n").encode()) == strategy_id


def test_fixtures_and_bundled_lists_never_contradict_themselves():
    paths = sorted(FIXTURES.glob("**/*.lis"))
    assert len(paths) > 90
    # The checks see a list's bytes only (named t.lis): a list the fixtures hold more than once (the axis
    # lists machines share, 111 of 427) is checked once.
    for data in dict.fromkeys(path.read_bytes() for path in paths):
        assert_consistent(data)
