"""TwinCAT exports: axis XML found by content, other XML skipped with a note, an export folder is one machine."""

from __future__ import annotations

import json
from pathlib import Path

AXIS = """<?xml version="1.0" encoding="utf-8"?>
<TreeItem><ItemName>{name}</ItemName><ItemId>{number}</ItemId>
<IsgAxisDef><DriveType>4</DriveType><Spindle>false</Spindle>
<AchsMds><![CDATA[#TC_AXIS_DESC:    {name}
kopf.achs_nr                     {number}
kopf.log_achs_name               {name}
kenngr.antr_typ                  4
Ende
]]></AchsMds></IsgAxisDef></TreeItem>
"""
CHANNEL = '<?xml version="1.0"?>\n<TreeItem><IsgChannelDef><SdaMds><![CDATA[kanal_id 1\nEnde\n]]></SdaMds></IsgChannelDef></TreeItem>\n'
ZERO_OFFSETS = '<?xml version="1.0"?>\n<ZeroOffsets><Offset Axis="X" Value="0"/></ZeroOffsets>\n'


def export(folder: Path) -> Path:
    """Three axes under names TwinCAT chooses (no `achsmds` in them), the third reusing ItemId 1 (the tree
    item's number, which LIS501 compares in TwinCAT exports)."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "Axis_X.xti").write_text(AXIS.format(name="X", number=1))
    (folder / "Axis_Y.xml").write_text(AXIS.format(name="Y", number=2))
    (folder / "Axis_Z.xti").write_text(AXIS.format(name="Z", number=1))
    (folder / "Channel_1.xti").write_text(CHANNEL)
    (folder / "ZeroOffsets.xml").write_text(ZERO_OFFSETS)
    return folder


def codes(result) -> list[tuple[str, str]]:
    return sorted(
        (Path(d["path"]).name, d["code"])
        for d in json.loads(result.stdout)["diagnostics"]
        if d["code"].startswith("LIS5")
    )


def test_export_folder_is_found_by_content_and_is_one_machine(cli, tmp_path):
    folder = export(tmp_path / "Export")
    result = cli("lint", str(folder), "--format", "json", "--fail-on", "warning")
    assert result.returncode == 1, result.stderr.decode()  # LIS501 is a warning
    assert codes(result) == [("Axis_Z.xti", "LIS501")]  # across files, not only inside one
    assert json.loads(result.stdout)["summary"]["files"] == 3
    notes = result.stderr.decode().splitlines()
    assert len(notes) == 2 and all("skipped, an XML file without an axis list" in n for n in notes)
    assert any("Channel_1.xti" in n and "<TreeItem>" in n for n in notes)


def test_non_axis_xml_named_with_axis_xml_is_skipped_not_an_abort(cli, tmp_path):
    folder = export(tmp_path / "Export")
    result = cli(
        "lint",
        str(folder / "Axis_X.xti"),
        str(folder / "Channel_1.xti"),
        str(folder / "ZeroOffsets.xml"),
        "--format",
        "json",
    )
    assert result.returncode == 0, result.stderr.decode()
    assert json.loads(result.stdout)["summary"]["files"] == 1
    assert result.stderr.decode().count("skipped") == 2
    quiet = cli("lint", str(folder / "Axis_X.xti"), str(folder / "Channel_1.xti"), "-q")
    assert quiet.returncode == 0 and quiet.stderr == b""


def test_a_folder_of_only_other_xml_is_an_empty_run(cli, tmp_path):
    folder = tmp_path / "Update"
    folder.mkdir()
    (folder / "Channel_1.xti").write_text(CHANNEL)
    result = cli("lint", str(folder))
    assert result.returncode == 2 and "no axis list found" in result.stderr.decode()


def test_fmt_leaves_xml_found_in_a_folder_alone(cli, tmp_path):
    folder = export(tmp_path / "Export")
    (folder / "achsmds9.lis").write_text("kopf.achs_nr 9\nEnde\n")
    result = cli("fmt", "--check", str(folder))
    assert result.returncode == 1 and b"not XML" not in result.stderr
