"""Cross-list machine rules (issue 24 item 4) through the command line: what a channel list, the axis lists
and the start-up list say about each other (LIS512–LIS518, and LIS504 for unreadable channel and default
lists). Each rule on its fixture machine, the branches the fixtures do not show, and the fixture machines
of the SDK layouts, which must give none of these findings."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from .conftest import FIXTURES, run_cli

RULES = FIXTURES / "rules"
MACHINES = FIXTURES / "machines"
CROSS = ("LIS512", "LIS513", "LIS514", "LIS515", "LIS516", "LIS517", "LIS518")


def lint(target: Path, select: str = "LIS5") -> list[dict]:
    """The diagnostics of `achslint lint TARGET --select SELECT` as JSON objects."""
    result = run_cli("lint", str(target), "--select", select, "--format", "json", "--exit-zero")
    assert result.returncode == 0, result.stderr
    return list(json.loads(result.stdout)["diagnostics"])


def where(found: list[dict]) -> list[tuple[str, int, str]]:
    return sorted((Path(d["path"]).name, d["line"], d["code"]) for d in found)


# --- each rule on its fixture machine, linted as a folder -------------------------------------------------


@pytest.mark.parametrize(
    ("code", "expected"),
    [
        ("LIS512", [("sda_mds1.lis", 6, "LIS512"), ("sda_mds1.lis", 8, "LIS512")]),
        ("LIS513", [("sda_mds1.lis", 6, "LIS513"), ("sda_mds1.lis", 8, "LIS513")]),
        ("LIS514", [("sda_mds1.lis", 6, "LIS514")]),
        (
            "LIS515",
            [("sda_mds1.lis", 11, "LIS515"), ("sda_mds1.lis", 14, "LIS515"), ("sda_mds1.lis", 17, "LIS515")],
        ),
        ("LIS516", [("hochlauf.lis", 5, "LIS516"), ("hochlauf.lis", 9, "LIS516")]),
        ("LIS517", [("hochlauf.lis", 2, "LIS517"), ("hochlauf.lis", 5, "LIS517")]),
        ("LIS518", [("hochlauf.lis", 5, "LIS518"), ("hochlauf.lis", 6, "LIS518")]),
    ],
)
def test_the_bad_machine_folder_gives_the_rule_s_findings_and_the_good_one_none(code, expected):
    assert where(lint(RULES / code / "bad", code)) == expected
    assert lint(RULES / code / "good", code) == []


@pytest.mark.parametrize(
    "machine", ["sdk", "sdk4", "extschedule", "variants", "update", "xml_export", "twincat_export"]
)
def test_the_sdk_style_fixture_machines_give_no_cross_list_finding(machine):
    assert [d for d in lint(MACHINES / machine) if d["code"] in CROSS] == []


def test_the_portal_leaves_its_gantry_slave_out_of_the_channel_as_the_manual_says(tmp_path):
    # Y2 (axis 7) follows Y through kenngr.gantry_ax_nr 2: the channel names only Y and has no pair for them
    assert [d for d in lint(MACHINES / "portal") if d["code"] in CROSS] == []
    # named in the channel after all (as the portal once was), it is LIS514, and a pair repeating the static
    # gantry is LIS515
    copy = tmp_path / "portal"
    shutil.copytree(MACHINES / "portal", copy)
    channel = copy / "listen" / "sda_mds1.lis"
    text = channel.read_text(encoding="latin-1").replace(
        "achs_anzahl                                  6", "achs_anzahl 7"
    )
    added = (
        "gruppe[0].achse[6].bezeichnung Y2\ngruppe[0].achse[6].log_achs_nr 7\n"
        "synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_master 2\n"
        "synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_slave 7\nEnde\n"
    )
    channel.write_text(text.replace("Ende\n", added), encoding="latin-1")
    found = [d for d in lint(copy) if d["code"] in CROSS]
    assert where(found) == [("sda_mds1.lis", 22, "LIS514"), ("sda_mds1.lis", 24, "LIS515")]
    assert "`Y2`" in found[0]["message"] and "program its master `Y`" in found[0]["message"]


# --- branches ---------------------------------------------------------------------------------------------

AXIS = (
    "kopf.achs_nr  {n}\nkopf.log_achs_name  {name}\nkenngr.antr_typ  1\nlr_hw[0].cam_direct_access  0\nEnde\n"
)


def machine(
    folder: Path, startup: str, channel: str | None = None, axes: dict[int, str] | None = None
) -> Path:
    """A machine in `folder`: hochlauf.lis, achsmds<n>.lis for each axis number -> name, and sda_mds1.lis."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "hochlauf.lis").write_text(startup, encoding="latin-1")
    for number, name in (axes or {}).items():
        (folder / f"achsmds{number}.lis").write_text(AXIS.format(n=number, name=name), encoding="latin-1")
    if channel is not None:
        (folder / "sda_mds1.lis").write_text(channel, encoding="latin-1")
    return folder / "hochlauf.lis"


TWO_AXES = (
    "zahl_mds 2\nachs_mds[0] ./achsmds1.lis\nachs_mds[1] ./achsmds2.lis\nsda_mds[0] ./sda_mds1.lis\nEnde\n"
)


