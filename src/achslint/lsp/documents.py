"""Open documents: their text, LSP positions, and a parse that only re-reads edited lines.

This module does not import pygls, so the benchmarks and tests can use it on its own.

Lines are numbered as the parser numbers them (only CR, LF and CRLF end a line, as in the
Language Server Protocol), not by `str.splitlines`, which also breaks at form feeds and
U+2028 and would shift every line after them. Columns in achslint are code points, 1-based;
LSP positions are 0-based and count UTF-16 code units unless the client agreed on UTF-32
(code points) or UTF-8.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field, replace
from pathlib import Path

from ..core.pause import pause
from ..syntax.parser import BLANK, END, Line, ListFile, parse_text, split_lines

BOM = "\ufeff"


def units(text: str, encoding: str) -> int:
    """The length of `text` in the client's position units."""
    if encoding == "utf-32" or text.isascii():
        return len(text)
    if encoding == "utf-8":
        return len(text.encode("utf-8", "surrogatepass"))
    return len(text) + sum(1 for char in text if ord(char) > 0xFFFF)


def code_points(text: str, count: int, encoding: str) -> int:
    """How many code points of `text` make up `count` units (clamped to the text)."""
    if encoding == "utf-32" or text.isascii():
        return max(0, min(count, len(text)))
    seen = 0
    for index, char in enumerate(text):
        if seen >= count:
            return index
        seen += units(char, encoding)
    return len(text)


class LineCache:
    """Parses a document line by line, reusing the lines an edit did not touch.

    Every line of a list is read on its own by the grammar (a line break always ends a
    statement), so parsing the changed lines and keeping the others gives the same lines
    as parsing the whole text; a test checks this on generated edits.
    """

    LIMIT = 1 << 16  # distinct line texts kept; a pathological document cannot grow it without bound
    PAUSE_EVERY = 4096  # lines between two pause points of the language server's worker (a few ms)

    def __init__(self, templates: LineCache | None = None) -> None:
        # line body -> its parse (number 0, no line break); shared with `templates` (read-only lines, each
        # thread parsing with its own cache keeps its own `_previous`)
        self._parsed: dict[str, Line] = templates._parsed if templates is not None else {}
        self._previous: dict[
            tuple[int, str], Line
        ] = {}  # (number, text with break) -> Line of the last parse

    def line(self, body: str) -> Line:
        """The parse of one line's text (no line break; number 0): shared, never to be changed."""
        template = self._parsed.get(body)
        if template is None:
            if len(self._parsed) > self.LIMIT:
                self._parsed.clear()
            template = self._parsed[body] = parse_text(body).lines[0]
        return template

    def parse(self, text: str, name: str, raw_lines: list[str] | None = None) -> ListFile:
        raw_lines = list(raw_lines) if raw_lines is not None else split_lines(text, keepends=True)
        if not raw_lines or raw_lines[-1].endswith(("\n", "\r")):
            raw_lines.append("")  # the parser reads an empty last line after a final line break
        previous, current = self._previous, {}
        lines: list[Line] = []
        end_index = None
        for number, raw in enumerate(raw_lines, 1):
            if not number % self.PAUSE_EVERY:
                pause()
            key = (number, raw)
            line = previous.get(key)
            if line is None:
                body = raw.rstrip("\r\n")
                line = copy.copy(self.line(body))
                line.newline = raw[len(body) :]
                line.number = number
            current[key] = line
            lines.append(line)
            if end_index is None and line.kind == END:
                end_index = number - 1
        self._previous = current
        return ListFile(name=name, lines=lines, end_index=end_index)


