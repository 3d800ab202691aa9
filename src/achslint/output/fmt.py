"""`achslint fmt` as people read it: per file what happened (or the diff, or the formatted standard input),
then one summary line."""

from __future__ import annotations

import codecs
import sys
from collections.abc import Sequence
from typing import Protocol

from . import Screen


class Formatted(Protocol):
    """What is shown of one file's formatting (`api.Formatted`)."""

    @property
    def name(self) -> str: ...
    @property
    def changed(self) -> bool: ...
    @property
    def written(self) -> bool: ...
    @property
    def diff(self) -> str: ...
    @property
    def output(self) -> bytes | None: ...


class Formatting(Protocol):
    """What is shown of a whole run (`api.FormatOutcome`)."""

    @property
    def results(self) -> Sequence[Formatted]: ...
    @property
    def changed(self) -> int: ...
    @property
    def written(self) -> int: ...


def write_results(outcome: Formatting, mode: str, quiet: bool, screen: Screen) -> None:
    """Standard input formatted, a file's diff (`--diff`), or one line per file that was (`--check`: would
    be) reformatted; those lines not when `quiet`."""
    from ..core.display import printable

    for result in outcome.results:
        if result.output is not None:
            screen.write_bytes(result.output)
        elif result.diff:
            _write_diff(result.diff, screen)
        elif result.changed and not quiet and (result.written or mode == "check"):
            screen.echo(printable(f"{'would reformat' if mode == 'check' else 'reformatted'} {result.name}"))


def _write_diff(diff: str, screen: Screen) -> None:
    """A diff as it is, as `lint --fix --diff` writes one: not through `echo`, which drops the escape sequences
    a list may hold when standard output is no terminal (the diff would then not show what fmt writes)."""
    stream = screen.file or sys.stdout
    if not hasattr(stream, "buffer"):
        stream.write(diff)
        return
    encoding = getattr(stream, "encoding", None) or "utf-8"
    if codecs.lookup(encoding).name == "ascii":  # a misconfigured locale: UTF-8, as echo writes then
        encoding = "utf-8"
    try:
        data = diff.encode(
            encoding, "surrogateescape"
        )  # (a file name's bytes that are not UTF-8 as they were)
    except UnicodeEncodeError:
        data = diff.encode(encoding, "replace")
    screen.write_bytes(data)


def summary(outcome: Formatting, mode: str, quiet: bool) -> str | None:
    """The closing line: how many files were (or would be) reformatted and how many were left alone; None
    when there is nothing to sum up (quiet, a diff, nothing formatted, only standard input written)."""
    stdin_only = all(result.output is not None for result in outcome.results)
    if quiet or mode == "diff" or not outcome.results or (mode != "check" and stdin_only):
        return None

    def files(count: int) -> str:
        return f"{count} file{'s' if count != 1 else ''}"

    unchanged = len(outcome.results) - outcome.changed
    if mode == "check":
        return f"{files(outcome.changed)} would be reformatted, {unchanged} left unchanged"
    # only what was really written counts; refused or failed writes are errors above
    line = f"{files(outcome.written)} reformatted, {unchanged} left unchanged"
    missed = (
        outcome.changed - outcome.written - sum(r.output is not None and r.changed for r in outcome.results)
    )
    return line + (f", {missed} not written" if missed > 0 else "")
