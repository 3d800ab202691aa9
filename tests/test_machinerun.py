"""The machine dry-run: a homing program over several axes, checked against hand-computed times."""

from __future__ import annotations

import itertools
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from achslint.axis.resolved import resolve_bytes
from achslint.dryrun import DryRunRefused
from achslint.homing.scenario import ScenarioError
from achslint.machine.model import (
    AxisWord,
    ChannelView,
    HomingBlock,
    Location,
    MachineAxis,
    MoveBlock,
    Program,
    ProgramProblem,
    SkippedBlock,
)
from achslint.machine.run import MachinePlan, run_machine, sweep
from achslint.machine.scenario import parse_machine_scenario

from .conftest import examples

# A linear axis homed in three phases (cam, zero pulse), as in tests/test_engine.py: fast 100 mm/s,
# slow 10 mm/s, a_ref 500 mm/s², reference position 0.1 mm, software limits ±1000 mm.
LINEAR = (
    "kenngr.antr_typ 1\nkenngr.ref_richt 0\nkenngr.fast_from_cam 1\n"
    "kenngr.swe_neg -10000000\nkenngr.swe_pos 10000000\n"
    "getriebe[0].vb_refmax 100000\ngetriebe[0].vb_reflow 10000\ngetriebe[0].a_ref 500\n"
    "getriebe[0].pos_refpkt 1000\n"
)
# The same with the fast speed halved (50 mm/s).
HALF_FAST = LINEAR.replace("vb_refmax 100000", "vb_refmax 50000")
SPINDLE = (
    "kenngr.achs_typ 4\nkenngr.achs_mode 0x4\nkenngr.antr_typ 1\nkenngr.ref_ohne_rev 1\n"
    "kenngr.ref_ohne_nocken 0\nkenngr.ref_richt 1\ngetriebe[0].vb_reflow 90000\n"
    "getriebe[0].lslope_profil.a_grenz_stufe_1 360\ngetriebe[0].lslope_profil.a_grenz_stufe_2 720\n"
    "getriebe[0].pos_refpkt 0\n"
)
GEOMETRY = {
    "cam": [-120.0, -100.0],
    "zero_pulse_period": 5.0,
    "zero_pulse_phase": -102.5,
    "hardware_latch": True,
    "cycle_time_ms": 1.0,
    "limit_switches": [-1010.0, 1010.0],
}
PROGRAM = "rfp.nc"


def make_axis(name: str, number: int, text: str, **extra: object) -> MachineAxis:
    data = (f"kopf.achs_nr {number}\nkopf.log_achs_name {name}\n" + text + "Ende\n").encode()
    return MachineAxis(name, number, None, data, None, resolve_bytes(data, f"{name}.lis"), **extra)


def make_machine(*axes: MachineAxis, pairs: list[tuple[str, str]] | None = None) -> ChannelView:
    return ChannelView(None, {a.name: a for a in axes}, pairs or [])


def at(line: int, column: int = 1) -> Location:
    return Location(PROGRAM, line, column)


def g74(line: int, number: int | None, *words: tuple[str, int]) -> HomingBlock:
    return HomingBlock(
        at(line), number, tuple(AxisWord(n, float(v), at(line, 5 + 3 * i)) for i, (n, v) in enumerate(words))
    )


def g01(
    line: int, number: int | None, feed: float | None, *targets: tuple[str, float], **kw: bool
) -> MoveBlock:
    return MoveBlock(
        at(line),
        number,
        kw.get("rapid", False),
        kw.get("absolute", True),
        feed,
        tuple(AxisWord(n, v, at(line, 12)) for n, v in targets),
    )


def scenario(axes: dict[str, dict[str, object]] | None = None, **defaults: object) -> object:
    return parse_machine_scenario({**GEOMETRY, **defaults, "axes": axes or {}}, "machine.toml")


def close(value: float | None, expected: float) -> bool:
    return value is not None and math.isclose(value, expected, abs_tol=1e-9)


