"""`achslint fmt`: consistent whitespace in the layout a list already has.

fmt first looks at how the file is laid out and keeps it:

* **where the values stand**: in one common column (left-aligned), or ending in
  one common column (right-aligned, as the numbers and names of ISG's sample
  lists are). The alignment most values share is the file's *main* alignment.
  A run of at least three consecutive value lines that shares another alignment
  (a section written in another style, as in the SDK's start-up list) is a
  *block* alignment: lines in it are kept too;
* **where the comments after values start**: the column most of them share,
  counting only comments set off by two or more blanks (a single blank after a
  value shows no column);
* **tabs or blanks** between name, value and comment (tab stops every
  `TAB_WIDTH` columns; columns are counted with tabs expanded).

A line whose layout already fits is left byte for byte as it is. A value in
none of the file's alignments moves to the main alignment (a name too long for
it keeps its value where it is); a comment moves to the comment column, or one
blank after the value when the value reaches past it; when the file has no
comment column, each comment keeps its column. `FmtOptions` replaces what is
detected by fixed choices. A file whose values share no column at all gets the
canonical layout:

* assignments start in column 1 and their values in one common column, two
  blanks after the longest parameter path of the file, separated by blanks;
* one blank before the comment that follows a value.

In every layout:

* the blanks before text after a string value that is not a `(` comment are
  left alone: they may be part of what the CNC reads (LIS007);
* no trailing blanks, and blank-only lines become empty lines;
* the end marker stands alone in column 1 and is the last line: blank lines
  after it are dropped and the file ends with a line break after `Ende`.

"Blank" means the space and the tab, nothing else: a no-break space, a form
feed or U+2028 is content to the CNC and to fmt. Names, values and comment text
are never touched, nor are lines the parser could not read (LIS001). Each line
keeps its own line break (no two lines are ever joined), the file keeps its
encoding and byte-order mark, and formatting twice changes nothing: lines are
only ever moved onto the alignments and the comment column that were detected,
so the formatted file shows the same layout again.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import BinaryIO, Literal, NamedTuple

from .core.decode import UnreadableInput, decode
from .core.files import is_xml, read_list, reason, write_atomically
from .linting.config import KEEP, LEFT, RIGHT, FmtOptions
from .linting.discovery import Finder
from .linting.run import not_rewritten, write_error
from .syntax import parser as syntax
from .syntax.diff import unified_diff

NUMERIC_OR_REFERENCE = {syntax.INT, syntax.HEX, syntax.REAL, syntax.REFERENCE}
BLANKS = " \t"
TAB_WIDTH = 8
MIN_BLOCK = 3  # consecutive value lines that make a block alignment of their own


class Alignment(NamedTuple):
    """Values starting (left) or ending (right) in one column, counted from 0 with tabs expanded.

    For right alignment `column` is the column just after the last character. (A named tuple: every row
    makes two and the layout is found by counting them, which a dataclass makes several times slower.)
    """

    kind: Literal["left", "right"]
    column: int

    def describe(self) -> str:
        if self.kind == LEFT:
            return f"values start in column {self.column + 1}"
        return f"values end in column {self.column}"


@dataclass(frozen=True)
class Style:
    """The layout of a file: what fmt keeps. `values` None means the canonical layout."""

    values: Alignment | None
    blocks: tuple[Alignment, ...] = ()
    comments: int | None = None  # 0-based column of comments after values; None: each where it is
    tabs: bool = False

    def describe(self) -> str:
        if self.values is None:
            return "no common value column: canonical layout"
        parts = [self.values.describe()]
        parts += [f"a block where {block.describe()}" for block in self.blocks]
        parts.append(
            f"comments in column {self.comments + 1}" if self.comments is not None else "comments kept"
        )
        parts.append("tabs" if self.tabs else "blanks")
        return ", ".join(parts)


def _advance(column: int, text: str) -> int:
    """The column after `text` written from `column` (tabs to the next tab stop)."""
    if "\t" not in text:
        return column + len(text)
    for char in text:
        column = _next_stop(column) if char == "\t" else column + 1
    return column


def _next_stop(column: int) -> int:
    return (column // TAB_WIDTH + 1) * TAB_WIDTH


def _pad(start: int, stop: int, tabs: bool) -> str:
    """Whitespace from column `start` to `stop`: tabs as far as they go (if `tabs`), then blanks."""
    out = ""
    while tabs and _next_stop(start) <= stop:
        out += "\t"
        start = _next_stop(start)
    return out + " " * (stop - start)


def _comment_is_free(line: syntax.Line) -> bool:
    """Whether the blanks before the trailing text are plain separators the CNC ignores."""
    return line.value_kind in NUMERIC_OR_REFERENCE or (line.rest or "").startswith("(")


@dataclass(slots=True)
class _Row:
    """A line with a value, and the whitespace fmt may change in it."""

    line: syntax.Line
    _indent: str
    _sep: str
    sep2: str
    free: bool = field(init=False)
    # worked out once, forgotten when the indent or the separator changes: `alignments()`, where the value
    # starts and ends (-1: not yet)
    aligned: tuple[Alignment, Alignment] | None = field(default=None, init=False)
    _start: int = field(default=-1, init=False)
    _end: int = field(default=-1, init=False)

    def __post_init__(self) -> None:
        self.free = self.line.rest is not None and _comment_is_free(self.line)

    @property
    def indent(self) -> str:
        return self._indent

    @indent.setter
    def indent(self, indent: str) -> None:
        self._indent = indent
        self.aligned, self._start, self._end = None, -1, -1

    @property
    def sep(self) -> str:
        return self._sep

    @sep.setter
    def sep(self, sep: str) -> None:
        self._sep = sep
        self.aligned, self._start, self._end = None, -1, -1

    @property
    def path(self) -> str:
        return self.line.path or ""

    @property
    def value(self) -> str:
        return self.line.value or ""

    @property
    def path_end(self) -> int:
        return _advance(0, self.indent) + len(self.path)

    @property
    def value_start(self) -> int:
        if self._start < 0:
            self._start = _advance(self.path_end, self._sep)
        return self._start

    @property
    def value_end(self) -> int:
        if self._end < 0:
            self._end = _advance(self.value_start, self.value)
        return self._end

    @property
    def tail(self) -> str:
        """What belongs to the value's right edge: the text after a string the CNC may read as part of it."""
        if self.line.rest is None or self.free:
            return self.value
        return self.value + self.sep2 + self.line.rest.rstrip(BLANKS)

    @property
    def extent_end(self) -> int:
        return _advance(self.value_start, self.tail)

    @property
    def comment_start(self) -> int:
        return _advance(self.value_end, self.sep2)

    def alignments(self) -> tuple[Alignment, Alignment]:
        """Where the value stands, both ways."""
        if self.aligned is None:
            start = self.value_start
            self.aligned = Alignment(LEFT, start), Alignment(RIGHT, _advance(start, self.tail))
        return self.aligned

    def fits(self, kept: set[Alignment]) -> bool:
        """Whether the value stands in one of the `kept` alignments (an indented line never does)."""
        return not self.indent and any(alignment in kept for alignment in self.alignments())

    def start_for(self, alignment: Alignment) -> int | None:
        """Where the value starts in `alignment`, written without indent; None if the line cannot get there."""
        if alignment.kind == LEFT:
            start = alignment.column
        elif "\t" in self.tail:  # its width would change with where it stands
            return None
        else:
            start = alignment.column - len(self.tail)
        return start if start > len(self.path) else None

    def body(self) -> str:
        line = self.line
        text = self.indent + self.path + self.sep + self.value
        if line.rest is not None:
            text += self.sep2 + line.rest
        return text.rstrip(BLANKS)


