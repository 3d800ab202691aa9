"""Command-line interface: flags -> request or settings -> library call -> output registry -> exit code.

What a command prints is rendered in `achslint.output` (a registry per command from `--format` to
renderer); here are only the options, the one-line failures and the exit codes. Heavy imports (lark,
rich, pydantic, the rules, a command's output module) happen inside the commands so that `--help` and
`--version` stay fast.
"""

# No `from __future__ import annotations` here: typer reads every option's annotation, and string
# annotations would each be compiled and evaluated on every run (a third of building the lint command).
import contextlib
import copy
import functools
import gc
import math
import os
import re
import sys
from collections.abc import Callable, Iterable, Sequence
from enum import Enum
from pathlib import Path
from typing import TYPE_CHECKING, Any, NoReturn, TextIO, get_args

from .core import codecache, streams

# Set up the process for a short command-line run before the modules below load:
# - the code of the dataclass methods comes from the per-user cache (core/codecache.py);
# - the collector runs after every 50,000 new objects, not 700: a run mostly makes objects that live until
#   it ends (modules, classes, the catalogue), and walking them again and again was 3 % of a cold lint.
codecache.install()
gc.set_threshold(50_000, 10, 10)

import typer  # noqa: E402

from . import __version__  # noqa: E402
from .catalogue.kinds import CONTENT_KINDS  # noqa: E402
from .homing.scenario import CYCLE_TIME_US  # noqa: E402
from .linting.config import MAX_TOLERANCE_UM, SeverityName  # noqa: E402
from .linting.config import UnknownParameters as UnknownParametersChoice  # noqa: E402
from .output.reporters import REPORTERS  # noqa: E402

EXIT_OK, EXIT_FINDINGS, EXIT_ERROR = 0, 1, 2

app = typer.Typer(
    add_completion=True,
    no_args_is_help=True,
    help="Lint, explain and check TwinCAT 3 CNC / ISG CNC axis parameter lists (achsmds*.lis).",
    context_settings={"help_option_names": ["-h", "--help"]},
    pretty_exceptions_enable=False,
)


def _choices(name: str, values: Iterable[str]) -> type[Enum]:
    """A choice option's values as the Enum typer wants, taken from where they are defined."""
    return Enum(name, {value: value for value in values}, type=str)  # type: ignore[return-value]


if TYPE_CHECKING:
    from .catalogue import Catalogue
    from .explanation import Found
    from .linting.run import LintOutcome, LintRequest
    from .output import Screen

if TYPE_CHECKING:  # for the type checker these are plain enums; typer needs the real classes below
    OutputFormat = Enum
    FailOn = Enum
    UnknownParameters = Enum
    ListKind = Enum
else:
    OutputFormat = _choices("OutputFormat", REPORTERS)
    FailOn = _choices("FailOn", get_args(SeverityName))
    UnknownParameters = _choices("UnknownParameters", get_args(UnknownParametersChoice))
    ListKind = _choices("ListKind", (kind.id for kind in CONTENT_KINDS))  # one per catalogue


class Color(str, Enum):
    auto = "auto"
    always = "always"
    never = "never"


class UsageError(Exception):
    """A problem with what the user asked for: exit code 2 with a one-line message."""

    # (raised by our own option checks; click's usage errors are turned into the same one line in `main`)


def _say(message: str) -> None:
    """One line on stderr, with control characters from file names and lists shown escaped."""
    from .core.display import printable

    typer.echo(f"achslint: {printable(message)}", err=True)


def _fail(message: str) -> NoReturn:
    _say(message)
    raise typer.Exit(EXIT_ERROR)


def _codes(values: list[str] | None, option: str) -> list[str]:
    from .linting.config import parse_codes

    try:
        return parse_codes(values or [])
    except ValueError as exc:
        raise UsageError(f"{option}: {exc}") from None


def _folder(text: str, option: str) -> str:
    """An existing folder given on the command line, made absolute."""
    from .core.files import is_folder

    if not is_folder(Path(text)):
        raise UsageError(f"{option} {text}: not a folder")
    return os.path.abspath(text)


def _use_color(choice: Color, stream: TextIO) -> bool:
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
    version: bool = typer.Option(
        False, "--version", callback=version_callback, is_eager=True, help="Show the version and exit."
    ),
) -> None:
    """achslint: the linter for CNC axis parameter lists."""


def _default_format(stream: TextIO) -> str:
    if os.environ.get("GITHUB_ACTIONS") == "true":
        return "github"
    return "full" if stream.isatty() else "concise"