def test_z_alone_then_x_y_in_parallel_then_a_b():
    machine = make_machine(
        make_axis("X", 1, LINEAR),
        make_axis("Y", 2, LINEAR),
        make_axis("Z", 3, LINEAR),
        make_axis("A", 4, HALF_FAST),
        make_axis("B", 5, HALF_FAST),
    )
    program = Program(PROGRAM, [g74(1, 10, ("Z", 1)), g74(2, 20, ("X", 1), ("Y", 1), ("A", 2), ("B", 2))])
    run = run_machine(
        machine, program, scenario({"Y": {"start_position": -50.0}, "B": {"start_position": -50.0}})
    )
    # From 0 at 100 mm/s (a = 500: 0.2 s and 10 mm to full speed) the cam edge -100 is reached at
    # 0.2 + 90/100 = 1.1 s, braked at -110 by 1.3 s; back off the cam to -90 by 1.7 s; at 10 mm/s the
    # latched pulse at -102.5 (12.5 mm away) comes at 0.02 + 12.4/10 = 1.26 s, braked 0.1 mm -> 2.98 s.
    # Z: 0 -> 2.98 s. X the same, 2.98 -> 5.96 s; Y starts 50 mm nearer: 0.2 + 40/100 = 0.6 s to the
    # edge, then the same 1.68 s as X -> 2.48 s, so the group ends with X at 5.96 s.
    # A at 50 mm/s (0.1 s, 2.5 mm to full speed): edge at 0.1 + 97.5/50 = 2.05 s, braked at -102.5 by
    # 2.15 s; off the cam: the edge is 2.5 mm = one ramp away, 0.1 s, braked at -97.5 by 2.35 s; pulse 5 mm
    # away at 0.02 + 4.9/10 = 0.51 s, braked by 0.53 s -> 2.88 s; B from -50: 0.1 + 47.5/50 = 1.05 s to the
    # edge, braked by 1.15 s, then the same 0.73 s -> 1.88 s. The group ends with A at 5.96 + 2.88 = 8.84 s.
    z, x, y, a, b = (run.axes[n] for n in "ZXYAB")
    assert close(z.phases[0].start_time, 0.0) and close(z.phases[-1].end_time, 2.98)
    assert close(x.phases[0].start_time, 2.98) and close(x.phases[-1].end_time, 5.96)
    assert close(y.phases[0].start_time, 2.98) and close(y.phases[-1].end_time, 5.46)
    assert close(a.phases[0].start_time, 5.96) and close(a.phases[-1].end_time, 8.84)
    assert close(b.phases[-1].end_time, 5.96 + 1.88)
    first, second = run.blocks
    assert (close(first.start_time, 0.0), close(first.end_time, 2.98)) == (True, True)
    groups = second.groups
    assert [g.axes for g in groups] == [["X", "Y"], ["A", "B"]]
    assert close(groups[0].start_time, 2.98) and close(groups[0].end_time, 5.96)
    assert close(groups[1].start_time, 5.96) and close(groups[1].end_time, 8.84)
    assert close(run.total_time, 8.84) and run.failure is None
    # Every axis stands 0.1 mm (slow braking) beyond its reference 0.1 mm: homed at 0.
    for axis in (z, x, y, a, b):
        assert axis.outcome == "homed" and close(axis.final_position, 0.0)
        assert close(axis.reference["position"], -102.5) and close(axis.reference["value"], 0.1)


