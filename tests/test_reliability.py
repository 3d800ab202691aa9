"""Never lose, never leak, never crash (issue 14): one regression test per finding of the adversarial pass.

The numbers in the test names are the items of the issue's "Why". The command line is run in-process
through `achslint.cli.main`; files are made in `tmp_path`. Permission tests that cannot apply when run as
root say so and skip; ownership is tested for real as root (with `os.chown`).
"""

from __future__ import annotations

import io
import json
import os
import signal
import socket
import stat
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path
from subprocess import CompletedProcess

import pytest

from achslint.catalogue import catalogue
from achslint.cli import main
from achslint.core import files
from achslint.core.files import ChangedOnDisk, Refused, not_a_list_file, write_atomically
from achslint.core.signals import Stopped, stopping_on_signals
from achslint.linting.linter import lint_file

from .conftest import jenkins_junit_errors

ROOT = hasattr(os, "geteuid") and os.geteuid() == 0
NOT_ROOT_ONLY = pytest.mark.skipif(ROOT, reason="root may read and write regardless of permissions")
MESSY = b"kopf.achs_nr 1\nkenngr.achs_typ     1\nEnde\n"
TIDY = b"kopf.achs_nr     1\nkenngr.achs_typ  1\nEnde\n"
SECRET = "TOP-SECRET-4711"
Cli = Callable[..., CompletedProcess]


@pytest.fixture
def run(capsys, monkeypatch):
    """The command line in this process: (exit code, stdout, stderr)."""

    def invoke(*args: str, stdin: bytes = b""):
        monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(stdin)))
        code = main([str(a) for a in args])
        out, err = capsys.readouterr()
        return code, out, err

    return invoke


def one_line(err: str) -> str:
    """The one message line of a failed command (--fix adds its count of fixes after it)."""
    lines = [line for line in err.splitlines() if not line.startswith("fixed ")]
    assert len(lines) == 1, lines
    assert "Traceback" not in err and "internal error" not in err
    return lines[0]


# -- 1. writes: links, owner, mode, hard links, read-only files ---------------------------------------


def test_1_fmt_writes_the_target_of_a_symlink_and_keeps_the_link(run, tmp_path):
    target = tmp_path / "real" / "achsmds1.lis"
    target.parent.mkdir()
    target.write_bytes(MESSY)
    link = tmp_path / "achsmds1.lis"
    link.symlink_to(target)
    code, _, err = run("fmt", link)
    assert code == 0, err
    assert link.is_symlink() and target.read_bytes() == TIDY


def test_1_a_link_in_a_folder_leading_outside_is_neither_read_nor_written(run, tmp_path):
    outside = tmp_path / "outside.lis"
    outside.write_bytes(MESSY)
    folder = tmp_path / "machine"
    folder.mkdir()
    (folder / "achsmds1.lis").symlink_to(outside)
    code, _, err = run("fmt", folder)
    assert (
        code == 2 and "outside the paths given" in err and "no axis list found" in err
    )  # nothing was checked
    code, _, err = run("fmt", folder, "--allow-empty")
    assert code == 0 and "outside the paths given" in err
    assert outside.read_bytes() == MESSY


