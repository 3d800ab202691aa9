"""Never leak, never hang (issue 22, items 3-6 and 11): what a start-up list, a configuration and the
files named on the command line can make achslint read, and how big and how odd those files may be.

A pull request controls the lists, the start-up list, the NC programs and the configuration of the
repository CI lints; none of them may make achslint read a file outside that repository, block on a FIFO,
or take unbounded memory. Files are made in `tmp_path`; a `.git` folder marks the repository.
"""

from __future__ import annotations

import json
import os
import subprocess
from collections.abc import Iterator
from pathlib import Path

import pytest

from achslint.core.files import LIST_LIMIT, PROGRAM_LIMIT, SETTINGS_LIMIT, Refused, read_list
from achslint.linting.config import ConfigError, forget_cached, load_file, repository_of
from achslint.machine.startup import default_cnc_root, read_startup

from .conftest import run_cli
from .warm_cli import warm_achslint

SECRET = "TOP-SECRET-4711"
AXIS = "kopf.achs_nr  {n}\nkopf.log_achs_name  {name}\nkenngr.achs_typ  1\nEnde\n"
PROGRAM = "%rfp\nN10 G74 X1\nM30\n"


@pytest.fixture(autouse=True)
def _fresh_configuration_cache():
    forget_cached()
    yield
    forget_cached()


def _machine(root: Path, *, startup_folder: str = "listen", entries: str = "") -> Path:
    """A one-axis machine in the SDK layout (`listen/hochlauf.lis` naming `./listen/achsmds1.lis`)."""
    listen = root / "listen"
    listen.mkdir(parents=True, exist_ok=True)
    (listen / "achsmds1.lis").write_text(AXIS.format(n=1, name="X"))
    folder = root / startup_folder
    folder.mkdir(parents=True, exist_ok=True)
    startup = folder / "hochlauf.lis"
    startup.write_text(f"achs_mds[0]  ./listen/achsmds1.lis\n{entries}Ende\n")
    return startup


def _run(cwd: Path, *args: str) -> subprocess.CompletedProcess:
    before = os.getcwd()
    os.chdir(cwd)
    try:
        return run_cli(*args)
    finally:
        os.chdir(before)


@pytest.fixture(scope="module")
def warm(tmp_path_factory) -> Iterator[Path]:
    with warm_achslint(tmp_path_factory.mktemp("warm")) as folder:
        yield folder / "achslint"


def _real(warm: Path, cwd: Path, *args: str, timeout: float = 60) -> subprocess.CompletedProcess:
    """The CLI in a child process of its own (tests/warm_cli.py), not this one: for the cases that hung
    before (a FIFO blocks `open`); the child is ended if it hangs."""
    env = {**os.environ, "NO_COLOR": "1"}
    return subprocess.run([warm, *args], cwd=cwd, capture_output=True, timeout=timeout, env=env)


def _lis504(result: subprocess.CompletedProcess) -> list[str]:
    return [d["message"] for d in json.loads(result.stdout)["diagnostics"] if d["code"] == "LIS504"]


# -- 3. start-up lists read only under their CNC root -------------------------------------------------


@pytest.mark.parametrize(
    ("startup", "root"),
    [
        ("m/hochlauf.lis", "m"),  # the start-up list's own folder
        ("m/listen/hochlauf.lis", "m"),  # the SDK layout: the folder above listen/
        ("m/LISTEN/hochlauf.lis", "m"),
        ("m/listen/ExtSchedule/hochlauf.lis", "m"),  # the external-scheduling variant
        ("m/a/b/hochlauf.lis", "m/a/b"),  # never a folder further up, wherever files happen to exist
    ],
)
def test_3_the_default_cnc_root_is_fixed_by_where_the_startup_list_lies(tmp_path, startup, root):
    assert default_cnc_root(tmp_path / startup) == tmp_path / root