def test_move_block_between_homing_blocks():
    machine = make_machine(make_axis("X", 1, LINEAR), make_axis("Z", 3, LINEAR))
    program = Program(PROGRAM, [g74(1, 10, ("Z", 1)), g01(2, 15, 500.0, ("Z", 200.0)), g74(3, 20, ("X", 1))])
    run = run_machine(machine, program, scenario())
    # Z homes in 2.98 s and stands at 0 (homed), actual value -102.6 (offset +102.6).
    # G01 Z200 F500: 200 mm at 500/60 = 8.333 mm/s with the linear slope's 1000 mm/s² (default a_grenz):
    # ramps of 8.333/1000 = 0.008333 s each covering 0.0347 mm, so the time is 200/8.333 + 8.333/1000 =
    # 24 + 0.008333 s, from 2.98 to 26.988333 s. X then homes in 2.98 s: 26.988333 -> 29.968333 s.
    z = run.axes["Z"]
    move = run.blocks[1]
    assert move.kind == "move" and close(move.start_time, 2.98)
    assert close(move.end_time, 2.98 + 24 + 25 / 3 / 1000)
    assert close(z.final_position, 200.0) and close(z.position, 200.0 - 102.6)
    phase = next(p for p in z.phases if p.kind == "move")
    assert close(phase.velocity, 500 / 60) and phase.direction == "positive"
    assert close(phase.end_position - phase.start_position, 200.0)
    assert close(run.blocks[2].end_time, 2.98 + 24 + 25 / 3 / 1000 + 2.98)
    assert close(run.total_time, 29.968333333333334)


def test_rapid_move_and_move_before_homing():
    machine = make_machine(make_axis("Z", 3, LINEAR + "getriebe[0].vb_eilgang 50000\n"))
    program = Program(PROGRAM, [g01(1, 5, None, ("Z", 100.0), rapid=True, absolute=False)])
    run = run_machine(machine, program, scenario())
    # G00 at vb_eilgang 50 mm/s (below vb_max 200 mm/s), a 1000 mm/s²: 100/50 + 50/1000 = 2.05 s.
    assert close(run.total_time, 2.05) and close(run.axes["Z"].position, 100.0)
    assert not run.axes["Z"].homed
    assert any("before it is homed" in w["message"] for w in run.warnings)


def test_gantry_slave_follows_its_master():
    slave = LINEAR.replace("pos_refpkt 1000", "pos_refpkt 2000") + (
        "kenngr.gantry_ax_nr 1\nkenngr.gantry_slave_no_homing 1\n"
    )
    machine = make_machine(
        make_axis("X", 1, LINEAR), make_axis("X2", 2, slave, gantry_master="X"), pairs=[("X", "X2")]
    )
    program = Program(PROGRAM, [g74(1, 10, ("X", 1))])
    run = run_machine(machine, program, scenario({"X2": {"start_position": 10.0}}))
    x, x2 = run.axes["X"], run.axes["X2"]
    # X homes in 2.98 s; X2 stands 10 mm further on and makes the same moves at the same times.
    assert [p.kind for p in x2.phases] == ["following"] * 3
    assert [(p.start_time, p.end_time) for p in x2.phases] == [(p.start_time, p.end_time) for p in x.phases]
    assert close(x2.phases[-1].end_position, x.phases[-1].end_position + 10.0)
    # X's pulse at -102.5 puts X2 at -92.5, which becomes X2's own reference 0.2 mm; it then brakes 0.1 mm
    # with its master: X at 0.1 - 0.1 = 0, X2 at 0.2 - 0.1 = 0.1.
    assert x2.outcome == "homed" and close(x2.reference["position"], -92.5)
    assert close(x.final_position, 0.0) and close(x2.final_position, 0.1)
    assert run.blocks[0].groups[0].following == ["X2"]


def test_gantry_slave_named_alone_does_not_move():
    slave = LINEAR + "kenngr.gantry_ax_nr 1\nkenngr.gantry_slave_no_homing 1\n"
    machine = make_machine(make_axis("X", 1, LINEAR), make_axis("X2", 2, slave), pairs=[("X", "X2")])
    run = run_machine(machine, Program(PROGRAM, [g74(1, 10, ("X2", 1))]), scenario())
    assert run.axes["X2"].outcome == "skipped" and run.total_time == 0.0
    assert run.axes["X"].outcome == "not_commanded"
    assert "suppressed" in run.axes["X2"].warnings[0]["message"]