def test_1_fmt_keeps_mode_and_hard_links(run, tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(MESSY)
    os.chmod(path, 0o640)
    twin = tmp_path / "copy.lis"
    os.link(path, twin)
    inode = path.stat().st_ino
    assert run("fmt", path)[0] == 0
    assert twin.read_bytes() == TIDY and path.stat().st_ino == inode  # rewritten in place
    assert stat.S_IMODE(path.stat().st_mode) == 0o640


def test_1_fmt_keeps_mode_when_it_renames(run, tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(MESSY)
    os.chmod(path, 0o600)
    assert run("fmt", path)[0] == 0
    assert path.read_bytes() == TIDY and stat.S_IMODE(path.stat().st_mode) == 0o600


@pytest.mark.skipif(not ROOT, reason="only root can give a file to another owner")
def test_1_fmt_keeps_owner_and_group(run, tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(MESSY)
    os.chown(path, 4711, 4712)
    assert run("fmt", path)[0] == 0
    info = path.stat()
    assert (info.st_uid, info.st_gid) == (4711, 4712) and path.read_bytes() == TIDY


def test_1_a_read_only_list_is_refused_not_replaced(run, tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(MESSY)
    os.chmod(path, 0o444)
    code, _, err = run("fmt", path)
    assert code == 2 and "read-only" in err and "0 files reformatted" in err
    assert path.read_bytes() == MESSY
    fixable = tmp_path / "achsmds2.lis"
    fixable.write_bytes(b"kopf.achs_nr 1\nEnd\n")
    os.chmod(fixable, 0o444)
    code, _, err = run("lint", "--fix", fixable)
    assert code == 2 and "fixed 0 diagnostics" in err and "read-only" in err
    assert fixable.read_bytes() == b"kopf.achs_nr 1\nEnd\n"


def test_1_fix_writes_and_counts(run, tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(b"kenngr.homing_type CNC_CONTROLLED\nEnd\n")
    _code, _, err = run("lint", "--fix", path)
    assert "fixed 2 diagnostics" in err
    assert path.read_bytes() == b"kenngr.homing.homing_type CNC_CONTROLLED\nEnde\n"


@NOT_ROOT_ONLY
def test_1_a_list_the_user_may_not_write_is_refused(run, tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(MESSY)
    os.chmod(tmp_path, 0o555)  # not even a temporary file next to it
    os.chmod(path, 0o644)
    try:
        code, _, _err = run("fmt", path)
    finally:
        os.chmod(tmp_path, 0o755)
    assert code == 0 and path.read_bytes() == TIDY  # the file itself may be written: in place


def test_1_the_writer_refuses_what_is_not_a_regular_file(tmp_path):
    with pytest.raises(Refused):
        write_atomically(tmp_path, b"x")


# The usual rewrite (a temporary file renamed over the list) not allowed: simulated, so it also runs as root.


def test_fmt_rewrites_in_place_when_the_folder_may_not_be_written(
    cli: Cli, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(MESSY)
    inode = path.stat().st_ino

    def no_new_files(*args: object, **kwargs: object) -> tuple[int, str]:
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(tempfile, "mkstemp", no_new_files)
    result = cli("fmt", str(path))
    assert result.returncode == 0, result.stderr
    assert path.read_bytes() == TIDY and path.stat().st_ino == inode


def test_fmt_rewrites_in_place_when_the_owner_cannot_be_kept(
    cli: Cli, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(MESSY)
    inode = path.stat().st_ino
    real_stat = os.stat

    def another_owner(target: object, *args: object, **kwargs: object) -> os.stat_result:
        """The list belongs to someone else (uid 4711); the temporary file would be ours."""
        info = real_stat(target, *args, **kwargs)  # type: ignore[arg-type]
        if Path(str(target)) != path:
            return info
        fields = list(info)
        fields[4] = 4711
        return os.stat_result(fields)

    def not_allowed(*args: object) -> None:
        raise PermissionError(1, "Operation not permitted")

    monkeypatch.setattr(files.os, "stat", another_owner)
    monkeypatch.setattr(files.os, "chown", not_allowed)
    result = cli("fmt", str(path))
    assert result.returncode == 0, result.stderr
    assert path.read_bytes() == TIDY and path.stat().st_ino == inode
    assert [p.name for p in tmp_path.iterdir()] == ["achsmds1.lis"]  # no temporary file left


def test_a_list_removed_while_it_is_written_is_not_written(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(MESSY)

    def removed_meanwhile(temporary: str, info: os.stat_result) -> bool:
        path.unlink()
        return True

    monkeypatch.setattr(files, "_keep_owner", removed_meanwhile)
    with pytest.raises(ChangedOnDisk, match="was removed while achslint was working on it; nothing written"):
        write_atomically(path, TIDY, expected=MESSY)
    assert list(tmp_path.iterdir()) == []  # neither the list nor a temporary file


def test_without_an_expected_content_the_list_is_simply_replaced(tmp_path: Path) -> None:
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(b"anything\n")
    write_atomically(path, TIDY)
    assert path.read_bytes() == TIDY


# -- 2. start-up lists stay inside the project; non-lists are never echoed ---------------------------


@pytest.fixture
def escape_attempts(tmp_path):
    """A machine whose start-up list names /proc/self/environ, an absolute path and a `..` escape."""
    outside = tmp_path / "outside"
    outside.mkdir()
    secret = outside / "secret.lis"
    secret.write_text(f"kopf.log_achs_name {SECRET}\nkenngr.homing_type TORQ\nEnd\n")
    passwd = outside / "passwd"
    passwd.write_text(f"root:x:0:0:{SECRET}:/root:/bin/bash\n")
    machine = tmp_path / "project" / "machine"
    machine.mkdir(parents=True)
    (machine / "achsmds1.lis").write_bytes(MESSY)
    startup = machine / "hochlauf.lis"
    startup.write_text(
        f"achs_mds[0] ./achsmds1.lis\nachs_mds[1] /proc/self/environ\nachs_mds[2] {passwd}\n"
        "achs_mds[3] ../../outside/secret.lis\nEnde\n"
    )
    return startup, [secret, passwd]


@pytest.mark.parametrize("fmt", ["full", "concise", "github", "json", "gitlab", "junit", "sarif"])
def test_2_nothing_outside_the_project_is_read_or_printed(run, escape_attempts, monkeypatch, fmt):
    startup, _outside = escape_attempts
    monkeypatch.setenv("ACHSLINT_TEST_SECRET", SECRET)
    _code, out, err = run("lint", startup, "--format", fmt)
    assert SECRET not in out + err
    assert out.count("LIS504") >= 3 or fmt in ("json", "gitlab", "junit", "sarif")
    assert "Traceback" not in err


def test_2_start_up_escapes_are_reported_and_nothing_outside_is_written(run, escape_attempts):
    startup, outside = escape_attempts
    before = [path.read_bytes() for path in outside]
    _code, out, _ = run("lint", startup, "--format", "json", "--select", "LIS504")
    refused = [d for d in json.loads(out)["diagnostics"]]
    assert [d["line"] for d in refused] == [2, 3, 4]
    assert all("does not read" in d["message"] for d in refused)
    run("fmt", startup)
    run("lint", "--fix", startup)
    assert [path.read_bytes() for path in outside] == before
    assert (startup.parent / "achsmds1.lis").read_bytes() == TIDY  # the machine's own list was formatted


def test_2_a_path_the_user_gives_is_read_through_the_start_up_list(run, escape_attempts):
    startup, (secret, _) = escape_attempts
    _code, out, _ = run("lint", startup, secret.parent, "--format", "json", "--select", "LIS004")
    assert any(Path(d["path"]).resolve() == secret for d in json.loads(out)["diagnostics"])


def test_2_a_file_that_is_not_an_axis_list_is_reported_once_without_its_content(run, tmp_path):
    passwd = tmp_path / "passwd.lis"
    passwd.write_text(f"root:x:0:0:{SECRET}:/root:/bin/bash\ndaemon:x:1:1::/:/bin/false\n")
    for fmt in ("full", "github", "json"):
        code, out, err = run("lint", passwd, "--format", fmt)
        assert code == 2 and SECRET not in out + err
        assert "not an axis list" in one_line(err)


def test_2_a_list_with_content_is_still_linted_line_by_line():
    # Only a file without any assignment or `Ende` is "not an axis list".
    result = lint_file(b"%bad line\nkopf.achs_nr 1\n", "a.lis")
    assert result.error is None and {d.code for d in result.diagnostics} >= {"LIS001", "LIS002"}


def test_2_control_characters_in_messages_on_stderr_are_escaped(run, tmp_path):
    code, _, err = run("lint", tmp_path / "achsmds\x1b[2J.lis")
    assert code == 2 and "\x1b" not in err and "\\x1b[2J" in one_line(err)


# -- 5. signals ----------------------------------------------------------------------------------------


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGHUP, signal.SIGINT])
def test_5_a_signal_during_a_write_leaves_no_temporary_file(tmp_path, monkeypatch, signum):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(MESSY)

    def signalled(fd):
        os.kill(os.getpid(), signum)

    monkeypatch.setattr(files.os, "fsync", signalled)
    with stopping_on_signals(), pytest.raises(Stopped) as stopped:
        write_atomically(path, TIDY, expected=MESSY)
    assert stopped.value.exit_code == 128 + signum
    assert [p.name for p in tmp_path.iterdir()] == ["achsmds1.lis"] and path.read_bytes() == MESSY


@pytest.mark.parametrize(
    ("signum", "words"), [(signal.SIGINT, "interrupted"), (signal.SIGTERM, "terminated")]
)
def test_5_a_signal_ends_the_command_line_with_one_line(run, tmp_path, monkeypatch, signum, words):
    (tmp_path / "achsmds1.lis").write_bytes(MESSY)

    def stopped(*_args, **_kwargs):
        os.kill(os.getpid(), signum)

    monkeypatch.setattr("achslint.linting.run.LintRun.run", stopped)
    code, _, err = run("lint", tmp_path)
    assert code == 128 + signum and one_line(err) == f"achslint: {words}"


# -- 7. files that used to crash ------------------------------------------------------------------------


def test_7_a_symlink_loop_in_a_folder_is_one_line_and_exit_2(run, tmp_path):
    (tmp_path / "achsmds1.lis").symlink_to(tmp_path / "achsmds1.lis")
    for args in (("lint", tmp_path), ("fmt", tmp_path), ("lint", "--fix", tmp_path)):
        code, _, err = run(*args)
        assert code == 2 and "loop of symbolic links" in one_line(err), args
    code, out, err = run("config", "--show", tmp_path / "achsmds1.lis")
    assert code == 0 and "built-in defaults" in out


def test_7_names_too_long_for_the_file_system(run, tmp_path):
    long = tmp_path / ("x" * 300 + ".lis")
    code, _, err = run("lint", long)
    assert code == 2 and "too long" in one_line(err)
    code, _out, err = run(
        "lint", "-", "--stdin-filename", "y" * 300 + ".lis", stdin=b"kopf.achs_nr 1\nEnde\n"
    )
    assert code == 0, err
    code, _, err = run("explain", "z" * 300)
    assert code == 2 and "neither a file nor a known parameter" in one_line(err)


@NOT_ROOT_ONLY
def test_7_an_unreadable_folder_on_the_way_is_one_line(run, tmp_path):
    locked = tmp_path / "locked"
    (locked / "inner").mkdir(parents=True)
    (locked / "inner" / "achsmds1.lis").write_bytes(MESSY)
    os.chmod(locked, 0o000)
    try:
        code, _, err = run("lint", locked)
    finally:
        os.chmod(locked, 0o755)
    assert code == 2 and "permission denied" in one_line(err)


@pytest.mark.parametrize("tool", ["tool = 5", 'tool = "achslint"'])
def test_7_a_foreign_tool_key_in_a_parent_pyproject_is_not_ours(run, tmp_path, tool):
    (tmp_path / "pyproject.toml").write_text(tool + "\n")
    (tmp_path / "achsmds1.lis").write_bytes(TIDY)
    code, _, err = run("lint", tmp_path / "achsmds1.lis")
    assert code == 0 and err == ""


def test_7_a_non_table_achslint_key_is_a_configuration_error(run, tmp_path):
    (tmp_path / "pyproject.toml").write_text("[tool]\nachslint = 5\n")
    (tmp_path / "achsmds1.lis").write_bytes(TIDY)
    code, _, err = run("lint", tmp_path / "achsmds1.lis")
    assert code == 2 and "must be a table" in one_line(err)


def test_7_xml_with_an_unknown_encoding_is_one_line(run, tmp_path):
    path = tmp_path / "axis.xml"
    path.write_bytes(b'<?xml version="1.0" encoding="x-nonsense"?><AchsMds>Ende</AchsMds>')
    code, _, err = run("lint", path)
    assert code == 2 and "unknown encoding" in one_line(err)


def test_7_a_plot_into_a_missing_folder_is_one_line(run, tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(TIDY)
    code, _, err = run("dry-run", path, "--plot", tmp_path / "nowhere" / "x.png")
    assert code == 2 and "cannot write the plot" in one_line(err)


@pytest.mark.parametrize("fmt", ["full", "concise", "json", "sarif", "github", "gitlab", "junit"])
def test_7_a_file_name_that_is_not_utf8_works_in_every_format(run, tmp_path, fmt):
    name = os.fsdecode(os.fsencode(str(tmp_path)) + b"/achsmds\xff1.lis")
    Path(name).write_bytes(b"kenngr.ref_ricth 1\nEnde\n")
    code, out, err = run("lint", name, "--format", fmt)
    assert code in (0, 1), err
    out.encode("utf-8")  # nothing a strict UTF-8 stream refuses
    assert "achsmds\\xff1.lis" in out.replace("\\\\", "\\") or fmt == "sarif"  # sarif: a percent-encoded URI
    if fmt in ("json", "sarif", "gitlab"):
        json.loads(out)
    elif fmt == "junit":
        assert jenkins_junit_errors(out) == []


# -- 8. FIFOs and devices ----------------------------------------------------------------------------------


def test_8_a_fifo_in_a_folder_is_skipped_with_a_note(run, tmp_path):
    os.mkfifo(tmp_path / "achsmds2.lis")
    (tmp_path / "achsmds1.lis").write_bytes(TIDY)
    for command in ("lint", "fmt"):
        code, _, err = run(command, tmp_path)
        assert code == 0 and "achsmds2.lis: skipped, it is a FIFO" in err


def test_8_a_fifo_or_device_named_on_the_command_line_is_exit_2(run, tmp_path):
    fifo = tmp_path / "achsmds1.lis"
    os.mkfifo(fifo)
    for args in (("lint", fifo), ("fmt", fifo), ("explain", fifo), ("lint", "/dev/null")):
        code, _, err = run(*args)
        assert code == 2 and "not a regular file" in one_line(err), args


def test_8_reading_never_blocks_on_a_fifo_put_in_place_of_a_list(tmp_path):
    fifo = tmp_path / "achsmds1.lis"
    os.mkfifo(fifo)
    with pytest.raises(Refused, match="FIFO"):
        files.read_list(fifo)


def test_devices_sockets_and_impossible_names_are_not_lists(cli: Cli, tmp_path: Path) -> None:
    assert not_a_list_file(Path("/dev/null")) == "a device, not a regular file"
    assert not_a_list_file(tmp_path / "achs\x00mds.lis") == "a name the file system cannot hold"
    path = tmp_path / "achsmds1.lis"
    with socket.socket(socket.AF_UNIX) as server:
        server.bind(str(path))
        assert not_a_list_file(path) == "a socket, not a regular file"
        result = cli("lint", str(path))
    assert result.returncode == 2
    assert result.stderr.decode() == f"achslint: {path}: a socket, not a regular file\n"


# -- 9. folders that cannot be read; the same file twice --------------------------------------------------


def test_9_an_unreadable_subfolder_is_an_error_not_silence(run, tmp_path, monkeypatch):
    (tmp_path / "achsmds1.lis").write_bytes(TIDY)
    (tmp_path / "hidden").mkdir()
    real_scandir = os.scandir

    def scandir(path="."):  # (rmtree of the test's folder calls it with a file descriptor)
        if isinstance(path, (str, os.PathLike)) and Path(path).name == "hidden":
            raise PermissionError(13, "Permission denied", str(path))
        return real_scandir(path)

    monkeypatch.setattr(os, "scandir", scandir)
    code, _, err = run("lint", tmp_path)
    assert code == 2 and "cannot read folder" in one_line(err) and "permission denied" in err


@NOT_ROOT_ONLY
def test_9_an_unreadable_subfolder_for_real(run, tmp_path):
    (tmp_path / "achsmds1.lis").write_bytes(TIDY)
    hidden = tmp_path / "hidden"
    hidden.mkdir()
    os.chmod(hidden, 0o000)
    try:
        code, _, err = run("lint", tmp_path)
    finally:
        os.chmod(hidden, 0o755)
    assert code == 2 and "cannot read folder" in err


def test_9_the_same_file_given_twice_is_linted_once(run, tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(b"kopf.achs_nr 1\nkopf.log_achs_name X\nEnde\n")
    for args in ((path, path), (tmp_path, path), (path, tmp_path / "." / "achsmds1.lis")):
        _code, out, _err = run("lint", *args, "--format", "json")
        document = json.loads(out)
        assert document["summary"]["files"] == 1 and not document["diagnostics"], args


def test_9_fix_on_many_files_with_jobs_reports_no_spurious_change(run, tmp_path):
    for number in range(12):
        (tmp_path / f"achsmds{number}.lis").write_bytes(b"kenngr.homing_type CNC_CONTROLLED\nEnd\n")
    _code, _, err = run("lint", "--fix", "--jobs", "4", tmp_path, *sorted(tmp_path.iterdir()))
    assert "changed while" not in err and "fixed 24 diagnostics" in err


# -- 10. explain, dry-run and diff read XML through the one parser ----------------------------------------


BOMB = (
    b'<?xml version="1.0"?><!DOCTYPE x [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;">]>'
    b"<TreeItem><AchsMds>&b;</AchsMds></TreeItem>"
)
UPDATE = b"<TreeItem><IsgAxisDef><AchsMds><![CDATA[kopf.achs_nr 1\nkenngr.ref_richt 1\nEnde\n]]></AchsMds></IsgAxisDef></TreeItem>"


def test_10_explain_dry_run_and_diff_refuse_an_entity_bomb(run, tmp_path):
    bomb, update = tmp_path / "billion.xml", tmp_path / "update.xml"
    bomb.write_bytes(BOMB)
    update.write_bytes(UPDATE)
    for args in (("explain", bomb), ("dry-run", bomb), ("diff", update, bomb)):
        code, _out, err = run(*args)
        assert code == 2 and "refusing to read" in one_line(err), args


def test_10_diff_and_explain_read_the_list_inside_xml(run, tmp_path):
    update, plain = tmp_path / "update.xml", tmp_path / "achsmds1.lis"
    update.write_bytes(UPDATE)
    plain.write_bytes(b"kopf.achs_nr 1\nkenngr.ref_richt 0\nEnde\n")
    code, out, _ = run("diff", plain, update, "--format", "json")
    assert code == 1 and [row["parameter"] for row in json.loads(out)["differences"]] == ["kenngr.ref_richt"]
    assert run("explain", update, "--format", "json")[0] == 0


# -- 12. closest-name suggestions --------------------------------------------------------------------------


def test_12_the_closest_name_is_searched_once_per_distinct_name(monkeypatch):
    import achslint.catalogue as module

    calls = []
    real = module.scored_matches
    monkeypatch.setattr(module, "scored_matches", lambda *a, **k: calls.append(a[0]) or real(*a, **k))
    lint_file(b"kenngr.ref_ricth_zz 1\n" * 500 + b"kenngr.vb_reflow_zz 1\n" * 500 + b"Ende\n", "a.lis")
    assert sorted(calls) == ["kenngr.ref_ricth_zz", "kenngr.vb_reflow_zz"]
    catalogue()._suggestions.clear()


def test_12_a_name_too_long_for_any_match_skips_the_search_with_the_same_answer(monkeypatch):
    # Past 7/3 of the longest known name no candidate can reach difflib's 0.6 cutoff: the search is left
    # out, and the suggestions are what the full search gives (the same member in another group, or none).
    import achslint.catalogue as module

    cat = catalogue()
    longest = cat._longest
    names = [
        "kenngr." + "q" * (longest * 7 // 3 + 1),  # just too long: no fuzzy match, no member
        "x" * (longest * 3) + ".vb_reflow",  # too long, but a known member name
        "kenngr.vb_reflowx",  # ordinary: searched
    ]
    calls: list[str] = []
    real = module.scored_matches
    monkeypatch.setattr(module, "scored_matches", lambda *a, **k: calls.append(a[0]) or real(*a, **k))
    shortcut = [cat._suggest(name, 3) for name in names]
    assert calls == ["kenngr.vb_reflowx"]
    monkeypatch.setitem(cat.__dict__, "_longest", 10**9)  # no name is too long: the full search everywhere
    assert [cat._suggest(name, 3) for name in names] == shortcut
    assert calls == ["kenngr.vb_reflowx", *names]
    assert shortcut[0] == [] and "getriebe[i].vb_reflow" in shortcut[1] and shortcut[2]


# -- 13. output ------------------------------------------------------------------------------------------


@pytest.mark.parametrize("fmt", ["json", "sarif", "gitlab", "junit"])
def test_13_statistics_never_spoil_a_machine_format(run, fmt):
    _code, out, err = run(
        "lint", Path(__file__).parents[1] / "fixtures" / "multi_rule.lis", "--format", fmt, "--statistics"
    )
    if fmt == "junit":
        assert jenkins_junit_errors(out) == []
    else:
        json.loads(out)
    assert "LIS203" in err  # the counts went to stderr


def test_13_usage_errors_are_one_line_with_a_hint(run):
    for args in (
        ("lint", "--bogus", "x"),
        ("lint", "x", "--format", "nope"),
        ("nope",),
        ("lint", "--jobs", "0", "x"),
    ):
        code, _, err = run(*args)
        line = one_line(err)
        assert code == 2 and line.startswith("achslint: error: ") and "--help`)" in line, args


def test_13_diff_of_fmt_marks_a_missing_final_line_break(run, tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(b"kopf.achs_nr 1\nEnde")
    code, out, _ = run("fmt", "--diff", path)
    assert code == 1 and "-Ende\n\\ No newline at end of file\n" in out


def test_13_a_refused_write_is_not_counted(run, tmp_path):
    (tmp_path / "achsmds1.lis").write_bytes(MESSY)
    (tmp_path / "achsmds2.lis").write_bytes(MESSY)
    os.chmod(tmp_path / "achsmds2.lis", 0o444)
    code, _, err = run("fmt", tmp_path)
    assert code == 2 and "1 file reformatted, 0 left unchanged, 1 not written" in err


def test_changed_on_disk_is_checked_before_an_in_place_write(tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(b"edited meanwhile\n")
    os.link(path, tmp_path / "twin.lis")
    with pytest.raises(ChangedOnDisk):
        write_atomically(path, TIDY, expected=MESSY)
    assert path.read_bytes() == b"edited meanwhile\n"
