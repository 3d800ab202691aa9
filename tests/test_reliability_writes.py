"""Never lose (issue 22, items 1 and 2): rewrites the file system stops part-way, and a report file that
names one of the inputs.

A full disk is played by the file-size limit (RLIMIT_FSIZE) of the real entry point run in a child
process: writing past it fails with EFBIG exactly where a full disk fails with ENOSPC, and it needs no
privilege. The cases that take a folder we may not write, or a file whose owner we cannot keep, run the
child as the unprivileged user `nobody` when the tests run as root, and are skipped otherwise (an
ordinary user can neither make someone else's file nor give one away).
"""

from __future__ import annotations

import os
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

from achslint.core import files
from achslint.core.files import UNCHANGED, WriteFailed, write_atomically

MESSY = b"kopf.achs_nr 1\nkenngr.achs_typ     1\nEnde\n"  # fmt aligns it: the new text is longer
BROKEN_END = b"kopf.achs_nr     1\nkenngr.achs_typ  1\nEnd\n"  # lint --fix writes `Ende`: one byte more
ROOT = hasattr(os, "geteuid") and os.geteuid() == 0
NOBODY = 65534
AS_ROOT_ONLY = pytest.mark.skipif(
    not ROOT, reason="needs root to make a file of another user and run as nobody"
)


def _limited(size: int) -> dict:
    """subprocess.run arguments: the child may not write past `size` bytes."""

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (size, size))

    return {"preexec_fn": limit}


def _achslint(*args: str, cwd: Path, **extra) -> subprocess.CompletedProcess:
    env = {**os.environ, "NO_COLOR": "1", "HOME": str(cwd)}
    env.pop("FORCE_COLOR", None)
    for name in [name for name in env if name.startswith("COVERAGE_")]:
        env.pop(name)  # the child cannot write its coverage data past the file-size limit
    return subprocess.run(
        [sys.executable, "-m", "achslint", *args],
        capture_output=True,
        text=True,
        env=env,
        cwd=cwd,
        timeout=120,
        **extra,
    )


@pytest.fixture
def shared_folder():
    """A folder outside pytest's private tmp tree (which only root may enter), removed afterwards."""
    folder = Path(tempfile.mkdtemp(prefix="achslint-writes-"))
    folder.chmod(0o755)
    try:
        yield folder
    finally:
        for path in sorted(folder.rglob("*"), reverse=True):
            path.chmod(0o700) if path.is_dir() else path.unlink()
            if path.is_dir():
                path.rmdir()
        folder.rmdir()


def _no_temporaries(folder: Path) -> list[str]:
    return [p.name for p in folder.iterdir() if p.name.endswith(".achslint")]


# -- 1. a write that fails part-way leaves the old bytes ----------------------------------------------


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
@pytest.mark.parametrize(
    ("command", "original"),
    [(("fmt",), MESSY), (("lint", "--fix"), BROKEN_END)],
    ids=["fmt", "lint --fix"],
)
def test_1_hard_linked_list_full_disk_keeps_old_bytes(tmp_path, command, original):
    """A hard-linked list is rewritten in place; with the disk full after its old length, the
    rewrite stops part-way. Before the fix the list was left cut at the limit, neither old nor new."""
    target = tmp_path / "achsmds1.lis"
    target.write_bytes(original)
    os.link(target, tmp_path / "copy.lis")
    done = _achslint(*command, "achsmds1.lis", cwd=tmp_path, **_limited(len(original)))
    assert target.read_bytes() == original
    assert (tmp_path / "copy.lis").read_bytes() == original
    assert done.returncode == 2, done.stderr
    assert "cannot write achsmds1.lis" in done.stderr
    assert "unchanged" in done.stderr
    assert "Traceback" not in done.stderr
    assert "1 file reformatted" not in done.stdout + done.stderr  # a write that did not happen is not counted
    assert "fixed 1" not in done.stderr


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_1_temporary_file_on_a_full_disk_leaves_the_list_and_no_temporary(tmp_path):
    """The ordinary path (temporary file, then rename) with the disk full: the list is untouched, the
    temporary file removed, and the message says the list is unchanged."""
    target = tmp_path / "achsmds1.lis"
    target.write_bytes(MESSY)
    done = _achslint("fmt", "achsmds1.lis", cwd=tmp_path, **_limited(len(MESSY) - 5))
    assert target.read_bytes() == MESSY
    assert _no_temporaries(tmp_path) == []
    assert done.returncode == 2
    assert f"; {UNCHANGED}" in done.stderr