def test_disabled_axis_stops_the_program():
    disabled = LINEAR + "kenngr.abs_pos_gueltig 1\nkenngr.homing.homing_type DISABLED\n"
    machine = make_machine(
        make_axis("X", 1, LINEAR),
        make_axis("Y", 2, LINEAR),
        make_axis("Z", 3, LINEAR),
        make_axis("C", 4, disabled),
    )
    program = Program(PROGRAM, [g74(1, 10, ("Z", 1)), g74(2, 20, ("X", 1), ("C", 2)), g74(3, 30, ("Y", 1))])
    run = run_machine(machine, program, scenario())
    # Z 0 -> 2.98 s, X 2.98 -> 5.96 s; the group of C starts at 5.96 s and ends the program there.
    failure = run.failure
    assert failure is not None and failure.axis == "C" and failure.code == "P-ERR-50686"
    assert close(failure.time, 5.96) and failure.at.line == 2
    assert [b.outcome for b in run.blocks] == ["done", "failed", "not_run"]
    assert [g.outcome for g in run.blocks[1].groups] == ["done", "failed"]
    assert (run.axes["X"].outcome, run.axes["C"].outcome, run.axes["Y"].outcome) == (
        "homed",
        "failed",
        "not_run",
    )
    assert run.axes["Y"].phases == [] and close(run.total_time, 5.96)


def test_failure_brakes_the_other_axes_of_the_group():
    machine = make_machine(make_axis("X", 1, LINEAR), make_axis("Y", 2, LINEAR))
    program = Program(PROGRAM, [g74(1, 10, ("X", 1), ("Y", 1)), g74(2, 20, ("X", 1))])
    # Y's limit switch at -60: from 0 it reaches it at 0.2 + 50/100 = 0.7 s and brakes 10 mm to -70 at 0.9 s.
    # X is then at full speed (-60 as well) and brakes with its own 500 mm/s² to -70 at 0.9 s.
    run = run_machine(machine, program, scenario({"Y": {"limit_switches": [-60.0, 1010.0]}}))
    failure = run.failure
    assert failure is not None and failure.axis == "Y" and close(failure.time, 0.7)
    assert "limit switch" in failure.reason
    x = run.axes["X"]
    assert x.outcome == "aborted" and len(x.phases) == 1
    assert close(x.phases[0].end_time, 0.9) and close(x.phases[0].end_position, -70.0)
    assert x.phases[0].ended_by == "stopped: Y failed"
    assert run.blocks[1].outcome == "not_run" and close(run.total_time, 0.9)


def test_ignore_abs_pos_axis_stands_still_in_a_moving_group():
    ignored = LINEAR + "kenngr.abs_pos_gueltig 1\nkenngr.homing.homing_type IGNORE_ABS_POS\n"
    machine = make_machine(make_axis("X", 1, LINEAR), make_axis("W", 2, ignored))
    run = run_machine(machine, Program(PROGRAM, [g74(1, 10, ("X", 1), ("W", 1))]), scenario())
    w = run.axes["W"]
    group = run.blocks[0].groups[0]
    assert group.still == ["W"] and group.moving == ["X"]
    assert [p.kind for p in w.phases] == ["still"]
    assert close(w.phases[0].start_time, 0.0) and close(w.phases[0].end_time, 2.98)
    assert w.outcome == "skipped" and w.homed  # the absolute encoder gives its position
    assert run.failure is None
    assert any(warning["code"] == "LIS607" and "collide" in warning["message"] for warning in run.warnings)


