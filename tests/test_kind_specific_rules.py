"""Kind rules (issue 25 item 3) beyond their fixtures: the channel list's slots and counts (LIS701–LIS703),
the compensation tables (LIS704, LIS705), and the machine rules about compensation lists, offsets and the
number of channels (LIS519–LIS522). Each test is a small list or machine and the findings it must give, or
must not give, with the manual's reason in a comment."""

from __future__ import annotations

import json
from pathlib import Path

from achslint.core.diagnostics import Severity
from achslint.linting.linter import FileSettings, lint_file

from .conftest import run_cli


def found(text: str, kind: str, select: tuple[str, ...]) -> list[tuple[str, int, str]]:
    """(code, line, message) of the chosen rules on a list of `kind`."""
    result = lint_file((text + "Ende\n").encode(), "list.lis", FileSettings(kind=kind))
    assert result.error is None
    return [(d.code, d.line, d.message) for d in result.diagnostics if d.code in select]


CHANNEL = ("LIS701", "LIS702", "LIS703")
TABLES = ("LIS704", "LIS705")


# --- channel lists --------------------------------------------------------------------------------------


def test_a_spindle_with_a_path_axis_number_is_one_finding_on_the_spindle() -> None:
    text = (
        "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 1\n"
        "gruppe[0].achse[1].log_achs_nr 0\n"  # an empty slot: number 0 is no axis (P-CHAN-00035)
        "spindel[0].bezeichnung S\nspindel[0].log_achs_nr 1\n"
        "spindel[1].bezeichnung S2\n"  # no number: names no axis
    )
    [(code, line, message)] = found(text, "channel", CHANNEL)
    assert (code, line) == ("LIS701", 5)
    assert "gruppe[0].achse[0] (`X`, logical axis 1)" in message and "error 20426" in message


def test_names_are_compared_without_case_and_per_kind_of_slot() -> None:
    text = (
        "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 1\n"
        "gruppe[0].achse[1].bezeichnung x\ngruppe[0].achse[1].log_achs_nr 2\n"
        "spindel[0].bezeichnung S\nspindel[0].log_achs_nr 3\n"
        "spindel[1].bezeichnung s\nspindel[1].log_achs_nr 4\n"
    )
    assert [(code, line) for code, line, _ in found(text, "channel", CHANNEL)] == [
        ("LIS702", 3),
        ("LIS702", 7),
    ]
    # one logical axis with one name twice is no second name (LIS508 judges two names for one number)
    same = "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 1\n"
    assert [
        code
        for code, *_ in found(
            same + same.replace("[0].b", "[1].b").replace("[0].l", "[1].l"), "channel", CHANNEL
        )
    ] == ["LIS702"]


def test_a_count_the_channel_list_does_not_write_is_not_judged() -> None:
    # the default channel list underneath may set it (P-STUP-00034)
    text = "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 1\nspindel[0].log_achs_nr 3\n"
    assert found(text, "channel", CHANNEL) == []
    # a written count of 0 with a spindle entered is judged; an empty path-axis slot is not counted
    text += "spdl_anzahl 0\ngruppe[0].achs_anzahl 1\ngruppe[0].achse[1].log_achs_nr 0\n"
    [(code, line, message)] = found(text, "channel", CHANNEL)
    assert (code, line) == ("LIS703", 4) and "defines 1: spindel[0] (logical axis 3)" in message


def test_a_count_out_of_range_is_left_to_lis202() -> None:
    text = "spdl_anzahl 70000\nspindel[0].bezeichnung S\nspindel[0].log_achs_nr 3\n"
    result = lint_file((text + "Ende\n").encode(), "list.lis", FileSettings(kind="channel"))
    assert [d.code for d in result.diagnostics] == ["LIS202"]


def test_the_channel_rules_judge_no_default_channel_list() -> None:
    # a default channel list lies under every channel list: its slots are not a channel's own
    text = "spdl_anzahl 0\nspindel[0].bezeichnung S\nspindel[0].log_achs_nr 3\n"
    assert found(text, "default_channel", CHANNEL) == []
    assert [code for code, *_ in found(text, "channel", CHANNEL)] == ["LIS703"]


# --- compensation tables --------------------------------------------------------------------------------

HEAD = "kopf.achs_nr 1\nkopf.log_achs_name X\n"


