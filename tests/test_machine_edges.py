"""Edge cases of machines and list kinds that a review of issue 24's work found (each failed before its fix)."""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

from achslint.lsp.documents import Document
from achslint.lsp.session import Session

from .conftest import FIXTURES, run_cli

SDK = FIXTURES / "machines" / "sdk" / "listen"


def machine_copy(tmp_path: Path) -> Path:
    listen = tmp_path / "listen"
    shutil.copytree(SDK, listen)
    return listen


def found(result) -> list[tuple[str, str, str]]:
    return [(Path(d["path"]).name, d["code"], d["message"]) for d in json.loads(result.stdout)["diagnostics"]]


def test_a_huge_zahl_mds_is_judged_without_looping_over_it(tmp_path: Path) -> None:
    listen = machine_copy(tmp_path)
    startup = listen / "hochlauf.lis"
    startup.write_text(
        startup.read_text().replace(
            "zahl_mds                                              3", "zahl_mds 999999999999"
        )
    )
    result = run_cli("lint", str(listen / "achsmds1.lis"), "--format", "json", "--select", "LIS517")
    assert result.returncode == 0  # the start-up list is context here: its own findings are not reported
    named = run_cli("lint", str(startup), "--format", "json", "--select", "LIS202,LIS517")
    # out of range (P-STUP-00014: 1 ... 32): LIS202's finding alone, no missing entry counted up to it
    [(_, code, message)] = found(named)
    assert code == "LIS202" and "999999999999" in message and "at most 32" in message


def test_an_axis_entry_wins_over_another_start_up_list_naming_the_file_as_a_channel_list(
    tmp_path: Path,
) -> None:
    listen = machine_copy(tmp_path)
    axis = listen / "achsmds1.lis"
    text = axis.read_text(encoding="latin-1")
    axis.write_text(text.replace("kopf.achs_nr ", "kopf.achs_nr -5 ( was ", 1), encoding="latin-1")
    (listen / "hochlauf-alt.lis").write_text("sda_mds[0]  ./listen/achsmds1.lis\nEnde\n")
    result = run_cli("lint", str(axis), "--format", "json", "--select", "LIS202,LIS101")
    assert ("achsmds1.lis", "LIS202") in [(name, code) for name, code, _ in found(result)]


def test_comments_citing_start_up_ids_do_not_make_an_axis_list_a_start_up_list(tmp_path: Path) -> None:
    axis = tmp_path / "achsmds1.lis"
    axis.write_text(
        "# zahl_mds (P-STUP-00014), achs_mds (P-STUP-00015) and hand_mds (P-STUP-00013) name this list\n"
        "# see P-STUP-00014\n# see P-STUP-00015\n"
        "kopf.achs_nr 1\nkenngr.swe_negg 5\ngetriebe[0].dynamik.vb_max -7\nEnde\n"
    )
    result = run_cli("lint", str(axis), "--format", "json")
    codes = {code for _, code, _ in found(result)}
    assert "LIS202" in codes and result.returncode == 1


def test_a_machine_table_pattern_must_stay_inside_the_configuration_folder(tmp_path: Path) -> None:
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr 1\nEnde\n")
    for pattern, said in (
        ("/etc/*", "not a pattern relative"),
        ("", "not a pattern relative"),
        ("../*.lis", "`..`"),
    ):
        (tmp_path / ".achslint.toml").write_text(f'[[machine]]\nlists = ["{pattern}"]\n')
        result = run_cli("lint", str(tmp_path / "achsmds1.lis"))
        assert result.returncode == 2 and said in result.stderr.decode(), result.stderr
        assert b"internal error" not in result.stderr


def test_a_machine_table_never_takes_in_list_updates(tmp_path: Path) -> None:
    listen = tmp_path / "listen"
    shutil.copytree(FIXTURES / "machines" / "update" / "listen", listen)
    (listen / "hochlauf.lis").unlink()
    (tmp_path / ".achslint.toml").write_text('[[machine]]\nlists = ["listen/**/*"]\n')
    result = run_cli("lint", str(listen / "achsmds1.lis"), "--format", "json", "--select", "LIS501,LIS502")
    assert found(result) == []


