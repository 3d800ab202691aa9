"""One machine as the CNC loads it (issue 24 item 3): lint, explain and the dry-run of one axis list read the
list with the default axis list its start-up list loads underneath, and the machine reads each list it names
once, through the start-up list's reader."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from achslint.axis.resolved import resolve_bytes
from achslint.linting.discovery import Finder
from achslint.machine.build import channel_view
from achslint.machine.resolved import Machine, MachineError
from achslint.machine.startup import read_startup

from .conftest import FIXTURES, run_cli

PORTAL = FIXTURES / "machines" / "portal"


def _portal(tmp_path: Path) -> Path:
    shutil.copytree(PORTAL, tmp_path / "portal")
    return tmp_path / "portal" / "listen"


def test_explain_shows_the_values_of_the_default_list_the_start_up_list_loads(tmp_path: Path) -> None:
    listen = _portal(tmp_path)
    # achsmds5.lis writes no homing speed; default_mds.lis (default_achs_mds of hochlauf.lis) writes
    # getriebe[0].vb_refmax 50000 on its line 2. The catalogue's default would be 83333.
    done = run_cli("explain", str(listen / "achsmds5.lis"), "--format", "json")
    assert done.returncode == 0, done.stderr
    report = json.loads(done.stdout)
    row = next(r for r in report["parameters"] if r["parameter"] == "getriebe[0].vb_refmax")
    assert row["value"] == 50000 and row["source"] == {"kind": "default list", "line": 2}
    assert "default_mds.lis" in report["loaded_under"] and "hochlauf.lis" in report["loaded_under"]
    # and the value is the one lint judges: the resolved axis over the same default list
    [machine] = Finder().machines_of(listen / "achsmds5.lis")
    assert machine.defaults is not None
    values = resolve_bytes(
        (listen / "achsmds5.lis").read_bytes(), "achsmds5.lis", machine.defaults.read_bytes()
    )
    assert values.get("getriebe[0].vb_refmax") == row["value"]
    text = run_cli("explain", str(listen / "achsmds5.lis")).stdout.decode()
    assert "Read as the CNC loads it: default axis list" in text and "default list line 2" in text


def test_a_list_no_start_up_list_names_is_explained_alone(tmp_path: Path) -> None:
    alone = tmp_path / "achsmds1.lis"
    shutil.copy(PORTAL / "listen" / "achsmds5.lis", alone)
    report = json.loads(run_cli("explain", str(alone), "--format", "json").stdout)
    row = next(r for r in report["parameters"] if r["parameter"] == "getriebe[0].vb_refmax")
    assert report["loaded_under"] is None and row["source"]["kind"] == "default" and row["value"] == 83333


def test_the_dry_run_of_one_list_homes_with_the_default_lists_speeds(tmp_path: Path) -> None:
    listen = _portal(tmp_path)
    # achsmds3.lis writes its own speeds (vb_refmax 60000 µm/s on line 24): the list wins over the default list
    done = run_cli("dry-run", str(listen / "achsmds3.lis"), "--format", "json")
    report = json.loads(done.stdout)
    assert any("default axis list" in w["message"] for w in report["warnings"]), report["warnings"]
    # with its speed line removed, the default list's 50000 µm/s = 50 mm/s is the speed of phase 1
    text = (listen / "achsmds3.lis").read_text(encoding="latin-1")
    kept = [line for line in text.splitlines() if not line.startswith("getriebe[0].vb_refmax")]
    (listen / "achsmds3.lis").write_text("\n".join(kept) + "\n", encoding="latin-1")
    report = json.loads(run_cli("dry-run", str(listen / "achsmds3.lis"), "--format", "json").stdout)
    explained = json.loads(run_cli("explain", str(listen / "achsmds3.lis"), "--format", "json").stdout)
    row = next(r for r in explained["parameters"] if r["parameter"] == "getriebe[0].vb_refmax")
    assert row["value"] == 50000
    speeds = [abs(p["velocity"]) for p in report["phases"] if p.get("velocity") is not None]
    assert speeds and max(speeds) == 50.0, report["phases"]


def test_a_machine_reads_each_list_once_through_its_reader(tmp_path: Path) -> None:
    listen = _portal(tmp_path)
    reads: list[str] = []
    startup = read_startup(listen / "hochlauf.lis")

    def counting(path: Path) -> bytes:
        reads.append(Path(path).name)
        return Path(path).read_bytes()

    startup.reader = counting
    machine = Machine.of(startup)
    for _ in range(3):  # every rule asks; the lists are read once
        channels = machine.channel_lists()
    assert [channel.name.rsplit("/", 1)[-1] for _, channel in channels] == ["sda_mds1.lis"]
    view = channel_view(machine, 1)
    assert sorted(reads) == sorted(
        ["sda_mds1.lis", "default_sda.lis", "default_mds.lis", *(f"achsmds{n}.lis" for n in range(1, 9))]
    )
    assert {"X", "Y", "Z"} <= set(view.axes)


def test_a_missing_list_is_the_error_of_the_entry_that_names_it(tmp_path: Path) -> None:
    listen = _portal(tmp_path)
    (listen / "sda_mds1.lis").unlink()
    machine = Machine.of(read_startup(listen / "hochlauf.lis"))
    [entry] = machine.startup.channels if machine.startup else []
    assert machine.channel(entry) is None and machine.channel_lists() == []
    try:
        machine.channel(entry, strict=True)
    except MachineError as exc:
        assert exc.line == entry.line and "which does not exist" in str(exc) and "sda_mds1.lis" in str(exc)
    else:
        raise AssertionError("a missing channel list is an error when it is needed")


def test_a_start_up_list_named_otherwise_is_explained_and_compared_as_a_machine(tmp_path: Path) -> None:
    listen = _portal(tmp_path)
    (listen / "hochlauf.lis").rename(listen / "basis.lis")  # told by its content: achs_mds[i], zahl_mds ...
    done = run_cli("explain", str(listen / "basis.lis"), "--format", "json")
    assert done.returncode == 0, done.stderr
    report = json.loads(done.stdout)
    assert {"X", "Y", "Z"} <= {axis["name"] for axis in report["axes"]}
    backup = tmp_path / "backup"
    shutil.copytree(tmp_path / "portal", backup)
    same = run_cli(
        "diff", str(listen / "basis.lis"), str(backup / "listen" / "basis.lis"), "--format", "json"
    )
    assert same.returncode == 0 and json.loads(same.stdout)["kind"] == "machines", same.stderr
    # a folder holding it is a machine too
    folders = run_cli("diff", str(listen), str(backup / "listen"), "--format", "json")
    assert folders.returncode == 0 and json.loads(folders.stdout)["differ"] is False, folders.stderr


_TREE_ITEM = """<?xml version="1.0" encoding="utf-8"?>
<TreeItem><ItemName>Axis_{name}</ItemName><PathName>TICC^CNC^Axes^Axis_{name}</PathName><ItemId>{item}</ItemId>
<IsgAxisDef><DriveType>4</DriveType><Spindle>false</Spindle><DefaultChannel>1</DefaultChannel>
<DefaultProgName>{name}</DefaultProgName>
<AchsMds><![CDATA[#TC_AXIS_DESC:    axis
kopf.achs_nr                     {number}
kopf.log_achs_name               {header}
kenngr.antr_typ                  4
{extra}Ende
]]></AchsMds></IsgAxisDef></TreeItem>
"""


def _export(folder: Path, numbers: tuple[int, int, int]) -> Path:
    folder.mkdir()
    for item, (name, number) in enumerate(zip("XYZ", numbers, strict=True), start=1):
        # Y is a gantry slave of logical axis 7, which no axis of the export has by its header
        extra = "kenngr.gantry_ax_nr              7\n" if name == "Y" else ""
        header = "X_Achse" if len(set(numbers)) == 1 else name
        (folder / f"Axis_{name}.xti").write_text(
            _TREE_ITEM.format(name=name, item=item, number=number, header=header, extra=extra)
        )
    return folder


def test_gantry_rules_do_not_pair_axes_by_the_template_number_of_an_export(tmp_path: Path) -> None:
    # Every axis embeds TwinCAT's template header (kopf.achs_nr 1): that number is not the axis's, so the
    # gantry rules cannot tell whether logical axis 7 exists — no LIS503 from a template number.
    template = _export(tmp_path / "template", (1, 1, 1))
    found = json.loads(run_cli("lint", str(template), "--format", "json").stdout)["diagnostics"]
    assert [d["code"] for d in found if d["code"].startswith("LIS5")] == []
    # With headers that tell the axes apart (1, 2, 3) the number is the axis's: the missing master is LIS503.
    numbered = _export(tmp_path / "numbered", (1, 2, 3))
    found = json.loads(run_cli("lint", str(numbered), "--format", "json").stdout)["diagnostics"]
    assert [(Path(d["path"]).name, d["code"]) for d in found if d["code"].startswith("LIS5")] == [
        ("Axis_Y.xti", "LIS503")
    ]


def test_a_gantry_master_numbered_by_the_repeated_template_header_is_not_missing(tmp_path: Path) -> None:
    # X and Y keep the template header (kopf.achs_nr 1), Z was given its own number 3 and names 1 as its
    # gantry master (P-AXIS-00070): two lists have kopf.achs_nr 1, so "no axis list has it" (LIS503) is false.
    folder = tmp_path / "export"
    folder.mkdir()
    for item, (name, number, extra) in enumerate(
        [("X", 1, ""), ("Y", 1, ""), ("Z", 3, "kenngr.gantry_ax_nr              1\n")], start=1
    ):
        (folder / f"Axis_{name}.xti").write_text(
            _TREE_ITEM.format(name=name, item=item, number=number, header=name, extra=extra)
        )
    found = json.loads(run_cli("lint", str(folder), "--format", "json").stdout)["diagnostics"]
    assert [d["code"] for d in found if d["code"] == "LIS503"] == []
    # a master number no list carries is still missing
    text = (
        (folder / "Axis_Z.xti")
        .read_text()
        .replace("gantry_ax_nr              1", "gantry_ax_nr              7")
    )
    (folder / "Axis_Z.xti").write_text(text)
    found = json.loads(run_cli("lint", str(folder), "--format", "json").stdout)["diagnostics"]
    assert [(Path(d["path"]).name, d["code"]) for d in found if d["code"] == "LIS503"] == [
        ("Axis_Z.xti", "LIS503")
    ]


def test_a_start_up_list_is_linted_as_a_list_and_so_are_the_compensation_lists_it_names(
    tmp_path: Path,
) -> None:
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr  1\nkopf.log_achs_name  X\nEnde\n")
    # a compensation table of five points of which only two are written (LIS704: the others default to 0)
    (tmp_path / "achskw1.lis").write_text(
        "kopf.achs_nr  1\nkw.ssfk.kw_nr_max  5\nkw.ssfk.table[0].pos  0\nkw.ssfk.table[1].pos  12\nEnde\n"
    )
    (tmp_path / "hochlauf.lis").write_text(
        "zahl_mds  1\nachs_mds[0]  ./achsmds1.lis\nzahl_kw  1\nachs_kw[0]  ./achskw1.lis\n"
        "achs_kw_log_ax_nr[0]  1\nEnde\nzahl_mdz  2\n"
    )
    done = run_cli("lint", str(tmp_path / "hochlauf.lis"), "--format", "json")
    found = {(Path(d["path"]).name, d["line"], d["code"]) for d in json.loads(done.stdout)["diagnostics"]}
    # its own line after `Ende` (the CNC ignores it), and the compensation list against its own catalogue
    assert ("hochlauf.lis", 7, "LIS003") in found
    assert any(name == "achskw1.lis" and code == "LIS704" for name, _, code in found), found
    assert json.loads(done.stdout)["summary"]["files"] == 3


def _codes(target: Path) -> list[tuple[str, int, str]]:
    done = run_cli("lint", str(target), "--format", "json", "--exit-zero")
    assert done.returncode == 0, done.stderr
    return sorted(
        (Path(d["path"]).name, d["line"], d["code"]) for d in json.loads(done.stdout)["diagnostics"]
    )


def _axes(folder: Path, *numbers: int, spindle: int | None = None) -> None:
    for number in numbers:
        kind = "kenngr.achs_typ  4\nkenngr.achs_mode  0x4\n" if number == spindle else ""
        (folder / f"achsmds{number}.lis").write_text(
            f"kopf.achs_nr  {number}\nkopf.log_achs_name  A{number}\nkenngr.antr_typ  4\n{kind}Ende\n"
        )


def test_a_channel_list_beyond_kanal_anzahl_is_no_configured_channel(tmp_path: Path) -> None:
    # kanal_anzahl 1 (P-STUP-00001): sda_mds[1] belongs to no configured channel — LIS522 says so, and neither
    # LIS504 (missing) nor the channel rules (LIS512 on its axis 9) judge a channel the CNC does not set up
    _axes(tmp_path, 1)
    (tmp_path / "sda_mds1.lis").write_text(
        "gruppe[0].achse[0].bezeichnung  X\ngruppe[0].achse[0].log_achs_nr  1\nEnde\n"
    )
    (tmp_path / "sda_mds2.lis").write_text(
        "gruppe[0].achse[0].bezeichnung  Q\ngruppe[0].achse[0].log_achs_nr  9\nEnde\n"
    )
    startup = (
        "kanal_anzahl  1\nsda_mds[0]  ./sda_mds1.lis\nsda_mds[1]  ./sda_mds2.lis\nsda_mds[2]  ./gone.lis\n"
    )
    (tmp_path / "hochlauf.lis").write_text(startup + "zahl_mds  1\nachs_mds[0]  ./achsmds1.lis\nEnde\n")
    found = [c for c in _codes(tmp_path / "hochlauf.lis") if c[2] in ("LIS504", "LIS512", "LIS522")]
    assert {code for *_, code in found} == {"LIS522"}, found
    # explain --channel 2 agrees: the list is named, but not loaded (it said the start-up list names none).
    done = run_cli("explain", str(tmp_path / "hochlauf.lis"), "--channel", "2")
    err = done.stderr.decode()
    assert done.returncode == 2 and "there is no channel 2: `sda_mds[1]` names a list for it" in err
    assert "`kanal_anzahl 1` configures fewer channels" in err and "(LIS522)" in err


def test_an_entry_written_twice_names_the_later_list_as_the_cnc_reads_it(tmp_path: Path) -> None:
    # achs_mds[1] twice (LIS005: the CNC takes the later value): the machine loads achsmds3.lis, not achsmds2
    _axes(tmp_path, 1, 2, 3)
    (tmp_path / "hochlauf.lis").write_text(
        "achs_mds[0]  ./achsmds1.lis\nachs_mds[1]  ./achsmds2.lis\nachs_mds[1]  ./achsmds3.lis\nEnde\n"
    )
    startup = read_startup(tmp_path / "hochlauf.lis")
    assert [(e.key, e.raw) for e in startup.axes] == [
        ("achs_mds[0]", "./achsmds1.lis"),
        ("achs_mds[1]", "./achsmds3.lis"),
    ]
    report = json.loads(run_cli("explain", str(tmp_path / "hochlauf.lis"), "--format", "json").stdout)
    assert sorted(axis["name"] for axis in report["axes"]) == ["A1", "A3"]
    assert ("hochlauf.lis", 3, "LIS005") in _codes(tmp_path / "hochlauf.lis")


def test_one_number_for_a_path_axis_and_a_spindle_is_lis701s_not_lis513s(tmp_path: Path) -> None:
    # spindel[0] takes logical axis 2, which gruppe[0].achse[1] has: LIS701; LIS513's advice (change the axis
    # list's type) would only move the fault to the other slot
    _axes(tmp_path, 1, 2)
    (tmp_path / "sda_mds1.lis").write_text(
        "gruppe[0].achse[0].bezeichnung  X\ngruppe[0].achse[0].log_achs_nr  1\n"
        "gruppe[0].achse[1].bezeichnung  Y\ngruppe[0].achse[1].log_achs_nr  2\n"
        "spindel[0].bezeichnung  S\nspindel[0].log_achs_nr  2\nEnde\n"
    )
    (tmp_path / "hochlauf.lis").write_text(
        "sda_mds[0]  ./sda_mds1.lis\nachs_mds[0]  ./achsmds1.lis\nachs_mds[1]  ./achsmds2.lis\nEnde\n"
    )
    codes = {code for *_, code in _codes(tmp_path / "hochlauf.lis")}
    assert "LIS701" in codes and "LIS513" not in codes


def test_a_second_master_in_the_channel_is_said_once(tmp_path: Path) -> None:
    # axis 2 is the static gantry slave of 1 (P-AXIS-00070), and the channel couples it to 1 and then to 3:
    # LIS706 says the channel gives it two masters; LIS515 speaks of the first pair only
    _axes(tmp_path, 1, 3)
    (tmp_path / "achsmds2.lis").write_text(
        "kopf.achs_nr  2\nkenngr.gantry_ax_nr  1\nkenngr.antr_typ  4\nEnde\n"
    )
    pair = "synchro_data.koppel_gruppe[0].paar[{i}].log_achs_nr_{r}  {n}\n"
    (tmp_path / "sda_mds1.lis").write_text(
        "gruppe[0].achse[0].bezeichnung  X\ngruppe[0].achse[0].log_achs_nr  1\n"
        "gruppe[0].achse[1].bezeichnung  Z\ngruppe[0].achse[1].log_achs_nr  3\n"
        + pair.format(i=0, r="master", n=1)
        + pair.format(i=0, r="slave", n=2)
        + pair.format(i=1, r="master", n=3)
        + pair.format(i=1, r="slave", n=2)
        + "Ende\n"
    )
    (tmp_path / "hochlauf.lis").write_text(
        "sda_mds[0]  ./sda_mds1.lis\n"
        + "".join(f"achs_mds[{n - 1}]  ./achsmds{n}.lis\n" for n in (1, 2, 3))
        + "Ende\n"
    )
    found = [(line, code) for name, line, code in _codes(tmp_path / "hochlauf.lis") if name == "sda_mds1.lis"]
    assert found == [(5, "LIS515"), (8, "LIS706")]


def test_one_axis_in_two_slots_is_told_as_such() -> None:
    text = (
        "gruppe[0].achse[0].bezeichnung  Y\ngruppe[0].achse[0].log_achs_nr  2\n"
        "gruppe[0].achse[1].bezeichnung  Y\ngruppe[0].achse[1].log_achs_nr  2\nEnde\n"
    )
    from achslint.linting.linter import FileSettings, lint_file

    [finding] = [
        d
        for d in lint_file(text.encode(), "sda.lis", FileSettings(kind="channel")).diagnostics
        if d.code == "LIS702"
    ]
    assert "repeats gruppe[0].achse[0]" in finding.message and "remove one of the slots" in finding.message


def test_a_missing_list_of_another_kind_is_a_warning_and_one_beyond_zahl_kw_none(tmp_path: Path) -> None:
    _axes(tmp_path, 1)
    (tmp_path / "hochlauf.lis").write_text(
        "zahl_mds  1\nachs_mds[0]  ./achsmds1.lis\nzahl_kw  1\nachs_kw[0]  ./achskw1.lis\n"
        "achs_kw_log_ax_nr[0]  1\nachs_kw[1]  ./achskw2.lis\nwerkz_data[0]  ./werkz.lis\nEnde\n"
    )
    done = run_cli("lint", str(tmp_path / "hochlauf.lis"), "--format", "json", "--select", "LIS504")
    found = [(d["line"], d["severity"]) for d in json.loads(done.stdout)["diagnostics"]]
    # achs_kw[1] lies beyond zahl_kw 1 (LIS516's): never loaded, so not missing to the CNC
    assert found == [(4, "warning"), (7, "warning")]
    assert done.returncode == 0  # warnings only


def test_the_channel_count_counts_the_slots_of_the_default_channel_list_too(tmp_path: Path) -> None:
    # default_sda.lis defines Z (gruppe[0].achse[2]); sda_mds1.lis X and Y and achs_anzahl 3: the CNC loads
    # three axes (P-CHAN-00003), as LIS512/LIS521 and explain count them, so LIS703 has nothing to say
    _axes(tmp_path, 1, 2, 3)
    (tmp_path / "default_sda.lis").write_text(
        "gruppe[0].achse[2].bezeichnung  Z\ngruppe[0].achse[2].log_achs_nr  3\nEnde\n"
    )
    (tmp_path / "sda_mds1.lis").write_text(
        "gruppe[0].achs_anzahl  3\ngruppe[0].achse[0].bezeichnung  X\ngruppe[0].achse[0].log_achs_nr  1\n"
        "gruppe[0].achse[1].bezeichnung  Y\ngruppe[0].achse[1].log_achs_nr  2\nEnde\n"
    )
    (tmp_path / "hochlauf.lis").write_text(
        "default_sda_mds  ./default_sda.lis\nsda_mds[0]  ./sda_mds1.lis\n"
        + "".join(f"achs_mds[{n - 1}]  ./achsmds{n}.lis\n" for n in (1, 2, 3))
        + "Ende\n"
    )
    assert [c for c in _codes(tmp_path / "hochlauf.lis") if c[2] == "LIS703"] == []
    assert [c for c in _codes(tmp_path) if c[2] == "LIS703"] == []  # the folder: the same machine
    # alone (no start-up list names it) the channel list defines two: LIS703
    alone = tmp_path / "alone"
    alone.mkdir()
    (alone / "sda_mds1.lis").write_bytes((tmp_path / "sda_mds1.lis").read_bytes())
    assert [c[2] for c in _codes(alone / "sda_mds1.lis")] == ["LIS703"]


def test_a_block_with_extended_axis_names_reads_back_as_written() -> None:
    # `A1=1 A2=2`: an axis name with digits takes `=` (ISG extended addresses); `A11 A22` would be other words
    from achslint.machine.model import AxisWord, HomingBlock, Location, MoveBlock
    from achslint.machine.run import block_text

    at = Location("rfp.nc", 1)
    homing = HomingBlock(at, 10, (AxisWord("A1", 1, at), AxisWord("X", 2, at)))
    assert block_text(homing) == "N10 G74 A1=1 X2"
    move = MoveBlock(at, 20, rapid=True, absolute=True, feed_mm_min=None, targets=(AxisWord("Z2", 5.5, at),))
    assert block_text(move) == "N20 G00 G90 Z2=5.5"