def test_3_the_root_is_not_guessed_from_where_entries_exist(tmp_path, cli):
    """Before, the root was the nearest folder upwards where the entries existed: a start-up list in
    `deep/er/` naming `./secret.lis` made achslint read (and lint) `secret.lis` two folders up."""
    (tmp_path / "secret.lis").write_text(f"kopf.achs_nr 1\n{SECRET} 1\nEnde\n")
    startup = tmp_path / "deep" / "er" / "hochlauf.lis"
    startup.parent.mkdir(parents=True)
    startup.write_text("achs_mds[0]  ./secret.lis\nEnde\n")
    result = _run(tmp_path, "lint", "deep/er/hochlauf.lis", "--format", "json")
    assert SECRET.encode() not in result.stdout + result.stderr
    [message] = _lis504(result)
    assert "does not exist" in message and "deep/er/secret.lis" in message
    assert "the start-up list folder" in message


def test_3_a_symlink_inside_the_machine_that_leads_out_is_not_read(tmp_path):
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "achsmds2.lis").write_text(f"kopf.achs_nr 2\n{SECRET} 1\nEnde\n")
    machine = tmp_path / "machine"
    startup = _machine(machine, entries="achs_mds[1]  ./listen/achsmds2.lis\n")
    (machine / "listen" / "achsmds2.lis").symlink_to(outside / "achsmds2.lis")
    result = _run(machine, "lint", "listen/hochlauf.lis", "--format", "json")
    assert SECRET.encode() not in result.stdout + result.stderr
    [message] = _lis504(result)
    assert "symbolic link that leads outside the CNC root" in message
    entries = read_startup(startup)
    assert entries.axes[1].path is None and entries.axes[1].refused
    # the machine commands refuse it too, naming the entry
    explained = _run(machine, "explain", "listen/hochlauf.lis")
    assert explained.returncode == 2 and b"achs_mds[1]" in explained.stderr
    assert SECRET.encode() not in explained.stdout + explained.stderr


def test_3_nothing_is_looked_up_outside_the_root(tmp_path):
    """A file outside the root that exists and one that does not get the same words: a start-up list
    cannot probe the machine that lints it for which files exist."""
    (tmp_path / "exists.lis").write_text("kopf.achs_nr 1\nEnde\n")
    startup = _machine(
        tmp_path / "machine", entries="achs_mds[1]  ../exists.lis\nachs_mds[2]  ../missing.lis\n"
    )
    entries = read_startup(startup)
    root = tmp_path / "machine"
    assert [entry.refused for entry in entries.axes[1:]] == [
        f"it lies outside the CNC root {root} (the folder above `listen/`; --cnc-root sets another)"
    ] * 2


def test_3_a_symlinked_folder_on_the_way_out_is_refused_too(tmp_path):
    (tmp_path / "outside").mkdir()
    (tmp_path / "outside" / "achsmds1.lis").write_text(f"kopf.achs_nr 1\n{SECRET} 1\nEnde\n")
    machine = tmp_path / "machine"
    machine.mkdir()
    (machine / "listen").symlink_to(tmp_path / "outside", target_is_directory=True)
    startup = machine / "hochlauf.lis"
    startup.write_text("achs_mds[0]  ./listen/achsmds1.lis\nEnde\n")
    result = _run(machine, "lint", "hochlauf.lis", "--format", "json")
    assert SECRET.encode() not in result.stdout + result.stderr
    assert "symbolic link that leads outside" in _lis504(result)[0]


@pytest.mark.parametrize(
    ("value", "problem"),
    [
        ("/", "lies outside"),
        ("../..", "lies outside"),
        ("{outside}", "lies outside"),
        ("../escape", "through a symbolic link"),
    ],
)
def test_3_cnc_root_from_a_configuration_stays_in_its_repository(tmp_path, value, problem):
    repository = tmp_path / "repo"
    _machine(repository / "machine")
    (repository / ".git").mkdir()
    (tmp_path / "elsewhere").mkdir()
    (repository / "escape").symlink_to(tmp_path / "elsewhere", target_is_directory=True)
    config = repository / "machine" / "achslint.toml"
    config.write_text(f'cnc-root = "{value.format(outside=tmp_path / "elsewhere")}"\n')
    result = _run(repository, "lint", "machine/listen/hochlauf.lis")
    assert result.returncode == 2
    message = result.stderr.decode()
    assert str(config) in message and "key `cnc-root`" in message and problem in message
    assert "Traceback" not in message and message.count("\n") == 1