def test_machine_diff_compares_the_axis_lists_the_cnc_loads(tmp_path: Path) -> None:
    first, second = tmp_path / "a", tmp_path / "b"
    shutil.copytree(SDK.parent, first)
    shutil.copytree(SDK.parent, second)
    startup = second / "listen" / "hochlauf.lis"
    startup.write_text(
        startup.read_text().replace("zahl_mds                                              3", "zahl_mds 2")
    )
    assert run_cli("diff", str(first), str(second)).returncode == 1  # b loads two axes, a three
    (second / "listen" / "achsmds3.lis").unlink()  # never loaded in b anyway
    result = run_cli("diff", str(first), str(second))
    assert result.returncode == 1 and b"internal error" not in result.stderr


def test_lis504_is_quiet_about_an_entry_the_cnc_never_reads(tmp_path: Path) -> None:
    listen = machine_copy(tmp_path)
    startup = listen / "hochlauf.lis"
    startup.write_text(
        startup.read_text().replace("zahl_mds                                              3", "zahl_mds 2")
    )
    (listen / "achsmds3.lis").unlink()
    result = run_cli("lint", str(startup), "--format", "json", "--select", "LIS504,LIS516")
    assert [code for _, code, _ in found(result)] == ["LIS516"]


def test_a_default_channel_list_named_like_its_entry_is_no_default_axis_list(tmp_path: Path) -> None:
    channel = tmp_path / "default_sda_mds.lis"
    shutil.copy(FIXTURES / "machines" / "sdk4" / "listen" / "sda_mds1.lis", channel)
    result = run_cli("lint", str(channel), "--format", "json")
    assert all(not (code == "LIS101" and "warning" in m) for _, code, m in found(result))
    assert [d["severity"] for d in json.loads(result.stdout)["diagnostics"] if d["code"] == "LIS101"] in (
        [],
        ["info"],
    )


def test_the_editor_judges_a_default_list_named_otherwise_as_a_default_list(tmp_path: Path) -> None:
    listen = machine_copy(tmp_path)
    (listen / "default_mds.lis").rename(listen / "basis.lis")
    startup = listen / "hochlauf.lis"
    startup.write_text(startup.read_text().replace("default_mds.lis", "basis.lis"))
    path = listen / "basis.lis"
    session = Session(tmp_path)
    document = Document(path.as_uri(), path, path.read_bytes().decode("latin-1"), 1)
    session.open(document)
    assert [d.code for d in session.diagnostics(document.uri)[1] if d.code.startswith("LIS50")] == []
    assert found(run_cli("lint", str(path), "--format", "json", "--select", "LIS50")) == []


def test_a_relative_cache_home_is_ignored(tmp_path: Path, monkeypatch) -> None:
    from achslint.core import codecache

    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("XDG_CACHE_HOME", "relcache")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    folder = codecache.private_folder()
    assert folder is not None and os.path.isabs(folder) and not (tmp_path / "relcache").exists()


def test_a_start_up_list_named_otherwise_makes_its_machine_in_a_folder_lint(tmp_path: Path) -> None:
    listen = machine_copy(tmp_path)
    (listen / "hochlauf.lis").rename(listen / "machine.lis")
    axis = listen / "achsmds1.lis"
    text = axis.read_text(encoding="latin-1")
    axis.write_text(text.replace("kopf.achs_nr ", "kopf.achs_nr 2 ( was ", 1), encoding="latin-1")
    for target in (listen, axis):  # the folder, and the list alone (pre-commit)
        result = run_cli("lint", str(target), "--format", "json", "--select", "LIS501")
        assert [code for _, code, _ in found(result)] == ["LIS501"], target


def test_one_file_named_twice_through_a_hard_link_is_lis518(tmp_path: Path) -> None:
    listen = machine_copy(tmp_path)
    os.link(listen / "achsmds1.lis", listen / "achsmds1_copy.lis")
    startup = listen / "hochlauf.lis"
    text = startup.read_text(encoding="latin-1").replace(
        "zahl_mds                                              3", "zahl_mds 4"
    )
    startup.write_text(
        text.replace("Ende", "achs_mds[3] ./listen/achsmds1_copy.lis\nEnde"), encoding="latin-1"
    )
    result = run_cli("lint", str(startup), "--format", "json", "--select", "LIS518")
    assert [code for _, code, _ in found(result)] == ["LIS518"]