@app.command()
def lint(
    paths: list[str] = typer.Argument(
        ..., metavar="PATH...", help="Files, directories (searched recursively) or - for standard input."
    ),
    output_format: OutputFormat | None = typer.Option(
        None,
        "--format",
        "--output-format",
        help="Output format (default: github under GitHub Actions, full on a terminal, concise otherwise).",
    ),
    config: str | None = typer.Option(
        None, "--config", metavar="FILE", help="Use this configuration file instead of searching for one."
    ),
    select: list[str] | None = typer.Option(
        None,
        "--select",
        metavar="CODES",
        help="Only these rule codes or prefixes (comma-separated, e.g. LIS1,LIS202).",
    ),
    extend_select: list[str] | None = typer.Option(
        None, "--extend-select", metavar="CODES", help="Add rule codes or prefixes to the selection."
    ),
    ignore: list[str] | None = typer.Option(
        None, "--ignore", metavar="CODES", help="Skip these rule codes or prefixes."
    ),
    fail_on: FailOn | None = typer.Option(
        None, "--fail-on", help="Lowest severity that makes the exit code 1 (default: error)."
    ),
    exit_zero: bool = typer.Option(False, "--exit-zero", help="Exit 0 even when diagnostics are found."),
    fix: bool = typer.Option(
        False, "--fix", help="Apply safe fixes (End -> Ende, BOM, old names, unambiguous typos)."
    ),
    unsafe_fixes: bool = typer.Option(False, "--unsafe-fixes", help="With --fix, also apply unsafe fixes."),
    show_diff: bool = typer.Option(
        False, "--diff", help="Print the changes --fix would make as a diff; writes nothing."
    ),
    unknown_parameters: UnknownParameters | None = typer.Option(
        None, "--unknown-parameters", help="How to report unknown parameter names (default: warn)."
    ),
    include: list[str] | None = typer.Option(
        None,
        "--include",
        metavar="PATTERN",
        help="File name patterns searched in folders, repeated or comma-separated (default: achsmds*.lis; axis XML is found by content).",
    ),
    extend_exclude: list[str] | None = typer.Option(
        None,
        "--extend-exclude",
        metavar="PATTERN",
        help="Paths to leave out, in addition to `exclude` from the configuration.",
    ),
    force_exclude: bool = typer.Option(
        False,
        "--force-exclude",
        help="Apply the exclude patterns to files named on the command line too (for pre-commit).",
    ),
    respect_gitignore: bool = typer.Option(
        True,
        "--respect-gitignore/--no-respect-gitignore",
        help="Leave out files git ignores when searching folders.",
    ),
    cycle_time_ms: float | None = typer.Option(
        None,
        "--cycle-time-ms",
        metavar="MS",
        min=CYCLE_TIME_US[0] / 1000,
        max=CYCLE_TIME_US[1] / 1000,
        help="CNC cycle time in ms, as in dry-run (for LIS403; default 1).",
    ),
    cycle_time_us: int | None = typer.Option(
        None,
        "--cycle-time-us",
        min=CYCLE_TIME_US[0],
        max=CYCLE_TIME_US[1],
        hidden=True,
        help="The cycle time in µs (old spelling of --cycle-time-ms).",
    ),
    repeatability_tolerance_um: float | None = typer.Option(
        None,
        "--repeatability-tolerance-um",
        metavar="UM",
        min=0.0,
        max=MAX_TOLERANCE_UM,
        help="Required homing repeatability in µm (for LIS403; default 20).",
    ),
    stdin_filename: str | None = typer.Option(
        None,
        "--stdin-filename",
        metavar="NAME",
        help="Name to report (and to find the configuration) for input read from -.",
    ),
    jobs: int | None = typer.Option(
        None, "--jobs", "-j", metavar="N", min=1, help="Worker processes (default: all cores for large runs)."
    ),
    color: Color = typer.Option(
        Color.auto, "--color", help="Colour the full output (honours NO_COLOR and FORCE_COLOR)."
    ),
    quiet: bool = typer.Option(
        False, "--quiet", "-q", help="Print the diagnostics only: no summary, notes or progress."
    ),
    silent: bool = typer.Option(
        False, "--silent", "-s", help="Print nothing but errors; only the exit code tells the result."
    ),
    statistics: bool = typer.Option(
        False, "--statistics", help="Print only the number of diagnostics per rule code."
    ),
    output_file: str | None = typer.Option(
        None,
        "--output-file",
        "-o",
        metavar="FILE",
        help="Write the report to FILE (UTF-8) instead of standard output.",
    ),
    debug: bool = typer.Option(False, "--debug", help="Show a traceback on internal errors."),
    allow_empty: bool = typer.Option(
        False, "--allow-empty", help="Exit 0 when the paths hold no list at all (default: exit 2)."
    ),
    docs_url: str | None = typer.Option(
        None,
        "--docs-url",
        metavar="URL",
        help="Address of the rule documentation page for links in json and sarif output (default: `docs-url` from the configuration, else the project's docs site).",
    ),
    cnc_root: str | None = typer.Option(
        None,
        "--cnc-root",
        metavar="DIR",
        help="The CNC's working directory: start-up list entries (./listen/achsmds1.lis) are resolved against it (default: the nearest folder above the start-up list where they exist).",
    ),
    machine: str | None = typer.Option(
        None,
        "--machine",
        metavar="STARTUP",
        help="Start-up list (hochlauf.lis) of the machine the NC programs among PATH (rfp.nc) are checked against (LIS6xx).",
    ),
    channel: int = typer.Option(
        1,
        "--channel",
        metavar="N",
        min=1,
        max=12,
        help="With --machine: the channel whose axis names the programs use.",
    ),
    follow_startup: bool = typer.Option(
        False,
        "--follow-startup",
        help="With --fix: also rewrite the lists a named start-up list reaches outside the paths given.",
    ),
    add_noqa: bool = typer.Option(
        False,
        "--add-noqa",
        help="Write a `noqa` comment for every finding into the lists (to adopt achslint on a machine as it is).",
    ),
    show_files: bool = typer.Option(
        False, "--show-files", help="Print the files that would be linted (kind, machine) and exit."
    ),
    show_settings: bool = typer.Option(
        False,
        "--show-settings",
        help="Print the settings for the first PATH (TOML; JSON with --format json) and exit.",
    ),
    watch: bool = typer.Option(False, "--watch", "-w", help="Lint again whenever a file changes."),
) -> None:
    """Lint axis parameter lists, and homing programs (rfp.nc) against a machine (--machine)."""
    from .linting.config import ConfigError, Overrides
    from .linting.run import LintRequest, OutputIsInput, run_lint  # what `api` re-exports, without fmt
    from .output import OutputFailed
    from .output import lint as shown

    for option, number in (
        ("--cycle-time-ms", cycle_time_ms),
        ("--repeatability-tolerance-um", repeatability_tolerance_um),
    ):
        if number is not None and not math.isfinite(number):  # (nan passes click's range check)
            _fail(f"{option} {number}: give a finite number")
    try:
        overrides = Overrides(
            select=_codes(select, "--select") or None,
            extend_select=_codes(extend_select, "--extend-select"),
            ignore=_codes(ignore, "--ignore"),
            fail_on=fail_on.value if fail_on else None,
            unknown_parameters=unknown_parameters.value if unknown_parameters else None,
            cycle_time_us=round(cycle_time_ms * 1000) if cycle_time_ms is not None else cycle_time_us,
            repeatability_tolerance_um=repeatability_tolerance_um,
            include=_patterns(include),
            extend_exclude=_patterns(extend_exclude),
            cnc_root=_folder(cnc_root, "--cnc-root") if cnc_root is not None else None,
        )
    except UsageError as exc:
        _fail(str(exc))
    fixing = {"fix" if fix or not show_diff else "diff": fix or show_diff}  # the one the user typed
    fix = fix or show_diff  # as in ruff: --diff shows what --fix would do
    if unsafe_fixes and not fix:
        _fail("--unsafe-fixes goes with --fix or --diff")
    _one_mode(**fixing, add_noqa=add_noqa, show_files=show_files, show_settings=show_settings, watch=watch)
    if (add_noqa or watch) and "-" in paths:
        _fail(f"{'--add-noqa' if add_noqa else '--watch'} reads files: it cannot take standard input (-)")
    fmt = output_format.value if output_format else _default_format(sys.stdout)
    request = LintRequest(
        paths=paths,
        overrides=overrides,
        config_file=config,
        stdin_filename=stdin_filename,
        jobs=jobs,
        fix=fix,
        unsafe_fixes=unsafe_fixes,
        show_diff=show_diff,
        keep_source=REPORTERS[fmt].needs_source,
        force_exclude=force_exclude,
        respect_gitignore=respect_gitignore,
        machine=machine,
        channel=channel,
        output=output_file if not silent else None,
        follow_startup=follow_startup,
        add_noqa=add_noqa,
    )
    quiet = quiet or silent
    if show_files or show_settings:
        _show(request, show_files, fmt)
    if watch:
        _watch(
            request,
            lambda: _lint_once(request, fmt, color, docs_url, config, quiet, silent, statistics),
            output_file,
        )
    try:
        with shown.progress(quiet) as progress:
            outcome = run_lint(request, stdin=sys.stdin.buffer if "-" in paths else None, progress=progress)
    except (ConfigError, OutputIsInput) as exc:
        _fail(str(exc))
    _tell(outcome.errors, outcome.notes, quiet)
    if machine is not None and not any("--machine" in error for error in outcome.errors):
        _machine_readable(machine)  # read only for the programs among PATH: without them, checked here
    if not outcome.results and not outcome.skipped and not outcome.errors and not allow_empty:
        _fail(_nothing_found(paths, outcome.excluded))
    if add_noqa:  # as in ruff: what was added, on stderr; exit 0 unless a list could not be read or written
        if not quiet:
            typer.echo(shown.noqa_count(outcome.results), err=True)
        raise typer.Exit(EXIT_ERROR if outcome.errors else EXIT_OK)
    report_stream = sys.stdout
    if fix:
        report_stream = shown.write_fixes(outcome.results, show_diff)
        if not quiet:
            typer.echo(shown.fix_count(outcome.results, show_diff), err=True)
    if not silent:
        try:
            _lint_report(
                outcome, fmt, output_file, report_stream, color, docs_url, config, statistics, quiet, fix
            )
        except OutputFailed as exc:
            _fail(str(exc))
    if outcome.errors:
        raise typer.Exit(EXIT_ERROR)
    raise typer.Exit(EXIT_FINDINGS if outcome.failing and not exit_zero else EXIT_OK)