def test_3_cnc_root_inside_the_repository_is_used(tmp_path):
    repository = tmp_path / "repo"
    startup = _machine(repository / "machine", startup_folder="config")  # lists in listen/, not below config/
    (repository / ".git").mkdir()
    (repository / "machine" / "achslint.toml").write_text('cnc-root = "."\n')
    result = _run(repository, "lint", str(startup.relative_to(repository)), "--format", "json")
    assert result.returncode == 0, result.stderr
    assert _lis504(result) == []


def test_3_without_git_the_repository_is_the_configuration_folder(tmp_path):
    (tmp_path / "a").mkdir()
    assert repository_of(tmp_path / "a" / "achslint.toml") == tmp_path / "a"
    (tmp_path / ".git").write_text("gitdir: elsewhere\n")  # a worktree's .git is a file
    assert repository_of(tmp_path / "a" / "achslint.toml") == tmp_path
    (tmp_path / "a" / "achslint.toml").write_text('cnc-root = ".."\n')
    assert load_file(tmp_path / "a" / "achslint.toml").cnc_root() == tmp_path


# -- 4. homing-programs of a configuration --------------------------------------------------------------


def _programs_repository(tmp_path: Path, programs: str) -> Path:
    repository = tmp_path / "repo"
    _machine(repository)
    (repository / ".git").mkdir()
    (repository / "achslint.toml").write_text(f"homing-programs = [{programs}]\n")
    return repository


@pytest.mark.parametrize(
    ("programs", "problem"),
    [
        ('"/etc/passwd.nc"', "lies outside"),
        ('"../outside.nc"', "lies outside"),
        ('"listen/achsmds1.lis"', "is not an NC program"),
        ('"rfp.txt"', "is not an NC program"),
    ],
)
def test_4_homing_programs_outside_or_not_programs_are_configuration_errors(tmp_path, programs, problem):
    (tmp_path / "outside.nc").write_text(f"%\nN10 G74 X1 ({SECRET})\nM30\n")
    repository = _programs_repository(tmp_path, programs)
    result = _run(repository, "lint", "listen/hochlauf.lis")
    assert result.returncode == 2
    message = result.stderr.decode()
    assert "key `homing-programs`" in message and problem in message
    assert SECRET not in message and message.count("\n") == 1


def test_4_a_binary_homing_program_is_one_configuration_error_not_findings(tmp_path):
    repository = _programs_repository(tmp_path, '"rfp.nc"')
    (repository / "rfp.nc").write_bytes(b"\x7fELF\x02\x01\x01\x00" + SECRET.encode() + b"\x00" * 64)
    result = _run(repository, "lint", "listen/hochlauf.lis", "--format", "json")
    assert result.returncode == 2
    assert "key `homing-programs`" in result.stderr.decode() and "not text" in result.stderr.decode()
    assert SECRET.encode() not in result.stdout + result.stderr
    assert [d for d in json.loads(result.stdout)["diagnostics"] if d["path"].endswith("rfp.nc")] == []


def test_4_a_homing_program_over_the_size_limit_is_not_read(tmp_path):
    repository = _programs_repository(tmp_path, '"rfp.nc"')
    with open(repository / "rfp.nc", "wb") as stream:  # sparse: no disk is used
        stream.truncate(PROGRAM_LIMIT + 1)
    result = _run(repository, "lint", "listen/hochlauf.lis")
    assert result.returncode == 2
    assert "more than the 16 MB achslint reads for an NC program" in result.stderr.decode()


def test_4_a_text_homing_program_inside_the_repository_is_checked(tmp_path):
    repository = _programs_repository(tmp_path, '"rfp.nc"')
    (repository / "rfp.nc").write_text("%\nN10 G74 Q1\nM30\n")
    result = _run(repository, "lint", "listen/hochlauf.lis", "--format", "json")
    assert "LIS602" in {d["code"] for d in json.loads(result.stdout)["diagnostics"]}


# -- 5. one reader for every file: no FIFO, no device, no file over its limit --------------------------


