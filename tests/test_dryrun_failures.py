"""Failures that say why, with numbers (issue 26 item 11): a limit-switch failure names the switch and what the move
searched for beyond it; a path-monitoring failure names homing_max_movement_dist with its value (P-AXIS-00412,
P-ERR-70394); a mode the simulator does not cover is "not simulated" (exit 0 with a note), never "failed"; the
plot's range includes the position searched for.

Numbers on the shared axis of engine_scene.py (homing negative, 100 mm/s fast, 10 mm/s slow, 500 mm/s²)."""

from __future__ import annotations

import contextlib
import io
import json

import pytest

from achslint.cli import main
from achslint.dryrun import dry_run
from achslint.homing.scenario import ScenarioInput

from .engine_scene import SERCOS_DRIVE, approx, drive_run, run

ZERO_PULSE_ONLY = "kenngr.ref_ohne_nocken 1\nkenngr.ref_ohne_rev 1\n"  # §2.3.3.3, type II


def test_a_limit_switch_failure_names_the_switch_and_the_pulse_beyond_it():
    # Zero pulses every 50 mm at -30: from 0 the first pulse in the negative homing direction is -30, but the
    # limit switch at -20 comes first. The axis reaches it after 20 mm at 10 mm/s and brakes 0.1 mm to -20.1.
    trace = run(
        ZERO_PULSE_ONLY, zero_pulse_period=50.0, zero_pulse_phase=-30.0, limit_switches=(-20.0, 1010.0)
    )
    assert trace.outcome == "failed"
    assert (
        trace.failure
        == "to the zero pulse: the limit switch at -20 mm was reached before the zero pulse at -30 mm"
    )
    assert trace.searched == ("the zero pulse", -30.0)
    assert trace.phases[-1].ended_by == "limit switch reached"  # what a sweep counts, the same for every run
    assert approx(trace.phases[-1].end_position, -20.1)


def test_a_pulse_after_the_cam_beyond_the_switch():
    # Three phases (§2.3.1) from -101, on the cam [-120, -100]: phase 1 is skipped; phase 2 leaves the cam
    # positive at 100 mm/s (edge 1 mm away: seen at the 0.064 s cycle, 250·0.064² = 1.024 mm, 32 mm/s, braking
    # 1.024 mm: stands at -98.952). Phase 3 at 10 mm/s arms the logic at the cam edge (-100.002, sampled); the
    # next pulse of a 50 mm lattice at -104.5 lies beyond the limit switch at -102, 3.048 mm from -98.952.
    trace = run(
        zero_pulse_period=50.0,
        zero_pulse_phase=-104.5,
        limit_switches=(-102.0, 1010.0),
        start_position=-101.0,
    )
    assert approx(trace.phases[0].end_position, -98.952)
    assert trace.failure == (
        "onto the cam and reference: the limit switch at -102 mm was reached before the zero pulse after the cam "
        "at -104.5 mm"
    )
    assert trace.searched == ("the zero pulse after the cam", pytest.approx(-104.5))


def test_path_monitoring_failure_names_the_limit():
    # A modulo rotary axis homing negative (test_dryrun_fidelity.rotary): the cam edge -325 is 325° from the start
    # 0, but homing_max_movement_dist 3000000 × 0.0001° = 300° ends the move (P-AXIS-00412, P-ERR-70394).
    rotary = (
        "kenngr.antr_typ 1\nkenngr.achs_typ 2\nkenngr.achs_mode 0x4\nkenngr.ref_richt 0\nkenngr.fast_from_cam 1\n"
        "getriebe[0].vb_refmax 100000\ngetriebe[0].vb_reflow 10000\ngetriebe[0].a_ref 500\n"
        "kenngr.homing_max_movement_dist 3000000\nEnde\n"
    )
    scene = ScenarioInput(
        start_position=0.0, cam=(-345.0, -325.0), zero_pulse_period=5.0, zero_pulse_phase=-327.5
    )
    trace = dry_run(rotary.encode(), "r.lis", scene).trace
    assert trace.failure == (
        "to the reference cam: homing_max_movement_dist (300 ° from the start at 0 °) was exceeded "
        "(P-ERR-70394) before the cam at -325 °"
    )