def _machine_readable(machine: str) -> None:
    """Exit 2 when --machine names no file achslint can read (a mistyped name must not pass unseen)."""
    from .core.files import not_a_list_file

    problem = not_a_list_file(Path(machine), what="a start-up list")
    if problem is not None:
        _fail(f"--machine {machine}: {problem}; give the start-up list (hochlauf.lis) of the machine")


def _one_mode(**modes: bool) -> None:
    """--fix, --add-noqa, --show-files, --show-settings and --watch each make a run of its own kind."""
    chosen = [f"--{name.replace('_', '-')}" for name, given in modes.items() if given]
    if len(chosen) > 1:
        _fail(f"{' and '.join(chosen)} do not go together; give one of them")


def _show(request: "LintRequest", files: bool, fmt: str) -> NoReturn:
    """--show-files: what the run would lint, one file a line; --show-settings: the settings of the first
    path (with the command line applied), as TOML, or JSON with --format json."""
    from .linting.config import ConfigError
    from .linting.run import files_to_lint, settings_for
    from .output import config as shown

    screen = _screen(Color.never)
    try:
        if files:
            shown.files(files_to_lint(request), screen)
        else:
            resolved, settings = settings_for(request)
            shown.settings(resolved, settings, "json" if fmt == "json" else "toml", screen)
    except ConfigError as exc:
        _fail(str(exc))
    raise typer.Exit(EXIT_OK)


def _lint_report(
    outcome: "LintOutcome",
    fmt: str,
    output: str | None,
    fallback: TextIO,
    color: Color,
    docs_url: str | None,
    config: str | None,
    statistics: bool,
    quiet: bool,
    fixing: bool,
) -> None:
    """The lint report in `fmt`, to `output` (a file) or else `fallback`; raises `OutputFailed`."""
    from .output import lint as shown

    with shown.destination(output, fallback) as stream:
        shown.write_report(
            outcome.results,
            fmt,
            stream,
            color=_use_color(color, stream),
            sources=outcome.sources,
            docs_url=lambda: _docs_url(docs_url, config),
            statistics=statistics,
            quiet=quiet,
            fixing=fixing,
            failed=bool(outcome.errors),
        )


def _lint_once(
    request: "LintRequest",
    fmt: str,
    color: Color,
    docs_url: str | None,
    config: str | None,
    quiet: bool,
    silent: bool,
    statistics: bool,
) -> None:
    """One run of --watch: the report as `lint` writes it, or the one-line errors (the watch goes on)."""
    from .linting.config import ConfigError, forget_cached
    from .linting.run import OutputIsInput, run_lint
    from .output import OutputFailed

    forget_cached()  # a configuration may have changed since the last run
    try:
        outcome = run_lint(request)
    except (ConfigError, OutputIsInput) as exc:
        _say(str(exc))
        return
    _tell(outcome.errors, outcome.notes, quiet)
    if silent:
        return
    try:
        _lint_report(
            outcome, fmt, request.output, sys.stdout, color, docs_url, config, statistics, quiet, False
        )
    except OutputFailed as exc:
        _say(str(exc))
    sys.stdout.flush()


def _watch(
    request: "LintRequest", lint_once: "Callable[[], None]", output_file: str | None = None
) -> NoReturn:
    """--watch: lint, then again whenever a file of the run (a list, a configuration, a start-up list, a
    folder named) changes, until interrupted (Ctrl-C: exit 130); the report it writes itself is no change."""
    from .linting.watch import Watcher

    lint_once()  # (first: the output file exists then, and the watcher knows it for its own)
    watcher = Watcher(request.paths, request.config_file, written=[output_file] if output_file else None)
    while True:
        _say("watching for changes (Ctrl-C to stop)")
        watcher.wait()
        lint_once()


def _patterns(values: list[str] | None) -> list[str] | None:
    """Repeated and comma-separated patterns as one list (None when the option was not given)."""
    if not values:
        return None
    return [part.strip() for value in values for part in value.split(",") if part.strip()]


def _machine_inputs(startup: str, config: str | None) -> list[str]:
    from .linting.config import ConfigError
    from .linting.discovery import machine_files

    try:
        return [str(path) for path in machine_files(Path(startup), config_file=config)]
    except ConfigError as exc:
        _fail(str(exc))


def _not_over_inputs(output: str, option: str, inputs: Iterable[str | None]) -> None:
    """Exit 2 when the file an option writes is one of the files the command reads."""
    from .linting.run import OutputIsInput, refuse_output_over_input

    try:
        refuse_output_over_input(output, [Path(path) for path in inputs if path and path != "-"], option)
    except OutputIsInput as exc:
        _fail(str(exc))


def _docs_url(given: str | None, config_file: str | None) -> str | None:
    """--docs-url, else `docs-url` of the configuration for the working directory (a run-wide setting)."""
    if given is not None:
        if not given.startswith(("http://", "https://")):
            _fail(f"--docs-url {given}: give an absolute http(s) address")
        return given
    from .linting.config import ConfigError, discover, load_file

    try:
        return (load_file(Path(config_file)) if config_file else discover(Path.cwd())).settings.docs_url
    except ConfigError as exc:
        _fail(str(exc))


def _nothing_found(paths: list[str], excluded: Sequence[str] = ()) -> str:
    """Why a run that checked nothing fails (a CI job pointed at the wrong folder must not pass)."""
    shown = ", ".join(paths)
    if excluded:  # found, and left out on request: say so rather than send the user looking for them
        left_out = ", ".join(excluded[:3]) + (f" and {len(excluded) - 3} more" if len(excluded) > 3 else "")
        return (
            f"no axis list found in {shown}: {left_out} "
            f"{'is' if len(excluded) == 1 else 'are'} excluded (`exclude` of the configuration or "
            "--extend-exclude, applied to named files by --force-exclude); pass --allow-empty when an "
            "empty run is fine"
        )
    return (
        f"no axis list found in {shown} (folders are searched for the `include` patterns, achsmds*.lis by "
        "default, and for XML exports holding <AchsMds> or <AX_MDS>); check the path or --include, "
        "or pass --allow-empty when an empty run is fine"
    )


