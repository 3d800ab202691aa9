"""`achslint explain` for lists and parameters, through the real entry point: the JSON form, and the text
of parameter cards, strategy variants, fixed-stop and drive-controlled homing and the CNC's corrections."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from subprocess import CompletedProcess

from .conftest import FIXTURES


def test_explain_list_text(cli):
    result = cli("explain", str(FIXTURES / "lists" / "achsmds1.lis"))
    out = result.stdout.decode()
    assert result.returncode == 0, result.stderr
    assert "three-phase homing on the cam and the zero pulse (type III)" in out
    assert "1. to the reference cam: move negative at 100000 µm/s (= 100 mm/s = 6 m/min)" in out
    assert "3. onto the cam and reference: move negative at 10000 µm/s" in out
    assert "getriebe[0].vb_reflow" in out and "line 34" in out


def test_explain_list_json(cli):
    result = cli("explain", str(FIXTURES / "lists" / "achsmds1.lis"), "--format", "json")
    report = json.loads(result.stdout)
    assert report["strategy"]["id"] == "cam_zero_pulse"
    assert report["strategy"]["manual_type"] == "III"
    assert [p["direction"] for p in report["phases"]] == ["negative", "positive", "negative"]
    rows = {row["parameter"]: row for row in report["parameters"]}
    assert rows["getriebe[0].vb_reflow"]["value"] == 10000
    assert rows["getriebe[0].vb_reflow"]["source"] == {"kind": "list", "line": 34}
    assert rows["getriebe[0].vb_reflow"]["human"] == "10 mm/s = 0.6 m/min"
    assert rows["antr.simu.rpf_weg_bis_nip"]["effective"] is False
    assert rows["getriebe[0].tr_ref"]["source"]["kind"] == "default"


def test_explain_gear_stage(cli, tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(b"kenngr.antr_typ 1\ngetriebe[2].vb_refmax 50000\nEnde\n")
    report = json.loads(cli("explain", str(path), "--format", "json", "--gear", "2").stdout)
    assert report["phases"][0]["velocity"] == 50000
    assert report["phases"][0]["velocity_parameter"] == "getriebe[2].vb_refmax"


def test_explain_drive_controlled_marks_sequence_parameters_ineffective(cli):
    report = json.loads(cli("explain", str(FIXTURES / "lists" / "achsmds4.lis"), "--format", "json").stdout)
    assert report["strategy"]["id"] == "drive_controlled"
    rows = {row["parameter"]: row for row in report["parameters"]}
    assert rows["kenngr.ref_richt"]["effective"] is False
    assert "drive" in rows["kenngr.ref_richt"]["reason"]


def test_explain_parameter_by_name_alias_and_id(cli):
    for query in ("vb_reflow", "getriebe[3].vb_reflow", "P-AXIS-00218"):
        card = json.loads(cli("explain", query, "--format", "json").stdout)
        assert card["p_axis"] == "P-AXIS-00218"
        assert card["path"] == "getriebe[i].vb_reflow"
        assert card["units"]["linear"] == "µm/s"
        assert "LIS302" in card["rules"]
        assert "cam_zero_pulse" in [strategy["id"] for strategy in card["strategies"]]
    old = json.loads(cli("explain", "kenngr.homing_type", "--format", "json").stdout)
    assert old["p_axis"] == "P-AXIS-00299"


def test_explain_unknown_parameter_suggests(cli):
    result = cli("explain", "kenngr.ref_ricth")
    assert result.returncode == 2
    assert b"kenngr.ref_richt" in result.stderr


# --- the text form ----------------------------------------------------------------------------------

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
    assert "  checked by       LIS201, LIS202, LIS204, LIS309, LIS314, LIS320, LIS327" in lines
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
