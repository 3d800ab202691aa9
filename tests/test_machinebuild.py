"""Machines from start-up lists: names from the channel list, gantry pairs, fallbacks and clear errors."""

from __future__ import annotations

from pathlib import Path

import pytest

from achslint.machine.build import MachineError, build_machine, rename
from achslint.machine.channel import read_channel_list

from .conftest import FIXTURES

SDK4 = FIXTURES / "machines" / "sdk4" / "listen" / "hochlauf.lis"
PORTAL = FIXTURES / "machines" / "portal" / "listen" / "hochlauf.lis"


def axis_list(number: int, name: str, *extra: str) -> str:
    return "\n".join([f"kopf.achs_nr {number}", f"kopf.log_achs_name {name}", *extra, "Ende", ""])


def machine_folder(tmp_path: Path, files: dict[str, str | bytes]) -> Path:
    for name, text in files.items():
        (tmp_path / name).write_bytes(text if isinstance(text, bytes) else text.encode("latin-1"))
    return tmp_path / "hochlauf.lis"


def test_the_sdk_layout_names_axes_from_its_channel_list():
    machine = build_machine(SDK4)
    assert {name: axis.logical_number for name, axis in machine.axes.items()} == {
        "X": 1,
        "Y": 2,
        "Z": 3,
        "S": 4,
    }
    assert machine.channel == 1 and machine.channel_list is not None
    assert machine.channel_list.name == "sda_mds1.lis"
    assert [name for name, axis in machine.axes.items() if axis.spindle] == ["S"]
    x = machine.axes["X"]
    assert x.list_path is not None and x.list_path.name == "achsmds1.lis"
    assert x.defaults is not None  # default_mds.lis is loaded underneath
    assert x.defined_at is not None and Path(x.defined_at.path).name == "sda_mds1.lis"
    assert x.defined_at.line == 5  # `gruppe[0].achse[0].bezeichnung X`
    assert x.resolved.homing_type == "CNC_CONTROLLED"
    assert machine.gantry_pairs == [] and machine.notes == [] and machine.other_axes == []


def test_the_portal_couples_its_slave_outside_the_channel_to_its_master():
    machine = build_machine(PORTAL)
    # achsmds7.lis (Y2, logical 7) sets kenngr.gantry_ax_nr 2; the channel list names only its master Y
    assert "Y2" not in machine.axes
    assert [(axis.name, axis.logical_number, axis.gantry_master) for axis in machine.followers()] == [
        ("Y2", 7, "Y")
    ]
    assert machine.gantry_pairs == [("Y", "Y2")] and machine.notes == []
    assert machine.axes["Y"].gantry_master is None
    assert {n: a.resolved.homing_type for n, a in machine.axes.items() if n in "BC"} == {
        "B": "IGNORE_ABS_POS",
        "C": "DISABLED",
    }


def test_without_a_channel_list_the_axes_go_by_their_log_achs_name(tmp_path):
    startup = machine_folder(
        tmp_path,
        {
            "hochlauf.lis": "achs_mds[0] achsmds1.lis\nachs_mds[1] achsmds2.lis\nachs_mds[2] achsmds3.lis\nEnde\n",
            "achsmds1.lis": axis_list(1, "x"),
            "achsmds2.lis": axis_list(2, "Z"),
            "achsmds3.lis": axis_list(3, "X"),
        },
    )
    machine = build_machine(startup)
    assert list(machine.axes) == ["X", "Z"]  # upper case; the second X is set aside
    assert machine.axes["X"].defined_at.line == 2
    assert [axis.logical_number for axis in machine.other_axes] == [3]
    assert any("no channel list" in note for note in machine.notes)
    assert any("kopf.log_achs_name X is the name of" in note for note in machine.notes)