def test_zero_pulse_search_limit_while_braking_names_its_value_and_the_pulse():
    # One phase (§2.3.3.2): armed at the cam edge -100, 1 mm of search (10000 × 0.1 µm, P-AXIS-00084's
    # neighbour lr_hw[0].zero_pulse_search_max_dist) ends at -101, short of the pulse -102.5, while braking.
    trace = run("kenngr.ref_ohne_rev 1\nlr_hw[0].zero_pulse_search_max_dist 10000\n")
    assert trace.failure == (
        "to the reference cam: zero_pulse_search_max_dist (1 mm from where the zero-pulse logic was armed) was "
        "exceeded while braking after the cam before the zero pulse at -102.5 mm"
    )


def run_main(*args: str) -> tuple[int, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(list(args))
    return code, out.getvalue()


def test_a_mode_the_simulator_does_not_cover_is_not_simulated_and_exits_0(tmp_path):
    # Drive-controlled homing without a [drive] table: the drive's own sequence is not simulated.
    trace = dry_run(SERCOS_DRIVE, "drive.lis").trace
    assert trace.outcome == "not_simulated" and trace.failure is None
    assert "not simulated" in trace.warnings[0]["message"]
    listed = tmp_path / "achsmds1.lis"
    listed.write_bytes(SERCOS_DRIVE)
    code, out = run_main("dry-run", str(listed), "--format", "json")
    assert code == 0 and json.loads(out)["outcome"] == "not_simulated"
    code, out = run_main("dry-run", str(listed))
    assert code == 0 and "Outcome: not_simulated" in out and "note: drive-controlled homing" in out
    # The AX5000 sync search back towards the cam: after the cam search, the rest is not simulated.
    back = drive_run(
        80.0,
        {
            "method": "nc",
            "reference_mode": "hardware-sync",
            "invert_sync_search": True,
            "reference_position": 0.0,
        },
    )
    assert back.outcome == "not_simulated" and [p.name for p in back.phases] == ["to the reference cam"]


def test_the_plot_range_includes_the_position_searched_for():
    pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    from achslint.output.figures import build_figure

    # The motion spans 0 .. -20.1 mm; the pulse it searched for lies at -30: the view reaches it and marks it.
    trace = run(
        ZERO_PULSE_ONLY, zero_pulse_period=50.0, zero_pulse_phase=-30.0, limit_switches=(-20.0, 1010.0)
    )
    figure = build_figure(trace)
    top = figure.axes[0]
    low, high = top.get_ylim()
    assert low < -30.0 < high
    [line] = [line for line in top.get_lines() if line.get_gid() == "searched"]
    assert approx(line.get_ydata()[0], -30.0)
    labels = [text.get_text() for text in top.get_legend().get_texts()]
    assert any(label.startswith("searched for: the zero pulse at −30 mm") for label in labels)
    plt.close("all")


TORQ = (
    b"kenngr.antr_typ 2\nkenngr.homing.homing_type TORQ\nkenngr.homing.torq_homing_dir POSITIVE\n"
    b"getriebe[0].homing.torq_move_velocity 5000\ngetriebe[0].homing.torq_move_acceleration 50\n"
    b"kenngr.homing.torq_max_distance 2000000\n"
    b"antr.fixed_stop.drive_ident[0].id TORQUE_LIMIT\nantr.fixed_stop.drive_ident[0].wr_ident S_0_0092\nEnde\n"
)  # with the torque limit a SERCOS drive needs for the move (P-AXIS-00719; LIS328 otherwise)


def test_a_fixed_stop_beyond_torq_max_distance_names_both():
    # torq_max_distance 2000000 × 0.1 µm = 200 mm (§2.3.3.4); the stop at 300 mm lies 300 mm from the start 0.
    trace = dry_run(TORQ, "t.lis", ScenarioInput(start_position=0.0, fixed_stop=300.0)).trace
    assert trace.failure == (
        "no fixed stop within torq_max_distance (200 mm): the fixed stop at 300 mm lies 300 mm away; homing aborted"
    )
    assert trace.searched == ("the fixed stop", 300.0)
    behind = dry_run(TORQ, "t.lis", ScenarioInput(start_position=0.0, fixed_stop=-300.0)).trace
    assert "the scenario has no fixed stop ahead in the positive direction" in behind.failure
    assert behind.searched is None
