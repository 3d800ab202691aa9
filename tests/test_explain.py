"""`achslint explain` for lists and parameters, through the real entry point."""

from __future__ import annotations

import json

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