def test_points_not_equidistant_need_each_setpoint() -> None:
    # interval 0 (its default): each interpolation point is given (P-COMP-00018); unilateral: no `neg`
    text = (
        HEAD
        + "kw.ssfk.kw_nr_max 2\nkw.ssfk.table[0].pos 1\nkw.ssfk.table[0].setpoint 0\nkw.ssfk.table[1].pos 2\n"
    )
    [(code, line, message)] = found(text, "compensation", TABLES)
    assert (code, line) == ("LIS704", 3)
    assert "does not write kw.ssfk.table[1].setpoint:" in message and ".neg" not in message


def test_a_table_without_its_count_is_measured_by_the_count_s_default() -> None:
    # kw_nr_max not written is 0: every entry lies outside; last_index not written is 0: one entry
    text = HEAD + "kw.ssfk.interval 100\nkw.ssfk.table[0].pos 1\nkw.crosscomp.table[0].setpoint 5\n"
    assert [(code, line) for code, line, _ in found(text, "compensation", TABLES)] == [
        ("LIS704", 4),
        ("LIS704", 5),
    ]
    _, _, missing = found(text, "compensation", TABLES)[1]
    assert missing.startswith(
        "`kw.crosscomp.last_index` = 0 (not written) gives the table the entries kw.crosscomp.table[0]"
    )


def test_a_plane_compensation_table_runs_j_over_master_2() -> None:
    # table[j][i]: j up to last_index_master2, i up to last_index_master1 (P-COMP-00016)
    text = HEAD + (
        "kw.crosscomp2.last_index_master1 2\nkw.crosscomp2.last_index_master2 0\n"
        "kw.crosscomp2.table[0][0].correction 1\nkw.crosscomp2.table[0][1].correction 1\n"
        "kw.crosscomp2.table[0][2].correction 1\n"
    )
    assert found(text, "compensation", TABLES) == []
    swapped = text.replace("[0][1]", "[1][0]")
    assert [(code, line) for code, line, _ in found(swapped, "compensation", TABLES)] == [
        ("LIS704", 4),  # table[0][1] not written (at the first count, last_index_master2)
        ("LIS704", 6),  # table[1][0] beyond master 2's single row
    ]


def test_max_points_bounds_the_table_size_and_zero_is_the_default() -> None:
    full = "".join(f"frict_comp.table[{i}].in {i + 1}\nfrict_comp.table[{i}].out 1\n" for i in range(21))
    # exactly max_points entries are allowed (P-COMP-00062: the largest number of entries)
    at_limit = HEAD + "frict_comp.max_points 21\nfrict_comp.table_entries 21\n" + full
    assert found(at_limit, "compensation", TABLES) == []
    # 0 written is the default 20 (P-COMP-00061 says so of plane compensation; read alike here)
    zero = HEAD + "frict_comp.max_points 0\nfrict_comp.table_entries 21\n" + full
    [(code, line, message)] = found(zero, "compensation", TABLES)
    assert (code, line) == ("LIS705", 4)
    assert "`frict_comp.max_points` = 0, which means its default 20" in message  # written: not "not set"
    # a table out of its range gets LIS705 only: what the CNC makes of its entries is not known
    sparse = HEAD + "frict_comp.table_entries 30\nfrict_comp.table[0].in 1\n"
    assert [code for code, *_ in found(sparse, "compensation", TABLES)] == ["LIS705"]


def test_a_huge_table_is_not_listed_entry_by_entry() -> None:
    # a count within its own type's range and max_points raised as far: no enumeration of 2e9 entries
    text = HEAD + "kw.ssfk.interval 100\nkw.ssfk.max_points 4000000000\nkw.ssfk.kw_nr_max 2000000000\n"
    assert found(text, "compensation", TABLES) == []
    # last indices beyond the plane table's own range are LIS202's; the table is not judged with them
    plane = HEAD + "kw.crosscomp2.last_index_master1 2000000000\nkw.crosscomp2.last_index_master2 5\n"
    assert [code for code, _ in _codes(plane, "compensation")] == ["LIS202"]


def _codes(text: str, kind: str) -> list[tuple[str, Severity]]:
    result = lint_file((text + "Ende\n").encode(), "list.lis", FileSettings(kind=kind))
    return [(d.code, d.severity) for d in result.diagnostics]