def _as_nobody(folder: Path, size: int, *args: str) -> tuple[int, str]:
    """The command line run by `nobody` in a forked child (this interpreter may live where nobody may
    not start it), with the file-size limit `size`: (exit code, what it printed)."""
    from achslint.cli import main

    # the interpreter's own modules may lie where nobody may not read them: everything the command
    # imports on its way is imported here first, by the same command on a scratch copy
    scratch = Path(tempfile.mkdtemp())
    (scratch / "achsmds1.lis").write_bytes(MESSY)
    main([*args[:-1], str(scratch / "achsmds1.lis")])
    os.link(scratch / "achsmds1.lis", scratch / "linked.lis")
    main([*args[:-1], str(scratch / "achsmds1.lis")])
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: never returns into pytest
        code = 99
        try:
            os.dup2(write_end, 1)
            os.dup2(write_end, 2)
            resource.setrlimit(resource.RLIMIT_FSIZE, (size, size))
            os.setgroups([])
            os.setgid(NOBODY)
            os.setuid(NOBODY)
            os.chdir(folder)
            sys.stdout = sys.stderr = os.fdopen(2, "w", closefd=False)
            code = main(list(args))
            sys.stdout.flush()
        finally:
            os._exit(code)
    os.close(write_end)
    with os.fdopen(read_end) as stream:
        printed = stream.read()
    _, status = os.waitpid(pid, 0)
    return os.waitstatus_to_exitcode(status), printed


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
@AS_ROOT_ONLY
def test_1_list_in_a_folder_we_may_not_write_full_disk(shared_folder):
    """nobody may write the list but not its folder (no temporary file there): rewritten in place."""
    target = shared_folder / "achsmds1.lis"
    target.write_bytes(MESSY)
    os.chown(target, NOBODY, NOBODY)
    code, printed = _as_nobody(shared_folder, len(MESSY), "fmt", "achsmds1.lis")
    assert target.read_bytes() == MESSY
    assert code == 2, printed
    assert "put back" in printed


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
@AS_ROOT_ONLY
def test_1_list_whose_owner_cannot_be_kept_full_disk(shared_folder):
    """nobody may write root's list (mode 666) and the folder, but cannot give a new file root's owner:
    the temporary file fills the disk first, or else the list is rewritten in place; either way the
    list is as it was, root's, and no temporary file is left."""
    shared_folder.chmod(0o777)
    target = shared_folder / "achsmds1.lis"
    target.write_bytes(MESSY)
    target.chmod(0o666)
    code, printed = _as_nobody(shared_folder, len(MESSY), "fmt", "achsmds1.lis")
    assert target.read_bytes() == MESSY
    assert os.stat(target).st_uid == 0
    assert _no_temporaries(shared_folder) == []
    assert code == 2, printed
    assert "the list is unchanged" in printed


