"""LIS523: a start-up entry that names a list whose content is clearly of another kind (P-STUP-00015
`achs_mds[i]` naming a channel list, P-STUP-00009 `sda_mds[i]` naming an axis list ...), and what the named
file's own lint says then (LIS101 agrees with it). The rule's fixture machines are in fixtures/rules/LIS523;
these are the branches they do not show."""

from __future__ import annotations

import json
from pathlib import Path

from achslint.machine.resolved import Machine
from achslint.machine.startup import read_startup
from achslint.rules import lis523_entry_names_list_of_other_kind as lis523

from .conftest import run_cli

AXIS = "kopf.achs_nr {n}\nkopf.log_achs_name {name}\nkenngr.achs_typ 1\nEnde\n"
CHANNEL = (
    "grp_anzahl 1\ngruppe[0].achs_anzahl 1\ngruppe[0].achse[0].bezeichnung X\n"
    "gruppe[0].achse[0].log_achs_nr 1\nEnde\n"
)
SWAPPED = "kanal_anzahl 1\nzahl_mds 1\nachs_mds[0] ./sda_mds1.lis\nsda_mds[0] ./achsmds1.lis\nEnde\n"


def machine(folder: Path, startup: str, files: dict[str, str]) -> Path:
    for name, text in {"hochlauf.lis": startup, **files}.items():
        (folder / name).write_text(text, encoding="latin-1")
    return folder / "hochlauf.lis"


def lint(target: Path, select: str) -> list[dict]:
    result = run_cli("lint", str(target), "--select", select, "--format", "json", "--exit-zero")
    assert result.returncode == 0, result.stderr
    return sorted(
        json.loads(result.stdout)["diagnostics"], key=lambda d: (Path(d["path"]).name, d["line"], d["code"])
    )


def test_swapped_axis_and_channel_entries_are_told_and_the_files_own_lint_agrees(tmp_path):
    target = machine(tmp_path, SWAPPED, {"achsmds1.lis": AXIS.format(n=1, name="X"), "sda_mds1.lis": CHANNEL})
    found = lint(tmp_path, "LIS5,LIS101")
    on_entries = [(d["line"], d["severity"]) for d in found if d["code"] == "LIS523"]
    assert on_entries == [(3, "warning"), (4, "warning")]
    first, second = (d["message"] for d in found if d["code"] == "LIS523")
    assert "`achs_mds[0]` names `./sda_mds1.lis`, whose content is a channel list" in first
    assert "reads it as an axis list" in first and "`sda_mds[i]`" in first
    assert "whose content is an axis list" in second and "channel 1 gets no channel list" in second
    assert not [d for d in found if d["code"] == "LIS504"]  # both files exist and are read
    # The axis list read as a channel list: its names are told as axis parameters, not as channel
    # parameters achslint's partial catalogue might lack ("not checked").
    in_axis_list = [d for d in found if Path(d["path"]).name == "achsmds1.lis" and d["code"] == "LIS101"]
    assert len(in_axis_list) == 3
    for d in in_axis_list:
        assert "not checked" not in d["message"] and "LIS523" in d["message"]
    assert "P-AXIS-00016" in in_axis_list[0]["message"]
    # The channel list read as an axis list: told as channel parameters that belong in `sda_mds[i]`.
    in_channel_list = [d for d in found if Path(d["path"]).name == "sda_mds1.lis" and d["code"] == "LIS101"]
    assert in_channel_list and all("`sda_mds[i]`" in d["message"] for d in in_channel_list)
    # With the entries the right way round, none of it.
    target.write_text(
        SWAPPED.replace("./sda_mds1", "./TMP")
        .replace("./achsmds1", "./sda_mds1")
        .replace("./TMP", "./achsmds1")
    )
    assert lint(tmp_path, "LIS523,LIS101") == []


def test_a_list_too_short_to_show_its_kind_and_an_entry_never_loaded_are_left_alone(tmp_path):
    # two channel parameters are not clear evidence (three are); achs_mds[1] lies beyond zahl_mds (LIS516)
    startup = (
        "zahl_mds 1\nachs_mds[0] ./short.lis\nachs_mds[1] ./sda_mds1.lis\nsda_mds[0] ./achsmds1.lis\nEnde\n"
    )
    short = "grp_anzahl 1\ngruppe[0].achs_anzahl 1\nEnde\n"
    files = {"short.lis": short, "sda_mds1.lis": CHANNEL, "achsmds1.lis": "kopf.achs_nr 1\nEnde\n"}
    assert lint(machine(tmp_path, startup, files), "LIS523") == []
    # the same short file with a third channel parameter is clear
    (tmp_path / "short.lis").write_text(short.replace("Ende", "gruppe[0].achse[0].bezeichnung X\nEnde"))
    assert [d["line"] for d in lint(tmp_path / "hochlauf.lis", "LIS523")] == [2]


def test_an_entry_of_a_kind_without_a_catalogue_is_left_alone(tmp_path):
    # the content of an HMI object list is not known, so an axis list there cannot be told apart from one
    startup = "zahl_mds 1\nachs_mds[0] ./achsmds1.lis\nhmi[0].objects ./achsmds2.lis\nEnde\n"
    files = {"achsmds1.lis": AXIS.format(n=1, name="X"), "achsmds2.lis": AXIS.format(n=2, name="Y")}
    assert lint(machine(tmp_path, startup, files), "LIS523") == []


def test_the_list_is_read_as_the_machine_reads_it(tmp_path):
    """The editor's buffers count: the start-up list's reader gives the content, not the file on disk."""
    target = machine(
        tmp_path,
        "zahl_mds 1\nachs_mds[0] ./achsmds1.lis\nEnde\n",
        {"achsmds1.lis": AXIS.format(n=1, name="X")},
    )
    startup = read_startup(target)
    assert list(lis523.check_machine(Machine.of(startup))) == []
    open_buffer = {str(tmp_path / "achsmds1.lis"): CHANNEL.encode("latin-1")}
    startup.reader = lambda path: open_buffer.get(str(path)) or path.read_bytes()
    found = list(lis523.check_machine(Machine.of(startup)))
    assert [(d.line, d.code) for d in found] == [(2, "LIS523")]
    assert "whose content is a channel list" in found[0].message
