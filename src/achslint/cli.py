"""Command-line interface: flags -> settings -> api call -> exit code.

Heavy imports (lark, rich, pydantic, the rules) happen inside the commands so
that `--help` and `--version` stay fast.
"""

from __future__ import annotations

import os
import sys
from enum import Enum
from pathlib import Path
from typing import List, Optional

import typer

from . import __version__

EXIT_OK, EXIT_FINDINGS, EXIT_ERROR = 0, 1, 2

app = typer.Typer(
    add_completion=False,
    no_args_is_help=True,
    help="Lint, explain and check TwinCAT 3 CNC / ISG CNC axis parameter lists (achsmds*.lis).",
    context_settings={"help_option_names": ["-h", "--help"]},
    pretty_exceptions_enable=False,
)


class OutputFormat(str, Enum):
    full = "full"
    concise = "concise"
    json = "json"


class FailOn(str, Enum):
    error = "error"
    warning = "warning"
    info = "info"


class Color(str, Enum):
    auto = "auto"
    always = "always"
    never = "never"


class UnknownParameters(str, Enum):
    warn = "warn"
    error = "error"
    ignore = "ignore"


class UsageError(Exception):
    """A problem with what the user asked for: exit code 2 with a one-line message."""


def _fail(message: str) -> None:
    typer.echo(f"achslint: {message}", err=True)
    raise typer.Exit(EXIT_ERROR)


def _codes(values: Optional[List[str]]) -> list[str]:
    codes: list[str] = []
    for value in values or []:
        codes.extend(part.strip().upper() for part in value.split(",") if part.strip())
    return codes


def _use_color(choice: Color, stream) -> bool:
    if choice == Color.always:
        return True
    if choice == Color.never or os.environ.get("NO_COLOR"):
        return False
    if os.environ.get("FORCE_COLOR"):
        return True
    return hasattr(stream, "isatty") and stream.isatty()


def version_callback(value: bool) -> None:
    if value:
        typer.echo(f"achslint {__version__}")
        raise typer.Exit()


@app.callback()
def main_callback(
    version: bool = typer.Option(False, "--version", callback=version_callback, is_eager=True, help="Show the version and exit."),
) -> None:
    """achslint: the linter for CNC axis parameter lists."""


@app.command()
def lint(
    paths: List[str] = typer.Argument(..., help="Files, directories (searched recursively) or - for standard input."),
    output_format: Optional[OutputFormat] = typer.Option(None, "--format", "--output-format", help="Output format (default: full on a terminal, concise otherwise)."),
    select: Optional[List[str]] = typer.Option(None, "--select", help="Only these rule codes or prefixes (comma-separated, e.g. LIS1,LIS202)."),
    extend_select: Optional[List[str]] = typer.Option(None, "--extend-select", help="Add rule codes or prefixes to the selection."),
    ignore: Optional[List[str]] = typer.Option(None, "--ignore", help="Skip these rule codes or prefixes."),
    fail_on: FailOn = typer.Option(FailOn.error, "--fail-on", help="Lowest severity that makes the exit code 1."),
    exit_zero: bool = typer.Option(False, "--exit-zero", help="Exit 0 even when diagnostics are found."),
    unknown_parameters: UnknownParameters = typer.Option(UnknownParameters.warn, "--unknown-parameters", help="How to report unknown parameter names."),
    include: str = typer.Option("achsmds*.lis", "--include", help="File name pattern used when searching directories."),
    cycle_time_us: int = typer.Option(1000, "--cycle-time-us", min=1, help="CNC cycle time in µs (for LIS403)."),
    repeatability_tolerance_um: float = typer.Option(20.0, "--repeatability-tolerance-um", min=0.0, help="Required homing repeatability in µm (for LIS403)."),
    stdin_filename: Optional[str] = typer.Option(None, "--stdin-filename", help="Name to report for input read from -."),
    color: Color = typer.Option(Color.auto, "--color", help="Colour the full output (honours NO_COLOR and FORCE_COLOR)."),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="Print nothing; only the exit code tells the result."),
    statistics: bool = typer.Option(False, "--statistics", help="Print the number of diagnostics per rule code."),
    debug: bool = typer.Option(False, "--debug", help="Show a traceback on internal errors."),
) -> None:
    """Lint axis parameter lists."""
    from .api import LintRequest, run_lint

    request = LintRequest(
        paths=paths,
        select=_codes(select) or None,
        extend_select=_codes(extend_select),
        ignore=_codes(ignore),
        unknown_parameters=unknown_parameters.value,
        include=include,
        cycle_time_us=cycle_time_us,
        repeatability_tolerance_um=repeatability_tolerance_um,
        stdin_filename=stdin_filename,
    )
    fmt = output_format.value if output_format else ("full" if sys.stdout.isatty() else "concise")
    try:
        outcome = run_lint(request, stdin=sys.stdin.buffer if "-" in paths else None)
    except UsageError as exc:
        _fail(str(exc))
    for message in outcome.errors:
        typer.echo(f"achslint: {message}", err=True)
    if not quiet:
        from .reporters import get

        get(fmt)(outcome.results, sys.stdout, color=_use_color(color, sys.stdout), sources=outcome.sources)
        if statistics:
            _print_statistics(outcome.results)
    if outcome.errors:
        raise typer.Exit(EXIT_ERROR)
    from .diagnostics import Severity

    threshold = Severity(fail_on.value).rank
    failing = any(d.severity.rank >= threshold for r in outcome.results for d in r.diagnostics)
    raise typer.Exit(EXIT_FINDINGS if failing and not exit_zero else EXIT_OK)