def test_lis512_waits_for_lis504_when_an_axis_list_of_the_machine_is_missing(tmp_path):
    # achsmds2.lis is missing: its number is unknown, so the channel's axis 2 is not reported as listless.
    channel = "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 1\n"
    channel += "gruppe[0].achse[1].bezeichnung Y\ngruppe[0].achse[1].log_achs_nr 2\nEnde\n"
    startup = machine(tmp_path, TWO_AXES, channel, {1: "X"})
    assert where(lint(startup)) == [("hochlauf.lis", 3, "LIS504")]
    # With the list there but of another number, LIS512 says which numbers the machine has.
    (tmp_path / "achsmds2.lis").write_text(AXIS.format(n=3, name="Y"), encoding="latin-1")
    found = lint(startup)
    assert where(found) == [("sda_mds1.lis", 3, "LIS512")]
    assert "(its axis lists have 1, 3)" in found[0]["message"] and "error 3210" in found[0]["message"]


def test_lis512_is_not_silenced_by_an_entry_beyond_zahl_mds_that_names_a_missing_list(tmp_path):
    # achs_mds[2] lies beyond zahl_mds 2 (LIS516): the CNC never reads it, so its missing file leaves no
    # axis number unknown, and the channel's axis 3 still has no axis list.
    channel = "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 1\n"
    channel += "gruppe[0].achse[1].bezeichnung Z\ngruppe[0].achse[1].log_achs_nr 3\nEnde\n"
    text = TWO_AXES.replace("sda_mds", "achs_mds[2] ./achsmds3.lis\nsda_mds", 1)
    found = lint(machine(tmp_path, text, channel, {1: "X", 2: "Y"}), "LIS512,LIS516")
    assert where(found) == [("hochlauf.lis", 4, "LIS516"), ("sda_mds1.lis", 3, "LIS512")]


def test_lis513_names_the_default_type_of_a_spindle_slot_s_axis_list(tmp_path):
    channel = "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 1\n"
    channel += "spindel[0].bezeichnung S\nspindel[0].log_achs_nr 2\nEnde\n"
    found = lint(machine(tmp_path, TWO_AXES, channel, {1: "X", 2: "S"}), "LIS513")
    assert where(found) == [("sda_mds1.lis", 3, "LIS513")]
    assert "kenngr.achs_typ is not set, so it is a linear axis" in found[0]["message"]
    assert "error 110304" in found[0]["message"]


def test_lis514_and_lis515_leave_a_pure_channel_coupling_alone(tmp_path):
    # No kenngr.gantry_ax_nr anywhere: the pair is the channel's synchronous operation, nothing contradicts it.
    channel = "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 1\n"
    channel += "gruppe[0].achse[1].bezeichnung X2\ngruppe[0].achse[1].log_achs_nr 2\n"
    channel += "synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_master 1\n"
    channel += "synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_slave 2\nEnde\n"
    assert lint(machine(tmp_path, TWO_AXES, channel, {1: "X", 2: "X2"})) == []


def test_lis515_leaves_a_circle_of_static_couplings_to_lis507(tmp_path):
    # X and Y name each other as gantry master (P-AXIS-00070): LIS507 says no axis leads; "Y is already a
    # static gantry of X, remove the pair" (LIS515) would contradict it, as LIS514 would with "its master".
    channel = "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 1\n"
    channel += "synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_master 1\n"
    channel += "synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_slave 2\nEnde\n"
    startup = machine(tmp_path, TWO_AXES, channel, {1: "X", 2: "Y"})
    couple = "kenngr.gantry_ax_nr  {}\nEnde\n"
    (tmp_path / "achsmds2.lis").write_text(AXIS.format(n=2, name="Y").replace("Ende\n", couple.format(1)))
    assert where(lint(startup, "LIS507,LIS515")) == [("sda_mds1.lis", 3, "LIS515")]
    (tmp_path / "achsmds1.lis").write_text(AXIS.format(n=1, name="X").replace("Ende\n", couple.format(2)))
    assert [d["code"] for d in lint(startup, "LIS507,LIS515")] == ["LIS507", "LIS507"]


def test_lis516_and_lis518_without_a_written_zahl_mds(tmp_path):
    # No count to compare with: LIS516 says nothing, and LIS518 compares every entry (as explain reads them).
    text = "achs_mds[0] ./achsmds1.lis\nachs_mds[1] ./achsmds2.lis\nachs_mds[2] ./achsmds1.lis\nEnde\n"
    assert where(lint(machine(tmp_path, text, None, {1: "X", 2: "Y"}), "LIS516,LIS518")) == [
        ("hochlauf.lis", 3, "LIS518")
    ]


def test_lis518_compares_the_files_entries_lead_to_and_only_entries_the_cnc_reads(tmp_path):
    text = "zahl_mds 2\nachs_mds[0] ./achsmds1.lis\nachs_mds[1] ./sub/../achsmds1.lis\nachs_mds[2] ./achsmds1.lis\nEnde\n"
    (tmp_path / "sub").mkdir()
    found = lint(machine(tmp_path, text, None, {1: "X"}), "LIS516,LIS518")
    # achs_mds[1] is the same file by another path; achs_mds[2] is beyond zahl_mds, so only LIS516 speaks.
    assert where(found) == [("hochlauf.lis", 3, "LIS518"), ("hochlauf.lis", 4, "LIS516")]
    assert "`./sub/../achsmds1.lis` (`./achsmds1.lis`)" in found[0]["message"]