def _rows(file: syntax.ListFile) -> list[_Row]:
    return [
        _Row(line, line.indent, line.sep, line.sep2)
        for line in file.lines
        if line.kind == syntax.ASSIGNMENT
        and line.path_ok
        and line.value is not None
        and line.value_kind != syntax.BAD_STRING
    ]


def _uses_tabs(rows: Iterable[_Row]) -> bool:
    """Whether the file separates with tabs: more tab-holding than blank-only gaps wide enough for a tab."""
    votes: Counter[bool] = Counter()
    for row in rows:
        if _next_stop(row.path_end) <= row.value_start:
            votes["\t" in row.sep] += 1
    return votes[True] > votes[False]


def _most_common(counts: Counter[Alignment], kinds: Sequence[str]) -> Alignment | None:
    """The alignment most lines share (ties: left before right, then the smaller column)."""
    candidates = [alignment for alignment in counts if alignment.kind in kinds]
    if not candidates:
        return None
    return max(candidates, key=lambda a: (counts[a], a.kind == LEFT, -a.column))


def _blocks(rows: Sequence[_Row], main: Alignment) -> tuple[Alignment, ...]:
    """Alignments shared by a run of `MIN_BLOCK` consecutive value lines outside the main alignment."""
    longest: Counter[Alignment] = Counter()
    run: dict[Alignment, int] = {}
    for row in rows:
        here = () if row.indent else row.alignments()
        if main in here:
            here = ()
        run = {alignment: run.get(alignment, 0) + 1 for alignment in here}
        for alignment, length in run.items():
            longest[alignment] = max(longest[alignment], length)
    return tuple(sorted(alignment for alignment, length in longest.items() if length >= MIN_BLOCK))


