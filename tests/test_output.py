"""What every command prints goes through `achslint.output` (issue 23 item 6): one registry per command from
`--format` to a renderer, the CLI only picks the entry; a command's output module loads only when that
command runs, so a lint never pays for explain's or dry-run's renderers."""

from __future__ import annotations

import io
import json
import subprocess
import sys
from enum import Enum
from pathlib import Path

import pytest

from achslint.catalogue import catalogue
from achslint.cli import ExplainFormat, ExplainOutput
from achslint.explanation import explain_list, parameter_card
from achslint.listdiff import diff_lists
from achslint.output import FORMATS, OutputFailed, Screen
from achslint.output import diff as diff_output
from achslint.output import dryrun as dryrun_output
from achslint.output import explain as explain_output
from achslint.output import machine as machine_output
from achslint.output.plot import write_plot

from .conftest import FIXTURES, run_cli

LIST = FIXTURES / "lists" / "achsmds1.lis"
OTHER = FIXTURES / "lists" / "achsmds2.lis"

REGISTRIES = {
    "explain LIST": explain_output.LIST,
    "explain PARAM": explain_output.PARAMETER,
    "explain STARTUP": explain_output.MACHINE,
    "dry-run": dryrun_output.RENDERERS,
    "dry-run --program": machine_output.RENDERERS,
    "diff": diff_output.RENDERERS,
}


def _choices(option: type[Enum]) -> list[str]:
    return [member.value for member in option]


@pytest.mark.parametrize("command", REGISTRIES)
def test_every_format_the_cli_offers_has_a_renderer(command: str) -> None:
    assert _choices(ExplainFormat) == list(FORMATS)
    # explain also writes Markdown (the CI job page summary); the other commands text and JSON
    offered = _choices(ExplainOutput) if command.startswith("explain") else list(FORMATS)
    assert sorted(REGISTRIES[command]) == sorted(offered)


def _rendered(render, report) -> str:  # type: ignore[no-untyped-def]
    stream = io.StringIO()
    render(report, Screen(file=stream))
    return stream.getvalue()


def test_the_cli_prints_what_the_registry_renders() -> None:
    """The CLI adds nothing of its own: its output is the renderer's, byte for byte, in both formats."""
    report = explain_list(LIST.read_bytes(), str(LIST))
    card = parameter_card(catalogue().find("vb_reflow"))  # type: ignore[arg-type]
    diff = diff_lists(LIST.read_bytes(), str(LIST), OTHER.read_bytes(), str(OTHER))
    cases = [
        (["explain", str(LIST)], explain_output.LIST, report),
        (["explain", "vb_reflow"], explain_output.PARAMETER, card),
        (["diff", str(LIST), str(OTHER)], diff_output.RENDERERS, diff),
    ]
    for args, registry, document in cases:
        for fmt in FORMATS:
            done = run_cli(*args, "--format", fmt)
            assert done.stdout.decode("utf-8") == _rendered(registry[fmt], document), (args, fmt)
    assert json.loads(_rendered(explain_output.PARAMETER["json"], card))["p_axis"] == card["p_axis"]


def test_a_screen_writes_bytes_after_the_text_before_them() -> None:
    """Formatted standard input (bytes) comes after the text already written to the stream, even text
    still waiting in the stream's buffer, never before it."""
    raw = io.BytesIO()
    stream = io.TextIOWrapper(raw, encoding="utf-8")
    screen = Screen(file=stream)
    screen.echo("--- a.lis", newline=False)
    screen.echo(" (fixed)")
    stream.write("+++ b.lis\n")  # not flushed yet
    screen.write_bytes(b"kenngr.antr_typ 2\n")
    assert raw.getvalue() == b"--- a.lis (fixed)\n+++ b.lis\nkenngr.antr_typ 2\n"


def test_a_piped_screen_neither_colours_nor_wraps_and_draws_tables_160_wide() -> None:
    from rich.table import Table

    stream = io.StringIO()
    screen = Screen(file=stream)
    screen.console.print("[bold]x[/bold] " + "y" * 300)
    table = Table("parameter")
    table.add_row("z" * 150)  # folded at the 80 columns rich assumes for a pipe
    screen.console.print(table)
    lines = stream.getvalue().splitlines()
    assert lines[0] == "x " + "y" * 300
    assert any("z" * 150 in line for line in lines) and "\x1b" not in stream.getvalue()


@pytest.mark.parametrize(
    ("error", "shown"),
    [
        (FileNotFoundError(2, "No such file or directory"), "cannot write the plot to out.png: "),
        (PermissionError(13, "Permission denied"), "cannot write the plot to out.png: "),
    ],
)
def test_a_plot_that_cannot_be_written_is_one_line(error: OSError, shown: str) -> None:
    def draw(target: str) -> None:
        raise error

    with pytest.raises(OutputFailed) as failed:
        write_plot(draw, "out.png")
    assert str(failed.value).startswith(shown) and "\n" not in str(failed.value)


def test_a_plot_file_name_that_is_no_image_is_refused_before_drawing(tmp_path: Path) -> None:
    from achslint.output.plot import plot_trace

    drawn: list[str] = []

    def draw(target: str) -> None:
        drawn.append(target)
        plot_trace(None, target)  # type: ignore[arg-type]  # refused on the name, before the trace is read

    with pytest.raises(OutputFailed, match=r"--plot needs a \.png or \.svg file name, not '.*plot\.txt'"):
        write_plot(draw, str(tmp_path / "plot.txt"))
    assert drawn and not (tmp_path / "plot.txt").exists()


# The output modules each command loads, in the order the probe runs them; none loads another's (start-up
# time: a lint never imports explain's or dry-run's renderers).
LOADED_BY = {
    "--version": set(),
    "lint": {"output.lint", "output.reporters.concise"},
    "fmt": {"output.fmt"},
    "explain": {"output.explain"},
    "diff": {"output.diff"},
    "dry-run": {"output.dryrun", "output.plot"},
}
ALWAYS = {"output", "output.reporters"}  # lint's --format choices come from the registry


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_a_command_loads_only_its_own_output_module(tmp_path: Path) -> None:
    """One process runs the commands one after another; what each loads on top of the ones before is its own
    output module (so a command's module cannot hide behind an earlier command's)."""
    runs = {
        "--version": ["--version"],
        "lint": ["lint", str(LIST)],
        "fmt": ["fmt", "--check", str(LIST)],
        "explain": ["explain", str(LIST)],
        "diff": ["diff", str(LIST), str(OTHER)],
        "dry-run": ["dry-run", str(LIST)],
    }
    probe = (
        "import contextlib, io, json, sys\n"
        "from achslint.cli import main\n"
        "def loaded():\n"
        "    return {m.removeprefix('achslint.') for m in sys.modules if m.startswith('achslint.output')}\n"
        "found = {'import': sorted(loaded())}\n"
        "for name, args in json.loads(sys.argv[1]).items():\n"
        "    before = loaded()\n"
        "    with contextlib.redirect_stdout(io.StringIO()):\n"
        "        code = main(args)\n"
        "    found[name] = [code, sorted(loaded() - before)]\n"
        "print(json.dumps(found))\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", probe, json.dumps(runs)],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=60,
    )
    found = json.loads(done.stdout.splitlines()[-1])
    assert set(found.pop("import")) == ALWAYS
    assert {name: set(new) for name, (_, new) in found.items()} == LOADED_BY, done.stderr
    assert all(code in (0, 1) for code, _ in found.values()), done.stderr
