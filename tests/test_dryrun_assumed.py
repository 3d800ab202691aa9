"""Assumed geometry only where it matters (issue 26 item 12): the default geometry fills in, and lists as assumed,
only what the strategy's run reads. An absolute axis is described as "absolute, position valid"
(P-AXIS-00014), not by a homing sequence it never runs."""

from __future__ import annotations

import io

from rich.console import Console

from achslint.dryrun import dry_run
from achslint.homing.scenario import ScenarioInput
from achslint.output.dryrun import render, trace_json

from .engine_scene import SERCOS_DRIVE


def assumed(text: str, given: ScenarioInput | None = None) -> list[str]:
    return dry_run(text.encode(), "a.lis", given).trace.scenario.assumed


def rendered(text: str) -> str:
    console = Console(file=io.StringIO(), width=200, color_system=None)
    render(dry_run(text.encode(), "a.lis"), console)
    return console.file.getvalue()


def test_three_phase_homing_reads_cam_pulses_latch_and_switches_but_no_fixed_stop():
    # Type III (§2.3.1): the cam, the zero pulses, the latch, the limit switches and the cycle; no fixed stop.
    names = assumed("kenngr.antr_typ 1\nEnde\n")
    assert names == [
        "start_position",
        "cam",
        "zero_pulse_period",
        "zero_pulse_phase",
        "hardware_latch",
        "cycle_time_ms",
        "limit_switches",
        "cam_jitter",
    ]


def test_a_simulated_drive_reads_no_cam_no_zero_pulse_no_latch():
    # Drive type 4 (simulation, §3.4): one move over antr.simu.rpf_weg_bis_nip to a simulated pulse.
    run = dry_run(b"kenngr.antr_typ 4\nantr.simu.rpf_weg_bis_nip 200\nEnde\n", "sim.lis")
    assert run.trace.strategy.id == "simulation"
    assert run.trace.scenario.assumed == ["start_position", "cycle_time_ms", "limit_switches"]
    assert run.trace.scenario.cam is None and run.trace.scenario.fixed_stop is None
    scenario = trace_json(run)["scenario"]
    assert scenario["zero_pulse_period"] is None and scenario["hardware_latch"] is None


def test_fixed_stop_is_assumed_only_for_torq_on_a_real_drive():
    torq = "kenngr.homing.homing_type TORQ\nantr.fixed_stop.drive_ident[0].id TORQUE_LIMIT\n"
    # TORQ on SERCOS (§2.3.3.4): the fixed stop is where the scenario puts it, here assumed; no cam or pulses.
    assert assumed("kenngr.antr_typ 2\n" + torq + "Ende\n") == [
        "start_position",
        "cycle_time_ms",
        "limit_switches",
        "fixed_stop",
    ]
    # TORQ on a simulated drive: its stop lies kenngr.homing.torq_distance_to_block away, no scenario stop.
    assert "fixed_stop" not in assumed("kenngr.antr_typ 4\n" + torq + "Ende\n")


def test_axes_that_do_not_move_assume_nothing_but_the_start():
    # Absolute (P-AXIS-00014), DISABLED and IGNORE_ABS_POS (P-AXIS-00299), and drive-controlled homing without a
    # [drive] table: no cam, pulses, latch, switches, cycle or stop.
    for text in (
        "kenngr.antr_typ 2\nkenngr.abs_pos_gueltig 1\nEnde\n",
        "kenngr.antr_typ 2\nkenngr.abs_pos_gueltig 1\nkenngr.homing.homing_type DISABLED\nEnde\n",
        "kenngr.antr_typ 2\nkenngr.abs_pos_gueltig 1\nkenngr.homing.homing_type IGNORE_ABS_POS\nEnde\n",
        SERCOS_DRIVE.decode(),
    ):
        trace = dry_run(text.encode(), "a.lis").trace
        assert trace.scenario.assumed == ["start_position"], text
        assert trace.scenario.cam is None and trace.scenario.limit_switches is None


def test_drive_controlled_homing_reads_what_its_searches_look_for():
    # A Triamec standard method searching a cam, then a zero pulse: cam and pulses, no fixed stop or latch.
    drive = {
        "method": "standard",
        "first_search": {"trigger": "cam", "signed_max_distance": 80.0},
        "second_search": {"trigger": "zero_pulse", "signed_max_distance": -10.0},
    }
    names = assumed(SERCOS_DRIVE.decode(), ScenarioInput(drive=drive))
    assert names == [
        "start_position",
        "cam",
        "zero_pulse_period",
        "zero_pulse_phase",
        "cycle_time_ms",
        "limit_switches",
        "cam_jitter",
    ]


def test_a_spindle_without_cam_assumes_no_cam():
    # Flying homing without cam (§2.3.2.1, ref_ohne_nocken 1): only the zero pulse (one per revolution).
    text = "kenngr.antr_typ 1\nkenngr.achs_typ 4\nkenngr.achs_mode 0x4\nkenngr.ref_ohne_rev 1\nkenngr.ref_ohne_nocken 1\nEnde\n"
    run = dry_run(text.encode(), "s.lis")
    assert "cam" not in run.trace.scenario.assumed and run.trace.scenario.cam is None
    assert {"zero_pulse_period", "zero_pulse_phase", "start_velocity"} <= set(run.trace.scenario.assumed)
    assert "fixed_stop" not in run.trace.scenario.assumed


def test_an_absolute_axis_is_described_as_absolute_position_valid():
    text = rendered("kenngr.antr_typ 2\nkenngr.abs_pos_gueltig 1\nEnde\n")
    assert "Absolute, position valid" in text and "P-AXIS-00014" in text
    # No homing sequence it never runs: no acceleration, no cam or zero pulses in the scenario line.
    assert "Homing acceleration" not in text and "cam [" not in text and "zero pulse" not in text
    assert "Scenario: start 0 mm\n" in text and "Outcome: not_required" in text
    document = trace_json(dry_run(b"kenngr.antr_typ 2\nkenngr.abs_pos_gueltig 1\nEnde\n", "a.lis"))
    assert document["axis"]["acceleration"] is None
    assert document["axis"]["acceleration_source"] == "none: the axis makes no homing move"