def _tell(errors: list[str], notes: list[str], quiet: bool) -> None:
    """Errors always go to stderr; notes (files skipped on purpose) unless --quiet."""
    for message in errors:
        _say(message)
    if not quiet:
        for message in notes:
            _say(f"note: {message}")


@app.command()
def fmt(
    paths: list[str] = typer.Argument(
        ...,
        metavar="PATH...",
        help="Files, directories (searched recursively) or - (formatted to standard output).",
    ),
    check: bool = typer.Option(
        False, "--check", help="Change nothing; exit 1 when a file would be reformatted."
    ),
    diff: bool = typer.Option(
        False, "--diff", help="Print the changes as a unified diff instead of writing them."
    ),
    config: str | None = typer.Option(
        None, "--config", metavar="FILE", help="Use this configuration file instead of searching for one."
    ),
    stdin_filename: str | None = typer.Option(
        None, "--stdin-filename", metavar="NAME", help="Name used for input read from -."
    ),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="Print nothing but errors."),
    allow_empty: bool = typer.Option(
        False, "--allow-empty", help="Exit 0 when the paths hold no list at all (default: exit 2)."
    ),
    follow_startup: bool = typer.Option(
        False,
        "--follow-startup",
        help="Also rewrite the lists a named start-up list reaches outside the paths given.",
    ),
) -> None:
    """Reformat lists canonically (whitespace only; encoding and line endings kept)."""
    from .api import FormatRequest, run_format
    from .linting.config import ConfigError
    from .output import Screen
    from .output import fmt as shown

    mode = "diff" if diff else "check" if check else "write"
    try:
        outcome = run_format(
            FormatRequest(paths, config, stdin_filename, mode, follow_startup), stdin=sys.stdin.buffer
        )
    except ConfigError as exc:
        _fail(str(exc))
    if not outcome.found and not outcome.errors and not allow_empty:
        _tell([], outcome.notes, quiet)
        _fail(_nothing_found(paths))
    shown.write_results(outcome, mode, quiet, Screen(echo=typer.echo))
    _tell(outcome.errors, outcome.notes, quiet)
    closing = shown.summary(outcome, mode, quiet)
    if closing is not None:
        typer.echo(closing, err=True)
    if outcome.errors:
        raise typer.Exit(EXIT_ERROR)
    raise typer.Exit(EXIT_FINDINGS if outcome.changed and mode != "write" else EXIT_OK)


class ExplainFormat(str, Enum):
    text = "text"
    json = "json"


class ExplainOutput(str, Enum):  # explain also writes the Markdown summary of CI job pages
    text = "text"
    json = "json"
    markdown = "markdown"


@app.command()
def rules(
    output_format: ExplainFormat = typer.Option(
        ExplainFormat.text,
        "--format",
        "--output-format",
        help="text (a table) or json (every rule with its documentation).",
    ),
) -> None:
    """List every rule with its code, name, default severity and fix."""
    if output_format == ExplainFormat.json:
        from .docs import rules_document
        from .output import write_json

        write_json(rules_document(), _screen(Color.never))
        return
    from .docs import rules_table

    typer.echo(rules_table())


@app.command()
def rule(code: str = typer.Argument(..., metavar="CODE", help="Rule code, e.g. LIS202.")) -> None:
    """Show the documentation of one rule."""
    from .docs import rule_text
    from .rules import registry

    found = registry().get(code.strip().upper())
    if found is None:
        from .rules.codes import code_hint

        _fail(f"unknown rule code '{code}'; {code_hint(code)}")
    typer.echo(rule_text(found))


@app.command()
def explain(
    target: str = typer.Argument(
        ...,
        metavar="TARGET",
        help="An axis list, a start-up list (the machine), a channel list (the machine, with that channel's "
        "names), or a parameter of any list: name, alias or id (vb_reflow, getriebe[0].vb_reflow, "
        "P-AXIS-00218, P-CHAN-00036).",
    ),
    kind: ListKind | None = typer.Option(
        None,
        "--kind",
        help="With a parameter: look it up in this kind of list (channel, startup, tools ...); "
        "without it an axis parameter wins, then the one kind that knows the name.",
    ),
    output_format: ExplainOutput = typer.Option(
        ExplainOutput.text, "--format", "--output-format", help="text, json or markdown."
    ),
    gear: int = typer.Option(
        0, "--gear", metavar="N", min=0, max=5, help="Gear stage whose homing speeds are shown."
    ),
    color: Color = typer.Option(Color.auto, "--color", help="Colour the text output."),
    program: str | None = typer.Option(
        None, "--program", metavar="NC", help="With a start-up list: show the homing order of this program."
    ),
    channel: int = typer.Option(
        1,
        "--channel",
        metavar="N",
        min=1,
        max=12,
        help="With a start-up list: the channel whose axis names are shown.",
    ),
    cnc_root: str | None = typer.Option(
        None,
        "--cnc-root",
        metavar="DIR",
        help="With a start-up list: the CNC's working directory its entries are resolved against.",
    ),
) -> None:
    """Explain the homing configuration of a list or a machine (start-up list), or describe one parameter."""

    from .core.files import not_a_list_file, shown_path
    from .explanation import default_underneath, explain_list, parameter_card
    from .linting.discovery import is_startup
    from .output import explain as shown

    path = Path(target)
    problem = not_a_list_file(path)
    screen = _screen(color)
    if kind is not None and (problem is None or problem not in NOT_A_FILE):
        _fail("--kind goes with a parameter name, not with a file")
    startup = path if problem is None and is_startup(path) else None  # by its name, or by its content
    data, loaded = _read_for_explain(path) if problem is None and startup is None else (None, None)
    if loaded is not None:  # a channel list a start-up list loads: its machine, with that channel's names
        startup, number = loaded
        if channel not in (1, number):
            _fail(
                f"{target} is the list of channel {number} of {shown_path(startup)}, not of channel {channel}"
            )
        channel = number
    if startup is not None:
        report = _machine_report(startup, program, channel, cnc_root, gear)
        shown.MACHINE[output_format.value](report, screen)
    elif program is not None:
        _fail("--program goes with a start-up list (hochlauf.lis)")
    elif problem is None or problem not in NOT_A_FILE:
        defaults, under = default_underneath(path)
        listed = data if data is not None else _one_list(path, target)  # (which says why it cannot be read)
        axis_report = explain_list(listed, target, gear, defaults, under)
        shown.LIST[output_format.value](axis_report, screen)
    elif kind is None and _names_a_file(target):  # no parameter is spelt like a path: the file is missing
        _fail(f"{target}: {problem}")
    else:
        found = _parameter(target, kind.value if kind is not None else None)
        shown.PARAMETER[output_format.value](parameter_card(found.parameter, found.kind), screen)