def _print_statistics(results) -> None:
    from collections import Counter

    from .rules import registry

    counts = Counter(d.code for r in results for d in r.diagnostics)
    rules = registry()
    for code, count in sorted(counts.items(), key=lambda item: (-item[1], item[0])):
        rule = rules.get(code)
        name = rule.name if rule else ""
        typer.echo(f"{count:6d}  {code}  {name}")


@app.command()
def rules() -> None:
    """List every rule with its code, name, default severity and fix."""
    from .docs import rules_table

    typer.echo(rules_table())


@app.command()
def rule(code: str = typer.Argument(..., help="Rule code, e.g. LIS202.")) -> None:
    """Show the documentation of one rule."""
    from .docs import rule_text
    from .rules import registry

    found = registry().get(code.strip().upper())
    if found is None:
        _fail(f"unknown rule code {code!r}; `achslint rules` lists them")
    typer.echo(rule_text(found))


class ExplainFormat(str, Enum):
    text = "text"
    json = "json"


@app.command()
def explain(
    target: str = typer.Argument(..., help="An axis list file, or a parameter: name, alias or id (vb_reflow, getriebe[0].vb_reflow, P-AXIS-00218)."),
    output_format: ExplainFormat = typer.Option(ExplainFormat.text, "--format", "--output-format", help="text or json."),
    gear: int = typer.Option(0, "--gear", min=0, max=5, help="Gear stage whose homing speeds are shown."),
    color: Color = typer.Option(Color.auto, "--color", help="Colour the text output."),
) -> None:
    """Explain the homing configuration of a list, or describe one parameter."""
    import json
    from pathlib import Path

    from .explain import explain_list, parameter_card, render_card, render_list

    path = Path(target)
    if path.is_file():
        try:
            report = explain_list(path.read_bytes(), target, gear)
        except OSError as exc:
            _fail(f"cannot read {target}: {exc.strerror or exc}")
        except Exception as exc:  # noqa: BLE001 - UnreadableInput and friends become one line
            from .decode import UnreadableInput

            if isinstance(exc, UnreadableInput):
                _fail(f"{target}: {exc}")
            raise
        render = render_list
    else:
        from .catalogue import catalogue

        parameter = catalogue().find(target)
        if parameter is None:
            hint = ""
            suggestions = catalogue().suggest(target)
            if suggestions:
                hint = "; did you mean " + ", ".join(f"`{s}`" for s in suggestions) + "?"
            _fail(f"{target!r} is neither a file nor a known parameter{hint}")
        report = parameter_card(parameter)
        render = render_card
    if output_format == ExplainFormat.json:
        typer.echo(json.dumps(report, indent=2, ensure_ascii=False))
        return
    from rich.console import Console

    use = _use_color(color, sys.stdout)
    render(report, Console(force_terminal=use, no_color=not use, highlight=False, width=160 if not sys.stdout.isatty() else None))


@app.command()
def schema() -> None:
    """Print the JSON Schema of the axis parameter model."""
    import json

    from .model import json_schema

    typer.echo(json.dumps(json_schema(), indent=2, ensure_ascii=False))


def main() -> None:
    """Console-script entry point: never lets a traceback reach the user unless --debug."""
    debug = "--debug" in sys.argv
    try:
        app(standalone_mode=True)
    except SystemExit:
        raise
    except KeyboardInterrupt:
        typer.echo("achslint: interrupted", err=True)
        sys.exit(EXIT_ERROR)
    except Exception as exc:  # noqa: BLE001 - the last line of defence
        if debug:
            raise
        typer.echo(f"achslint: internal error: {type(exc).__name__}: {exc} (run with --debug for details)", err=True)
        sys.exit(EXIT_ERROR)