def test_spindle_in_the_program():
    machine = make_machine(make_axis("X", 1, LINEAR), make_axis("S", 6, SPINDLE, spindle=True))
    spindle = {
        "start_position": 300.0,
        "cam": [240.0, 270.0],
        "zero_pulse_period": 360.0,
        "zero_pulse_phase": 45.0,
    }
    run = run_machine(machine, Program(PROGRAM, [g74(1, 20, ("X", 1), ("S", 2))]), scenario({"S": spindle}))
    # Flying homing at 90°/s with 360°/s² (0.25 s, 11.25° to full speed): the zero pulse at 765° (= 45°,
    # 465° away) comes at 0.25 + 453.75/90 = 5.291667 s; the spindle keeps turning. Group 2 starts when X is
    # homed (2.98 s) and ends at the pulse: 8.271667 s.
    s = run.axes["S"]
    assert s.unit == "deg" and s.outcome == "homed" and s.ends_moving
    assert close(s.reference["time"], 2.98 + 0.25 + 453.75 / 90)
    assert close(run.blocks[0].groups[1].end_time, 2.98 + 0.25 + 453.75 / 90)
    assert close(s.final_position, 0.0)


def test_skipped_blocks_and_program_problems():
    machine = make_machine(make_axis("Z", 3, LINEAR))
    program = Program(PROGRAM, [SkippedBlock(at(1), "N5 M3 S500", "spindle command"), g74(2, 10, ("Z", 1))])
    run = run_machine(machine, program, scenario())
    assert run.blocks[0].outcome == "not_simulated" and run.blocks[0].note == "spindle command"
    assert close(run.total_time, 2.98)
    broken = Program(PROGRAM, [g74(2, 10, ("Z", 1))], [ProgramProblem(at(4, 7), "comment not closed")])
    with pytest.raises(DryRunRefused, match=r"rfp\.nc:4:7: comment not closed"):
        run_machine(machine, broken, scenario())


def test_unknown_axis_and_soft_limits_stop_the_program():
    machine = make_machine(make_axis("Z", 3, LINEAR))
    run = run_machine(machine, Program(PROGRAM, [g74(1, 10, ("Q", 1))]), scenario())
    assert run.failure is not None and "not an axis of the machine" in run.failure.reason
    homed_then_far = Program(PROGRAM, [g74(1, 10, ("Z", 1)), g01(2, 15, 500.0, ("Z", 1200.0))])
    run = run_machine(machine, homed_then_far, scenario())
    assert (
        run.failure is not None and "software limits" in run.failure.reason and close(run.failure.time, 2.98)
    )


def test_bad_scenarios_name_the_file_and_the_key():
    machine = make_machine(make_axis("X", 1, LINEAR), make_axis("Z", 3, LINEAR))
    program = Program(PROGRAM, [g74(1, 10, ("Z", 1))])
    with pytest.raises(
        ScenarioError,
        match=r"machine\.toml: \[axes\.Z1\]: the machine has no axis Z1.*did you mean \[axes\.Z\]",
    ):
        run_machine(machine, program, scenario({"Z1": {"start_position": 1.0}}))
    with pytest.raises(ScenarioError, match=r"machine\.toml: \[axes\.X\]: unknown key `speed`"):
        scenario({"X": {"speed": 3}})
    with pytest.raises(ScenarioError, match=r"machine\.toml: unknown key `axis`"):
        parse_machine_scenario({"axis": {}}, "machine.toml")
    with pytest.raises(ScenarioError, match=r"\[axes\.X\]: `start_position`"):
        scenario({"X": {"start_position": math.nan}})
    with pytest.raises(
        ScenarioError, match=r"\[axes\.X\]: `cycle_time_ms` is the same for the whole machine"
    ):
        scenario({"X": {"cycle_time_ms": 2.0}})
    with pytest.raises(ScenarioError, match=r"\[axes\.X\]: the \[drive\] table"):
        run_machine(machine, program, scenario({"X": {"drive": {"method": "immediate"}}}))
    with pytest.raises(ScenarioError, match=r"two tables"):
        scenario({"X": {}, "x": {}})


