"""The commands that read one axis list (explain FILE, dry-run, diff, report; the API's explain and dry_run)
refuse a list of another kind, told as lint tells it: read as an axis list, a channel or tool list would be an
axis of catalogue defaults, explained and homed as if it existed."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

import achslint
from achslint.core.decode import UnreadableInput

from .conftest import FIXTURES
from .conftest import run_cli as run_cli_bytes

KINDS = FIXTURES / "kinds"
OTHER_KINDS = {  # fixture -> the kind lint reads it as
    "sda_mds1.lis": "channel list",
    "werkz_d1.lis": "tool data list",
    "achskw1.lis": "axis compensation list",
    "ext_var1.lis": "external variable list",
}


def run_cli(*args: str) -> subprocess.CompletedProcess[str]:
    result = run_cli_bytes(*args)
    return subprocess.CompletedProcess(
        result.args, result.returncode, result.stdout.decode(), result.stderr.decode()
    )


@pytest.mark.parametrize("name", sorted(OTHER_KINDS))
def test_explain_and_dry_run_name_the_kind_and_show_nothing_of_it(name: str) -> None:
    path = str(KINDS / name)
    for command in ("explain", "dry-run"):
        result = run_cli(command, path)
        assert result.returncode == 2, (command, result.stdout)
        assert result.stdout == ""
        assert f"is an {OTHER_KINDS[name]}" in result.stderr or f"is a {OTHER_KINDS[name]}" in result.stderr
        assert "not an axis list" in result.stderr and "Traceback" not in result.stderr
    with pytest.raises(UnreadableInput, match="not an axis list"):
        achslint.explain(path)
    with pytest.raises(UnreadableInput, match="not an axis list"):
        achslint.dry_run(Path(path).read_bytes())


def test_a_channel_list_points_to_the_machine_that_shows_its_axes() -> None:
    result = run_cli("explain", str(KINDS / "sda_mds1.lis"))
    assert "is a channel list" in result.stderr and "--channel" in result.stderr


def test_two_channel_lists_are_not_compared_as_axes() -> None:
    channel = str(KINDS / "sda_mds1.lis")
    other = str(FIXTURES / "machines" / "sdk4" / "listen" / "sda_mds1.lis")
    result = run_cli("diff", channel, other)
    assert result.returncode == 2 and result.stdout == "" and "is a channel list" in result.stderr


def test_axis_lists_and_default_axis_lists_are_still_read(tmp_path: Path) -> None:
    result = run_cli("explain", str(KINDS / "achsmds_z.lis"))
    assert result.returncode == 0 and "Axis Z (logical axis 3)" in result.stdout
    default = FIXTURES / "machines" / "sdk4" / "listen" / "default_mds.lis"
    assert run_cli("explain", str(default)).returncode == 0
    assert achslint.explain(KINDS / "achsmds_z.lis")["axis"]["number"] == 3


def test_a_twincat_channel_item_is_named_as_one() -> None:
    result = run_cli("explain", str(FIXTURES / "machines" / "twincat_export" / "Channel_1.xti"))
    assert result.returncode == 2 and result.stdout == ""
    assert "is a TwinCAT channel item (<IsgChannelDef> with <SdaMds>" in result.stderr


PORTAL = FIXTURES / "machines" / "portal"


def test_an_nc_program_is_refused_by_every_command_that_reads_one_axis_list(tmp_path: Path) -> None:
    # The homing program read as an axis list was an axis of catalogue defaults, explained and homed.
    program = str(PORTAL / "rfp.nc")
    for args in (["explain", program], ["dry-run", program], ["diff", program, program]):
        result = run_cli(*args)
        assert result.returncode == 2 and result.stdout == "", args
        assert "rfp.nc is an NC program, not an axis list" in result.stderr
        assert "--program rfp.nc" in result.stderr
    report = run_cli("report", program, "-o", str(tmp_path / "report.html"))
    assert report.returncode == 2 and not (tmp_path / "report.html").exists()
    for function in (achslint.explain, achslint.dry_run, achslint.load):
        with pytest.raises(UnreadableInput, match="is an NC program"):
            function(program)


def test_a_text_that_names_no_known_parameter_is_no_axis_list(tmp_path: Path) -> None:
    # The same program under a list's name: none of its names is a parameter of any list kind.
    renamed = tmp_path / "achsmds1.lis"
    renamed.write_bytes((PORTAL / "rfp.nc").read_bytes())
    result = run_cli("explain", str(renamed))
    assert result.returncode == 2 and "none of its assignments names a parameter" in result.stderr
    with pytest.raises(UnreadableInput, match="none of its assignments"):
        achslint.dry_run(renamed.read_bytes())
    # An empty list is still an axis of defaults, and a list with a typo beside a known name is read.
    assert achslint.loads("Ende\n").kopf.achs_nr == 1
    assert achslint.loads("kopf.achs_nr 4\nkenngr.made_up 1\nEnde\n").kopf.achs_nr == 4


@pytest.mark.parametrize("name", ["sda_mds1.lis", "hochlauf.lis"])
def test_load_and_loads_refuse_a_list_of_another_kind(name: str) -> None:
    path = KINDS / name
    with pytest.raises(UnreadableInput, match="not an axis list"):
        achslint.load(path)
    with pytest.raises(UnreadableInput, match="not an axis list"):
        achslint.loads(path.read_text(encoding="latin-1"), filename=name)


def test_fmt_leaves_an_nc_program_as_it_is(tmp_path: Path) -> None:
    # A program's blocks are no `parameter value` lines: aligned like a list, `N10   G74 X1` would be rewritten.
    program = tmp_path / "rfp.nc"
    text = b"N10   G74 X1\nN20 G74    Y1\nM30\n"
    program.write_bytes(text)
    for mode in ((), ("--check",), ("--diff",)):
        result = run_cli("fmt", *mode, str(program))
        assert result.returncode == 2 and result.stdout == "", mode
        assert "fmt rewrites lists only, not NC programs" in result.stderr
    assert program.read_bytes() == text


def test_schema_refuses_a_kind_it_would_ignore() -> None:
    result = run_cli("schema", "--output", "lint", "--kind", "channel")
    assert result.returncode == 2 and result.stdout == ""
    assert "--kind goes with --output model" in result.stderr
    channel = run_cli("schema", "--kind", "channel")
    axis = run_cli("schema")
    assert channel.returncode == axis.returncode == 0 and channel.stdout != axis.stdout
    assert '"Antr"' in axis.stdout and '"Antr"' not in channel.stdout


def test_a_channel_list_a_start_up_list_loads_is_explained_as_that_channel_of_its_machine() -> None:
    machine = FIXTURES / "rules" / "LIS522" / "good"  # two channels: sda_mds[0], sda_mds[1]
    startup = str(machine / "hochlauf.lis")
    second = str(machine / "sda_mds2.lis")
    for fmt in ("text", "json"):
        result = run_cli("explain", second, "--format", fmt)
        assert result.returncode == 0, result.stderr
        assert result.stdout == run_cli("explain", startup, "--channel", "2", "--format", fmt).stdout
        assert result.stdout != run_cli("explain", startup, "--format", fmt).stdout  # channel 1's names
    assert run_cli("explain", second, "--channel", "2").returncode == 0
    other = run_cli("explain", second, "--channel", "1")  # 1 is the default: the list's own channel wins
    assert other.returncode == 0 and other.stdout == run_cli("explain", second).stdout
    wrong = run_cli("explain", second, "--channel", "3")
    assert wrong.returncode == 2 and "is the list of channel 2 of" in wrong.stderr and wrong.stdout == ""


def test_the_api_says_a_folder_is_not_one_list(tmp_path: Path) -> None:
    for call in (achslint.explain, achslint.dry_run, achslint.load):
        with pytest.raises(IsADirectoryError, match="a folder, not one list"):
            call(tmp_path)
    listen = FIXTURES / "machines" / "sdk4" / "listen"
    assert isinstance(achslint.lint(listen), list)  # lint takes a folder: the machine