def test_a_coupled_pair_of_the_channel_list_alone_makes_a_gantry(tmp_path):
    startup = machine_folder(
        tmp_path,
        {
            "hochlauf.lis": "sda_mds[0] sda.lis\nachs_mds[0] a1.lis\nachs_mds[1] a2.lis\nEnde\n",
            "a1.lis": axis_list(1, "X1"),
            "a2.lis": axis_list(2, "X2"),
            "sda.lis": "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 1\n"
            "gruppe[0].achse[1].bezeichnung XS\ngruppe[0].achse[1].log_achs_nr 2\n"
            "synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_master 1\n"
            "synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_slave 2\nEnde\n",
        },
    )
    machine = build_machine(startup)
    assert list(machine.axes) == ["X", "XS"]  # the channel's names, not kopf.log_achs_name
    assert machine.gantry_pairs == [("X", "XS")]


def gantry_outside_the_channel(tmp_path: Path, slave_name: str, *channel: str) -> Path:
    """Y (logical 1) and its static gantry slave (logical 2); the channel names Y and whatever `channel`
    adds (pairs of lines: name, logical number)."""
    names = ["gruppe[0].achse[0].bezeichnung Y", "gruppe[0].achse[0].log_achs_nr 1"]
    for i in range(0, len(channel), 2):
        slot = i // 2 + 1
        names += [f"gruppe[0].achse[{slot}].bezeichnung {channel[i]}"]
        names += [f"gruppe[0].achse[{slot}].log_achs_nr {channel[i + 1]}"]
    slave = "\n".join(["kopf.achs_nr 2", *([f"kopf.log_achs_name {slave_name}"] if slave_name else [])])
    return machine_folder(
        tmp_path,
        {
            "hochlauf.lis": "sda_mds[0] sda.lis\nachs_mds[0] a1.lis\nachs_mds[1] a2.lis\n"
            "achs_mds[2] a3.lis\nEnde\n",
            "a1.lis": axis_list(1, "Y"),
            "a2.lis": slave + "\nkenngr.gantry_ax_nr 1\nEnde\n",
            "a3.lis": axis_list(3, "X"),
            "sda.lis": "\n".join(names) + "\nEnde\n",
        },
    )


@pytest.mark.parametrize(
    ("slave_name", "channel", "expected"),
    [
        ("Y2", ("X", "3"), "Y2"),  # its kopf.log_achs_name
        ("", ("X", "3"), "slave of Y"),  # none: named after its master
        ("X", ("X", "3"), "slave of Y"),  # the channel calls axis 3 X: the slave cannot go by X
    ],
)
def test_a_gantry_slave_the_channel_leaves_out_follows_its_master(tmp_path, slave_name, channel, expected):
    machine = build_machine(gantry_outside_the_channel(tmp_path, slave_name, *channel))
    assert list(machine.axes) == ["Y", "X"]
    assert [(a.name, a.logical_number, a.gantry_master) for a in machine.followers()] == [(expected, 2, "Y")]
    assert machine.gantry_pairs == [("Y", expected)]
    assert not any("left out" in note for note in machine.notes)


def test_a_gantry_slave_whose_master_the_channel_leaves_out_too_is_no_pair(tmp_path):
    # the channel names only axis 3: neither Y nor its slave is programmable, the pair is dropped with a note
    startup = gantry_outside_the_channel(tmp_path, "Y2")
    (tmp_path / "sda.lis").write_text(
        "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 3\nEnde\n"
    )
    machine = build_machine(startup)
    assert list(machine.axes) == ["X"] and machine.gantry_pairs == [] and machine.followers() == []
    assert any("logical number 1 has no name in this channel" in note for note in machine.notes)


def test_names_from_a_scenario_leave_a_coupled_slave_without_a_name_of_its_own_outside(tmp_path):
    # No channel list; the slave's kopf.log_achs_name repeats its master's, so it goes by "slave of Y".
    # [names] renames the master only: the slave keeps following it and does not become programmable.
    startup = machine_folder(
        tmp_path,
        {
            "hochlauf.lis": "achs_mds[0] a1.lis\nachs_mds[1] a2.lis\nEnde\n",
            "a1.lis": axis_list(1, "Y"),
            "a2.lis": axis_list(2, "Y", "kenngr.gantry_ax_nr 1"),
        },
    )
    machine = build_machine(startup)
    assert list(machine.axes) == ["Y"] and [a.name for a in machine.followers()] == ["slave of Y"]
    rename(machine, {"Y1": 1}, "machine.toml")
    assert list(machine.axes) == ["Y1"]
    assert [(a.name, a.gantry_master) for a in machine.followers()] == [("slave of Y", "Y1")]
    assert machine.gantry_pairs == [("Y1", "slave of Y")]