# --- machines -------------------------------------------------------------------------------------------

AXIS = (
    "kopf.achs_nr  {n}\nkopf.log_achs_name  {name}\nkenngr.antr_typ  1\nlr_hw[0].cam_direct_access  0\nEnde\n"
)
COMPENSATION = (
    "{head}kopf.log_achs_name X\nkw.ssfk.unit 1\nkw.ssfk.interval 500000\nkw.ssfk.kw_nr_max 1\n"
    "kw.ssfk.table[0].pos 0\nEnde\n"
)


def machine(tmp_path: Path, startup: str, **lists: str) -> Path:
    (tmp_path / "achsmds1.lis").write_text(AXIS.format(n=1, name="X"))
    (tmp_path / "achsmds2.lis").write_text(AXIS.format(n=2, name="Y"))
    for name, text in lists.items():
        (tmp_path / f"{name}.lis").write_text(text)
    path = tmp_path / "hochlauf.lis"
    path.write_text(
        "zahl_mds 2\nachs_mds[0] ./achsmds1.lis\nachs_mds[1] ./achsmds2.lis\n" + startup + "Ende\n"
    )
    return path


def lint_machine(path: Path, select: str) -> list[tuple[str, int, str, str]]:
    result = run_cli("lint", str(path), "--select", select, "--format", "json", "--exit-zero")
    assert result.returncode == 0, result.stderr
    return sorted(
        (Path(d["path"]).name, d["line"], d["code"], d["message"])
        for d in json.loads(result.stdout)["diagnostics"]
    )


def test_a_compensation_list_beyond_zahl_kw_is_left_to_lis516(tmp_path: Path) -> None:
    startup = "zahl_kw 1\nachs_kw[0] ./achskw1.lis\nachs_kw_log_ax_nr[0] 1\nachs_kw[1] ./achskw2.lis\n"
    path = machine(
        tmp_path,
        startup,
        achskw1=COMPENSATION.format(head="kopf.achs_nr 1\n"),
        achskw2=COMPENSATION.format(head="kopf.achs_nr 7\n"),
    )
    assert [row[:3] for row in lint_machine(path, "LIS516,LIS519,LIS520")] == [("hochlauf.lis", 7, "LIS516")]


def test_a_count_out_of_range_still_leaves_the_entries_above_it_to_lis516(tmp_path: Path) -> None:
    # zahl_kw 40 is above its range (1 ... 32, P-STUP-00016: LIS202), yet LIS516 reads it as written;
    # LIS519 must read it so too, or it would judge the assignment of a list LIS516 calls never loaded.
    startup = "zahl_kw -1\nachs_kw[0] ./achskw1.lis\nachs_kw_log_ax_nr[0] 7\n"
    path = machine(tmp_path, startup, achskw1=COMPENSATION.format(head="kopf.achs_nr 7\n"))
    assert [row[2:3] for row in lint_machine(path, "LIS516,LIS519,LIS520")] == [("LIS516",)]
    (tmp_path / "hochlauf.lis").write_text(
        (tmp_path / "hochlauf.lis").read_text().replace("zahl_kw -1", "zahl_kw 40")
    )
    # Out of range, the count is LIS202's alone: LIS517 calls no entry missing for it (how the CNC reads it is
    # not documented); at 32, the largest it accepts, the 31 unnamed entries are missing.
    assert [row[2] for row in lint_machine(path, "LIS202,LIS516,LIS517,LIS519")] == ["LIS202", "LIS519"]
    (tmp_path / "hochlauf.lis").write_text(
        (tmp_path / "hochlauf.lis").read_text().replace("zahl_kw 40", "zahl_kw 32")
    )
    [(_, _, code, message)] = lint_machine(path, "LIS202,LIS517")
    assert code == "LIS517" and "and 25 more" in message  # 31 missing: 6 shown


def test_an_axis_list_that_cannot_be_read_leaves_the_axis_numbers_unknown(tmp_path: Path) -> None:
    startup = "zahl_kw 1\nachs_kw[0] ./achskw1.lis\nachs_kw_log_ax_nr[0] 2\n"
    path = machine(tmp_path, startup, achskw1=COMPENSATION.format(head="kopf.achs_nr 2\n"))
    assert lint_machine(path, "LIS519") == []
    (tmp_path / "achsmds2.lis").unlink()  # LIS504: axis 2 may be in the missing list, so no LIS519
    assert [row[2] for row in lint_machine(path, "LIS504,LIS519")] == ["LIS504"]


