"""Review of the start-up list rules (LIS504, LIS516, LIS518, LIS522) and of how `machine.startup` reads a
start-up list's entries: Windows-style names (upper and lower case, drive letters), counts out of range,
and what the messages name. Each machine is built in a temporary folder from the SDK fixture's lists."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from achslint.machine.startup import read_startup

from .conftest import FIXTURES, run_cli

SDK = FIXTURES / "machines" / "sdk" / "listen"
AXES = "default_achs_mds ./listen/default_mds.lis\n"


def machine(tmp_path: Path, startup: str) -> Path:
    """A CNC root with the SDK fixture's axis lists in `listen/` and `startup` as `listen/hochlauf.lis`."""
    listen = tmp_path / "cnc" / "listen"
    listen.mkdir(parents=True)
    for source in SDK.glob("*.lis"):
        shutil.copy(source, listen / source.name)
    (listen / "hochlauf.lis").write_text(startup + "Ende\n")
    return listen / "hochlauf.lis"


def lint(startup: Path, select: str = "LIS5") -> list[dict]:
    result = run_cli("lint", str(startup), "--select", select, "--format", "json", "--exit-zero")
    assert result.returncode == 0, result.stderr
    return list(json.loads(result.stdout)["diagnostics"])


def codes(found: list[dict]) -> list[tuple[int, str, str]]:
    return sorted(
        (d["line"], d["code"], d["severity"]) for d in found if Path(d["path"]).name == "hochlauf.lis"
    )


# --- Windows names: the CNC runs on Windows, whose file names ignore case ---------------------------------


def test_an_entry_written_in_other_case_finds_the_list_as_the_cnc_does(tmp_path):
    startup = machine(
        tmp_path,
        "zahl_mds 2\n" + AXES + "achs_mds[0] .\\LISTEN\\ACHSMDS1.LIS\nachs_mds[1] ./Listen/AchsMds2.lis\n",
    )
    read = read_startup(startup)
    assert [entry.path for entry in read.axes] == [
        startup.parent / "achsmds1.lis",
        startup.parent / "achsmds2.lis",
    ]
    assert codes(lint(startup)) == []


def test_two_entries_that_differ_in_case_only_name_one_file(tmp_path):
    startup = machine(
        tmp_path,
        "zahl_mds 2\n" + AXES + "achs_mds[0] ./listen/achsmds1.lis\nachs_mds[1] ./listen/ACHSMDS1.lis\n",
    )
    assert codes(lint(startup, "LIS504,LIS518")) == [(4, "LIS518", "error")]


def test_a_windows_drive_path_is_not_looked_for_below_the_cnc_root(tmp_path):
    startup = machine(
        tmp_path,
        "zahl_mds 2\n" + AXES + "achs_mds[0] C:\\TwinCAT\\CNC\\listen\\achsmds1.lis\n"
        "achs_mds[1] ./listen/achsmds2.lis\n",
    )
    entry = read_startup(startup).axes[0]
    assert entry.path is None
    assert entry.refused is not None and "Windows" in entry.refused
    [found] = [d for d in lint(startup, "LIS504")]
    assert found["severity"] == "warning"
    assert "C:/" not in found["message"]  # not `<root>/C:/TwinCAT/...`, a path the CNC never looks at
    assert "relative to the CNC root" in found["message"]


# --- what the messages name ---------------------------------------------------------------------------------


def test_a_missing_list_names_the_cnc_root_itself(tmp_path):
    startup = machine(
        tmp_path, "zahl_mds 1\n" + AXES + "achs_mds[0] ./listen/gone.lis\nwerkz_data[0] ./w.lis\n"
    )
    found = lint(startup, "LIS504")
    assert len(found) == 2
    root = str(startup.parent.parent)
    for finding in found:  # the path looked for begins with the root's (it is not said twice)
        assert (
            f"looked for `{root}/" in finding["message"]
            and "(the CNC root is the folder above" in (finding["message"])
        ), finding["message"]


# --- counts ----------------------------------------------------------------------------------------------


def test_kanal_anzahl_0_is_told_it_configures_no_channel(tmp_path):
    startup = machine(
        tmp_path,
        "kanal_anzahl 0\nzahl_mds 1\n" + AXES + "achs_mds[0] ./listen/achsmds1.lis\n"
        "sda_mds[0] ./listen/achsmds1.lis\n",
    )
    [found] = lint(startup, "LIS522")
    assert "0 … -1" not in found["message"]
    assert "configures no channel" in found["message"]


@pytest.mark.parametrize("comment", ["( the first axis", "\t( tab and comment"])
def test_a_comment_after_an_entry_is_no_part_of_the_name(tmp_path, comment):
    startup = machine(tmp_path, "zahl_mds 1\n" + AXES + f"achs_mds[0] ./listen/achsmds1.lis {comment}\n")
    assert read_startup(startup).axes[0].path == startup.parent / "achsmds1.lis"


def test_a_list_of_another_kind_achslint_does_not_read_is_told_so(tmp_path):
    outside = tmp_path / "outside.lis"
    outside.write_text("Ende\n")
    startup = machine(
        tmp_path,
        "kanal_anzahl 1\nzahl_mds 1\n" + AXES + "achs_mds[0] ./listen/achsmds1.lis\n"
        f"werkz_data[0] {outside}\nrtconf_lis ../outside.lis\nzahl_kw 1\nachs_kw[0] C:\\cnc\\kw.lis\n",
    )
    found = {d["line"]: d for d in lint(startup, "LIS504")}
    assert sorted(found) == [5, 6, 8]
    assert all(d["severity"] == "warning" and "does not read" in d["message"] for d in found.values())
    assert "outside the CNC root" in found[5]["message"] and "Windows" in found[8]["message"]


def test_offsets_of_a_channel_beyond_kanal_anzahl_are_not_compared_with_its_channel_list(tmp_path):
    """LIS522 says the lists of channel index 1 are never loaded with kanal_anzahl 1; LIS521 must not go on
    to say which of their offsets belong to no axis of that channel."""
    bad = FIXTURES / "rules" / "LIS521" / "bad"
    folder = tmp_path / "m"
    shutil.copytree(bad, folder)
    text = (folder / "hochlauf.lis").read_text()
    text = text.replace("sda_mds[0]               ./sda_mds1.lis", "sda_mds[1]               ./sda_mds1.lis")
    text = text.replace("nullp_data[0]", "nullp_data[1]").replace("pzv_data[0]", "pzv_data[1]")
    (folder / "hochlauf.lis").write_text(text)
    found = lint(folder / "hochlauf.lis", "LIS521,LIS522")
    assert {d["code"] for d in found} == {"LIS522"}
