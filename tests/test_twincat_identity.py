"""TwinCAT export folders are compared by the identity TwinCAT gives each axis (issue 24 item 7).

Every axis of `fixtures/machines/twincat_export` embeds the same template header (`kopf.achs_nr 1`,
`X_Achse`) inside a distinct tree item (`TICC^CNC^Axes^Axis_X`, ItemId 1, ...). LIS501/LIS502 compare the
tree items there, and the embedded headers only among lists without a tree item.
"""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path
from typing import Any

from achslint.linting.linter import lint_file
from achslint.syntax.xmlinput import extract

from .conftest import FIXTURES, run_cli
from .test_discovery import machine_findings_cli, machine_findings_editor

EXPORT = FIXTURES / "machines" / "twincat_export"
WITHOUT_TREE_ITEMS = FIXTURES / "machines" / "xml_export"


def machine_findings(folder: Path) -> list[dict[str, Any]]:
    """Every LIS501/LIS502 finding of `achslint lint FOLDER --format json`."""
    result = run_cli("lint", str(folder), "--select", "LIS501,LIS502", "--format", "json", "--exit-zero")
    assert result.returncode == 0, result.stderr
    found: list[dict[str, Any]] = json.loads(result.stdout)["diagnostics"]
    return found


def line_of(path: Path, text: str) -> int:
    """The 1-based line of the first line of `path` containing `text`."""
    return next(n for n, line in enumerate(path.read_text().splitlines(), 1) if text in line)


def export_copy(tmp_path: Path) -> Path:
    folder = tmp_path / "export"
    shutil.copytree(EXPORT, folder)
    return folder


def test_the_fixture_embeds_one_template_header_in_distinct_tree_items() -> None:
    lists = [
        embedded
        for path in sorted(EXPORT.glob("Axis_*.xti"))
        for embedded in extract(path.read_bytes(), path.name)
    ]
    assert len(lists) == 3
    headers = {tuple(re.findall(r"^kopf\.(?:achs_nr|log_achs_name) +(\S+)", e.text, re.M)) for e in lists}
    assert headers == {("1", "X_Achse")}
    assert len({e.tree_item.item_id for e in lists if e.tree_item}) == len(lists)


def test_distinct_tree_items_with_one_template_header_are_no_duplicates() -> None:
    assert machine_findings(EXPORT) == []


def test_the_summary_of_an_embedded_list_carries_its_tree_item() -> None:
    path = EXPORT / "Axis_Y.xti"
    (summary,) = lint_file(path.read_bytes(), str(path)).summaries
    identity = summary["identity"]
    assert identity["source"] == "TwinCAT tree item"
    assert (identity["item"], identity["item_id"], identity["object_id"]) == (
        "TICC^CNC^Axes^Axis_Y",
        2,
        "#x05510020",
    )
    assert (identity["channel"], identity["index"], identity["program_name"]) == (1, 1, "Y")
    assert identity["positions"]["ItemId"][0] == line_of(path, "<ItemId>")
    # the embedded template header is still read as written: it is just not what the rules compare
    assert summary["achs_nr"] == 1 and summary["name"] == "X_Achse"


def test_one_tree_item_exported_twice_is_reported_naming_the_item(tmp_path: Path) -> None:
    folder = export_copy(tmp_path)
    copy = folder / "Axis_Y - Copy.xti"
    shutil.copy(folder / "Axis_Y.xti", copy)
    found = machine_findings(folder)
    original = folder / "Axis_Y.xti"
    assert {(Path(d["path"]).name, d["line"], d["code"]) for d in found} == {
        ("Axis_Y.xti", line_of(original, "<ItemId>"), "LIS501"),
        ("Axis_Y.xti", line_of(original, "<PathName>"), "LIS502"),
    }
    assert len(found) == 2
    for finding in found:
        assert "TICC^CNC^Axes^Axis_Y" in finding["message"]
        assert "exported twice" in finding["message"]
        assert "not the kopf." in finding["message"]  # says which identity was compared
        (related,) = finding["related"]
        assert Path(related["path"]).name == copy.name
    number = next(d for d in found if d["code"] == "LIS501")
    assert "ItemId 2" in number["message"]