@pytest.fixture
def fifo(tmp_path) -> Path:
    path = tmp_path / "pipe"
    os.mkfifo(path)
    return path


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
@pytest.mark.parametrize(
    "args",
    [
        ("dry-run", "listen/hochlauf.lis", "--program", "{fifo}"),
        ("explain", "listen/hochlauf.lis", "--program", "{fifo}"),
        ("lint", "{fifo}.nc", "--machine", "listen/hochlauf.lis"),
        ("dry-run", "listen/achsmds1.lis", "--scenario", "{fifo}"),
        ("dry-run", "listen/hochlauf.lis", "--program", "rfp.nc", "--scenario", "{fifo}"),
        ("lint", "listen/achsmds1.lis", "--config", "{fifo}"),
        ("dry-run", "listen/achsmds1.lis", "--scenario", "/dev/zero"),
        ("lint", "listen/achsmds1.lis", "--config", "/dev/zero"),
        ("dry-run", "listen/hochlauf.lis", "--program", "/dev/zero"),
    ],
    ids=lambda args: " ".join(args[:1] + args[2:]),
)
def test_5_fifos_and_devices_are_refused_never_read(tmp_path, args, warm):
    """Before, --program, --scenario and --config blocked on a FIFO forever and read /dev/zero until
    memory ran out; each is one line and exit 2 now (the child is killed after a minute if it hangs)."""
    _machine(tmp_path)
    (tmp_path / "rfp.nc").write_text(PROGRAM)
    os.mkfifo(tmp_path / "pipe")
    os.mkfifo(tmp_path / "pipe.nc")
    done = _real(warm, tmp_path, *(a.format(fifo=tmp_path / "pipe") for a in args))
    assert done.returncode == 2, done.stderr
    message = done.stderr.decode()
    assert message.count("\n") == 1 and "Traceback" not in message
    assert "FIFO" in message or "device" in message


def test_5_a_configuration_that_is_a_fifo_is_an_error_not_skipped(tmp_path, cli):
    """Before, `achslint.toml` as a FIFO was skipped silently: the run used other settings."""
    (tmp_path / "achsmds1.lis").write_text(AXIS.format(n=1, name="X"))
    os.mkfifo(tmp_path / "achslint.toml")
    result = _run(tmp_path, "lint", "achsmds1.lis")
    assert result.returncode == 2
    assert b"achslint.toml is a FIFO" in result.stderr


@pytest.mark.parametrize(
    ("name", "limit", "args"),
    [
        ("machine.toml", SETTINGS_LIMIT, ("dry-run", "achsmds1.lis", "--scenario", "machine.toml")),
        ("achslint.toml", SETTINGS_LIMIT, ("lint", "achsmds1.lis")),
        ("achsmds2.lis", LIST_LIMIT, ("lint", "achsmds2.lis")),
    ],
)
def test_5_files_over_their_size_limit_are_refused(tmp_path, name, limit, args):
    (tmp_path / "achsmds1.lis").write_text(AXIS.format(n=1, name="X"))
    with open(tmp_path / name, "wb") as stream:  # sparse
        stream.truncate(limit + 1)
    result = _run(tmp_path, *args)
    assert result.returncode == 2
    assert b"achslint reads" in result.stderr and name.encode() in result.stderr


def test_5_the_reader_reads_at_most_the_limit(tmp_path):
    path = tmp_path / "a.lis"
    path.write_bytes(b"x" * 101)
    assert read_list(path, limit=101) == b"x" * 101
    with pytest.raises(Refused, match="more than the"):
        read_list(path, limit=100)
    assert read_list(path, 10, limit=100) == b"x" * 10


# -- 6. bounded settings ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("setting", "key"),
    [
        ("cycle-time-us = 9223372036854775807", "cycle-time-us"),
        ("cycle-time-us = 10", "cycle-time-us"),
        ("cycle-time-us = 100001", "cycle-time-us"),
        ("repeatability-tolerance-um = 1e300", "repeatability-tolerance-um"),
        ("repeatability-tolerance-deg = inf", "repeatability-tolerance-deg"),
        ("repeatability-tolerance-um = nan", "repeatability-tolerance-um"),
        ("[fmt]\nvalue-column = 9223372036854775807", "value-column"),
        ("[fmt]\ncomment-column = 100000000", "comment-column"),
    ],
)
def test_6_absurd_numbers_in_a_configuration_are_errors(tmp_path, setting, key):
    config = tmp_path / "achslint.toml"
    config.write_text(setting + "\n")
    with pytest.raises(ConfigError) as caught:
        load_file(config)
    assert key in str(caught.value) and str(config) in str(caught.value)
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr 1\nEnde\n")
    result = _run(tmp_path, "fmt", "--check", "achsmds1.lis")
    assert result.returncode == 2 and key.encode() in result.stderr