def test_lis504_reports_a_channel_list_and_a_default_channel_list_that_cannot_be_read(tmp_path):
    startup = "zahl_mds 1\nachs_mds[0] ./achsmds1.lis\nsda_mds[0] ./sda_mds1.lis\ndefault_sda_mds ./default_sda.lis\nEnde\n"
    target = machine(tmp_path, startup, None, {1: "X"})
    (tmp_path / "sda_mds1.lis").write_bytes("gruppe[0].achse[0].bezeichnung X\nEnde\n".encode("utf-16"))
    (tmp_path / "default_sda.lis").write_bytes(b"grp_anzahl 1\x00\nEnde\n")
    found = lint(target)
    assert where(found) == [("hochlauf.lis", 3, "LIS504"), ("hochlauf.lis", 4, "LIS504")]
    assert all(d["severity"] == "error" and "cannot be read as a list" in d["message"] for d in found)
    assert "UTF-16" in found[0]["message"] and "binary" in found[1]["message"]


@pytest.mark.parametrize("index", [32, 40, 10**18])
def test_lis516_does_not_ask_for_a_count_above_the_largest_one(tmp_path, index):
    """Found by review: an entry at index 32 or above asked to `raise zahl_mds to 33` (or to 10**18 + 1),
    a count LIS202 calls out of range (P-STUP-00014: 1 ... 32), so one finding's remedy was another's
    error. No count reaches such an entry: it names a free index below 32 or removing the entry instead."""
    text = f"zahl_mds 2\nachs_mds[0] ./achsmds1.lis\nachs_mds[1] ./achsmds2.lis\nachs_mds[{index}] ./achsmds3.lis\nEnde\n"
    found = lint(machine(tmp_path, text, None, {1: "X", 2: "Y", 3: "Z"}), "LIS516")
    assert where(found) == [("hochlauf.lis", 4, "LIS516")]
    message = found[0]["message"]
    assert "raise zahl_mds" not in message and f"{index + 1}" not in message
    assert "zahl_mds is at most 32" in message and "free index below 32" in message
    # below 32 the count is still the remedy
    text = text.replace(f"achs_mds[{index}]", "achs_mds[31]")
    assert "raise zahl_mds to 32 at least" in lint(machine(tmp_path, text), "LIS516")[0]["message"]


@pytest.mark.parametrize("counts", ["", "kanal_anzahl 20\nzahl_kw 40\n"])
def test_lis504_leaves_out_entries_no_count_reaches(tmp_path, counts):
    """Found by review: `sda_mds[12]` (kanal_anzahl is at most 12, P-STUP-00001), `achs_kw[32]` (zahl_kw at
    most 32, P-STUP-00016) and tool data of channel index 12 are never loaded, whatever the count says (LIS516
    and LIS522 say no count reaches them), yet LIS504 said the CNC aborts the start-up (or cannot load the
    list) when such an entry names a missing file. The last entries a count can reach are still reported.
    With no count written, or one out of range (LIS202), the range of the count bounds the entries."""
    text = (
        f"{counts}zahl_mds 1\nachs_mds[0] ./achsmds1.lis\n"
        "sda_mds[11] ./sda_mds12.lis\nsda_mds[12] ./sda_mds13.lis\n"
        "achs_kw[31] ./kw32.lis\nachs_kw[32] ./kw33.lis\n"
        "werkz_data[11] ./wz12.lis\nwerkz_data[12] ./wz13.lis\nEnde\n"
    )
    skip = 2 if counts else 0
    found = lint(machine(tmp_path, text, None, {1: "X"}), "LIS504")
    assert where(found) == [("hochlauf.lis", skip + line, "LIS504") for line in (3, 5, 7)]
    assert [d["severity"] for d in found] == ["error", "warning", "warning"]
    assert all("[11]" in d["message"] or "[31]" in d["message"] for d in found)


def test_an_object_list_entry_written_default_names_no_file(tmp_path):
    """ISG's own SDK start-up list writes `hmi[0].objects default` and `channel[0].objects default`: the
    built-in objects, not a file called `default` (LIS504 said the list was missing). Any other name of an
    object list is still looked for, and `default` means nothing special for the other entries."""
    text = (
        "zahl_mds 1\nachs_mds[0] ./achsmds1.lis\nhmi[0].objects default\nchannel[0].objects  DEFAULT\n"
        "channel[1].objects ./objekte2.lis\nwerkz_data[0] default\nEnde\n"
    )
    found = lint(machine(tmp_path, text, None, {1: "X"}), "LIS504")
    assert where(found) == [("hochlauf.lis", 5, "LIS504"), ("hochlauf.lis", 6, "LIS504")]
    assert "objekte2.lis" in found[0]["message"] and "`default`" in found[1]["message"]