def test_channel_list_problems_are_notes_and_unknown_parameters_are_passed_over(tmp_path):
    startup = machine_folder(
        tmp_path,
        {
            "hochlauf.lis": "default_sda_mds dsda.lis\nsda_mds[0] sda.lis\nachs_mds[0] a1.lis\nEnde\n",
            "a1.lis": axis_list(1, "X"),
            # the default channel list names the axis; the channel list only repeats the number
            "dsda.lis": "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 9\n"
            "some_channel_parameter 5\nEnde\n",
            "sda.lis": "gruppe[0].achse[0].log_achs_nr 1\nvector.acceleration 99\n"
            "gruppe[0].achse[1].bezeichnung Q\ngruppe[0].achse[1].log_achs_nr 7\n"
            "spindel[0].bezeichnung S\nspindel[0].log_achs_nr many\nEnde\n",
        },
    )
    machine = build_machine(startup)
    assert list(machine.axes) == ["X"]
    assert sorted(note.replace(f"{tmp_path}/", "") for note in machine.notes) == [
        "sda.lis:3: gruppe[0].achse[1] names Q as logical axis 7, but no axis list of the start-up list has "
        "that kopf.achs_nr; the name is left out",
        "sda.lis:6: spindel[0].log_achs_nr (P-CHAN-00036): `many` is not a whole number; this entry is left out",
    ]


def test_channel_values_are_checked_against_the_parameter_table():
    found = read_channel_list(
        b"gruppe[0].achse[0].bezeichnung ABCDEFGHIJKLMNOPQ\ngruppe[0].achse[0].log_achs_nr 1\n"
        b"spindel[0].bezeichnung S\nspindel[0].log_achs_nr 0\n"
        b'gruppe[0].achse[1].bezeichnung "Z"\ngruppe[0].achse[1].log_achs_nr 70000\nEnde\n',
        "sda.lis",
    )
    assert found.axes == []
    assert [(p.at.line, p.message.split(": ", 1)[1]) for p in found.problems] == [
        (1, "`ABCDEFGHIJKLMNOPQ` is longer than 16 characters; this entry is left out"),
        (4, "0 is outside 1 … 65535; this entry is left out"),
        (6, "70000 is outside 0 … 65535; this entry is left out"),
    ]


def test_a_missing_axis_list_names_the_start_up_line(tmp_path):
    startup = machine_folder(tmp_path, {"hochlauf.lis": "# machine\nachs_mds[0] gone.lis\nEnde\n"})
    with pytest.raises(MachineError) as caught:
        build_machine(startup)
    assert caught.value.line == 2 and caught.value.path == str(startup)
    assert str(caught.value).startswith(
        f"{startup}:2: `achs_mds[0]` names the axis list `gone.lis`, which does not exist"
    )


def test_a_missing_start_up_list(tmp_path):
    with pytest.raises(MachineError, match="cannot read the start-up list: no such file"):
        build_machine(tmp_path / "hochlauf.lis")


def test_a_channel_the_start_up_list_does_not_have(tmp_path):
    startup = machine_folder(
        tmp_path,
        {
            "hochlauf.lis": "sda_mds[0] sda.lis\nachs_mds[0] a1.lis\nEnde\n",
            "a1.lis": axis_list(1, "X"),
            "sda.lis": "Ende\n",
        },
    )
    with pytest.raises(MachineError, match=r"there is no channel 2: .* for channel 1"):
        build_machine(startup, channel=2)


def test_an_axis_list_that_is_no_list(tmp_path):
    startup = machine_folder(
        tmp_path, {"hochlauf.lis": "achs_mds[0] a1.lis\nEnde\n", "a1.lis": b"\x00\x01binary"}
    )
    with pytest.raises(
        MachineError, match=r"hochlauf.lis:1: the axis list `a1.lis` cannot be read: .*a binary file"
    ):
        build_machine(startup)