def test_sweep_counts_failures_per_axis():
    machine = make_machine(make_axis("X", 1, LINEAR), make_axis("Z", 3, LINEAR))
    program = Program(PROGRAM, [g74(1, 10, ("Z", 1)), g74(2, 20, ("X", 1))])
    # Starts between the limit switches [-130, 300]: an axis starting below the cam (-130 .. -120) runs
    # into its limit switch (it searches negative); one starting on the cam homes.
    plan = MachinePlan(machine, program, scenario(limit_switches=[-130.0, 300.0]))
    summary = sweep(plan, 200, seed=3)
    assert summary["runs"] == 200 and summary["completed"] + summary["failed"] == 200
    assert summary["failed"] > 0 and summary["completed"] > 0
    assert {entry["axis"] for entry in summary["failures"]} <= {"X", "Z"}
    assert all(r["reason"] == "limit switch reached" for e in summary["failures"] for r in e["reasons"])
    times = summary["total_time"]
    assert times["min"] <= times["median"] <= times["max"]
    # X only homes when Z did: X fails only in runs where Z completed.
    assert summary["start_ranges"]["X"] == [-130.0, 300.0]


@settings(max_examples=examples(40), deadline=None)
@given(st.lists(st.floats(-130.0, 300.0), min_size=4, max_size=4))
def test_timeline_invariants_from_any_start(starts):
    machine = make_machine(
        make_axis("X", 1, LINEAR),
        make_axis("Y", 2, LINEAR),
        make_axis("Z", 3, LINEAR),
        make_axis("A", 4, HALF_FAST),
    )
    program = Program(
        PROGRAM,
        [g74(1, 10, ("Z", 1)), g01(2, 15, 3000.0, ("Z", 150.0)), g74(3, 20, ("X", 1), ("Y", 1), ("A", 2))],
    )
    run = MachinePlan(machine, program, scenario(limit_switches=[-130.0, 300.0])).run(
        dict(zip("XYZA", starts, strict=True))
    )
    ran = [b for b in run.blocks if b.outcome != "not_run"]
    for before, after in itertools.pairwise(ran):
        assert after.start_time == before.end_time  # each block starts when the one before ends
    for block in ran:
        for group in block.groups:
            if group.outcome == "not_run":
                continue
            ends = [p.end_time for n in group.moving for p in run.axes[n].phases if p.block == block.index]
            if ends:  # the group ends with its slowest axis, and no axis of it runs on past that
                assert math.isclose(max(ends), group.end_time, abs_tol=1e-12)
    assert all(p.end_time <= run.total_time + 1e-12 for a in run.axes.values() for p in a.phases)
    if run.failure is None:
        assert all(run.axes[n].outcome == "homed" for n in "XYZA")
        assert close(run.axes["Z"].final_position, 150.0)
    else:
        assert run.blocks[run.failure.block].outcome == "failed"
        assert all(b.outcome == "not_run" for b in run.blocks[run.failure.block + 1 :])


# A modulo rotary axis (achs_typ 2, MODULO bit 0x4 of achs_mode, P-AXIS-00015; range 0..360°, the defaults
# of modulou/moduloo) homed like LINEAR, with a move acceleration of 100 °/s² (a_grenz_stufe_1/2).
ROTARY = (
    "kenngr.achs_typ 2\nkenngr.achs_mode 0x4\n"
    + LINEAR
    + "getriebe[0].lslope_profil.a_grenz_stufe_1 100\ngetriebe[0].lslope_profil.a_grenz_stufe_2 100\n"
)
ROTARY_GEOMETRY = {"cam": [240.0, 270.0], "zero_pulse_period": 360.0, "zero_pulse_phase": 250.0}