def _names_a_file(target: str) -> bool:
    """Whether `explain`'s argument is spelt as a file (a folder in it, or the ending of a list, a program or an
    export), which no parameter name is."""
    return any(mark in target for mark in "/\\") or target.lower().endswith((".lis", ".nc", ".xml", ".toml"))


def _parameter(target: str, kind_id: str | None) -> "Found":
    """The one parameter `explain PARAM` describes, or a one-line failure: unknown (with the closest names of
    the kind asked for, or of axis lists), or known to several kinds of list (then --kind chooses)."""
    from .catalogue.kinds import AXIS, BY_ID
    from .explanation import find_parameters

    kind = BY_ID[kind_id] if kind_id is not None else None
    found = find_parameters(target, kind)
    if len(found) > 1:
        kinds = ", ".join(f"{hit.kind.id} ({hit.parameter.id})" for hit in found)
        _fail(f"'{target}' is a parameter of several kinds of list: {kinds}; choose one with --kind")
    if not found:
        cat = (kind or AXIS).catalogue()
        suggestions = cat.suggest(target) if cat is not None else []
        if cat is not None and not suggestions and not any(mark in target for mark in ".[]"):
            suggestions = _members_like(target, cat)
        hint = "; did you mean " + ", ".join(f"`{s}`" for s in suggestions) + "?" if suggestions else ""
        where = f"of a {kind.name}" if kind is not None else "(--kind looks in another kind of list)"
        _fail(f"'{target}' is neither a file nor a known parameter {where}{hint}")
    return found[0]


def _members_like(name: str, cat: "Catalogue") -> list[str]:
    """For a mistyped bare name (`vb_reflw`): the closest member names, each as `explain` takes it (the name
    alone when one parameter has it, else the parameters' paths)."""
    from .core.closest import close_matches

    owners: dict[str, list[str]] = {}
    for parameter in cat.parameters:
        owners.setdefault(parameter.member, []).append(parameter.path)
    found: list[str] = []
    for member in close_matches(name, list(owners), n=3):
        found += [member] if len(owners[member]) == 1 else owners[member][:2]
    return found[:3]


def _screen(color: Color) -> "Screen":
    """Standard output for a command's report, coloured as --color says."""
    from .output import Screen

    return Screen(color=_use_color(color, sys.stdout), echo=typer.echo)


def _machine_report(
    path: Path, program: str | None, channel: int, cnc_root: str | None, gear: int
) -> dict[str, Any]:
    """`explain hochlauf.lis`: the machine's axes (and a program's homing order), or a one-line failure."""
    from .core.files import reason
    from .machine.build import MachineError
    from .machine.explain import explain_startup

    try:
        root = Path(_folder(cnc_root, "--cnc-root")) if cnc_root is not None else None
        return explain_startup(
            path, program=Path(program) if program else None, cnc_root=root, channel=channel, gear=gear
        )
    except (MachineError, UsageError) as exc:
        _fail(str(exc))
    except OSError as exc:
        _fail(str(exc) if exc.errno is None else f"cannot read {program}: {reason(exc)}")


# Why an argument of explain names no file at all (then it is taken as a parameter name).
NOT_A_FILE = (
    "no such file or directory",
    "a name too long for the file system",
    "a part of the path is not a folder",
    "a name the file system cannot hold",
)


def _read_for_explain(path: Path) -> tuple[bytes | None, tuple[Path, int] | None]:
    """`explain` of a file that is no start-up list, read once: its axis list, or for a channel list that exactly
    one start-up list loads, that start-up list and the channel's number (a channel list alone has no axes to
    explain); (None, None) for anything else, which `_one_list` refuses after the option checks."""
    from .core.decode import UnreadableInput
    from .linting.discovery import channel_loaded_by
    from .linting.linter import NotAnAxisList, read_axis_list

    try:
        return read_axis_list(path, str(path)), None
    except NotAnAxisList as exc:
        return None, channel_loaded_by(path) if exc.kind in ("channel", "default_channel") else None
    except (OSError, UnreadableInput):
        return None, None  # `_one_list` says why


def _one_list(path: Path, name: str) -> bytes:
    """The one axis list in a file, or a one-line failure (exit 2)."""
    from .core.decode import UnreadableInput
    from .core.files import Refused, reason
    from .linting.linter import read_axis_list

    try:
        return read_axis_list(path, name)
    except Refused as exc:
        _fail(str(exc))
    except OSError as exc:
        _fail(f"cannot read {name}: {reason(exc)}")
    except UnreadableInput as exc:
        _fail(str(exc))


def _pair(text: str | None, name: str) -> tuple[float, float] | None:
    if text is None:
        return None
    try:
        low, high = (float(part) for part in text.split(","))
    except ValueError:
        raise UsageError(f"{name} takes two numbers separated by a comma, e.g. -120,-100") from None
    return (low, high)


# The dry-run options that give a value of the scenario: its key, and the option that sets it.
_SCENARIO_OPTIONS = {
    "start_position": "--start",
    "cam": "--cam",
    "zero_pulse_period": "--zero-pulse-period",
    "zero_pulse_phase": "--zero-pulse-phase",
    "hardware_latch": "--latch",
    "cycle_time_ms": "--cycle-time-ms",
    "limit_switches": "--limit-switches",
    "fixed_stop": "--fixed-stop",
    "cam_jitter": "--cam-jitter",
}


def _option_at_fault(options: dict[str, Any], message: str) -> str:
    """A scenario failure caused by the command line, told by the option that gave the bad value (the
    scenario's checks name its keys, which the user never typed); any other failure as it is."""
    from .homing.scenario import ScenarioError, parse_input

    if not message.startswith("command-line scenario: "):
        return message
    for key, value in options.items():
        if value is None:
            continue
        try:
            parse_input({key: value}, "")
        except ScenarioError as exc:
            told = re.sub(r"^`[\w.]+`: ", "", str(exc).removeprefix(": ")).replace(
                f"{key} must be", "must be"
            )
            told = told.replace("Input should be", "should be").replace("Value should be", "should be")
            parts = value if isinstance(value, tuple) else (value,)
            shown = ",".join(str(part) if isinstance(part, bool) else f"{part:g}" for part in parts)
            return f"{_SCENARIO_OPTIONS[key]} {shown}: {told}"
    return message


