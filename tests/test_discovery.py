"""One discovery (issue 23 item 4): which lists form a machine is decided in one place for the command line,
the API and the language server, so both see the same machine and report the same machine-level findings."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from achslint.linting.config import forget_cached
from achslint.linting.discovery import Finder
from achslint.lsp.documents import Document
from achslint.lsp.session import Session

from .conftest import FIXTURES, run_cli

MACHINES = FIXTURES / "machines"


def machine_findings_cli(folder: Path) -> set[tuple[str, int, str]]:
    """(file name, line, code) of every machine-level finding of `achslint lint FOLDER`."""
    result = run_cli("lint", str(folder), "--select", "LIS5", "--format", "json", "--exit-zero")
    assert result.returncode == 0, result.stderr
    return {(Path(d["path"]).name, d["line"], d["code"]) for d in json.loads(result.stdout)["diagnostics"]}


def machine_findings_editor(folder: Path) -> set[tuple[str, int, str]]:
    """The same, as the language server reports them with every list of the folder open in the editor."""
    session = Session(folder)
    session.settings.select = ["LIS5"]
    files = sorted(p for p in folder.rglob("*") if p.suffix.lower() in (".lis", ".xti", ".xml"))
    documents = []
    for path in files:
        document = Document(path.as_uri(), path, path.read_bytes().decode("latin-1"), 1)
        session.open(document)
        documents.append((path, document))
    found = set()
    for path, document in documents:
        _, diagnostics, _ = session.diagnostics(document.uri)
        found |= {(path.name, d.line, d.code) for d in diagnostics if d.code.startswith("LIS5")}
    return found


@pytest.mark.parametrize(
    "machine", sorted(p.name for p in MACHINES.iterdir() if p.is_dir()), ids=lambda name: name
)
def test_the_editor_and_the_command_line_report_the_same_machine_findings(machine: str) -> None:
    folder = MACHINES / machine
    assert machine_findings_editor(folder) == machine_findings_cli(folder)


def test_two_start_up_lists_side_by_side_are_two_machines(tmp_path: Path) -> None:
    variants = MACHINES / "variants" / "listen"
    # Both variants use logical axes 1 and 2 named X and Y: neither LIS501 nor LIS502 between them.
    assert machine_findings_cli(variants) == set()
    # Within one variant a repeated number is still found.
    copy = tmp_path / "listen"
    shutil.copytree(variants, copy)
    second = copy / "achsmds2_soe.lis"
    second.write_text(
        second.read_text().replace("kopf.achs_nr                                    2", "kopf.achs_nr 1")
    )
    assert machine_findings_cli(copy) == {("achsmds2_soe.lis", 2, "LIS501")}
    assert machine_findings_editor(copy) == {("achsmds2_soe.lis", 2, "LIS501")}


def test_a_list_named_alone_is_compared_with_its_start_up_list_s_axes_only(tmp_path: Path) -> None:
    copy = tmp_path / "listen"
    shutil.copytree(MACHINES / "variants" / "listen", copy)
    (copy / "achsmds2_coe.lis").write_text("kopf.achs_nr  1\nkopf.log_achs_name  Y\nEnde\n")
    # pre-commit passes the changed list alone: its neighbour of the same variant counts, the other
    # variant's axis 1 does not.
    result = run_cli("lint", str(copy / "achsmds2_coe.lis"), "--select", "LIS501", "--format", "json")
    found = json.loads(result.stdout)["diagnostics"]
    assert [(Path(d["path"]).name, d["code"]) for d in found] == [("achsmds2_coe.lis", "LIS501")]
    assert "achsmds1_coe.lis" in found[0]["message"] and "_soe" not in found[0]["message"]


def test_a_start_up_list_found_in_a_folder_is_a_machine_of_its_own(tmp_path: Path) -> None:
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr  1\nEnde\n")
    (tmp_path / "hochlauf.lis").write_text("achs_mds[0]  ./achsmds1.lis\nachs_mds[1]  ./achsmds9.lis\nEnde\n")
    # The missing entry is reported on the start-up list the folder holds (before, only when it was named).
    assert machine_findings_cli(tmp_path) == {("hochlauf.lis", 2, "LIS504")}


def test_a_list_two_start_up_lists_name_belongs_to_both_machines(tmp_path: Path) -> None:
    (tmp_path / "shared.lis").write_text("kopf.achs_nr  1\nkopf.log_achs_name  X\nEnde\n")
    (tmp_path / "achsmds_a.lis").write_text("kopf.achs_nr  2\nkopf.log_achs_name  Y\nEnde\n")
    (tmp_path / "achsmds_b.lis").write_text("kopf.achs_nr  1\nkopf.log_achs_name  Z\nEnde\n")
    (tmp_path / "hochlauf_a.lis").write_text(
        "achs_mds[0]  ./shared.lis\nachs_mds[1]  ./achsmds_a.lis\nEnde\n"
    )
    (tmp_path / "hochlauf_b.lis").write_text(
        "achs_mds[0]  ./shared.lis\nachs_mds[1]  ./achsmds_b.lis\nEnde\n"
    )
    machines = Finder().machines_of(tmp_path / "shared.lis")
    assert sorted(Path(m.key).name for m in machines) == ["hochlauf_a.lis", "hochlauf_b.lis"]
    found = Finder().find([str(tmp_path)])
    shared = next(t for t in found.targets if t.path == tmp_path / "shared.lis")
    assert sorted(Path(key).name for key in shared.machines) == ["hochlauf_a.lis", "hochlauf_b.lis"]
    # Only machine b repeats number 1; the shared list is found once, by the list that repeats it.
    assert machine_findings_cli(tmp_path) == {("achsmds_b.lis", 1, "LIS501")}


def test_lists_no_start_up_list_names_are_compared_only_when_a_machine_is_declared(tmp_path: Path) -> None:
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr  1\nkopf.log_achs_name  X\nEnde\n")
    (tmp_path / "achsmds2.lis").write_text("kopf.achs_nr  1\nkopf.log_achs_name  Y\nEnde\n")
    (tmp_path / "achsmds1_old.lis").write_text("kopf.achs_nr  1\nEnde\n")  # a backup beside the lists
    (tmp_path / "hochlauf.lis").write_text("achs_mds[0]  ./achsmds1.lis\nEnde\n")
    # achsmds2 and the backup are named by no start-up list and no [[machine]] table: compared with nothing
    assert machine_findings_cli(tmp_path) == set()
    assert Finder().machines_of(tmp_path / "achsmds2.lis") == []
    # A [[machine]] table makes the lists it names one machine (not the backup); achsmds1 belongs to it and
    # to the start-up list's machine, so the repeated number is found in the table's machine.
    (tmp_path / ".achslint.toml").write_text('[[machine]]\nname = "mill"\nlists = ["achsmds[0-9].lis"]\n')
    forget_cached()
    [machine] = Finder().machines_of(tmp_path / "achsmds2.lis")
    assert machine.key.endswith(".achslint.toml#mill") and machine.startup is None
    assert [f.name for f in machine.files] == ["achsmds1.lis", "achsmds2.lis"]
    assert len(Finder().machines_of(tmp_path / "achsmds1.lis")) == 2
    assert machine_findings_cli(tmp_path) == {("achsmds2.lis", 1, "LIS501")}
    assert machine_findings_editor(tmp_path) == {("achsmds2.lis", 1, "LIS501")}


def test_a_machine_table_with_an_unknown_key_is_one_configuration_error(tmp_path: Path) -> None:
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr  1\nEnde\n")
    (tmp_path / ".achslint.toml").write_text('[[machine]]\nlist = ["*.lis"]\n')
    result = run_cli("lint", str(tmp_path))
    assert result.returncode == 2
    assert "unknown key `machine.0.list` (known keys: lists, name)" in result.stderr.decode()


def machine_in_two_folders(root: Path) -> tuple[Path, Path]:
    """The external-scheduling layout: `listen/ExtSchedule/hochlauf.lis` naming `./listen/achsmds1.lis`, an axis
    list in the folder above the start-up list's (the CNC root is the folder above `listen/`)."""
    (root / "listen" / "ExtSchedule").mkdir(parents=True)
    axis = root / "listen" / "achsmds1.lis"
    axis.write_bytes(b"kopf.achs_nr   1\nkopf.log_achs_name X\nEnd\n")  # misspelt end marker, odd spacing
    startup = root / "listen" / "ExtSchedule" / "hochlauf.lis"
    startup.write_text("achs_mds[0]  ./listen/achsmds1.lis\nEnde\n")
    return startup, axis


