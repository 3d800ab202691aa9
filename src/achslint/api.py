"""The public library API: lint, load, explain, dry-run and format lists, and whole lint / format runs.

Each function composes the stages below it (parse, resolve, lint, model, explain, dry-run, fmt); nothing
here decides anything of its own. The package re-exports the functions of `__all__`'s first group
(`achslint.lint`, `achslint.load`, ...) and the exceptions they raise.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .core.decode import UnreadableInput, text_bytes
from .core.diagnostics import Diagnostic, Severity
from .core.files import read_list
from .fmt import FormatOutcome, FormatRequest, run_format
from .homing.scenario import ScenarioError
from .linting.config import PROGRAM_SUFFIXES, ConfigError, Overrides, forget_cached, parse_codes
from .linting.discovery import is_startup
from .linting.linter import FileSettings, axis_list_only, findings, lint_file
from .linting.run import LintOutcome, LintRequest, LintRun, OutputIsInput, run_lint
from .machine.resolved import MachineError

if TYPE_CHECKING:
    from .dryrun import DryRun, DryRunRefused
    from .explanation import ListReport
    from .model.base import ListBase
    from .model.generated import AxisParameters


def __getattr__(name: str) -> type[Exception]:
    """`DryRunRefused`, loaded with the dry-run on first use (it would cost every lint and fmt run the
    simulator's import)."""
    if name == "DryRunRefused":
        from .dryrun import DryRunRefused

        return DryRunRefused
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


# A list given to the library functions: a path (str or PathLike) or the list's bytes.
Source = str | os.PathLike[str] | bytes


def _as_bytes(source: Source) -> tuple[bytes, str]:
    """The bytes and display name of a list given as a path (str or Path) or as bytes.

    A string is a path (`FileNotFoundError` when there is no such file), never list text: use `lint_text`
    and `loads` for text. Only a string with a line break, which cannot be a file name, is still read as
    list text, for callers written before `lint_text` existed.
    """
    if isinstance(source, (bytes, bytearray)):
        return bytes(source), "<bytes>"
    if isinstance(source, str) and "\n" in source:
        return text_bytes(source), "<string>"
    path = Path(source)
    if path.is_dir():
        raise IsADirectoryError(21, "a folder, not one list (lint and lint_paths take folders)", str(path))
    if not path.is_file():
        raise FileNotFoundError(2, "no such axis list", str(path))
    return read_list(path), str(path)


class LintFailed(Exception):
    """`lint_paths` could not lint some of the lists it found (unreadable, refused), or found none at all:
    `errors` says which and why, one message each, as `achslint lint` prints them."""

    def __init__(self, errors: list[str]) -> None:
        super().__init__("; ".join(errors))
        self.errors = errors


def _text(value: object, function: str, instead: str) -> str:
    """The text a text function was given, or a TypeError naming the function that takes what it got."""
    if isinstance(value, str):
        return value
    raise TypeError(f"{function}() takes the text of a list (str), not {type(value).__name__}{instead}")


def _codes(values: str | Iterable[str] | None, argument: str) -> list[str]:
    """Rule codes and prefixes given to `select` / `ignore`: a list, or one string (comma-separated, as on the
    command line). A string was taken letter by letter (`ignore="LIS101"` ignored every rule: prefix `L`).
    `ValueError` for one that picks no rule, as the command line refuses it."""
    if values is None:
        return []
    try:
        return parse_codes([values] if isinstance(values, str) else [str(value) for value in values])
    except ValueError as exc:
        raise ValueError(f"{argument}: {exc}") from None


GEAR_STAGES = range(6)  # getriebe[0] .. getriebe[5], as the command line's --gear


def _gear(gear: int) -> int:
    """The gear stage asked for, or a ValueError: a stage the axis does not have would be explained (or
    simulated) from defaults as if it existed."""
    if isinstance(gear, bool) or not isinstance(gear, int):
        raise TypeError(f"gear must be an int (a gear stage 0 to 5), not {type(gear).__name__}")
    if gear not in GEAR_STAGES:
        raise ValueError(f"gear {gear} does not exist: an axis has the gear stages 0 to 5 (getriebe[0..5])")
    return gear


def lint(
    source: Source,
    *,
    select: str | Iterable[str] | None = None,
    ignore: str | Iterable[str] | None = None,
    name: str | None = None,
) -> list[Diagnostic]:
    """Diagnostics for one list (a path or bytes), with the built-in defaults and no config files.

    A folder or a start-up list (told by its name or content) is a machine: linted as `lint_paths` does,
    with the configuration files found beside it, which is what `achslint lint PATH` reports (a folder
    without any list, or an NC program, raises `LintFailed`, as the command exits 2)."""
    if not isinstance(source, (bytes, bytearray)) and not (isinstance(source, str) and "\n" in source):
        path = Path(source)
        program = path.name.lower().endswith(PROGRAM_SUFFIXES)  # refused there, as the command refuses it
        if path.is_dir() or (path.is_file() and (program or is_startup(path))):
            return lint_paths([path], select=select, ignore=ignore)
    data, default_name = _as_bytes(source)
    settings = FileSettings.of(_codes(select, "select") or None, _codes(ignore, "ignore"))
    return findings(data, name or default_name, settings)


def lint_paths(
    paths: Iterable[str | os.PathLike[str]],
    *,
    select: str | Iterable[str] | None = None,
    ignore: str | Iterable[str] | None = None,
    config: str | os.PathLike[str] | None = None,
    allow_empty: bool = False,
) -> list[Diagnostic]:
    """What `achslint lint PATH...` reports: files, folders (searched) and start-up lists (their machines),
    with the configuration files found beside them (or `config` instead), in the command line's order.

    Raises `FileNotFoundError` for a path that does not exist, `ConfigError` for a bad configuration and
    `LintFailed` when a list that was found cannot be read, or when the paths hold no list at all (an
    empty result would read as "no findings"; `allow_empty=True` returns `[]` instead, as
    `--allow-empty`)."""
    if isinstance(paths, (str, bytes, os.PathLike)):  # a string would be taken letter by letter
        raise TypeError(
            f"lint_paths() takes a list of paths, not one {type(paths).__name__}: lint_paths([path])"
        )
    names = [os.fspath(path) for path in paths]
    for name in names:
        if not os.path.lexists(name):
            raise FileNotFoundError(2, "no such file or folder", name)
    forget_cached()  # configuration files read as they are now, not as an earlier call found them
    overrides = Overrides(select=_codes(select, "select") or None, ignore=_codes(ignore, "ignore"))
    request = LintRequest(
        paths=names,
        overrides=overrides,
        config_file=os.fspath(config) if config is not None else None,
        jobs=1,  # no worker processes from a library call
        keep_source=False,
    )
    outcome = run_lint(request)
    errors = list(dict.fromkeys([*outcome.errors, *(r.error for r in outcome.results if r.error)]))
    if errors:
        raise LintFailed(errors)
    if names and not outcome.results and not outcome.skipped and not allow_empty:
        excluded = (
            f" ({', '.join(outcome.excluded)} excluded by the configuration)" if outcome.excluded else ""
        )
        raise LintFailed(
            [
                f"no axis list found in {', '.join(names)}{excluded}: folders are searched for the "
                "`include` patterns (achsmds*.lis by default) and for XML exports holding an axis list; "
                "pass allow_empty=True when an empty result is fine"
            ]
        )
    return [d for result in outcome.results for d in result.diagnostics]


def lint_text(
    text: str,
    *,
    filename: str = "<string>",
    select: str | Iterable[str] | None = None,
    ignore: str | Iterable[str] | None = None,
) -> list[Diagnostic]:
    """Diagnostics for the text of one list, reported under `filename` (built-in defaults, no config files)."""
    text = _text(text, "lint_text", "; lint() takes a path or bytes")
    settings = FileSettings.of(_codes(select, "select") or None, _codes(ignore, "ignore"))
    return findings(text_bytes(text), filename, settings)


def _one_axis_list(data: bytes, name: str) -> bytes:
    """The one axis list `data` holds, as `explain FILE` reads it: an XML export's only list (through the
    one XML parser: `xmlinput.single_list`, which refuses DTDs, entities and files of several axes), and
    any list checked to be an axis list (`axis_list_only`)."""
    from .core.files import is_xml

    if is_xml(name):
        from .syntax.xmlinput import single_list

        data = single_list(data, name)
    return axis_list_only(data, name)


def load(source: Source, *, defaults: Source | None = None, strict: bool = False) -> AxisParameters:
    """The typed model of a list (a path or bytes) on top of an optional default list.

    Lenient by default: the findings of `lint` are kept on the model (`model.findings`). With
    `strict=True` every error-level finding is raised as one pydantic `ValidationError`. A missing path
    raises `FileNotFoundError`; a list of another kind (a channel or start-up list: `model.build_list_model`)
    or an NC program raises `UnreadableInput`, as `explain` does.
    """
    from .model import build_model, rule_errors

    data, name = _as_bytes(source)
    listed = _one_axis_list(data, name)  # the findings are the file's (of an XML export: at its lines)
    default_data = _as_bytes(defaults) if defaults is not None else None
    return _finish(build_model(listed, name, default_data), data, name, default_data, strict, rule_errors)


def _finish(
    model: AxisParameters,
    data: bytes,
    name: str,
    default_data: tuple[bytes, str] | None,
    strict: bool,
    rule_errors: Callable[[list[Diagnostic]], Exception],
) -> AxisParameters:
    settings = FileSettings(keep_source=False)
    found = lint_file(data, name, settings, default_data[0] if default_data else None).diagnostics
    model._findings = found
    errors = [d for d in found if d.severity is Severity.ERROR]
    if strict and errors:
        raise rule_errors(errors)
    return model


def loads(
    text: str, *, defaults: str | None = None, strict: bool = False, filename: str = "<string>"
) -> AxisParameters:
    """The typed model of a list's text (see `load`). Bytes raise TypeError: `load` takes them."""
    from .model import build_model, rule_errors

    data = axis_list_only(text_bytes(_text(text, "loads", "; load() takes a path or bytes")), filename)
    if defaults is not None:
        defaults = _text(defaults, "loads", " as defaults; load() takes a path or bytes")
    default_data = (text_bytes(defaults), "<defaults>") if defaults is not None else None
    return _finish(
        build_model(data, filename, default_data), data, filename, default_data, strict, rule_errors
    )


def dumps(model: ListBase) -> str:
    """A list in the canonical layout from a model of any kind (for lists generated by configuration tools):
    `loads(dumps(model)) == model` for an axis model."""
    from .fmt import canonical_text
    from .model import dumps as model_dumps
    from .model.base import ListBase

    if not isinstance(model, ListBase):
        raise TypeError(f"dumps() takes a list model (from load or loads), not {type(model).__name__}")
    return canonical_text(model_dumps(model))


def explain(source: Source, *, gear: int = 0, defaults: Source | None = None) -> ListReport:
    """What `achslint explain FILE --format json` prints: strategy, phases, corrections, homing parameters.
    A list of another kind (a channel or tool list) raises `UnreadableInput`, as the command refuses it;
    a gear stage outside 0..5 raises `ValueError`, as `--gear` does."""
    from .explanation import explain_list

    data, name = _as_bytes(source)
    return explain_list(
        _one_axis_list(data, name),
        name,
        _gear(gear),
        _as_bytes(defaults)[0] if defaults is not None else None,
    )


def dry_run(source: Source, scenario: dict[str, Any] | None = None, *, gear: int = 0) -> DryRun:
    """Simulate the homing of a list (path or bytes); `scenario` as in a scenario file (mm / degrees,
    seconds). Returns the run: `.trace` holds the phases, events and the outcome."""
    from .dryrun import dry_run as simulate
    from .homing.scenario import parse_input

    gear = _gear(gear)
    data, name = _as_bytes(source)
    return simulate(
        _one_axis_list(data, name), name, parse_input(dict(scenario or {}), "scenario"), gear=gear
    )


def format_text(text: str) -> str:
    """The text of a list as `achslint fmt` writes it (whitespace only)."""
    from .fmt import format_text as formatted

    return formatted(_text(text, "format_text", "; decode the bytes first"))


__all__ = [  # noqa: RUF022 (grouped: one list, then whole runs)
    # one list
    "dry_run",
    "dumps",
    "explain",
    "format_text",
    "lint",
    "lint_paths",
    "lint_text",
    "load",
    "loads",
    # what they return and raise
    "Diagnostic",
    "Severity",
    "ConfigError",
    "DryRunRefused",
    "LintFailed",
    "MachineError",
    "OutputIsInput",
    "ScenarioError",
    "UnreadableInput",
    # whole runs, as the command line does them
    "FormatOutcome",
    "FormatRequest",
    "LintOutcome",
    "LintRequest",
    "LintRun",
    "run_format",
    "run_lint",
]