def _canonical_column(file: syntax.ListFile) -> int:
    """Two blanks after the longest parameter path (0-based column of the values)."""
    lengths = [
        len(line.path) for line in file.lines if line.kind == syntax.ASSIGNMENT and line.path_ok and line.path
    ]
    return max(lengths, default=0) + 2


def _alignments(file: syntax.ListFile, rows: Sequence[_Row], options: FmtOptions) -> Style:
    """Where the values go; the blank character and the comment column are found after this."""
    evidence = [row for row in rows if not row.indent]
    counts = Counter(alignment for row in evidence for alignment in row.alignments())
    majority = len(rows) // 2 + 1
    main = _most_common(counts, (LEFT, RIGHT))
    if options.align_values == KEEP and options.value_column is None:
        if main is None or counts[main] < 2:
            return Style(None)
        blocks = _blocks(rows, main)
        kept = sum(1 for row in rows if row.fits({main, *blocks}))
        return Style(main, blocks) if kept >= majority else Style(None)
    # A column given alone means left-aligned values, as in the canonical layout: taking the kind
    # from the file instead would not survive formatting (the forced column can change which kind
    # the file shows).
    kind = RIGHT if options.align_values == RIGHT else LEFT
    if options.value_column is not None:
        return Style(Alignment(kind, options.value_column - 1 if kind == LEFT else options.value_column))
    usual = _most_common(counts, (kind,))
    if usual is not None and counts[usual] >= max(2, majority):
        return Style(usual)
    if kind == LEFT:
        return Style(Alignment(LEFT, _canonical_column(file)))
    widest = max((len(row.path) + 2 + len(row.tail) for row in rows if "\t" not in row.tail), default=0)
    return Style(Alignment(RIGHT, widest))


def _in_place(row: _Row, target: Alignment, kept: set[Alignment]) -> bool:
    """Whether the row's value stays where it is: in the style already, or unable to move."""
    return row.fits(kept) or row.start_for(target) is None


def _place_values(rows: Sequence[_Row], target: Alignment, kept: set[Alignment], tabs: bool) -> None:
    """Move values that are in none of the kept alignments; tidy the blanks of those that are."""
    for row in rows:
        if row.fits(kept):
            row.sep = _pad(row.path_end, row.value_start, tabs)
            continue
        start = row.start_for(target)
        if start is None:
            continue  # a name too long for the column: the value stays where it is
        comment = row.comment_start
        row.indent, row.sep = "", _pad(len(row.path), start, tabs)
        if row.free:  # the comment stays in its column when the value leaves room for it
            end = row.value_end
            row.sep2 = _pad(end, comment if comment > end else end + 1, tabs)