@pytest.mark.parametrize("command", [("lint", "--fix"), ("fmt",)], ids=["lint --fix", "fmt"])
def test_lists_reached_through_a_start_up_list_elsewhere_are_not_rewritten(
    tmp_path: Path, command: tuple[str, ...]
) -> None:
    startup, axis = machine_in_two_folders(tmp_path)
    before = axis.read_bytes()
    result = run_cli(*command, str(startup))
    assert axis.read_bytes() == before
    said = result.stderr.decode()
    assert "checked but not rewritten" in said and "--follow-startup" in said
    if command[0] == "lint":
        assert b"LIS004" in result.stdout  # still checked
    followed = run_cli(*command, str(startup), "--follow-startup")
    assert axis.read_bytes() != before, followed.stderr
    # Named (or its folder named), the list is rewritten as always.
    axis.write_bytes(before)
    run_cli(*command, str(axis.parent))
    assert axis.read_bytes() != before


def test_lists_in_the_start_up_list_s_own_folder_count_as_named(tmp_path: Path) -> None:
    (tmp_path / "achsmds1.lis").write_bytes(b"kopf.achs_nr 1\nEnd\n")
    (tmp_path / "hochlauf.lis").write_text("achs_mds[0]  ./achsmds1.lis\nEnde\n")
    result = run_cli("lint", "--fix", str(tmp_path / "hochlauf.lis"))
    assert (tmp_path / "achsmds1.lis").read_bytes() == b"kopf.achs_nr 1\nEnde\n", result.stderr