def test_a_list_assigned_to_an_axis_the_machine_lacks_is_lis519s_alone(tmp_path: Path) -> None:
    # achs_kw_log_ax_nr 7 (P-STUP-00036) names no axis of the machine: no axis loads the list, so the CNC never
    # compares its kopf.achs_nr (error 110229) and LIS520's "axis 7 runs without it" cannot happen
    startup = "zahl_kw 1\nachs_kw[0] ./achskw1.lis\nachs_kw_log_ax_nr[0] 7\n"
    path = machine(tmp_path, startup, achskw1=COMPENSATION.format(head="kopf.achs_nr 1\n"))
    assert [row[2] for row in lint_machine(path, "LIS519,LIS520")] == ["LIS519"]
    # assigned to axis 2, which the machine has, the header 1 is LIS520's
    (tmp_path / "hochlauf.lis").write_text((tmp_path / "hochlauf.lis").read_text().replace("] 7", "] 2"))
    assert [row[2] for row in lint_machine(path, "LIS519,LIS520")] == ["LIS520"]


def test_a_compensation_list_without_kopf_achs_nr_is_axis_0(tmp_path: Path) -> None:
    startup = "zahl_kw 1\nachs_kw[0] ./achskw1.lis\nachs_kw_log_ax_nr[0] 1\n"
    path = machine(tmp_path, startup, achskw1=COMPENSATION.format(head=""))
    [(name, line, code, message)] = lint_machine(path, "LIS520")
    assert (name, line, code) == ("achskw1.lis", 1, "LIS520")
    assert message.startswith("`kopf.achs_nr` is not written, so it is 0:") and "error 110229" in message
    # a number that is out of range is the list's own finding (LIS202 when the list is linted), not this one
    (tmp_path / "achskw1.lis").write_text(COMPENSATION.format(head="kopf.achs_nr -1\n"))
    assert lint_machine(path, "LIS520") == []
    assert [row[2] for row in lint_machine(tmp_path / "achskw1.lis", "LIS202")] == ["LIS202"]


CHANNEL_LIST = "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 1\n"


def test_offsets_follow_the_slots_of_the_channel_list_and_its_default_list(tmp_path: Path) -> None:
    startup = (
        "kanal_anzahl 1\ndefault_sda_mds ./default_sda.lis\nsda_mds[0] ./sda_mds1.lis\n"
        "nullp_data[0] ./nullp_d1.lis\n"
    )
    offsets = "np_grp[1].achse[0].versch 100\nnp_grp[1].achse[2].versch 300\nEnde\n"
    path = machine(
        tmp_path,
        startup,
        default_sda="gruppe[0].achse[2].bezeichnung Z\ngruppe[0].achse[2].log_achs_nr 2\nEnde\n",
        sda_mds1=CHANNEL_LIST + "Ende\n",
        nullp_d1=offsets,
    )
    # slot 2 comes from the default channel list underneath: an axis of the channel
    assert lint_machine(path, "LIS521") == []
    (tmp_path / "default_sda.lis").write_text("grp_anzahl 1\nEnde\n")
    [(name, line, code, message)] = lint_machine(path, "LIS521")
    assert (name, line, code) == ("nullp_d1.lis", 2, "LIS521") and "(`X`)" in message
    # a channel whose list is not named is not judged (LIS522 says the list is missing, and names the one
    # beyond kanal_anzahl)
    (tmp_path / "hochlauf.lis").write_text(
        (tmp_path / "hochlauf.lis")
        .read_text()
        .replace("sda_mds[0] ./sda_mds1.lis", "sda_mds[1] ./sda_mds1.lis")
    )
    assert [row[1:3] for row in lint_machine(path, "LIS521,LIS522")] == [(4, "LIS522"), (6, "LIS522")]


