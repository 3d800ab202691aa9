"""Review of the single-axis homing dry-run against the TF5200 homing description, worked out by hand.

The axis and scene are those of tests/engine_scene.py: fast 100 mm/s, slow 10 mm/s, 500 mm/s², so braking
from full speed takes 0.2 s and 10 mm, from the slow speed 0.02 s and 0.1 mm; cam [-120, -100], zero
pulses every 5 mm with one at -102.5, pos_refpkt -950 mm.
"""

from __future__ import annotations

import json
from pathlib import Path

from .conftest import run_cli
from .engine_scene import approx, run


def test_a_limit_switch_inside_the_braking_distance_after_the_cam_stops_homing():
    """§2.3.1.1: once the cam is reached the axis is decelerated to standstill, and that braking travel is
    still motion of phase 1. Fig. 1 puts the hardware limit switches around the travel: a switch the axis
    reaches while braking stops homing with an error, it is not ignored because the cam was already seen.

    By hand: the cam edge -100 is reached at t = 1.1 s at 100 mm/s; braking takes 10 mm, to -110, so the switch
    at -105 is passed 5 mm into the braking. The engine used to end phase 1 at -110, beyond the switch, and
    carry on homing."""
    trace = run(limit_switches=(-105.0, 1010.0))
    assert trace.outcome == "failed"
    assert trace.reference is None
    assert len(trace.phases) == 1
    phase = trace.phases[0]
    assert phase.name == "to the reference cam" and phase.ended_by == "limit switch reached"
    assert trace.failure is not None
    assert "the limit switch at -105 mm was reached while braking" in trace.failure


def test_a_limit_switch_inside_the_braking_distance_after_the_reference_stops_homing():
    """§2 (axis position after homing) and §2.3.1.3: after the zero pulse the axis brakes to standstill beyond
    the reference. A hardware limit switch in that braking travel is still reached (Fig. 1), so homing ends in
    an error instead of 'homed'.

    By hand: phase 3 runs at 10 mm/s, the pulse -102.5 is latched at t = 2.96 s and the axis brakes 0.1 mm to
    -102.6; a switch at -102.55 lies in that braking travel. The axis starts on the cam at -101 (phase 1 is
    skipped), so only the braking after the reference can reach the switch."""
    trace = run(limit_switches=(-102.55, 1010.0), start_position=-101.0)
    assert trace.outcome == "failed"
    assert trace.reference is None
    assert [p.name for p in trace.phases][-1] == "onto the cam and reference"
    assert trace.phases[-1].ended_by == "limit switch reached"
    assert trace.failure is not None and "-102.55 mm was reached while braking" in trace.failure


def test_a_limit_switch_just_beyond_the_braking_distance_is_not_reached():
    """The same scene with the switch 0.05 mm beyond the standstill after the reference (-102.6): homed."""
    trace = run(limit_switches=(-102.65, 1010.0), start_position=-101.0)
    assert trace.outcome == "homed"
    assert approx(trace.final_position, -950.1)


def test_the_assumed_fixed_stop_lies_where_the_axis_searches_it(tmp_path):
    """TORQ homing gives up after torq_max_distance (TF5200 homing §2.3.3.4.6; the manual's example: 20 mm),
    so a fixed stop assumed 100 mm away made that example fail on the assumed geometry ("torq_max_distance
    travelled without a stop"). The assumed stop lies between torq_min_distance and torq_max_distance (halfway
    when 100 mm is not), and stays 100 mm away when that lies between them."""
    from achslint.homing.scenario import fixed_stop_distance

    assert fixed_stop_distance(0.0, 20.0) == 10.0
    assert fixed_stop_distance(5.0, 0.0) == 100.0 and fixed_stop_distance(0.0, 300.0) == 100.0
    assert fixed_stop_distance(150.0, 0.0) == 160.0 and fixed_stop_distance(150.0, 250.0) == 200.0
    text = (
        (Path(__file__).parent.parent / "fixtures" / "manual" / "torq_sercos.lis")
        .read_text(encoding="latin-1")
        .replace("Ende", "getriebe[0].homing.torq_move_velocity 2000\nEnde")
    )
    path = tmp_path / "achsmds1.lis"
    path.write_text(text, encoding="latin-1")
    run = json.loads(run_cli("dry-run", str(path), "--format", "json").stdout)
    assert run["scenario"]["fixed_stop"] == 10.0 and "fixed_stop" in run["scenario"]["assumed"]
    assert run["outcome"] == "homed", run.get("failure")