def test_a_list_update_is_no_axis_and_is_checked_over_the_list_it_changes(tmp_path: Path) -> None:
    machine = MACHINES / "update"
    result = run_cli("lint", str(machine), "--format", "json", "--exit-zero")
    found = {(Path(d["path"]).name, d["code"]) for d in json.loads(result.stdout)["diagnostics"]}
    # Its repeated axis number 1 is the CNC's cross-check, not a second axis 1.
    assert not {code for _, code in found} & {"LIS501", "LIS502"}
    # vb_reflow 30000 is judged against the vb_refmax 20000 of achsmds1.lis, the list it changes.
    assert found == {("achsmds1-Update.xml", "LIS302")}
    # Without the list it changes, the update is checked alone (vb_refmax keeps its default) and says so.
    alone = tmp_path / "achsmds1-Update.xml"
    alone.write_bytes((machine / "listen" / "Update" / "achsmds1-Update.xml").read_bytes())
    result = run_cli("lint", str(alone), "--format", "json")
    assert json.loads(result.stdout)["diagnostics"] == []
    assert "a list update; the list it changes was not found" in result.stderr.decode()


def test_axis_lists_beyond_zahl_mds_are_not_members_of_the_machine(tmp_path: Path) -> None:
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr  1\nkopf.log_achs_name  X\nEnde\n")
    (tmp_path / "achsmds2.lis").write_text("kopf.achs_nr  1\nkopf.log_achs_name  X\nEnde\n")
    (tmp_path / "hochlauf.lis").write_text(
        "zahl_mds  1\nachs_mds[0]  ./achsmds1.lis\nachs_mds[1]  ./achsmds2.lis\nEnde\n"
    )
    # the CNC reads one axis list: the second is never loaded (LIS516 says so), so it repeats no number
    [machine] = Finder().machines_of(tmp_path / "achsmds1.lis")
    assert [f.name for f in machine.files] == ["achsmds1.lis"]
    assert machine_findings_cli(tmp_path) == {("hochlauf.lis", 3, "LIS516")}


def test_an_unreadable_default_list_is_named_in_the_error(tmp_path: Path) -> None:
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr  1\nEnde\n")
    (tmp_path / "default_mds.lis").write_bytes("getriebe[0].a_ref 5\nEnde\n".encode("utf-16"))
    (tmp_path / "hochlauf.lis").write_text(
        "default_achs_mds  ./default_mds.lis\nachs_mds[0]  ./achsmds1.lis\nEnde\n"
    )
    result = run_cli("lint", str(tmp_path / "hochlauf.lis"))
    assert result.returncode == 2
    said = result.stderr.decode()
    assert "achsmds1.lis: the list loaded under it," in said and "default_mds.lis, cannot be read" in said
    assert "UTF-16" in said
