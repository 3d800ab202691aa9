"""TwinCAT exports: axis XML and channel items found by content (each embedded list linted as its kind), other
XML skipped with a note, an export folder is one machine."""

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
    # the channel item is linted too (its channel list), the zero offsets of another tool are not a list
    assert json.loads(result.stdout)["summary"]["files"] == 4
    notes = result.stderr.decode().splitlines()
    assert len(notes) == 1 and "ZeroOffsets.xml: skipped, an XML file without a list" in notes[0]


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
    assert json.loads(result.stdout)["summary"]["files"] == 2  # the axis and the channel item
    assert result.stderr.decode().count("skipped") == 1
    quiet = cli("lint", str(folder / "Axis_X.xti"), str(folder / "ZeroOffsets.xml"), "-q")
    assert quiet.returncode == 0 and quiet.stderr == b""


def test_a_folder_of_only_other_xml_is_an_empty_run(cli, tmp_path):
    folder = tmp_path / "Export"
    folder.mkdir()
    (folder / "ZeroOffsets.xml").write_text(ZERO_OFFSETS)
    result = cli("lint", str(folder))
    assert result.returncode == 2 and "no axis list found" in result.stderr.decode()


def test_the_lists_of_a_channel_item_are_linted_as_their_kinds(cli, tmp_path):
    # <IsgChannelDef>: SdaMds is a channel list, NullpD zero offsets (format.md §12); a finding lands on the
    # XML line of the parameter
    item = tmp_path / "Channel_1.xti"
    item.write_text(
        '<?xml version="1.0"?>\n<TreeItem><IsgChannelDef>\n<SdaMds><![CDATA[gruppe[0].achse[0].bezeichnunk X\n'
        "Ende\n]]></SdaMds>\n<NullpD><![CDATA[Ende\n]]></NullpD></IsgChannelDef></TreeItem>\n"
    )
    result = cli("lint", str(item), "--format", "json")
    assert result.returncode == 0, result.stderr.decode()
    [finding] = json.loads(result.stdout)["diagnostics"]
    assert (finding["code"], finding["line"], finding["column"]) == ("LIS101", 3, 18)
    assert "channel list" in finding["message"] and "gruppe[0].achse[0].bezeichnung" in finding["message"]


def test_fmt_leaves_xml_found_in_a_folder_alone(cli, tmp_path):
    folder = export(tmp_path / "Export")
    (folder / "achsmds9.lis").write_text("kopf.achs_nr 9\nEnde\n")
    result = cli("fmt", "--check", str(folder))
    assert result.returncode == 1 and b"not XML" not in result.stderr
