"""`achslint explain` as text: parameter cards, strategy variants, fixed-stop and drive-controlled homing,
and the CNC's corrections (test_explain.py covers the JSON form)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from subprocess import CompletedProcess

Cli = Callable[..., CompletedProcess]


def explained(cli: Cli, tmp_path: Path, *lines: str) -> list[str]:
    """The text `explain` prints for a list of these lines (with `Ende`), as lines without trailing blanks."""
    path = tmp_path / "achsmds1.lis"
    path.write_text("\n".join([*lines, "Ende", ""]), encoding="latin-1")
    result = cli("explain", str(path))
    assert result.returncode == 0, result.stderr
    return [line.rstrip() for line in result.stdout.decode().splitlines()]


def test_parameter_card_as_text_names_the_rules_that_check_it(cli: Cli) -> None:
    result = cli("explain", "P-AXIS-00015")
    assert result.returncode == 0
    lines = result.stdout.decode().splitlines()
    assert lines[0] == "P-AXIS-00015  kenngr.achs_mode"
    assert "  checked by       LIS201, LIS202, LIS204, LIS314, LIS320, LIS327" in lines
    assert "  manual title     Axis mode" in lines
    assert not any(line.startswith("  matters for") for line in lines)  # not a homing parameter
    text = cli("explain", "kopf.log_achs_name").stdout.decode().splitlines()
    assert "  max length       15" in text and "  checked by       LIS206, LIS502" in text
    assert "  default          X_Achse" in text


def test_homing_parameter_card_names_the_strategies_that_read_it(cli: Cli) -> None:
    lines = cli("explain", "getriebe[0].vb_refmax").stdout.decode().splitlines()
    matters = next(line for line in lines if line.startswith("  matters for"))
    assert "three-phase homing on the cam and the zero pulse (type III)" in matters
    assert "  indices          0..5" in lines
    assert any(line.startswith("  units            linear: µm/s") for line in lines)


def test_variants_of_the_strategy_are_listed(cli: Cli, tmp_path: Path) -> None:
    lines = explained(cli, tmp_path, "kenngr.antr_typ 1", "lr_hw[0].cam_level 0")
    assert any(
        line.startswith("  • cam_level 0: the CNC takes a 0-signal as 'on the cam'.") for line in lines
    )
    assert (
        "  After the reference event the axis brakes, so it stops beyond the reference position by its "
        "braking distance." in lines
    )


def test_fixed_stop_homing_does_not_end_with_braking(cli: Cli, tmp_path: Path) -> None:
    lines = explained(cli, tmp_path, "kenngr.antr_typ 1", "kenngr.homing.homing_type TORQ")
    assert lines[2] == "Homing: homing to a fixed stop (TORQ) — homing_type TORQ"
    assert lines[5].startswith("  1. to the fixed stop: no move, getriebe[0].homing.torq_move_velocity is 0")
    assert not any("the axis brakes" in line for line in lines)


def test_drive_controlled_homing_has_no_phases_and_corrections_are_named(cli: Cli, tmp_path: Path) -> None:
    drive = explained(cli, tmp_path, "kenngr.antr_typ 2", "kenngr.homing.homing_type DRIVE_CONTROLLED")
    assert drive[2] == "Homing: drive-controlled homing — homing_type DRIVE_CONTROLLED"
    assert not any(line.startswith("Phases") for line in drive)
    corrected = explained(cli, tmp_path, "kenngr.antr_typ 1", "kenngr.homing_type DRIVE_CONTROLLED")
    correction = next(line for line in corrected if line.startswith("CNC correction"))
    assert correction.startswith(
        "CNC correction P-ERR-110384: `kenngr.homing.homing_type` DRIVE_CONTROLLED is used as CNC_CONTROLLED: "
    )