@pytest.mark.parametrize("value", ["0.001", "1000"])
def test_6_the_command_line_has_the_same_cycle_time_bounds(tmp_path, value):
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr 1\nEnde\n")
    result = _run(tmp_path, "lint", "achsmds1.lis", "--cycle-time-ms", value)
    assert result.returncode == 2 and b"--cycle-time-ms" in result.stderr


def test_6_the_bounds_themselves_are_accepted(tmp_path):
    config = tmp_path / "achslint.toml"
    config.write_text("cycle-time-us = 50\nrepeatability-tolerance-deg = 360\n[fmt]\nvalue-column = 400\n")
    settings = load_file(config).settings
    assert (settings.cycle_time_us, settings.repeatability_tolerance_deg, settings.fmt.value_column) == (
        50,
        360,
        400,
    )


# -- 11. honest output --------------------------------------------------------------------------------


@pytest.mark.parametrize("fmt", ["full", "concise", "json"])
def test_11_a_program_whose_machine_is_missing_is_not_a_clean_run(tmp_path, fmt):
    (tmp_path / "rfp.nc").write_text(PROGRAM)
    result = _run(tmp_path, "lint", "rfp.nc", "--machine", "missing/hochlauf.lis", "--format", fmt)
    assert result.returncode == 2
    assert b"All checks passed" not in result.stdout
    assert b"missing/hochlauf.lis" in result.stderr
    if fmt == "json":
        assert json.loads(result.stdout)["summary"]["unreadable"] == ["rfp.nc"]


def test_11_a_startup_list_naming_itself_is_one_finding_not_an_axis_list(tmp_path):
    """Before, the start-up list was also linted as an axis list of its own: LIS101 for every entry."""
    (tmp_path / "hochlauf.lis").write_text(
        "achs_mds[0]  ./hochlauf.lis\ndefault_achs_mds  ./hochlauf.lis\nEnde\n"
    )
    result = _run(tmp_path, "lint", "hochlauf.lis", "--format", "json")
    codes = [d["code"] for d in json.loads(result.stdout)["diagnostics"]]
    assert codes == ["LIS504", "LIS504"]


def test_11_text_with_a_lone_surrogate_is_linted_not_a_crash():
    """An editor or a caller can hand over text no UTF-8 can hold ("\\ud800" in JSON)."""
    from achslint import lint_text
    from achslint.lsp.session import xml_bytes

    found = lint_text("kopf.achs_nr 1\nkopf.na\ud800me 1\nEnde\n")
    assert [(d.code, d.line) for d in found] == [("LIS001", 2)]  # `?` in a name: not a parameter line
    assert xml_bytes('<?xml version="1.0" encoding="latin-1"?><a>\ud800</a>').endswith(b"<a>?</a>")


@pytest.mark.parametrize(
    ("setting", "words"),
    [
        ('cnc-root = "a\\u0000b"', "NUL character"),
        ('homing-programs = ["\\u0000.nc"]', "NUL character"),
    ],
)
def test_3_a_nul_in_a_configured_path_is_a_configuration_error(tmp_path, setting, words):
    """Found by a review: an internal error (ValueError: embedded null byte) before."""
    (tmp_path / "achslint.toml").write_text(setting + "\n")
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr 1\nEnde\n")
    result = _run(tmp_path, "lint", "achsmds1.lis")
    assert result.returncode == 2
    assert words.encode() in result.stderr and b"internal error" not in result.stderr


def test_4_an_over_long_homing_program_name_is_one_short_line(tmp_path):
    """Found by a review: OSError (file name too long) as an internal error, echoing the whole name."""
    repository = _programs_repository(tmp_path, '"' + "b" * 5000 + '.nc"')
    result = _run(repository, "lint", "listen/hochlauf.lis")
    assert result.returncode == 2
    message = result.stderr.decode()
    assert "a name too long for the file system" in message and "internal error" not in message
    assert len(message) < 400