@dataclass
class Document:
    """An open document. Its lines (with their breaks) are kept up to date by `apply`, which re-reads only
    the lines an edit touches: a keystroke in a 50,000-line list does not split the whole text again."""

    uri: str
    path: Path | None  # None for documents that are not files (untitled, other schemes)
    text: str
    version: int | None = None
    encoding: str = "utf-16"  # the position encoding agreed with the client
    _raw: list[str] | None = field(default=None, repr=False)  # the lines with their breaks (never mutated)
    cache: LineCache = field(default_factory=LineCache, repr=False)

    @property
    def name(self) -> str:
        """What diagnostics and results call the document: its path, else its URI."""
        return str(self.path) if self.path is not None else self.uri

    @property
    def lines(self) -> list[str]:
        """Line texts without their breaks, numbered as the parser numbers them."""
        return [self._text_of(number) for number in range(1, self.line_count + 1)]

    @property
    def raw_lines(self) -> list[str]:
        if self._raw is None:
            self._raw = split_lines(self.text, keepends=True)
        return self._raw

    @property
    def body_lines(self) -> list[str]:
        """The lines (with their breaks) of the text as achslint reads it: the first without a byte-order mark."""
        raw = self.raw_lines
        return [raw[0][1:], *raw[1:]] if self.bom else raw

    @property
    def line_count(self) -> int:
        """How many lines the parser reads (an empty last one after a final line break)."""
        raw = self.raw_lines
        return len(raw) + (1 if not raw or raw[-1].endswith(("\n", "\r")) else 0)

    @property
    def bom(self) -> bool:
        return self.text.startswith(BOM)

    @property
    def body(self) -> str:
        """The text as achslint reads it: without a byte-order mark the editor kept as a character."""
        return self.text[1:] if self.bom else self.text

    def _text_of(self, number: int) -> str:
        raw = self.raw_lines
        return raw[number - 1].rstrip("\r\n") if 1 <= number <= len(raw) else ""

    def line(self, number: int) -> str:
        """Line `number` (1-based) as achslint sees it (without the byte-order mark)."""
        text = self._text_of(number)
        return text[1:] if number == 1 and self.bom else text

    # -- positions -------------------------------------------------------------------------------
    def to_lsp(self, line: int, column: int) -> tuple[int, int]:
        """A 1-based achslint (line, column) as a 0-based LSP (line, character)."""
        line = max(1, min(line, self.line_count))
        text = self.line(line)
        column = max(1, min(column, len(text) + 1))
        shift = 1 if line == 1 and self.bom else 0
        return line - 1, units(text[: column - 1], self.encoding) + shift

    def from_lsp(self, line: int, character: int) -> tuple[int, int]:
        """A 0-based LSP position as a 1-based achslint (line, column), clamped to the document."""
        number = max(1, min(line + 1, self.line_count))
        text = self.line(number)
        if number == 1 and self.bom:
            character = max(0, character - 1)
        return number, code_points(text, character, self.encoding) + 1

    # -- edits -----------------------------------------------------------------------------------
    def offset(self, line: int, character: int) -> int:
        """The offset in `text` of an LSP position (clamped)."""
        raw = self.raw_lines
        if line >= len(raw):
            return len(self.text)
        start = sum(map(len, raw[:line]))
        body = raw[line].rstrip("\r\n")
        return start + code_points(body, character, self.encoding)

    def apply(self, start: tuple[int, int] | None, end: tuple[int, int] | None, new_text: str) -> None:
        """Apply one content change (a whole-document change when `start` is None)."""
        if start is None or end is None:
            self.text = new_text
            self._raw = None
            return
        raw = self.raw_lines
        a = self.offset(*start)
        b = max(a, self.offset(*end))
        # The lines from the one before the edit to the one after it are read again: a line break can join
        # or split only there (a CR before the edit and an LF after it become one CRLF, for example).
        first = max(min(start[0], len(raw)) - 1, 0)
        last = min((end[0] if b > a else start[0]) + 2, len(raw))
        region = sum(map(len, raw[:first]))
        old_length = sum(map(len, raw[first:last]))
        self.text = self.text[:a] + new_text + self.text[b:]
        changed = self.text[region : region + old_length + len(new_text) - (b - a)]
        self._raw = [*raw[:first], *split_lines(changed, keepends=True), *raw[last:]]

    def adopt_lines(self, other: Document) -> None:
        """Take the lines another thread split from this very text (they cost a pass over a large text)."""
        if self._raw is None and other.text is self.text:
            self._raw = other._raw

    def copy(self) -> Document:
        """This version of the document, to lint while the editor goes on changing the original: the text
        and its lines are shared (neither is ever changed in place), the parse cache too (only the worker
        thread parses)."""
        return Document(self.uri, self.path, self.text, self.version, self.encoding, self._raw, self.cache)

    def parse(self, cache: LineCache | None = None) -> ListFile:
        """The parse of the text, with the document's cache (the worker's) or `cache` (another thread's)."""
        cache = cache or self.cache
        if self.bom:  # read without the mark, and known to have one (LIS006)
            return replace(cache.parse(self.body, self.name), bom=True)
        return cache.parse(self.text, self.name, self.raw_lines)


def blank_file(name: str) -> ListFile:
    return ListFile(name=name, lines=[Line(BLANK, number=1)])
