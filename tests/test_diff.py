"""`achslint diff`: effective differences only."""

from __future__ import annotations

import json

A = b"kopf.achs_nr 1\nkenngr.homing_type CNC_CONTROLLED\ngetriebe[0].vb_reflow 20000 ( slow\nkenngr.achs_mode 0x1\nEnde\n"
B = (
    b"# the same axis, reformatted, one speed changed\nkopf.achs_nr      1\nkenngr.homing.homing_type   CNC_CONTROLLED\n"
    b"getriebe[0].vb_reflow   15000\nkenngr.achs_mode 1\ngetriebe[0].vb_refmax 83333\nEnde\n"
)


def test_only_effective_differences(cli, tmp_path):
    a, b = tmp_path / "a.lis", tmp_path / "b.lis"
    a.write_bytes(A)
    b.write_bytes(B)
    result = cli("diff", str(a), str(b), "--format", "json")
    report = json.loads(result.stdout)
    assert result.returncode == 1
    # Old vs new name, hex vs decimal, formatting, comments and a value equal to the default are no difference.
    assert [row["parameter"] for row in report["differences"]] == ["getriebe[0].vb_reflow"]
    row = report["differences"][0]
    assert (row["a"], row["b"], row["unit"], row["b_human"]) == (20000, 15000, "µm/s", "15 mm/s = 0.9 m/min")
    assert cli("diff", str(a), str(a)).returncode == 0


def test_default_list_counts(cli, tmp_path):
    a, b, defaults = tmp_path / "a.lis", tmp_path / "b.lis", tmp_path / "default_mds.lis"
    a.write_bytes(b"Ende\n")
    b.write_bytes(b"getriebe[0].vb_reflow 20000\nEnde\n")
    defaults.write_bytes(b"getriebe[0].vb_reflow 20000\nEnde\n")
    assert cli("diff", str(a), str(b)).returncode == 1
    assert cli("diff", str(a), str(b), "--defaults", str(defaults)).returncode == 0