@app.command("dry-run")
def dry_run_command(
    file: str = typer.Argument(
        ...,
        metavar="FILE",
        help="The axis list to simulate; with --program, the start-up list (hochlauf.lis) of the machine.",
    ),
    scenario: str | None = typer.Option(
        None, "--scenario", metavar="FILE", help="Scenario TOML (human units: mm or degrees, seconds)."
    ),
    output_format: ExplainFormat = typer.Option(
        ExplainFormat.text, "--format", "--output-format", help="text or json."
    ),
    gear: int = typer.Option(
        0, "--gear", metavar="N", min=0, max=5, help="Gear stage whose homing parameters are used."
    ),
    start: float | None = typer.Option(
        None, "--start", metavar="POS", help="Start position in mm or degrees (overrides the scenario)."
    ),
    cam: str | None = typer.Option(
        None, "--cam", metavar="FROM,TO", help="Reference cam zone in mm or degrees, e.g. -300,-250."
    ),
    zero_pulse_period: float | None = typer.Option(
        None,
        "--zero-pulse-period",
        metavar="LENGTH",
        help="Travel per encoder revolution (distance between zero pulses) in mm or degrees.",
    ),
    zero_pulse_phase: float | None = typer.Option(
        None, "--zero-pulse-phase", metavar="POS", help="Position of one zero pulse in mm or degrees."
    ),
    latch: bool | None = typer.Option(
        None, "--latch/--no-latch", help="Whether a hardware latch captures the zero pulse."
    ),
    cycle_time_ms: float | None = typer.Option(
        None,
        "--cycle-time-ms",
        metavar="MS",
        min=CYCLE_TIME_US[0] / 1000,
        max=CYCLE_TIME_US[1] / 1000,
        help="CNC cycle time in ms (default: cycle-time-ms of the configuration, else 1).",
    ),
    limit_switches: str | None = typer.Option(
        None,
        "--limit-switches",
        metavar="NEG,POS",
        help="Hardware limit switch positions in mm or degrees, e.g. -510,510.",
    ),
    fixed_stop: float | None = typer.Option(
        None, "--fixed-stop", metavar="POS", help="Position of the mechanical stop (TORQ) in mm or degrees."
    ),
    cam_jitter: float | None = typer.Option(
        None,
        "--cam-jitter",
        metavar="LENGTH",
        help="Spread of the cam edge in mm or degrees, for --sweep and LIS405.",
    ),
    sweep_runs: int = typer.Option(
        0,
        "--sweep",
        metavar="N",
        min=0,
        max=1_000_000,
        help="Simulate N start positions and cam jitters and report the outcomes and the spread.",
    ),
    allow_failures: bool = typer.Option(False, "--allow-failures", help="Exit 0 even when sweep runs fail."),
    plot: str | None = typer.Option(
        None, "--plot", metavar="FILE", help="Write position and velocity over time to a PNG or SVG file."
    ),
    config: str | None = typer.Option(
        None,
        "--config",
        metavar="FILE",
        help="Use this configuration file (its scenario table and cycle time) instead of searching for one.",
    ),
    color: Color = typer.Option(Color.auto, "--color", help="Colour the text output."),
    program: str | None = typer.Option(
        None,
        "--program",
        metavar="NC",
        help="Homing program (rfp.nc) to run over the whole machine of a start-up list.",
    ),
    channel: int = typer.Option(
        1, "--channel", metavar="N", min=1, max=12, help="Channel whose axis names the program uses."
    ),
) -> None:
    """Simulate the configured homing before a real axis moves."""
    if plot:
        _not_over_inputs(plot, "--plot", [file, program, scenario, config])
        if program is not None:  # the machine: every list its start-up list names, and its configuration
            _not_over_inputs(plot, "--plot", _machine_inputs(file, config))
    if program is not None:
        single = [start, cam, zero_pulse_period, zero_pulse_phase, latch, cycle_time_ms, limit_switches]
        if any(v is not None for v in [*single, fixed_stop, cam_jitter]) or gear:
            _fail(
                "with --program, give the geometry per axis in the machine scenario (--scenario, [axes.NAME])"
            )
        _machine_dry_run(
            file, program, scenario, config, channel, output_format, plot, color, sweep_runs, allow_failures
        )
        return
    from .linting.discovery import is_startup

    if is_startup(Path(file)):  # by its name or content; simulating it as an axis would invent one
        _fail(
            f"{file} is a start-up list (a whole machine): give its homing program with --program rfp.nc, "
            "or dry-run one of its axis lists"
        )

    from .core.decode import UnreadableInput
    from .core.files import reason
    from .dryrun import DryRunRefused, dry_run, scenario_input, sweep
    from .explanation import default_underneath
    from .homing.scenario import ScenarioError
    from .output import OutputFailed
    from .output import dryrun as shown

    try:
        options = {
            "start_position": start,
            "cam": _pair(cam, "--cam"),
            "zero_pulse_period": zero_pulse_period,
            "zero_pulse_phase": zero_pulse_phase,
            "hardware_latch": latch,
            "cycle_time_ms": cycle_time_ms,
            "limit_switches": _pair(limit_switches, "--limit-switches"),
            "fixed_stop": fixed_stop,
            "cam_jitter": cam_jitter,
        }
        given, cycle_time_us = scenario_input(
            Path(file), Path(scenario) if scenario else None, options, Path(config) if config else None
        )
    except ScenarioError as exc:
        _fail(_option_at_fault(options, str(exc)))
    except (UsageError, UnreadableInput) as exc:
        _fail(str(exc))
    except OSError as exc:
        _fail(f"cannot read {scenario}: {reason(exc)}")
    try:
        data = _one_list(Path(file), file)
        defaults, under = default_underneath(Path(file))
        run = dry_run(data, file, given, gear=gear, cycle_time_us=cycle_time_us, defaults=defaults)
        if under is not None:
            run.trace.warn(None, f"read as the CNC loads it: {under}")
        summary = sweep(run.simulator, sweep_runs) if sweep_runs else None
    except (ScenarioError, DryRunRefused) as exc:
        _fail(str(exc))
    report = shown.AxisDryRun(run, summary)
    if plot:
        try:
            shown.plot(report, plot)
        except OutputFailed as exc:
            _fail(str(exc))
    shown.RENDERERS[output_format.value](report, _screen(color))
    if plot:
        _say(f"wrote {plot}")
    sweep_failed = summary is not None and summary["outcomes"].get("failed", 0) > 0 and not allow_failures
    raise typer.Exit(EXIT_FINDINGS if run.trace.outcome == "failed" or sweep_failed else EXIT_OK)


def _machine_dry_run(
    file: str,
    program: str,
    scenario: str | None,
    config: str | None,
    channel: int,
    output_format: ExplainFormat,
    plot: str | None,
    color: Color,
    sweep_runs: int,
    allow_failures: bool,
) -> None:
    """`dry-run hochlauf.lis --program rfp.nc`: the homing program over the whole machine."""
    from .dryrun import DryRunRefused
    from .homing.scenario import ScenarioError
    from .machine.build import MachineError
    from .machine.run import machine_dry_run
    from .output import OutputFailed
    from .output import machine as shown

    try:
        run, summary = machine_dry_run(
            Path(file),
            Path(program),
            Path(scenario) if scenario else None,
            channel=channel,
            config=Path(config) if config else None,
            sweep_runs=sweep_runs,
        )
    except (MachineError, ScenarioError, DryRunRefused) as exc:
        _fail(str(exc))
    report = shown.MachineDryRun(run, summary)
    if plot:
        try:
            shown.plot(report, plot)
        except OutputFailed as exc:
            _fail(str(exc))
    shown.RENDERERS[output_format.value](report, _screen(color))
    if plot:
        _say(f"wrote {plot}")
    sweep_failed = summary is not None and summary["failed"] > 0 and not allow_failures
    raise typer.Exit(EXIT_FINDINGS if run.failure or sweep_failed else EXIT_OK)