def test_two_tree_items_with_one_item_id_are_a_duplicate_axis_number(tmp_path: Path) -> None:
    folder = export_copy(tmp_path)
    z = folder / "Axis_Z.xti"
    z.write_text(z.read_text().replace("<ItemId>3</ItemId>", "<ItemId>2</ItemId>"))
    found = machine_findings(folder)
    assert [(Path(d["path"]).name, d["line"], d["code"]) for d in found] == [
        ("Axis_Z.xti", line_of(z, "<ItemId>"), "LIS501")
    ]
    assert "tree items TICC^CNC^Axes^Axis_Z and TICC^CNC^Axes^Axis_Y" in found[0]["message"]
    assert "ItemId 2" in found[0]["message"]


def test_two_axes_with_one_program_name_in_one_channel_are_a_duplicate_name(tmp_path: Path) -> None:
    folder = export_copy(tmp_path)
    z = folder / "Axis_Z.xti"
    z.write_text(z.read_text().replace("<DefaultProgName>Z<", "<DefaultProgName>Y<"))
    found = machine_findings(folder)
    assert [(Path(d["path"]).name, d["line"], d["code"]) for d in found] == [
        ("Axis_Z.xti", line_of(z, "<DefaultProgName>"), "LIS502")
    ]
    assert "`Y` in channel 1" in found[0]["message"]
    # in another channel the same name is another channel's axis
    z.write_text(z.read_text().replace("<DefaultChannel>1<", "<DefaultChannel>2<"))
    assert machine_findings(folder) == []


def test_xml_without_tree_items_is_compared_by_its_header() -> None:
    found = machine_findings(WITHOUT_TREE_ITEMS)
    assert [(Path(d["path"]).name, d["code"]) for d in found] == [("Axis_Z.xti", "LIS501")]
    assert "kopf.achs_nr 2" in found[0]["message"]


def test_a_header_is_not_compared_with_tree_items(tmp_path: Path) -> None:
    # An axis definition without tree item whose header number 1 equals the template of the tree items: the
    # tree items are compared by their own identity, so neither side is a duplicate of the other.
    folder = export_copy(tmp_path)
    plain = folder / "Axis_A.xti"
    shutil.copy(WITHOUT_TREE_ITEMS / "Axis_X.xti", plain)
    assert "kopf.achs_nr                        1" in plain.read_text()
    assert machine_findings(folder) == []


def test_the_editor_reports_what_the_command_line_reports_for_a_duplicate_tree_item(tmp_path: Path) -> None:
    folder = export_copy(tmp_path)
    shutil.copy(folder / "Axis_X.xti", folder / "Axis_X_old.xti")
    cli = machine_findings_cli(folder)
    assert {code for _, _, code in cli} == {"LIS501", "LIS502"}
    assert machine_findings_editor(folder) == cli


def test_the_reader_finds_the_tree_item_before_or_after_the_axis_definition() -> None:
    axis = "<IsgAxisDef><DefaultChannel>2</DefaultChannel><AchsMds><![CDATA[kopf.achs_nr 1\nEnde\n]]></AchsMds></IsgAxisDef>"
    project = (
        "<Project>\n"
        f"<TreeItem><ItemName>A</ItemName><ItemId>4</ItemId>{axis}</TreeItem>\n"
        f"<TreeItem>{axis}<PathName>TICC^CNC^Axes^B</PathName><ItemId>5</ItemId></TreeItem>\n"
        f"<TcSmItem>{axis}</TcSmItem>\n"
        "</Project>\n"
    ).encode()
    first, second, third = (embedded.tree_item for embedded in extract(project, "project.tsproj"))
    assert first is not None and (first.label, first.item_id, first.channel) == ("A", 4, 2)
    assert second is not None and (second.label, second.item_id, second.channel) == ("TICC^CNC^Axes^B", 5, 2)
    assert (
        second.positions["ItemId"][0]
        == project.decode().count("\n", 0, project.decode().index("<ItemId>5")) + 1
    )
    assert third is None  # an axis definition without tree item names no identity
