"""The simulation records facts; the rules they belong to word them (issue 23 item 5).

A run of the motion and the strategy's sequence leaves `trace.facts` (soft-limit overshoot, start on the cam,
zero-pulse margin) and no rule message; the dry-run puts each fact in the words of LIS317, LIS402 or LIS405,
and `lint` (LIS317) words the same fact the same way.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from achslint.dryrun import dry_run, prepare
from achslint.homing.motion import PulseMargin, SoftLimitOvershoot, StartOnCam
from achslint.homing.scenario import ScenarioInput
from achslint.rules import lis317_homing_ends_outside_limits as lis317
from achslint.rules import lis402_one_phase_with_cam as lis402
from achslint.rules import lis405_zero_pulse_near_cam_edge as lis405
from achslint.rules.context import Context
from achslint.syntax.parser import parse_bytes

from .engine_scene import SCENE, listed
from .source_nodes import nodes

HOMING = Path(__file__).resolve().parents[1] / "src" / "achslint" / "homing"


def test_a_pulse_near_the_arming_point_is_a_fact_with_the_numbers_lis405_words() -> None:
    given = ScenarioInput(
        **{**SCENE, "zero_pulse_period": 4.0, "zero_pulse_phase": -100.01, "cam_jitter": 0.02}
    )
    simulator = prepare(listed(), "axis.lis", given)
    trace = simulator.run()
    # Three phases: armed at the cam edge -100, the pulse 0.01 mm on; the spread is one 1 ms cycle at 10 mm/s
    # plus the 0.02 mm jitter = 0.03 mm. Half a period away: shift (0.01 - 2) mod 4 = 2.01 mm, which makes the
    # logic take -104.01, one period (4 mm) on in the (negative) homing direction: pos_refpkt -950 -> -954 mm.
    assert trace.warnings == []
    (fact,) = trace.facts
    assert isinstance(fact, PulseMargin)
    assert fact.ahead == pytest.approx(0.01) and fact.behind == pytest.approx(3.99)
    assert fact.margin == pytest.approx(0.03) and fact.period == 4.0
    assert fact.wanted == pytest.approx(2.01) and fact.periods == 1
    assert fact.moved == pytest.approx(-4.0) and fact.reference_value == pytest.approx(-954.0)
    worded = dry_run(listed(), "axis.lis", given).trace.warnings
    assert worded == [{"code": "LIS405", "message": lis405.message(fact)}]
    assert "to about 20100 (= 2.01 mm)" in worded[0]["message"]


def test_starting_on_the_cam_in_one_phase_is_a_fact_lis402_words() -> None:
    one_phase = listed("kenngr.ref_ohne_rev 1\n")
    given = ScenarioInput(**{**SCENE, "start_position": -110.0})
    trace = prepare(one_phase, "axis.lis", given).run()
    assert trace.facts == [StartOnCam(-110.0)] and trace.warnings == []
    worded = dry_run(one_phase, "axis.lis", given).trace.warnings
    assert worded == [{"code": "LIS402", "message": lis402.start_on_cam(StartOnCam(-110.0))}]


@pytest.mark.parametrize(
    "extra,words",
    [
        # Reference -995 mm, 5 mm inside swe_neg -1000 mm; the slow phase brakes 0.1 mm beyond the pulse.
        (
            "getriebe[0].pos_refpkt -9950000\nkenngr.swe_neg -9950500\n",
            "after braking the axis stands at -995.1",
        ),
        ("getriebe[0].pos_refpkt -10050000\nkenngr.swe_neg -10000000\n", "the reference value -1005 mm lies"),
    ],
)
def test_lint_and_dry_run_word_the_same_soft_limit_fact(extra: str, words: str) -> None:
    data = listed(extra)
    probe = prepare(data, "axis.lis", ScenarioInput(**SCENE))
    fact = probe.check_soft_limits(probe.run())
    assert isinstance(fact, SoftLimitOvershoot) and not fact.retracted
    message = lis317.message(fact)
    assert message.startswith(words)
    dry = dry_run(data, "axis.lis", ScenarioInput(**SCENE)).trace.warnings
    assert {"code": "LIS317", "message": message} in dry
    linted = [d.message for d in lis317.check(Context("axis.lis", parse_bytes(data, "axis.lis")))]
    assert linted == [message]


def test_a_fixed_stop_ends_after_retracting() -> None:
    # The stop (homing negative) gets torq_homing_position 8 mm, 2 mm inside swe_pos 10 mm; the axis then
    # retracts 5 mm in the positive direction and stands at 13 mm, 3 mm outside.
    data = (
        b"kenngr.antr_typ 2\nkenngr.homing.homing_type TORQ\nkenngr.homing.torq_homing_dir NEGATIVE\n"
        b"getriebe[0].homing.torq_move_velocity 5000\ngetriebe[0].homing.torq_move_acceleration 50\n"
        b"kenngr.homing.torq_detect_time 25000\nkenngr.homing.torq_homing_position 80000\n"
        b"kenngr.homing.torq_retraction_distance 50000\nkenngr.swe_pos 100000\nEnde\n"
    )
    probe = prepare(data, "torq.lis", ScenarioInput(start_position=0.0, fixed_stop=-100.0))
    fact = probe.check_soft_limits(probe.run())
    assert fact is not None and fact.retracted and not fact.reference_outside
    assert (fact.value, fact.final) == (pytest.approx(8.0), pytest.approx(13.0))
    assert lis317.message(fact) == (
        "after retracting from the stop the axis stands at 13 mm, outside the software limits "
        f"[{fact.limits[0]:g}, 10] mm: move the reference position inside by at least 5 mm"
    )
    linted = [d.message for d in lis317.check(Context("torq.lis", parse_bytes(data, "torq.lis")))]
    assert linted == [lis317.message(fact)]


def test_the_simulation_builds_no_rule_message() -> None:
    """No `warn` call under homing/ names a rule: what a rule reports is a fact the rule words."""
    found = []
    for path in sorted(HOMING.rglob("*.py")):
        for node in nodes(path):
            if (
                isinstance(node, ast.Call)
                and isinstance(node.func, ast.Attribute)
                and node.func.attr == "warn"
                and node.args
                and isinstance(node.args[0], ast.Constant)
                and str(node.args[0].value).startswith("LIS")
            ):
                found.append(f"{path.name}:{node.lineno}")
    assert not found, found