def test_g90_on_a_modulo_axis_goes_the_short_way():
    from achslint.output.machine import machine_json

    machine = make_machine(make_axis("A", 4, ROTARY))
    program = Program(
        PROGRAM,
        [
            g74(1, 10, ("A", 1)),
            g01(2, 20, 600.0, ("A", 350.0)),
            g01(3, 30, 600.0, ("A", 10.0)),
            g01(4, 40, 600.0, ("A", 190.0)),
            g01(5, 50, 600.0, ("A", -30.0), absolute=False),
        ],
    )
    run = run_machine(machine, program, scenario({"A": ROTARY_GEOMETRY}))
    a = run.axes["A"]
    assert a.outcome == "homed" and run.failure is None
    moves = [p for p in a.phases if p.kind == "move"]
    assert len(moves) == 4
    across, half, back = moves[1], moves[2], moves[3]
    # N30 G90 A10 from 350°: the short way is +20° (10 - 350 = -340 ≡ +20 mod 360), not -340°.
    # F600 is 10 °/s; a = 100 °/s²: 0.1 s and 0.5° to full speed, so 20/10 + 10/100 = 2.1 s
    # (the long way, -340°, would take 340/10 + 0.1 = 34.1 s).
    assert across.direction == "positive"
    assert close(across.end_position - across.start_position, 20.0)
    assert close(across.end_time - across.start_time, 2.1)
    assert close(run.blocks[2].end_time - run.blocks[2].start_time, 2.1)
    # N40 G90 A190 from 10°: exactly half a revolution, taken the positive way: 180/10 + 0.1 = 18.1 s.
    assert half.direction == "positive"
    assert close(half.end_position - half.start_position, 180.0)
    assert close(half.end_time - half.start_time, 18.1)
    # N50 G91 A-30 from 190°: an incremental move goes as written, -30° to 160°: 30/10 + 0.1 = 3.1 s.
    assert back.direction == "negative" and close(back.end_time - back.start_time, 3.1)
    assert close(a.final_position, 160.0)
    # The report shows every position within [0, 360), in actual values: the reference pulse at 250°
    # becomes 0.1°, so homed = actual + 110.1 (mod 360). The run counts on (N30 from -120.1 to -100.1);
    # the report shows N30 from 350 - 110.1 = 239.9° to 10 - 110.1 + 360 = 259.9°, N40 on to
    # 190 - 110.1 = 79.9° and N50 back to 160 - 110.1 = 49.9°.
    assert close(across.start_position, -120.1) and close(across.end_position, -100.1)
    document = machine_json(run)
    (axis,) = document["axes"]
    shown = [(p["start_position"], p["end_position"]) for p in axis["phases"] if p["kind"] == "move"]
    assert [(round(x, 6), round(y, 6)) for x, y in shown[1:]] == [(239.9, 259.9), (259.9, 79.9), (79.9, 49.9)]
    assert close(axis["reference"]["position"], 250.0) and close(axis["position"], 49.9)
    assert close(axis["final_position"], 160.0)


def test_plot_shows_a_modulo_axis_within_its_range():
    pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    from achslint.output.figures import build_machine_figure

    machine = make_machine(make_axis("A", 4, ROTARY))
    program = Program(PROGRAM, [g74(1, 10, ("A", 1)), g01(2, 20, 600.0, ("A", 10.0))])
    run = run_machine(machine, program, scenario({"A": ROTARY_GEOMETRY}))
    # Homed at 0 (actual 249.9°, see above), N20 G90 A10 turns +10° to actual 259.9°. The homing itself
    # runs from 0 down to -110.1 (actual values counting on): below 0 the curve continues at 360 - ...,
    # broken once where it passes 0°, never drawn across the panel.
    figure = build_machine_figure(run)
    try:
        (line,) = [ln for ax in figure.axes for ln in ax.get_lines() if ln.get_gid() == "position A"]
        ys = [float(y) for y in line.get_ydata()]
    finally:
        plt.close(figure)
    shown = [y for y in ys if not math.isnan(y)]
    assert all(0.0 <= y <= 360.0 for y in shown)
    assert sum(math.isnan(y) for y in ys) == 1
    # the line is drawn up to the end of the range and on from the other end (downwards: 0, then 360)
    gap = next(i for i, y in enumerate(ys) if math.isnan(y))
    assert (ys[gap - 1], ys[gap + 1]) == (0.0, 360.0)
    assert close(shown[0], 0.0) and close(shown[-1], 259.9)