@app.command("diff")
def diff_command(
    a: str = typer.Argument(..., metavar="A", help="First list, or start-up list (or a folder holding one)."),
    b: str = typer.Argument(
        ..., metavar="B", help="Second list, or start-up list (or a folder holding one)."
    ),
    defaults: str | None = typer.Option(
        None, "--defaults", metavar="FILE", help="Default axis list loaded under both lists."
    ),
    output_format: ExplainFormat = typer.Option(
        ExplainFormat.text, "--format", "--output-format", help="text or json."
    ),
    color: Color = typer.Option(Color.auto, "--color", help="Colour the text output."),
    cnc_root: list[str] | None = typer.Option(
        None,
        "--cnc-root",
        metavar="DIR",
        help="With start-up lists: the CNC's working directory; once for both machines, twice for A then B.",
    ),
) -> None:
    """Show how two lists, or two machines (start-up lists), differ in their effective values, with units."""
    from .listdiff import diff_lists, differ
    from .machine.build import MachineError
    from .machinediff import MachineDiffError, diff_machines, machines_to_compare
    from .output.diff import MACHINE_RENDERERS, RENDERERS

    try:
        machines = machines_to_compare(Path(a), Path(b))
        if machines is None and cnc_root:
            raise UsageError("--cnc-root goes with start-up lists (hochlauf.lis), not with axis lists")
        if machines is not None:
            if defaults:
                raise UsageError(
                    "--defaults goes with axis lists; a start-up list names its own (default_achs_mds)"
                )
            if len(cnc_root or []) > 2:
                raise UsageError("--cnc-root is given once (both machines) or twice (A, then B)")
            roots = [Path(_folder(root, "--cnc-root")) for root in cnc_root or []]
            found = diff_machines(*machines, *(roots * 2 if len(roots) == 1 else roots))
            MACHINE_RENDERERS[output_format.value](found, _screen(color))
            raise typer.Exit(EXIT_FINDINGS if found["differ"] else EXIT_OK)
    except (MachineDiffError, MachineError, UsageError) as exc:
        _fail(str(exc))
    contents = [_one_list(Path(name), name) for name in (a, b, *([defaults] if defaults else []))]
    report = diff_lists(
        contents[0],
        a,
        contents[1],
        b,
        contents[2] if defaults else None,
        defaults_name=defaults or "default list",
    )
    RENDERERS[output_format.value](report, _screen(color))
    raise typer.Exit(EXIT_FINDINGS if differ(report) else EXIT_OK)


class ReportFormat(str, Enum):
    html = "html"
    markdown = "markdown"


@app.command()
def report(
    target: str = typer.Argument(
        ..., metavar="MACHINE", help="Start-up list (hochlauf.lis), a folder holding one, or one axis list."
    ),
    program: str | None = typer.Option(
        None, "--program", metavar="NC", help="Homing program (rfp.nc) run over the machine: the timeline."
    ),
    scenario: str | None = typer.Option(
        None,
        "--scenario",
        metavar="FILE",
        help="Scenario TOML: per axis (\\[axes.NAME]) for a machine, as dry-run reads it.",
    ),
    against: str | None = typer.Option(
        None,
        "--against",
        metavar="BACKUP",
        help="A backup of the machine (start-up list or folder) or of the list: what changed since.",
    ),
    output_file: str | None = typer.Option(
        None, "--output-file", "-o", metavar="FILE", help="Write the report to FILE (needed for html)."
    ),
    output_format: ReportFormat = typer.Option(
        ReportFormat.html,
        "--format",
        "--output-format",
        help="html: the page to review, print and sign; markdown: a summary for CI job pages.",
    ),
    config: str | None = typer.Option(
        None, "--config", metavar="FILE", help="Use this configuration file instead of searching for one."
    ),
    channel: int = typer.Option(
        1, "--channel", metavar="N", min=1, max=12, help="The channel whose axis names are shown."
    ),
    gear: int = typer.Option(
        0, "--gear", metavar="N", min=0, max=5, help="Gear stage whose homing parameters are shown."
    ),
    docs_url: str | None = typer.Option(
        None, "--docs-url", metavar="URL", help="Address of the rule documentation the findings link to."
    ),
) -> None:
    """Write a commissioning report of a machine: axes, homing, corrections, findings, timeline, changes."""
    from .linting.config import ConfigError
    from .output import OutputFailed
    from .output.lint import destination
    from .output.report import RENDERERS
    from .report import ReportFailed, ReportRequest, build_report, report_inputs

    request = ReportRequest(
        Path(target),
        program=Path(program) if program else None,
        scenario=Path(scenario) if scenario else None,
        against=Path(against) if against else None,
        config=Path(config) if config else None,
        channel=channel,
        gear=gear,
    )
    if output_file is not None:
        try:
            inputs = [str(path) for path in report_inputs(request)]
        except ConfigError as exc:
            _fail(str(exc))
        _not_over_inputs(output_file, "--output-file", inputs)
    elif output_format == ReportFormat.html and sys.stdout.isatty():
        _fail("the html report goes to a file: add -o report.html")
    try:
        found = build_report(request)
    except ReportFailed as exc:
        _fail(str(exc))
    text = RENDERERS[output_format.value](found, _docs_url(docs_url, config))
    try:
        with destination(output_file, sys.stdout) as stream:
            stream.write(text)
    except OutputFailed as exc:
        _fail(str(exc))
    if output_file is not None:
        _say(f"wrote {output_file}")
    failed = found.lint.failing or (found.run is not None and found.run.failure is not None)
    raise typer.Exit(EXIT_FINDINGS if failed else EXIT_OK)


@app.command("config")
def config_command(
    show: bool = typer.Option(False, "--show", help="Print the resolved settings."),
    path: str = typer.Argument(".", metavar="PATH", help="File or folder whose configuration is shown."),
    config: str | None = typer.Option(
        None, "--config", metavar="FILE", help="Use this configuration file instead of searching for one."
    ),
) -> None:
    """Show the configuration that applies to a path."""
    from .linting.config import ConfigError, discover, load_file
    from .output.config import as_text

    if not show:
        _fail("nothing to do; use `achslint config --show [PATH]`")
    if config is None and not os.path.lexists(path):  # the defaults of a path that is not there would mislead
        _fail(f"{path}: no such file or directory")
    try:
        resolved = load_file(Path(config)) if config else discover(Path(path))
    except ConfigError as exc:
        _fail(str(exc))
    as_text(resolved, _screen(Color.never))


class SchemaOutput(str, Enum):
    model = "model"
    lint = "lint"


