"""Review of the machine dry-run (scenario, gantry, groups, sweeps): each test failed before its fix."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from achslint.homing.scenario import ScenarioError
from achslint.machine.build import build_machine, rename
from achslint.machine.model import Program
from achslint.machine.run import MachinePlan, run_machine, sweep
from achslint.machine.scenario import parse_machine_scenario

from .conftest import run_cli
from .test_machinerun import LINEAR, PROGRAM, g74, make_axis, make_machine, scenario


def test_a_sweep_starts_a_gantry_slave_where_its_master_puts_it() -> None:
    # Y2 is coupled to Y: the two cannot start 1,000 mm apart. A sweep draws the master's start and keeps
    # the slave at the scenario's distance from it (here 7 mm), as the mechanics do.
    slave = LINEAR + "kenngr.gantry_ax_nr 2\nkenngr.gantry_slave_no_homing 0\n"
    machine = make_machine(
        make_axis("Y", 2, LINEAR), make_axis("Y2", 3, slave, gantry_master="Y"), pairs=[("Y", "Y2")]
    )
    program = Program(PROGRAM, [g74(1, 10, ("Y", 1), ("Y2", 1))])
    plan = MachinePlan(
        machine,
        program,
        scenario({"Y": {"start_position": 10.0}, "Y2": {"start_position": 17.0}}),
    )
    seen: list[tuple[float, float]] = []
    run = plan.run

    def recording(starts=None, cam_shifts=None):  # type: ignore[no-untyped-def]
        seen.append((starts["Y"], starts["Y2"]))
        return run(starts, cam_shifts)

    plan.run = recording  # type: ignore[method-assign]
    summary = sweep(plan, 20, seed=5)
    assert len(seen) == 20
    assert all(abs((y2 - y) - 7.0) < 1e-9 for y, y2 in seen), seen[:3]
    low, high = summary["start_ranges"]["Y"]
    assert summary["start_ranges"]["Y2"] == [low + 7.0, high + 7.0]
    assert sweep(plan, 20, seed=5) == summary  # the same seed, the same statistics


def test_a_machine_wide_key_an_axis_cannot_take_names_the_axis() -> None:
    # start_velocity is for spindles; written at the top of the file it reaches every axis, and the
    # refusal must say which one (there is no [axes.X] table to point at).
    machine = make_machine(make_axis("X", 1, LINEAR))
    program = Program(PROGRAM, [g74(1, 10, ("X", 1))])
    given = parse_machine_scenario({"start_velocity": 5.0}, "machine.toml")
    with pytest.raises(ScenarioError, match=r"machine\.toml: .*\bX\b.*`start_velocity`") as caught:
        run_machine(machine, program, given)
    assert "[axes.X]" in str(caught.value)  # where to give it instead


def test_names_that_take_another_axis_s_own_name_are_refused(tmp_path: Path) -> None:
    # [names] Y = 1 names axis 1 Y, but axis 2's list calls it Y: the second axis silently vanished from
    # the machine (not listed, not simulated). The clash is refused, naming both.
    (tmp_path / "hochlauf.lis").write_text(
        "zahl_mds 2\nachs_mds[0] ./x.lis\nachs_mds[1] ./y.lis\nEnde\n", encoding="latin-1"
    )
    (tmp_path / "x.lis").write_text("kopf.achs_nr 1\nkopf.log_achs_name X\nEnde\n")
    (tmp_path / "y.lis").write_text("kopf.achs_nr 2\nkopf.log_achs_name Y\nEnde\n")
    machine = build_machine(tmp_path / "hochlauf.lis")
    with pytest.raises(ValueError, match=r"machine\.toml: \[names\] Y = 1.*axis 2"):
        rename(machine, {"Y": 1}, "machine.toml")
    swapped = build_machine(tmp_path / "hochlauf.lis")
    rename(swapped, {"Y": 1, "X": 2}, "machine.toml")  # naming both is fine
    assert {n: a.logical_number for n, a in swapped.axes.items()} == {"Y": 1, "X": 2}


def test_the_dry_run_says_which_axis_lists_the_machine_left_out(tmp_path: Path) -> None:
    """explain says which axis list the machine leaves out (its name is another's); the dry-run said nothing."""
    (tmp_path / "hochlauf.lis").write_text("zahl_mds 2\nachs_mds[0] ./x.lis\nachs_mds[1] ./y.lis\nEnde\n")
    (tmp_path / "x.lis").write_text("kopf.achs_nr 1\nkopf.log_achs_name X\nEnde\n")
    (tmp_path / "y.lis").write_text("kopf.achs_nr 2\nkopf.log_achs_name X\nEnde\n")  # the same name
    (tmp_path / "rfp.nc").write_text("%RFP.NC\nN10 G74 X1\n")
    args = ["dry-run", str(tmp_path / "hochlauf.lis"), "--program", str(tmp_path / "rfp.nc")]
    text = run_cli(*args).stdout.decode()
    data = json.loads(run_cli(*args, "--format", "json").stdout)
    said = text + json.dumps(data)
    assert "y.lis" in text and "only the first axis goes by it" in said