def test_kanal_anzahl_out_of_range_is_not_compared(tmp_path: Path) -> None:
    path = machine(tmp_path, "kanal_anzahl 13\nsda_mds[0] ./sda_mds1.lis\n", sda_mds1=CHANNEL_LIST + "Ende\n")
    assert lint_machine(path, "LIS522") == []
    path = machine(
        tmp_path,
        "kanal_anzahl 1\nsda_mds[0] ./sda_mds1.lis\npzv_data[1] ./pzv.lis\n",
        sda_mds1=CHANNEL_LIST + "Ende\n",
        pzv="Ende\n",
    )
    [(_, line, code, message)] = lint_machine(path, "LIS522")
    assert (line, code) == (6, "LIS522") and "clamp position offset list of channel index 1" in message


def test_an_assignment_out_of_range_is_not_called_missing(tmp_path: Path) -> None:
    # achs_kw_log_ax_nr is 1 ... MAX(UNS16) (P-STUP-00036): -1 is LIS202's on the start-up list, not "not
    # written"; 0, its default, is accepted as written and assigns the list to no axis (LIS519, not LIS520)
    startup = "zahl_kw 1\nachs_kw[0] ./achskw1.lis\nachs_kw_log_ax_nr[0] -1\n"
    path = machine(tmp_path, startup, achskw1=COMPENSATION.format(head="kopf.achs_nr 1\n"))
    assert lint_machine(path, "LIS519,LIS520") == []
    (tmp_path / "hochlauf.lis").write_text((tmp_path / "hochlauf.lis").read_text().replace("] -1", "] 0"))
    [(_, line, code, message)] = lint_machine(path, "LIS519,LIS520")
    assert (line, code) == (6, "LIS519") and "= 0 assigns the axis compensation list" in message
    (tmp_path / "hochlauf.lis").write_text(
        (tmp_path / "hochlauf.lis").read_text().replace("achs_kw_log_ax_nr[0] 0\n", "")
    )
    [(_, line, code, message)] = lint_machine(path, "LIS519,LIS520")
    assert (line, code) == (5, "LIS519") and "`achs_kw_log_ax_nr[0]` is not written" in message


PAIR = "synchro_data.koppel_gruppe[0].paar[{i}].log_achs_nr_{role}  {number}\n"


def _pairs(*couples: tuple[int, int]) -> str:
    return "".join(
        PAIR.format(i=i, role="master", number=m) + PAIR.format(i=i, role="slave", number=s)
        for i, (m, s) in enumerate(couples)
    )


def test_coupled_pairs_in_a_circle_of_three_are_one_finding_on_the_pair_that_closes_it() -> None:
    # 1 leads 2, 2 leads 3, 3 leads 1 (P-CHAN-00037/38): the third pair (lines 5-6) closes the circle
    text = _pairs((1, 2), (2, 3), (3, 1)) + "Ende\n"
    [(code, line, message)] = found(text, "channel", ("LIS706",))
    assert (code, line) == (
        "LIS706",
        6,
    ) and "logical axes 3 → 1 → 2 → 3" in message  # 3 leads 1 (the new pair), 1 leads 2, 2 leads 3


def test_a_pair_of_a_spindle_and_a_path_axis_is_not_told_to_change_its_mode() -> None:
    # master 2 is a spindle, slave 1 a path axis (P-CHAN-00061: mode 0 path axes, 1 spindles): no mode fits
    # both, so "set mode to 1" would only move the finding to the slave
    slots = "gruppe[0].achse[0].log_achs_nr 1\nspindel[0].log_achs_nr 2\n"
    [(_, _, message)] = found(slots + _pairs((2, 1)), "channel", ("LIS706",))
    assert "its master, logical axis 2, is a spindle" in message and "couple axes of one kind" in message
    assert ".mode to" not in message
    # both spindles under mode 0: changing the mode is the remedy
    slots += "spindel[1].log_achs_nr 3\n"
    [(_, _, message)] = found(slots + _pairs((2, 3)), "channel", ("LIS706",))
    assert "synchro_data.koppel_gruppe[0].paar[0].mode to 1" in message


def test_a_chain_and_one_master_with_two_slaves_are_no_conflict() -> None:
    # 1 leads 2 and 3 (two slaves of one master); 3 leads 4 (a chain: not a circle, nothing documented
    # forbids it); the same pair written twice is no second master
    text = _pairs((1, 2), (1, 3), (3, 4), (1, 2)) + "Ende\n"
    assert found(text, "channel", ("LIS706",)) == []