def _comment_column(rows: Sequence[_Row], style: Style, options: FmtOptions) -> int | None:
    if options.comment_column is not None:
        return options.comment_column - 1
    if style.values is None:
        return None
    commented = [row for row in rows if row.free]
    starts = Counter(row.comment_start for row in commented if row.comment_start - row.value_end >= 2)
    if not starts:
        return None
    column = max(starts, key=lambda start: (starts[start], -start))
    return column if starts[column] >= 2 and 2 * starts[column] > len(commented) else None


def _place_comments(rows: Sequence[_Row], column: int | None, canonical: bool, tabs: bool) -> None:
    for row in rows:
        if not row.free:
            continue
        end, start = row.value_end, row.comment_start
        if column is not None and start != column:
            start = column if column > end else end + 1
        elif canonical and column is None:
            start = end + 1
        row.sep2 = _pad(end, start, tabs)


def _plan(file: syntax.ListFile, options: FmtOptions, canonical: bool = False) -> tuple[Style, list[_Row]]:
    rows = _rows(file)
    style = Style(None) if canonical else _alignments(file, rows, options)
    target = style.values or Alignment(LEFT, _canonical_column(file))
    kept = {target, *style.blocks}
    # Only rows that keep their value where it is vote: moving a row may narrow its gap below a tab.
    tabs = style.values is not None and _uses_tabs(row for row in rows if _in_place(row, target, kept))
    _place_values(rows, target, kept, tabs)
    comments = None if canonical else _comment_column(rows, style, options)
    _place_comments(rows, comments, style.values is None, tabs)
    return Style(style.values, style.blocks, comments, tabs), rows


def detect_style(file: syntax.ListFile, options: FmtOptions | None = None) -> Style:
    """The layout fmt keeps in a parsed list."""
    return _plan(file, options or FmtOptions())[0]


def _other_line(line: syntax.Line) -> str:
    """The body of a line without a value fmt could align."""
    if line.kind == syntax.BLANK:
        return ""
    if line.kind == syntax.COMMENT:
        return (line.indent + (line.comment or "")).rstrip(BLANKS)
    if line.kind == syntax.END:
        rest = f" {line.rest.rstrip(BLANKS)}" if line.rest else ""
        return (line.path or "") + rest
    if not line.path_ok or line.value_kind == syntax.BAD_STRING:
        return line.body.rstrip(BLANKS)
    return line.path or ""


def formatted_lines(
    file: syntax.ListFile, options: FmtOptions | None = None, *, canonical: bool = False
) -> list[str]:
    """The formatted body (without line break) of every line of the list, in order."""
    _, rows = _plan(file, options or FmtOptions(), canonical)
    bodies = {id(row.line): row.body() for row in rows}
    return [bodies[id(line)] if id(line) in bodies else _other_line(line) for line in file.lines]


def format_file(file: syntax.ListFile, options: FmtOptions | None = None, *, canonical: bool = False) -> str:
    """The formatted text of a parsed list (`canonical`: the canonical layout, whatever the file's own)."""
    bodies = formatted_lines(file, options, canonical=canonical)
    lines = list(file.lines)
    end = file.end_index
    if end is not None and all(line.kind == syntax.BLANK for line in lines[end + 1 :]):
        lines = lines[: end + 1]
    newlines = Counter(line.newline for line in file.lines if line.newline)
    usual = newlines.most_common(1)[0][0] if newlines else "\n"
    out = []
    previous = ""
    for position, line in enumerate(lines):
        newline = line.newline
        if position == len(lines) - 1 and end is not None and position == end and not newline:
            newline = usual
        body = bodies[position]
        if not body and previous.endswith("\r") and newline.startswith("\n"):
            body = line.body  # emptied, this line's LF would join the CR before it into one CRLF
        out.append(body + newline)
        previous = newline
    return "".join(out)


def format_text(text: str, name: str = "<string>", options: FmtOptions | None = None) -> str:
    """The formatted version of a list's text."""
    return format_file(syntax.parse_text(text, name), options)