class SchemaKind(str, Enum):  # the kinds of list with a typed model (achslint.model.MODELS; a test checks)
    axis = "axis"
    channel = "channel"
    startup = "startup"


@app.command()
def server() -> None:
    """Run the language server for editors on standard input/output (needs the lsp extra: `pip install '.\\[lsp]'`).

    The extra is installed from the achslint checkout."""
    from .lsp import MISSING, available

    if not available():
        _fail(MISSING)
    from .lsp.server import run

    run()


@app.command()
def schema(
    output: SchemaOutput = typer.Option(
        SchemaOutput.model,
        "--output",
        help="model: the typed parameter model of a kind of list (--kind); lint: the output of "
        "`lint --format json`.",
    ),
    kind: SchemaKind | None = typer.Option(
        None,
        "--kind",
        help="With --output model: the model of axis (the default), channel or start-up lists.",
        show_default=False,
    ),
) -> None:
    """Print a JSON Schema: of the parameter model of axis, channel or start-up lists, or of lint's JSON.

    Without options: the model of axis lists."""
    from .output import write_json

    if output == SchemaOutput.lint:
        if kind is not None:
            _fail("--kind goes with --output model: the output of `lint --format json` has one schema")
        from .output.reporters.json_format import SCHEMA as document
    else:
        from .model import json_schema

        document = json_schema((kind or SchemaKind.axis).value)
    write_json(document, _screen(Color.never))


def main(argv: list[str] | None = None) -> int:
    """Entry point (console script, `python -m achslint`, and in-process tests): returns the exit code.

    Whatever happens, the user gets one line on stderr, never a traceback (unless --debug): usage errors
    as `achslint: error: ...` with a hint, signals as "interrupted" / "terminated" with 128 + the signal
    number, anything unexpected as an internal error.
    """
    from .core.signals import Stopped, stopping_on_signals

    args = sys.argv[1:] if argv is None else list(argv)
    _tolerant_streams()
    try:
        with stopping_on_signals():
            code = _command(args).main(args=args, prog_name="achslint", standalone_mode=False)
    except Stopped as stop:
        _say(stop.words)
        return stop.exit_code
    except streams.StandardOutputFailed as exc:  # a full disk or a file-size limit (cli.run's output)
        _say(str(exc))
        return EXIT_ERROR
    except typer.Abort:
        _say("interrupted")
        return 130
    except typer.TyperException as exc:
        return _usage_error(exc, args)
    except Exception as exc:
        if "--debug" in args:
            raise
        _say(f"internal error: {type(exc).__name__}: {exc} (run with --debug for details)")
        return EXIT_ERROR
    return code if isinstance(code, int) else EXIT_OK


def _command(args: list[str]) -> Any:  # a click command (typer vendors click: no stable type to name)
    """What runs `args`: when they start with a command's name, a tree holding only that command.

    typer builds a command from its function's signature (every option's annotation is read), and a run
    uses one: building all ten was about 4 % of a cold `lint`. `--help`, `--version`, completion and a
    misspelt command name get the whole tree.
    """
    name = args[0] if args else ""
    return _command_tree(name if name in _command_names() else None)


def _command_names() -> dict[str, Any]:
    """Each command's name (as typed on the command line) and its typer registration."""
    return {
        info.name or typer.main.get_command_name(info.callback.__name__): info
        for info in app.registered_commands
        if info.callback is not None
    }


@functools.cache
def _command_tree(only: str | None) -> Any:
    """The command tree of `app` (or of `app` with the one command `only`), built once per process:
    typer would rebuild it on each call, which an editor or a test that runs many commands pays for."""
    if only is None:
        return typer.main.get_command(app)
    single = copy.copy(app)  # same callback (--version) and settings; app's own list is left alone
    single.registered_commands = [_command_names()[only]]
    return typer.main.get_command(single)


def run() -> NoReturn:
    """The console script and `python -m achslint`: `main()`, then exit.

    Before exiting, every object still alive is moved out of the garbage collector's reach
    (`gc.freeze`): the interpreter's last collection at shutdown would otherwise walk the whole parser,
    catalogue and command tree once more, about 30 ms of a 170 ms run (benchmarks/run --only cold).
    Buffers are still flushed and exit handlers still run. Not done in `main()`, which tests and the
    language server call in a process that goes on.
    """
    streams.install()
    code = main()
    try:
        sys.stdout.flush()  # what is left of the output, while a failure can still be told
    except streams.StandardOutputFailed as exc:
        _say(str(exc))
        code = EXIT_ERROR
    except BrokenPipeError:  # the reader has gone (`| head`): nothing more to say to it
        sys.stdout = open(os.devnull, "w")  # noqa: SIM115  # the interpreter's last flush goes nowhere
    gc.freeze()
    sys.exit(code)


def _usage_error(exc: Any, args: Sequence[str] = ()) -> int:  # a click usage error (typer vendors click)
    """A click/typer usage error as one line: `achslint: error: <what> (see `achslint lint --help`)`."""
    context = getattr(exc, "ctx", None)
    if type(exc).__name__ == "NoArgsIsHelpError":  # `achslint` alone: the help is the answer
        typer.echo(exc.format_message(), err=True)
        return EXIT_ERROR
    message = _plain_words(exc, context)
    if context is not None:
        where = context.command_path
    else:  # (an option without its value is told before the command has a context)
        where = f"achslint {args[0]}" if args and args[0] in _command_names() else "achslint"
    _say(f"error: {message[:1].lower()}{message[1:]}{' (see `' + where + ' --help`)'}")
    return getattr(exc, "exit_code", EXIT_ERROR)


# click's words for a value of the wrong type, and what a user reads instead (the type names are the code's)
_TYPE_WORDS = {
    "is not a valid int range": "is not a whole number",
    "is not a valid integer": "is not a whole number",
    "is not a valid float range": "is not a number",
    "is not a valid float": "is not a number",
}


def _plain_words(exc: Any, context: Any) -> str:
    """The message of a click usage error on one line, with the type names of the code in plain words and a
    mistyped option's closest options as a did-you-mean (one name per option, not each of its spellings)."""
    possibilities = getattr(exc, "possibilities", None)
    option = getattr(exc, "option_name", None)
    if possibilities and option:
        spellings = [param.opts for param in context.command.params] if context is not None else []
        closest: list[str] = []
        for name in possibilities:
            same = next((opts for opts in spellings if name in opts), [name])
            if not any(known in same for known in closest):
                closest.append(name)
        return f"no such option: {option}; did you mean {' or '.join(closest[:3])}?"
    message = " ".join(exc.format_message().split()).rstrip(".")
    for words, plain in _TYPE_WORDS.items():
        message = message.replace(words, plain)
    return message


def _tolerant_streams() -> None:
    """Characters the terminal's encoding cannot show become escapes instead of ending the run."""
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(AttributeError, ValueError, OSError):
            stream.reconfigure(errors="backslashreplace")  # type: ignore[union-attr]  # not every stream can
