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
    return subprocess.CompletedProcess(result.args, result.returncode, result.stdout.decode(), result.stderr.decode())


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
