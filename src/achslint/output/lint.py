"""`achslint lint` around the report of its format (`reporters/`): where the report goes (`--output-file`),
ruff's closing lines or `--statistics` instead, what `--fix` and `--diff` print, and the progress bar."""

from __future__ import annotations

import io
import sys
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, TextIO

from . import OutputFailed
from .reporters import REPORTERS, get

if TYPE_CHECKING:
    from rich.progress import Progress, TaskID

    from ..linting.linter import FileResult


class destination:
    """The report stream: `--output-file` collects the report and writes it at the end, as UTF-8 (never the
    console's code page) and through a temporary file (`files.write_output`: a full disk or Ctrl-C leaves
    the earlier report, never half of one); else `stream`. A file that cannot be written is an
    `OutputFailed` naming it."""

    def __init__(self, path: str | None, stream: TextIO) -> None:
        self.path, self.stream = path, stream
        self.file: io.StringIO | None = None

    def __enter__(self) -> TextIO:
        if self.path is None:
            return self.stream
        self.file = io.StringIO(newline="\n")
        return self.file

    def __exit__(self, kind: type[BaseException] | None, *rest: object) -> None:
        if self.file is None or self.path is None or kind is not None:
            return
        from ..core.files import reason, write_output

        try:
            write_output(Path(self.path), self.file.getvalue().encode("utf-8"))
        except (OSError, ValueError) as exc:  # ValueError: a NUL byte in the name
            why = reason(exc) if isinstance(exc, OSError) else "a name the file system cannot hold"
            raise OutputFailed(f"cannot write {self.path}: {why}") from None


def write_report(
    results: list[FileResult],
    fmt: str,
    stream: TextIO,
    *,
    color: bool,
    sources: dict[str, list[str]] | None,
    docs_url: Callable[[], str | None],
    statistics: bool,
    quiet: bool,
    fixing: bool,
    failed: bool,
) -> None:
    """The findings in format `fmt`. A format for people is followed by the closing lines (unless `quiet`),
    or replaced by the counts per rule when `statistics`; a machine format stays one document and its
    counts go to standard error. `docs_url` is asked only when the format is written."""
    if statistics and REPORTERS[fmt].text:
        write_statistics(results, stream)
        return
    get(fmt)(results, stream, color=color, sources=sources, docs_url=docs_url())
    if REPORTERS[fmt].text and not quiet:
        closing_lines(results, stream, fixing, failed)
    if statistics:
        write_statistics(results, sys.stderr)


def closing_lines(results: list[FileResult], stream: TextIO, fixing: bool, failed: bool = False) -> None:
    """ruff's closing lines: "All checks passed!" (never when something could not be checked: `failed`),
    or how many findings a fix would remove."""
    if not any(r.diagnostics for r in results):
        if not failed and not any(r.error for r in results):
            stream.write("All checks passed!\n")
        return
    if fixing:
        return
    safe = sum(
        1 for r in results for d in r.diagnostics if d.fix is not None and d.fix.applicability == "safe"
    )
    unsafe = sum(
        1 for r in results for d in r.diagnostics if d.fix is not None and d.fix.applicability != "safe"
    )
    if safe or unsafe:
        more = f" ({unsafe} more with --unsafe-fixes)" if unsafe else ""
        if safe:
            stream.write(f"{safe} fixable with --fix{more}\n")
        else:
            stream.write(f"{unsafe} fixable with --fix --unsafe-fixes\n")


def write_statistics(results: list[FileResult], stream: TextIO) -> None:
    """`--statistics`: one line per rule code, the most frequent first, with the rule's name."""
    from collections import Counter

    from ..rules import registry

    counts = Counter(d.code for r in results for d in r.diagnostics)
    rules = registry()
    for code, count in sorted(counts.items(), key=lambda item: (-item[1], item[0])):
        rule = rules.get(code)
        name = rule.name if rule else ""
        stream.write(f"{count:6d}  {code}  {name}\n")


def write_fixes(results: list[FileResult], show_diff: bool) -> TextIO:
    """What `--fix` / `--diff` put on standard output: the changes as a diff, the fixed list read from
    standard input. Returns where the findings go then: standard error once standard output holds either."""
    stream = sys.stdout
    for result in results:
        if show_diff and result.diff:
            sys.stdout.write(result.diff)
        if result.fixed_data is not None:
            sys.stdout.flush()
            sys.stdout.buffer.write(result.fixed_data)
            stream = sys.stderr
    if show_diff:
        stream = sys.stderr
    return stream


def fix_count(results: list[FileResult], show_diff: bool) -> str:
    """The line that says how many findings `--fix` removed (or `--diff` would remove)."""
    fixed = sum(r.fixed for r in results)
    verb = "would fix" if show_diff else "fixed"
    return f"{verb} {fixed} diagnostic{'s' if fixed != 1 else ''}"


def noqa_count(results: list[FileResult]) -> str:
    """What `--add-noqa` did, and what it left: findings a `noqa` in a list cannot suppress."""
    added = sum(r.noqa_added for r in results)
    said = f"added {added} noqa directive{'s' if added != 1 else ''}"
    # A list that could not be read or written (said above, exit 2) keeps its findings for another reason.
    left = sum(len(r.diagnostics) for r in results if r.error is None)
    if left:
        said += (
            f"; {left} finding{'s' if left != 1 else ''} left that a noqa in the list cannot suppress "
            "(machine rules, unused noqa LIS009): `achslint lint` shows them"
        )
    failed = sum(1 for r in results if r.error is not None)
    if failed:
        said += f"; {failed} list{'s' if failed != 1 else ''} not read or not written (said above)"
    return said


class progress:
    """A rich progress bar on standard error for long runs on a terminal; otherwise nothing."""

    MIN_FILES = 50

    def __init__(self, quiet: bool):
        self.enabled = not quiet and sys.stderr.isatty()
        self.bar: Progress | None = None
        self.task: TaskID | None = None

    def __enter__(self) -> Callable[[int], None] | None:
        return self.advance if self.enabled else None

    def advance(self, total: int) -> None:
        if self.bar is None:
            if total < self.MIN_FILES:
                self.enabled = False
                return
            from rich.console import Console
            from rich.progress import Progress

            self.bar = Progress(console=Console(stderr=True), transient=True)
            self.bar.start()
            self.task = self.bar.add_task("linting", total=total)
        if self.task is not None:
            self.bar.advance(self.task)

    def __exit__(self, *exc: object) -> None:
        if self.bar is not None:
            self.bar.stop()
