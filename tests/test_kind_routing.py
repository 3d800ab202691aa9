"""Every list by its kind (issue 24 item 2): a list is checked as an axis list only when it is one; lists of
other kinds against their own catalogue (issue 25), start-up lists are known by content, default lists by
their entry."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from .conftest import FIXTURES, run_cli

SDK4 = FIXTURES / "machines" / "sdk4" / "listen"


def diagnostics(result) -> list[tuple[str, str]]:
    return [(Path(d["path"]).name, d["code"]) for d in json.loads(result.stdout)["diagnostics"]]


def test_a_channel_list_passed_alone_is_checked_as_a_channel_list(tmp_path: Path) -> None:
    # what pre-commit passes when only the default channel list changed: checked against the channel
    # catalogue (issue 25), so no LIS101 for its parameters; the start-up list beside it names it
    # `default_sda_mds`
    result = run_cli("lint", str(SDK4 / "default_sda.lis"), "--format", "json")
    assert result.returncode == 0
    assert diagnostics(result) == []
    assert "skipped" not in result.stderr.decode()
    # without a start-up list, its content tells (eleven channel parameters)
    alone = tmp_path / "kanal.lis"
    shutil.copy(SDK4 / "sda_mds1.lis", alone)
    result = run_cli("lint", str(alone), "--format", "json")
    assert result.returncode == 0 and diagnostics(result) == []
    assert json.loads(result.stdout)["summary"]["files"] == 1 and "skipped" not in result.stderr.decode()


def test_a_start_up_list_named_otherwise_is_a_start_up_list(tmp_path: Path) -> None:
    folder = tmp_path / "listen"
    shutil.copytree(FIXTURES / "machines" / "sdk" / "listen", folder)
    (folder / "hochlauf.lis").rename(folder / "basis.lis")
    result = run_cli("lint", str(folder / "basis.lis"), "--format", "json", "--select", "LIS101,LIS5")
    assert result.returncode == 0, result.stderr
    # its entries were followed (the axis lists were linted), its own lines were read as start-up parameters
    # (no LIS101), not as axis parameters
    assert json.loads(result.stdout)["summary"]["files"] == 5  # itself, three axis lists and the default list
    assert diagnostics(result) == []


def test_an_axis_list_full_of_typos_is_still_an_axis_list(tmp_path: Path) -> None:
    axis = tmp_path / "achsmds1.lis"
    axis.write_text(
        "kopf.achs_nr 1\nkenngr.antr_typp 1\ngetriebe[0].vb_reflw 100\nkenngr.ref_richtng 1\nEnde\n"
    )
    result = run_cli("lint", str(axis), "--format", "json", "--select", "LIS101")
    assert diagnostics(result) == [("achsmds1.lis", "LIS101")] * 3


def test_a_few_names_of_another_catalogue_do_not_make_another_kind(tmp_path: Path) -> None:
    # `a` and `b` happen to be parameter names of another list kind: two names are no evidence
    tiny = tmp_path / "x.lis"
    tiny.write_text("a 1\nb 2\nEnde\n")
    result = run_cli("lint", str(tiny), "--format", "json", "--select", "LIS101")
    assert [code for _, code in diagnostics(result)] == ["LIS101", "LIS101"]


def test_a_default_list_named_otherwise_is_judged_as_a_default_list(tmp_path: Path) -> None:
    # P-AXIS-00016 must be 0 in a default list (LIS506); the start-up entry, not the file name, says it is one
    (tmp_path / "basis.lis").write_text("kopf.achs_nr 3\nEnde\n")
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr 1\nEnde\n")
    (tmp_path / "hochlauf.lis").write_text("default_achs_mds ./basis.lis\nachs_mds[0] ./achsmds1.lis\nEnde\n")
    (tmp_path / ".achslint.toml").write_text('include = ["*.lis"]\n')
    result = run_cli("lint", str(tmp_path), "--format", "json", "--select", "LIS506")
    assert ("basis.lis", "LIS506") in diagnostics(result)


def test_a_channel_list_passed_alone_gets_its_machine_s_findings() -> None:
    # pre-commit passes the changed channel list alone: the start-up list beside it makes it part of a
    # machine, so a channel axis no axis list backs (LIS512) is reported on it, not "All checks passed!"
    bad = FIXTURES / "rules" / "LIS512" / "bad"
    result = run_cli("lint", str(bad / "sda_mds1.lis"), "--format", "json", "--select", "LIS5")
    assert [code for name, code in diagnostics(result) if name == "sda_mds1.lis"] == ["LIS512", "LIS512"]
    assert {name for name, _ in diagnostics(result)} == {"sda_mds1.lis"}  # only the file passed


def test_the_real_time_list_is_told_by_its_start_up_entry() -> None:
    # rtconf.lis holds one line (`cycle_time`): too little for its content to tell, so the start-up list's
    # `rtconf_lis` entry says what it is, and it is checked against the real-time catalogue (no LIS101)
    rtconf = FIXTURES / "machines" / "extschedule" / "listen" / "rtconf.lis"
    result = run_cli("lint", str(rtconf), "--format", "json")
    assert result.returncode == 0 and diagnostics(result) == []
    copy_alone = run_cli(
        "lint", "-", "--stdin-filename", "rtconf.lis", "--format", "json", stdin=rtconf.read_bytes()
    )
    assert ("rtconf.lis", "LIS101") in diagnostics(copy_alone)  # without its start-up list: an axis list


def test_telling_a_start_up_list_by_content_does_not_parse_an_axis_list(monkeypatch, tmp_path: Path) -> None:
    # every named list is asked whether it is a start-up list; an axis list must not be parsed for that
    from achslint.linting import discovery

    parsed: list[str] = []
    real = discovery.parse_bytes
    monkeypatch.setattr(discovery, "parse_bytes", lambda data, name: parsed.append(name) or real(data, name))
    axis = tmp_path / "achsmds1.lis"
    axis.write_text("kopf.achs_nr 1\nkenngr.antr_typ 1\nEnde\n")
    startup = tmp_path / "basis.lis"
    startup.write_text("zahl_mds 1\nachs_mds[0] ./achsmds1.lis\nEnde\n")
    assert not discovery.is_startup(axis) and parsed == []
    assert discovery.is_startup(startup) and parsed == [str(startup)]


def test_linting_a_start_up_list_checks_every_list_it_names_against_its_own_catalogue(tmp_path: Path) -> None:
    listen = tmp_path / "listen"
    shutil.copytree(SDK4, listen)
    channel = listen / "sda_mds1.lis"
    channel.write_text(
        channel.read_text(encoding="latin-1").replace("Ende", "gruppe[0].bezeichnug x\nEnd"),
        encoding="latin-1",
    )
    result = run_cli("lint", str(listen / "hochlauf.lis"), "--format", "json")
    by_file = {(name, code) for name, code in diagnostics(result)}
    assert ("sda_mds1.lis", "LIS004") in by_file  # the channel list's misspelt end marker
    assert ("sda_mds1.lis", "LIS101") in by_file  # its unknown parameter, judged in the channel catalogue
    names = {Path(d["path"]).name for d in json.loads(result.stdout)["diagnostics"]}
    assert "default_sda.lis" not in names  # the default channel list is checked and clean
    fixed = run_cli("lint", "--fix", str(listen / "hochlauf.lis"))
    assert channel.read_text(encoding="latin-1").endswith("Ende\n"), fixed.stderr
