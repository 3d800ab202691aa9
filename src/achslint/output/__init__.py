"""What every command prints, in one package: the CLI turns flags into a request, runs it, and hands the
result to a renderer registered here; it formats no text itself (STYLE.md: "the CLI picks one and never
formats text itself").

- `reporters/`  lint: one module per `--format` (full, concise, json, sarif, github, gitlab, junit)
- `lint.py`     lint and fmt around the reports: closing lines, `--statistics`, fix counts, progress
- `explain.py`  explain: an axis list, a parameter card, a machine
- `dryrun.py`   dry-run of one axis, with its sweep
- `machine.py`  dry-run of a homing program over a whole machine, with its sweep
- `diff.py`     diff A B
- `plot.py`     `--plot`: which figure a run gets, written as PNG or SVG

Each command but lint offers the formats in `FORMATS`; its registry maps each name to a renderer,
`render(report, screen)`. This module is imported on every start of the CLI, so it imports nothing heavy;
the renderers load rich when they draw.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, TextIO

if TYPE_CHECKING:  # names for the type checker only: the CLI imports this module on every start
    from collections.abc import Callable, Mapping
    from typing import Protocol, TypeVar

    from rich.console import Console

    R = TypeVar("R")
    Renderer = Callable[[R, "Screen"], None]
    Registry = Mapping[str, Renderer[R]]  # format name -> renderer, one per command (or kind of report)

    class Echo(Protocol):
        """Writes a text and, unless `nl` is false, a newline (`typer.echo` is one)."""

        def __call__(self, message: str, *, nl: bool = True) -> object: ...


FORMATS = ("text", "json")  # the --format choices of explain, dry-run and diff


class OutputFailed(Exception):
    """An output file that could not be written: the message is the one line the user sees."""


class Screen:
    """Where a command's report goes: whole texts through `echo` (one call, newline added), tables and
    styled lines through a rich console.

    The CLI passes `typer.echo` as `echo`, which also copes with a standard output whose encoding is
    misconfigured; without it, texts are written to `file` (standard output when None). The console is
    built on first use: it is uncoloured unless `color`, and when standard output is not a terminal its
    lines are not wrapped and its tables are 160 columns wide.
    """

    def __init__(self, color: bool = False, file: TextIO | None = None, echo: Echo | None = None) -> None:
        self.color = color
        self.file = file
        self._echo = echo
        self._console: Console | None = None

    def echo(self, text: str, *, newline: bool = True) -> None:
        if self._echo is not None:
            self._echo(text, nl=newline)
            return
        stream = self.file or sys.stdout
        stream.write(text + "\n" if newline else text)
        stream.flush()

    def write_bytes(self, data: bytes) -> None:
        """Bytes as they are (a fixed or formatted list read from standard input), after any pending text."""
        stream = self.file or sys.stdout
        stream.flush()
        stream.buffer.write(data)

    @property
    def console(self) -> Console:
        if self._console is None:
            from rich.console import Console

            piped = not (self.file or sys.stdout).isatty()
            self._console = Console(
                file=self.file,
                force_terminal=self.color,
                no_color=not self.color,
                highlight=False,
                soft_wrap=piped,
                width=160 if piped else None,
            )
        return self._console


def write_json(document: object, screen: Screen, *, strict: bool = False) -> None:
    """A JSON document, indented, non-ASCII characters as they are. `strict` refuses NaN and infinities
    (the dry-run documents promise finite numbers and replace them before they get here)."""
    from ..core.display import indented_json  # json.dumps(indent=2, ensure_ascii=False), faster

    screen.echo(indented_json(document, allow_nan=not strict))