def test_1_a_failed_restore_is_said_plainly(tmp_path, monkeypatch):
    """When even the old bytes cannot go back, the message says so and what to do."""
    target = tmp_path / "achsmds1.lis"
    target.write_bytes(MESSY)
    os.link(target, tmp_path / "copy.lis")
    calls = []
    real = os.pwrite

    def failing(fd: int, data, offset: int) -> int:
        calls.append(offset)
        if len(calls) == 1:  # the first 3 bytes of the new text go in, then the disk is full
            return real(fd, bytes(data[:3]), offset)
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(files.os, "pwrite", failing)
    with pytest.raises(WriteFailed) as caught:
        write_atomically(target, MESSY + b"more", expected=MESSY)
    assert "No space left on device" in str(caught.value)
    assert "version control or a backup" in str(caught.value)
    assert calls == [0, 3, 0]  # the write, its continuation, then the attempt to put 3 old bytes back


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_1_a_list_larger_than_the_limit_is_restored_where_it_was_written(tmp_path):
    """The file-size limit lies inside the old content: only the bytes written before the write stopped
    are put back (writing the whole old content again would hit the same limit and wrongly report the
    list as damaged)."""
    original = b"kopf.achs_nr 1\n" + b"kenngr.achs_typ     1\n" * 400 + b"Ende\n"
    target = tmp_path / "achsmds1.lis"
    target.write_bytes(original)
    os.link(target, tmp_path / "copy.lis")
    done = _achslint("fmt", "achsmds1.lis", cwd=tmp_path, **_limited(len(original) // 2))
    assert target.read_bytes() == original
    assert done.returncode == 2
    assert "its old content was put back" in done.stderr


# -- 2. -o/--output-file naming an input --------------------------------------------------------------


def _list(folder: Path, name: str = "achsmds1.lis") -> Path:
    path = folder / name
    path.write_bytes(b"kopf.achs_nr  1\nkopf.unbekannt  5\nEnde\n")
    return path


@pytest.mark.parametrize("how", ["same name", "other spelling", "symlink", "hard link"])
def test_2_output_file_naming_an_input_is_a_usage_error(cli, tmp_path, monkeypatch, how):
    monkeypatch.chdir(tmp_path)
    target = _list(tmp_path)
    before = target.read_bytes()
    output = {
        "same name": "achsmds1.lis",
        "other spelling": "./sub/../achsmds1.lis",
        "symlink": "link.lis",
        "hard link": "hard.lis",
    }[how]
    (tmp_path / "sub").mkdir()
    (tmp_path / "link.lis").symlink_to(target)
    os.link(target, tmp_path / "hard.lis")
    done = cli("lint", "achsmds1.lis", "-o", output)
    assert done.returncode == 2
    assert b"--output-file" in done.stderr and b"achsmds1.lis" in done.stderr
    assert target.read_bytes() == before


def test_2_output_file_over_a_list_found_in_a_folder(cli, tmp_path, monkeypatch):
    """The input is not named but found in the named folder, or through the start-up list."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "machine").mkdir()
    target = _list(tmp_path / "machine")
    before = target.read_bytes()
    done = cli("lint", "machine", "--fix", "-o", "machine/achsmds1.lis")
    assert done.returncode == 2
    assert b"--output-file" in done.stderr
    assert target.read_bytes() == before  # neither fixed nor overwritten: refused before anything ran


def test_2_output_file_over_an_axis_list_of_a_startup_list(cli, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "listen").mkdir()
    axis = _list(tmp_path / "listen")
    before = axis.read_bytes()
    (tmp_path / "listen" / "hochlauf.lis").write_bytes(b"achs_mds[0]  ./listen/achsmds1.lis\nEnde\n")
    done = cli("lint", "listen/hochlauf.lis", "-o", "listen/achsmds1.lis")
    assert done.returncode == 2
    assert b"--output-file" in done.stderr
    assert axis.read_bytes() == before


def test_2_output_file_beside_the_inputs_is_written(cli, tmp_path, monkeypatch):
    """The ordinary use stays: a report next to the lists (even an old report of the same name)."""
    monkeypatch.chdir(tmp_path)
    _list(tmp_path)
    (tmp_path / "report.txt").write_text("old report\n")
    done = cli("lint", ".", "-o", "report.txt", "--format", "concise")
    assert done.returncode == 0  # LIS101 is a warning
    assert "LIS101" in (tmp_path / "report.txt").read_text()


def test_2_dry_run_plot_over_its_list_is_a_usage_error(cli, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    target = _list(tmp_path, "achsmds1.svg")
    before = target.read_bytes()
    done = cli("dry-run", "achsmds1.svg", "--plot", "achsmds1.svg")
    assert done.returncode == 2
    assert target.read_bytes() == before


def test_write_failed_is_an_os_error_with_the_cause():
    failure = WriteFailed(Path("a.lis"), OSError(27, "File too large"), UNCHANGED)
    assert isinstance(failure, OSError) and failure.errno == 27
    assert str(failure) == f"cannot write a.lis: File too large; {UNCHANGED}"


def _sdk_like(folder: Path) -> None:
    """A machine with a channel list and default lists, in the SDK layout."""
    listen = folder / "listen"
    listen.mkdir(parents=True)
    (listen / "achsmds1.lis").write_text("kopf.achs_nr 1\nkopf.log_achs_name X\nEnde\n")
    (listen / "default_mds.lis").write_text("kopf.achs_nr 0\nEnde\n")
    (listen / "sda_mds1.lis").write_text(
        "gruppe[0].achsen[0].log_achs_nr 1\ngruppe[0].achsen[0].bezeichnung X\nEnde\n"
    )
    (listen / "default_sda.lis").write_text("Ende\n")
    (listen / "hochlauf.lis").write_text(
        "default_sda_mds ./listen/default_sda.lis\nsda_mds[0] ./listen/sda_mds1.lis\n"
        "default_achs_mds ./listen/default_mds.lis\nachs_mds[0] ./listen/achsmds1.lis\nEnde\n"
    )
    (folder / "pyproject.toml").write_text("[tool.achslint]\nignore = []\n")
    (folder / "rfp.nc").write_text("%\nN10 G74 X1\nM30\n")


@pytest.mark.parametrize(
    ("args", "output"),
    [
        (("lint", "listen/hochlauf.lis"), "pyproject.toml"),  # the configuration found for the lists
        (("lint", "listen/achsmds1.lis"), "pyproject.toml"),
        (("lint", "listen/hochlauf.lis"), "listen/sda_mds1.lis"),  # channel lists the start-up list names
        (("lint", "listen/hochlauf.lis"), "listen/default_sda.lis"),
        (("lint", "rfp.nc", "--machine", "listen/hochlauf.lis"), "listen/achsmds1.lis"),  # --machine's lists
        (("lint", "rfp.nc", "--machine", "listen/hochlauf.lis"), "listen/default_sda.lis"),
    ],
)
def test_2_output_file_over_any_file_the_run_reads(cli, tmp_path, monkeypatch, args, output):
    """Found by a review: the configuration, the channel lists and the lists of --machine were not
    protected, and the report replaced them."""
    monkeypatch.chdir(tmp_path)
    _sdk_like(tmp_path)
    before = (tmp_path / output).read_bytes()
    done = cli(*args, "-o", output)
    assert done.returncode == 2, done.stderr
    assert b"--output-file" in done.stderr
    assert (tmp_path / output).read_bytes() == before


@pytest.mark.parametrize("target", ["listen/default_sda.lis", "listen/default_mds.lis", "pyproject.toml"])
def test_2_machine_plot_over_any_file_of_the_machine(cli, tmp_path, monkeypatch, target):
    monkeypatch.chdir(tmp_path)
    _sdk_like(tmp_path)
    os.link(tmp_path / target, tmp_path / "p.svg")
    before = (tmp_path / target).read_bytes()
    done = cli("dry-run", "listen/hochlauf.lis", "--program", "rfp.nc", "--plot", "p.svg")
    assert done.returncode == 2 and b"--plot" in done.stderr
    assert (tmp_path / target).read_bytes() == before


def test_1_a_failure_after_a_shorter_text_was_written_puts_the_whole_old_text_back(tmp_path, monkeypatch):
    """Found by review: the new text is shorter, the truncation went through, then fsync failed (EIO, or a
    quota reported late on NFS): only the first bytes went back and the rest of the list became NULs."""
    old = b"kopf.achs_nr     1\n" + b"kenngr.achs_typ  1\n" * 5 + b"Ende\n"
    target = tmp_path / "achsmds1.lis"
    target.write_bytes(old)
    os.link(target, tmp_path / "copy.lis")
    real, calls = os.fsync, []

    def failing_once(fd: int) -> None:
        calls.append(fd)
        if len(calls) == 1:
            raise OSError(5, "Input/output error")
        real(fd)

    monkeypatch.setattr(files.os, "fsync", failing_once)
    with pytest.raises(WriteFailed, match="its old content was put back"):
        write_atomically(target, b"kopf.achs_nr 1\nEnde\n", expected=old)
    assert target.read_bytes() == old


@pytest.mark.parametrize("stop_at", ["pwrite", "ftruncate", "fsync"])
def test_1_ctrl_c_in_the_middle_of_a_rewrite_in_place_puts_the_old_text_back(tmp_path, monkeypatch, stop_at):
    """Found by review: a hard-linked list is rewritten in place, and only an OSError put its old bytes
    back. Ctrl-C (or SIGTERM, which the command line turns into an exception too) arriving after the new,
    shorter text was written but before the file was cut left the new text followed by the old one's tail."""
    old = b"kopf.achs_nr     1\n" + b"kenngr.achs_typ  1\n" * 5 + b"Ende\n"
    new = b"kopf.achs_nr 1\nEnde\n"
    target = tmp_path / "achsmds1.lis"
    target.write_bytes(old)
    os.link(target, tmp_path / "copy.lis")
    real, calls = getattr(files.os, stop_at), []

    def interrupted_once(*args):
        result = real(*args)
        calls.append(args)
        if len(calls) == 1:
            raise KeyboardInterrupt
        return result

    monkeypatch.setattr(files.os, stop_at, interrupted_once)
    with pytest.raises(KeyboardInterrupt):
        write_atomically(target, new, expected=old)
    assert target.read_bytes() == old
    assert (tmp_path / "copy.lis").read_bytes() == old


# -- 3. files a command makes (-o, --plot): all of the new one or the old one -------------------------

OLD_REPORT = b"the report of yesterday's run\n"


def _many_findings(folder: Path) -> None:
    """A list whose reports (lint json, the html report, the plot) are well over 4 KB."""
    lines = b"".join(b"kopf.unbekannt_%d  %d\n" % (i, i) for i in range(60))
    (folder / "achsmds1.lis").write_bytes(b"kopf.achs_nr  1\n" + lines + b"Ende\n")


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
@pytest.mark.parametrize(
    ("args", "output"),
    [
        (("lint", "achsmds1.lis", "--format", "json", "-o"), "out.json"),
        (("report", "achsmds1.lis", "-o"), "report.html"),
        (("dry-run", "achsmds1.lis", "--plot"), "plot.svg"),
    ],
    ids=["lint -o", "report -o", "dry-run --plot"],
)
def test_3_an_output_file_the_disk_cannot_take_keeps_the_old_one(tmp_path, args, output):
    """Found by review: -o truncated the old report at once and wrote the new one over it, so a full disk
    left half a report (and `lint -o` / `report -o` ended in `internal error: OSError: [Errno 27] File too
    large`, naming no file). Now the new file is made beside it and renamed: the old report stays whole."""
    _many_findings(tmp_path)
    (tmp_path / output).write_bytes(OLD_REPORT)
    done = _achslint(*args, output, cwd=tmp_path, **_limited(4096))
    assert done.returncode == 2, done.stderr
    assert f"cannot write {'the plot to ' if 'plot' in output else ''}{output}" in done.stderr
    assert "internal error" not in done.stderr and "Traceback" not in done.stderr
    assert (tmp_path / output).read_bytes() == OLD_REPORT
    assert _no_temporaries(tmp_path) == []


def test_3_an_output_file_is_written_whole_through_a_link_and_keeps_its_mode(cli, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    _many_findings(tmp_path)
    (tmp_path / "reports").mkdir()
    real = tmp_path / "reports" / "out.json"
    real.write_bytes(OLD_REPORT)
    real.chmod(0o640)
    (tmp_path / "out.json").symlink_to(real)
    done = cli("lint", "achsmds1.lis", "--format", "json", "-o", "out.json")
    assert done.returncode == 0, done.stderr  # LIS101 is a warning
    assert (tmp_path / "out.json").is_symlink()
    assert "kopf.unbekannt_59" in real.read_text()
    assert real.stat().st_mode & 0o777 == 0o640
    assert _no_temporaries(tmp_path) == [] and _no_temporaries(tmp_path / "reports") == []


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_3_output_to_dev_stdout_appends_to_what_the_shell_opened(tmp_path):
    """`-o /dev/stdout` is written as it is (no temporary file beside /proc's link), and appended: a shell's
    `>> log` keeps what the log held."""
    _many_findings(tmp_path)
    log = tmp_path / "log"
    log.write_bytes(b"earlier\n")
    with log.open("ab") as stream:
        done = subprocess.run(
            [
                sys.executable,
                "-m",
                "achslint",
                "lint",
                "achsmds1.lis",
                "--format",
                "concise",
                "-o",
                "/dev/stdout",
            ],
            stdout=stream,
            stderr=subprocess.PIPE,
            cwd=tmp_path,
            env={**os.environ, "NO_COLOR": "1", "HOME": str(tmp_path)},
            timeout=120,
        )
    assert done.returncode == 0, done.stderr
    text = log.read_text()
    assert text.startswith("earlier\n") and "kopf.unbekannt_59" in text