def test_5_an_oversize_channel_list_or_axis_list_entry_is_a_finding(tmp_path):
    """Found by a review: a 20 GB channel list passed as "All checks passed!"."""
    startup = _machine(tmp_path, entries="sda_mds[0]  ./listen/sda_mds1.lis\nachs_mds[1]  ./listen/big.lis\n")
    for name in ("sda_mds1.lis", "big.lis"):
        with open(tmp_path / "listen" / name, "wb") as stream:
            stream.truncate(LIST_LIMIT + 1)
    result = _run(tmp_path, "lint", str(startup.relative_to(tmp_path)), "--format", "json")
    messages = _lis504(result)
    assert len(messages) == 2 and all("larger than the 64 MB achslint reads" in m for m in messages)


def test_5_a_fifo_entry_is_not_advised_to_be_named_on_the_command_line(tmp_path):
    """Found by a review: naming a FIFO on the command line is refused too, so that advice led nowhere."""
    startup = _machine(tmp_path, entries="achs_mds[1]  ./listen/pipe.lis\n")
    os.mkfifo(tmp_path / "listen" / "pipe.lis")
    [message] = _lis504(_run(tmp_path, "lint", str(startup.relative_to(tmp_path)), "--format", "json"))
    assert "a FIFO, not a regular file" in message and message.endswith("name a regular list file there")


def test_a_linked_folder_leading_outside_is_skipped_with_a_note(tmp_path):
    """Found by a review: the README promises a note for links that lead outside; a linked folder had none."""
    (tmp_path / "out").mkdir()
    (tmp_path / "out" / "achsmds9.lis").write_text(f"kopf.achs_nr 9\n{SECRET} 1\nEnde\n")
    (tmp_path / "d").mkdir()
    (tmp_path / "d" / "achsmds1.lis").write_text("kopf.achs_nr 1\nEnde\n")
    (tmp_path / "d" / "sub").symlink_to(tmp_path / "out", target_is_directory=True)
    result = _run(tmp_path, "lint", "d", "--format", "concise")
    assert b"d/sub: skipped, it links to" in result.stderr and b"outside the paths given" in result.stderr
    assert SECRET.encode() not in result.stdout + result.stderr


@pytest.mark.parametrize(
    "speeds", ["getriebe[0].vb_refmax 0\ngetriebe[0].vb_reflow 100", "getriebe[0].vb_refmax 0"]
)
def test_a_homing_speed_of_zero_is_a_finding_and_a_failed_dry_run_not_a_crash(tmp_path, speeds):
    """Found by review: ZeroDivisionError stopped the whole lint (LIS317 simulates) and the dry-run."""
    (tmp_path / "achsmds1.lis").write_text(f"kopf.achs_nr 1\nkenngr.antr_typ 1\n{speeds}\nEnde\n")
    linted = _run(tmp_path, "lint", "achsmds1.lis", "--format", "json")
    assert b"internal error" not in linted.stderr and linted.returncode in (0, 1)
    assert json.loads(linted.stdout)["summary"]["unreadable"] == []
    ran = _run(tmp_path, "dry-run", "achsmds1.lis", "--format", "json")
    assert b"internal error" not in ran.stderr
    document = json.loads(ran.stdout)
    assert document["outcome"] == "failed" and "cannot move" in document["failure"]


@pytest.mark.parametrize("kind", ["sparse", "proc"])
def test_5_a_configuration_refused_at_discovery_is_named_as_a_configuration(tmp_path, kind):
    """Found by a review: the refusal called it a list (and gave the 64 MB limit of lists)."""
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr 1\nEnde\n")
    config = tmp_path / "achslint.toml"
    if kind == "sparse":
        with open(config, "wb") as stream:
            stream.truncate(SETTINGS_LIMIT + 1)
    else:
        config.symlink_to("/proc/self/environ")
    result = _run(tmp_path, "lint", "achsmds1.lis")
    assert result.returncode == 2
    message = result.stderr.decode()
    words = (
        "larger than the 4 MB achslint reads for a configuration"
        if kind == "sparse"
        else "not a configuration"
    )
    assert words in message and "list" not in message.replace("achsmds1.lis", "")
