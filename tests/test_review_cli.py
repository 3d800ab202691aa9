"""The command line as a new user meets it: wrong usage gets one line on standard error that names what is
wrong (in the words of the command line, not of the code behind it) and what to do, with exit code 2."""

from __future__ import annotations

import re

import pytest

from .conftest import FIXTURES, run_cli

LISTS = FIXTURES / "lists"
AXIS = LISTS / "achsmds1.lis"
PORTAL = FIXTURES / "machines" / "portal"
STARTUP = PORTAL / "listen" / "hochlauf.lis"


def one_line(result) -> str:
    err = result.stderr.decode()
    assert result.returncode == 2, (result.returncode, err)
    assert err.count("\n") == 1 and err.startswith("achslint: "), err
    assert "Traceback" not in err and "internal error" not in err, err
    return err


# internal names: a missing argument is named as the help shows it, a bad number in plain words ---------------


@pytest.mark.parametrize(
    ("args", "shown"),
    [
        (["explain"], "TARGET"),
        (["rule"], "CODE"),
        (["diff", str(AXIS)], "B"),
        (["dry-run"], "FILE"),
        (["fmt"], "PATH..."),
        (["lint"], "PATH..."),
    ],
)
def test_a_missing_argument_is_named_as_the_help_names_it(args, shown):
    message = one_line(run_cli(*args))
    assert f"missing argument '{shown}'" in message
    help_text = run_cli(args[0], "--help", env={"COLUMNS": "200"}).stdout.decode()
    assert shown in help_text


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["dry-run", str(AXIS), "--gear", "x"], "'x' is not a whole number"),
        (["lint", str(LISTS), "-j", "x"], "'x' is not a whole number"),
        (["dry-run", str(AXIS), "--start", "abc"], "'abc' is not a number"),
    ],
)
def test_a_bad_number_is_told_in_plain_words(args, words):
    message = one_line(run_cli(*args))
    assert words in message
    assert "int range" not in message and "float" not in message


def test_no_help_shows_the_type_names_of_the_code():
    """(An argument's column shows its type as typer prints it; the options are ours to name.)"""
    for command in ("lint", "fmt", "explain", "dry-run", "diff", "report", "config", "schema", "rules"):
        text = run_cli(command, "--help", env={"COLUMNS": "200"}).stdout.decode().split("Options", 1)[-1]
        assert "<int range>" not in text and "<float>" not in text and "<str>" not in text, command


def test_a_mistyped_option_gets_a_did_you_mean():
    message = one_line(run_cli("lint", str(LISTS), "--formt", "json"))
    assert "no such option: --formt" in message and "did you mean --format?" in message
    assert "Possible options" not in message


def test_an_option_without_its_value_points_at_the_commands_help():
    message = one_line(run_cli("lint", "--select"))
    assert "option '--select' requires an argument" in message
    assert "(see `achslint lint --help`)" in message


# options that do not go together name the options given ----------------------------------------------------


def test_diff_with_add_noqa_names_diff():
    message = one_line(run_cli("lint", str(LISTS), "--diff", "--add-noqa"))
    assert "--diff and --add-noqa do not go together" in message


# numbers that are no numbers ------------------------------------------------------------------------------


@pytest.mark.parametrize("option", ["--cycle-time-ms", "--repeatability-tolerance-um"])
@pytest.mark.parametrize("value", ["nan", "inf"])
def test_lint_refuses_a_number_that_is_not_finite(option, value):
    message = one_line(run_cli("lint", str(LISTS), option, value))
    assert option in message


@pytest.mark.parametrize(
    ("option", "value"),
    [
        ("--zero-pulse-period", "-1"),
        ("--cam-jitter", "-1"),
        ("--start", "nan"),
        ("--fixed-stop", "inf"),
        ("--cycle-time-ms", "0"),
        ("--cam", "5,1"),
        ("--limit-switches", "nan,1"),
    ],
)
def test_dry_run_names_the_option_not_the_scenario_key(option, value):
    message = one_line(run_cli("dry-run", str(AXIS), option, value))
    assert option in message
    assert not re.search(r"`[a-z]+_[a-z_.0-9]+`", message), message  # no scenario key such as `cam_jitter`
    assert "command-line scenario" not in message


# paths that do not exist --------------------------------------------------------------------------------


def test_config_show_of_a_missing_path(tmp_path):
    message = one_line(run_cli("config", "--show", str(tmp_path / "nope")))
    assert "nope: no such file or directory" in message


def test_lint_machine_that_does_not_exist_fails_without_programs(tmp_path):
    result = run_cli("lint", str(LISTS), "--machine", str(tmp_path / "nope.lis"), "--format", "concise")
    message = one_line(result)
    assert "--machine" in message and "nope.lis" in message


@pytest.mark.parametrize(
    "target", ["C:\\machine\\achsmds1.lis", "C:\\machine", "machine/achsmds1.lis", "achsmds9.lis"]
)
def test_explain_of_a_missing_file_says_so(target):
    message = one_line(run_cli("explain", target))
    assert message == f"achslint: {target}: no such file or directory\n"  # as typed: no doubled backslash


# the help itself ---------------------------------------------------------------------------------------


@pytest.mark.parametrize("command", ["server", "schema"])
def test_the_command_list_shows_each_summary_unbroken(command):
    text = run_cli("--help", env={"COLUMNS": "200"}).stdout.decode()
    line = next(line for line in text.splitlines() if f"│ {command} " in line)
    following = text.splitlines()[text.splitlines().index(line) + 1]
    assert following.strip("│ ").startswith(("─", "╰")) or re.match(r"│ \w", following), following


def test_dry_run_help_gives_units_and_the_start_up_list():
    text = " ".join(run_cli("dry-run", "--help", env={"COLUMNS": "400"}).stdout.decode().split())
    assert "start-up list" in text.split("Options")[0]  # the argument takes one with --program
    for option in ("--start", "--cam ", "--zero-pulse-period", "--fixed-stop", "--cam-jitter"):
        described = text.split(option, 1)[1][:200]
        assert "mm or degrees" in described or "mm or °" in described, option


def test_every_option_of_every_command_is_in_the_readme():
    """Each option a command takes (hidden old spellings aside) is named in the README."""
    import typer

    from achslint.cli import app

    from .conftest import ROOT

    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    missing = [
        f"{name} {option}"
        for name, command in typer.main.get_command(app).commands.items()
        for param in command.params
        if not getattr(param, "hidden", False)
        for option in [*param.opts, *param.secondary_opts]
        if option.startswith("--")
        and option != "--help"
        and not re.search(re.escape(option) + r"(?![\w-])", readme)
    ]
    assert not missing, missing
