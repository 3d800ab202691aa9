"""Whole machines: start-up lists, default lists underneath, gantry pairs, duplicates across lists."""

from __future__ import annotations

import json
from pathlib import Path

from .conftest import one_machine


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="latin-1")
    return path


def findings(result) -> list[tuple[str, int, str]]:
    return sorted(
        (Path(d["path"]).name, d["line"], d["code"]) for d in json.loads(result.stdout)["diagnostics"]
    )


def test_default_list_is_applied_under_each_axis_list(cli, tmp_path):
    # vb_refmax comes from the default list only; with it, the axis list's vb_reflow is too fast (LIS302).
    write(tmp_path / "listen" / "default_mds.lis", "getriebe[0].vb_refmax 20000\nEnde\n")
    write(
        tmp_path / "listen" / "achsmds1.lis",
        "kopf.achs_nr 1\nkenngr.antr_typ 1\ngetriebe[0].a_ref 500\ngetriebe[0].vb_reflow 50000\nEnde\n",
    )
    startup = write(
        tmp_path / "listen" / "hochlauf.lis",
        "default_achs_mds ./listen/default_mds.lis\nachs_mds[0] ./listen/achsmds1.lis\nEnde\n",
    )
    machine = cli("lint", str(startup), "--format", "json", "--select", "LIS302")
    assert findings(machine) == [("achsmds1.lis", 4, "LIS302")]
    # Named alone, the list is still an axis of the start-up list beside it: the same default list applies
    # (as in the editor, which finds the machine the same way).
    named = cli("lint", str(tmp_path / "listen" / "achsmds1.lis"), "--format", "json", "--select", "LIS302")
    assert findings(named) == [("achsmds1.lis", 4, "LIS302")]
    # A copy no start-up list names is linted without it: vb_refmax default 83333 > 50000.
    write(tmp_path / "elsewhere" / "achsmds1.lis", (tmp_path / "listen" / "achsmds1.lis").read_text())
    alone = cli(
        "lint", str(tmp_path / "elsewhere" / "achsmds1.lis"), "--format", "json", "--select", "LIS302"
    )
    assert findings(alone) == []


def test_gantry_retraction_against_resettable_distance(cli, tmp_path):
    one_machine(tmp_path)
    write(
        tmp_path / "achsmds1.lis",
        "kopf.achs_nr 1\nkopf.log_achs_name X1\nkenngr.antr_typ 2\n"
        "kenngr.homing.homing_type TORQ\nkenngr.homing.torq_retraction_distance 500\n"
        "kenngr.homing.torq_detect_time 25000\nkenngr.homing.torq_max_distance 100000\nEnde\n",
    )
    write(
        tmp_path / "achsmds2.lis",
        "kopf.achs_nr 2\nkopf.log_achs_name X2\nkenngr.antr_typ 2\n"
        "kenngr.gantry_ax_nr 1\nkenngr.gantry_max_diff_resetable 1000\nEnde\n",
    )
    result = cli("lint", str(tmp_path), "--format", "json", "--select", "LIS316")
    assert findings(result) == [("achsmds2.lis", 4, "LIS316")]
    assert result.returncode == 1
    document = json.loads(result.stdout)
    assert document["diagnostics"][0]["related"][0]["path"].endswith("achsmds1.lis")


def test_lists_are_compared_only_within_a_declared_machine(cli, tmp_path):
    body = "kopf.achs_nr 1\nkopf.log_achs_name X\nEnde\n"
    write(tmp_path / "machine_a" / "achsmds1.lis", body)
    write(tmp_path / "machine_b" / "achsmds1.lis", body)
    write(tmp_path / "machine_b" / "achsmds2.lis", body)
    one_machine(tmp_path / "machine_a")
    # machine_b declares no machine and has no start-up list: its lists are compared with no other list
    assert findings(cli("lint", str(tmp_path), "--format", "json", "--select", "LIS50")) == []
    write(tmp_path / "machine_a" / "achsmds2.lis", body)
    assert findings(cli("lint", str(tmp_path), "--format", "json", "--select", "LIS50")) == [
        ("achsmds2.lis", 1, "LIS501"),
        ("achsmds2.lis", 2, "LIS502"),
    ]
    # two declared machines in two folders are two machines
    one_machine(tmp_path / "machine_b")
    assert len(findings(cli("lint", str(tmp_path), "--format", "json", "--select", "LIS50"))) == 4


def test_start_up_list_with_missing_lists_only(cli, tmp_path):
    startup = write(tmp_path / "hochlauf.lis", "achs_mds[0] ./nowhere.lis\nEnde\n")
    result = cli("lint", str(startup), "--format", "concise")
    assert result.returncode == 1
    assert "hochlauf.lis:1:13: LIS504 [error]" in result.stdout.decode()


def test_a_shared_default_name_says_it_is_the_default(cli, tmp_path):
    one_machine(tmp_path)
    write(tmp_path / "achsmds1.lis", "kopf.achs_nr 1\nEnde\n")
    write(tmp_path / "achsmds2.lis", "kopf.achs_nr 2\nEnde\n")
    result = cli("lint", str(tmp_path), "--format", "json", "--select", "LIS502")
    (message,) = [d["message"] for d in json.loads(result.stdout)["diagnostics"]]
    assert "`X_Achse` (not written in this list, so the default applies)" in message
    write(tmp_path / "achsmds2.lis", "kopf.achs_nr 2\nkopf.log_achs_name X_Achse\nEnde\n")
    result = cli("lint", str(tmp_path), "--format", "json", "--select", "LIS502")
    (message,) = [d["message"] for d in json.loads(result.stdout)["diagnostics"]]
    assert "not written" not in message  # written in the list that is reported


def test_machine_findings_on_a_utf8_list_show_its_text_as_written(cli, tmp_path):
    one_machine(tmp_path)
    # The second list only gets a finding from the machine-level rule (LIS501), so its lines are read
    # again for the code frame: through the same decoding as the list itself (UTF-8 here, not Latin-1).
    for number in (1, 2):
        (tmp_path / f"achsmds{number}.lis").write_text(
            "( Wegauflösung 1 µm )\nkopf.achs_nr 1\nEnde\n", encoding="utf-8"
        )
    shown = cli("lint", str(tmp_path), "--select", "LIS501", "--format", "full").stdout.decode()
    assert "LIS501" in shown
    assert "kopf.achs_nr 1" in shown
    assert "Ã" not in shown and "Â" not in shown