def test_the_machine_dry_run_names_a_gantry_slave_it_cannot_couple(tmp_path: Path) -> None:
    portal = tmp_path / "portal"
    shutil.copytree(FIXTURES / "machines" / "portal", portal)
    run = run_cli("dry-run", str(portal / "listen" / "hochlauf.lis"), "--program", str(portal / "rfp.nc"))
    assert b"cannot couple" not in run.stdout  # Y2 follows Y
    slave = portal / "listen" / "achsmds7.lis"
    lines = slave.read_text(encoding="latin-1").splitlines()
    lines = ["kenngr.gantry_ax_nr 99" if line.startswith("kenngr.gantry_ax_nr") else line for line in lines]
    slave.write_text("\n".join(lines) + "\n", encoding="latin-1")
    run = run_cli("dry-run", str(portal / "listen" / "hochlauf.lis"), "--program", str(portal / "rfp.nc"))
    said = run.stdout.decode()
    assert "LIS503: Y2" in said and "gantry slave of logical axis 99" in said and "does not move it" in said


def test_a_start_up_list_named_otherwise_shows_its_machine_findings_in_the_editor(tmp_path: Path) -> None:
    listen = machine_copy(tmp_path)
    startup = listen / "machine.lis"
    (listen / "hochlauf.lis").rename(startup)
    startup.write_text(
        startup.read_text(encoding="latin-1").replace("achsmds3.lis", "nowhere.lis"), encoding="latin-1"
    )
    session = Session(tmp_path)
    document = Document(startup.as_uri(), startup, startup.read_bytes().decode("latin-1"), 1)
    session.open(document)
    editor = [d.code for d in session.diagnostics(document.uri)[1] if d.code.startswith("LIS5")]
    cli = [
        code for _, code, _ in found(run_cli("lint", str(startup), "--format", "json", "--select", "LIS5"))
    ]
    assert editor == cli == ["LIS504"]


def test_a_gantry_circle_is_lis507_alone_not_also_lis514(tmp_path: Path) -> None:
    portal = tmp_path / "portal"
    shutil.copytree(FIXTURES / "machines" / "portal", portal)
    master = portal / "listen" / "achsmds2.lis"  # Y, whose slave Y2 (logical 7) names it as master
    master.write_text(
        master.read_text(encoding="latin-1").replace("Ende", "kenngr.gantry_ax_nr 7\nEnde"),
        encoding="latin-1",
    )
    result = run_cli(
        "lint", str(portal / "listen" / "hochlauf.lis"), "--format", "json", "--select", "LIS507,LIS514"
    )
    codes = {code for _, code, _ in found(result)}
    assert codes == {"LIS507"}


def test_the_editor_judges_a_channel_list_as_its_buffer_has_it(tmp_path: Path) -> None:
    portal = tmp_path / "portal"
    shutil.copytree(FIXTURES / "machines" / "portal", portal)
    channel = portal / "listen" / "sda_mds1.lis"
    clean = channel.read_bytes().decode("latin-1")
    slot = "gruppe[0].achse[5].log_achs_nr"
    assert slot in clean
    lines = clean.splitlines()
    # the buffer puts the gantry slave Y2 (logical 7) into the channel, the file on disk does not
    edited = "\n".join(
        line.replace(line.split()[-1], "7") if line.startswith(slot) else line for line in lines
    )
    session = Session(tmp_path)
    document = Document(channel.as_uri(), channel, edited + "\n", 2)
    session.open(document)
    assert "LIS514" in [d.code for d in session.diagnostics(document.uri)[1]]
    # and the other way round: the file has it, the buffer does not
    channel.write_text(edited + "\n", encoding="latin-1")
    session = Session(tmp_path)
    document = Document(channel.as_uri(), channel, clean, 1)
    session.open(document)
    assert "LIS514" not in [d.code for d in session.diagnostics(document.uri)[1]]