def canonical_text(text: str, name: str = "<string>") -> str:
    """A list's text in the canonical layout (for lists written by programs)."""
    return format_file(syntax.parse_text(text, name), canonical=True)


def format_bytes(data: bytes, name: str = "<bytes>", options: FmtOptions | None = None) -> tuple[bytes, bool]:
    """(formatted bytes, changed). Raises `decode.UnreadableInput` for UTF-16/32 input."""
    source = decode(data)
    file = syntax.parse_text(source.text, name, encoding=source.encoding, bom=source.bom)
    formatted = source.encode(format_file(file, options))
    return formatted, formatted != data


def changed_lines(data: bytes, options: FmtOptions | None = None) -> int:
    """How many lines formatting changes (dropped blank lines after `Ende` count too)."""
    formatted, _ = format_bytes(data, options=options)
    before = syntax.split_lines(decode(data).text, keepends=True)
    after = syntax.split_lines(decode(formatted).text, keepends=True)
    differing = sum(1 for old, new in zip(before, after, strict=False) if old != new)
    return differing + abs(len(before) - len(after))


@dataclass
class FormatRequest:
    paths: list[str]
    config_file: str | None = None
    stdin_filename: str | None = None
    mode: str = "write"  # write | check (change nothing) | diff (change nothing, say how)
    follow_startup: bool = False  # also rewrite the lists a named start-up list reaches in other folders


@dataclass
class Formatted:
    name: str
    changed: bool
    written: bool = False
    diff: str = ""  # mode diff: the unified diff
    output: bytes | None = None  # standard input in write mode: the formatted bytes


@dataclass
class FormatOutcome:
    results: list[Formatted]
    errors: list[str]
    notes: list[str]
    found: int  # lists found (XML files found in folders are not fmt's business and not counted)

    @property
    def changed(self) -> int:
        return sum(result.changed for result in self.results)

    @property
    def written(self) -> int:
        return sum(result.written for result in self.results)


def run_format(request: FormatRequest, stdin: BinaryIO | None = None) -> FormatOutcome:
    """`achslint fmt`: format every list the paths name, writing (atomically, only if the file did not
    change meanwhile), checking or diffing. Raises `ConfigError`."""

    finder = Finder(
        config_file=request.config_file,
        stdin_filename=request.stdin_filename,
        follow_startup=request.follow_startup,
        machine_rules=lambda path: False,  # fmt reads no neighbours
    )
    found = finder.find(request.paths)
    kept = [t for t in found.targets if not t.writable] if request.mode == "write" else []
    targets = found.targets  # the start-up lists named or found in a named folder among them (their own kind)
    outcome = FormatOutcome([], list(found.errors), [*found.notes, *not_rewritten(kept)], len(targets))
    for target in targets:
        if target in kept:
            continue
        if is_xml(target.name):
            if target.name in request.paths:  # XML found in a folder is simply not fmt's business
                outcome.errors.append(f"{target.name}: fmt rewrites plain lists only, not XML files")
            continue
        try:
            if target.path is not None:
                data = read_list(target.path)
            elif stdin is not None:
                data = stdin.read()
            else:
                outcome.errors.append(f"{target.name}: no standard input to read")
                continue
            formatted, differs = format_bytes(data, target.name, target.config.settings.fmt)
        except OSError as exc:
            outcome.errors.append(f"cannot read {target.name}: {reason(exc)}")
            continue
        except UnreadableInput as exc:
            outcome.errors.append(f"{target.name}: {exc}")
            continue
        result = Formatted(target.name, differs)
        if request.mode == "diff":
            result.diff = unified_diff(data, formatted, target.name) if differs else ""
        elif request.mode == "write" and target.path is None:
            result.output = formatted
        elif request.mode == "write" and differs and target.path is not None:
            try:
                write_atomically(target.path, formatted, expected=data)
                result.written = True
            except OSError as exc:
                outcome.errors.append(write_error(exc, target.name))
        outcome.results.append(result)
    return outcome
