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
from collections.abc import Callable, Iterable, Sequence, Set
from dataclasses import dataclass, field
from itertools import compress
from operator import ne
from typing import BinaryIO, Literal, NamedTuple, TypeVar

from .core.decode import UnreadableInput, decode
from .core.files import is_xml, read_list, reason, write_atomically
from .core.pause import pause
from .linting.config import KEEP, LEFT, RIGHT, FmtOptions
from .linting.discovery import Finder
from .linting.run import is_program, not_rewritten, write_error
from .syntax import parser as syntax
from .syntax.diff import unified_diff

NUMERIC_OR_REFERENCE = {syntax.INT, syntax.HEX, syntax.REAL, syntax.REFERENCE}
BLANKS = " \t"
TAB_WIDTH = 8
MIN_BLOCK = 3  # consecutive value lines that make a block alignment of their own
_Key = TypeVar("_Key")


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
    # worked out once, forgotten when the indent or the separator changes: `alignments()`, where the path
    # ends, where the value starts and ends (-1: not yet)
    aligned: tuple[Alignment, Alignment] | None = field(default=None, init=False)
    _path_end: int = field(default=-1, init=False)
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
        self.aligned, self._path_end, self._start, self._end = None, -1, -1, -1

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
        if self._path_end < 0:
            self._path_end = _advance(0, self._indent) + len(self.path)
        return self._path_end

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

    def fits(self, kept: Set[Alignment]) -> bool:
        """Whether the value stands in one of the `kept` alignments (an indented line never does)."""
        if self._indent:
            return False
        left, right = self.alignments()
        return left in kept or right in kept

    def copy(self) -> _Row:
        """The row as it is, to be changed on its own (with what it worked out already)."""
        row = _Row(self.line, self._indent, self._sep, self.sep2)
        row.aligned, row._path_end, row._start, row._end = (
            self.aligned,
            self._path_end,
            self._start,
            self._end,
        )
        return row

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


def _aligns(line: syntax.Line) -> bool:
    """Whether fmt aligns the line's value (an assignment it could read, with a value that is not broken)."""
    return (
        line.kind == syntax.ASSIGNMENT
        and line.path_ok
        and line.value is not None
        and line.value_kind != syntax.BAD_STRING
    )


def _rows(file: syntax.ListFile) -> list[_Row]:
    return [_Row(line, line.indent, line.sep, line.sep2) for line in file.lines if _aligns(line)]


def _row(line: syntax.Line) -> _Row:
    return _Row(line, line.indent, line.sep, line.sep2)


def _path_length(line: syntax.Line) -> int:
    """The length of the line's parameter path where it counts for the canonical column, else -1."""
    return len(line.path) if line.kind == syntax.ASSIGNMENT and line.path_ok and line.path else -1


def _width(row: _Row) -> int:
    """How wide the row is with two blanks between path and value (-1: a tab in its value's extent)."""
    return -1 if "\t" in row.tail else len(row.path) + 2 + len(row.tail)


def _vote(row: _Row, target: Alignment, kept: Set[Alignment]) -> bool | None:
    """The row's say in whether the file separates with tabs: whether its gap holds one, when the gap is wide
    enough for a tab and the row keeps its value where it is (None: no say). Only rows that stay vote:
    moving a row may narrow its gap below a tab."""
    if not _in_place(row, target, kept):
        return None
    if _next_stop(row.path_end) <= row.value_start:
        return "\t" in row.sep
    return None


def _uses_tabs(votes: Iterable[bool | None]) -> bool:
    """Whether the file separates with tabs: more tab-holding than blank-only gaps wide enough for a tab."""
    counted = Counter(votes)
    return counted[True] > counted[False]


def _most_common(counts: Counter[Alignment], kinds: Sequence[str]) -> Alignment | None:
    """The alignment most lines share (ties: left before right, then the smaller column)."""
    candidates = [alignment for alignment in counts if alignment.kind in kinds]
    if not candidates:
        return None
    return max(candidates, key=lambda a: (counts[a], a.kind == LEFT, -a.column))


def _here(row: _Row, main: Alignment) -> tuple[Alignment, ...]:
    """The alignments the row can make a block with: none when it is indented or in the main alignment."""
    if row.indent:
        return ()
    aligned = row.alignments()
    return () if main in aligned else aligned


def _blocks(rows: Sequence[_Row], main: Alignment) -> tuple[Alignment, ...]:
    """Alignments shared by a run of `MIN_BLOCK` consecutive value lines outside the main alignment."""
    longest: Counter[Alignment] = Counter()
    run: dict[Alignment, int] = {}
    for row in rows:
        run = {alignment: run.get(alignment, 0) + 1 for alignment in _here(row, main)}
        for alignment, length in run.items():
            longest[alignment] = max(longest[alignment], length)
    return tuple(sorted(alignment for alignment, length in longest.items() if length >= MIN_BLOCK))


def _canonical_column(file: syntax.ListFile) -> int:
    """Two blanks after the longest parameter path (0-based column of the values)."""
    return max(max(map(_path_length, file.lines), default=0), 0) + 2


class _Evidence(NamedTuple):
    """What the value alignment is decided from: the alignments of the value lines without indent (both
    ways), how many value lines there are, and the rest worked out only when the decision needs it."""

    counts: Counter[Alignment]
    rows: int
    blocks: Callable[[Alignment], tuple[Alignment, ...]]  # the block alignments beside a main one
    fitting: Callable[[set[Alignment]], int]  # how many value lines stand in one of these alignments
    canonical: Callable[[], int]  # the canonical value column
    widest: Callable[[], int]  # the widest value line written with two blanks (tab-free ones)


def _alignments(evidence: _Evidence, options: FmtOptions) -> Style:
    """Where the values go; the blank character and the comment column are found after this."""
    counts = evidence.counts
    majority = evidence.rows // 2 + 1
    main = _most_common(counts, (LEFT, RIGHT))
    if options.align_values == KEEP and options.value_column is None:
        if main is None or counts[main] < 2:
            return Style(None)
        blocks = evidence.blocks(main)
        kept = evidence.fitting({main, *blocks})
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
        return Style(Alignment(LEFT, evidence.canonical()))
    return Style(Alignment(RIGHT, evidence.widest()))


def _in_place(row: _Row, target: Alignment, kept: Set[Alignment]) -> bool:
    """Whether the row's value stays where it is: in the style already, or unable to move."""
    return row.fits(kept) or row.start_for(target) is None


def _place_value(row: _Row, target: Alignment, kept: Set[Alignment], tabs: bool) -> None:
    """Move the value if it is in none of the kept alignments; tidy the blanks if it is."""
    if row.fits(kept):
        row.sep = _pad(row.path_end, row.value_start, tabs)
        return
    start = row.start_for(target)
    if start is None:
        return  # a name too long for the column: the value stays where it is
    comment = row.comment_start
    row.indent, row.sep = "", _pad(len(row.path), start, tabs)
    if row.free:  # the comment stays in its column when the value leaves room for it
        end = row.value_end
        row.sep2 = _pad(end, comment if comment > end else end + 1, tabs)


def _mark(row: _Row) -> int | None:
    """Where the row's comment after its value starts, once placed, if it shows a column (two or more blanks
    before it); -1 when it shows none; None without such a comment."""
    if not row.free:
        return None
    start = row.comment_start
    return start if start - row.value_end >= 2 else -1


def _comment_column(marks: Iterable[int | None], style: Style, options: FmtOptions) -> int | None:
    """The comment column: the one given, else the start most comments showing a column share, if at least
    two and more than half of all comments after values do."""
    if options.comment_column is not None:
        return options.comment_column - 1
    if style.values is None:
        return None
    commented = 0
    starts: Counter[int] = Counter()
    for mark in marks:
        if mark is not None:
            commented += 1
            if mark >= 0:
                starts[mark] += 1
    return _chosen_column(starts, commented)


def _chosen_column(starts: Counter[int], commented: int) -> int | None:
    if not starts:
        return None
    column = max(starts, key=lambda start: (starts[start], -start))
    return column if starts[column] >= 2 and 2 * starts[column] > commented else None


def _place_comment(row: _Row, column: int | None, canonical: bool, tabs: bool) -> None:
    if not row.free:
        return
    end, start = row.value_end, row.comment_start
    if column is not None and start != column:
        start = column if column > end else end + 1
    elif canonical and column is None:
        start = end + 1
    row.sep2 = _pad(end, start, tabs)


def _evidence(file: syntax.ListFile, rows: Sequence[_Row]) -> _Evidence:
    return _Evidence(
        Counter(alignment for row in rows if not row.indent for alignment in row.alignments()),
        len(rows),
        lambda main: _blocks(rows, main),
        lambda kept: sum(1 for row in rows if row.fits(kept)),
        lambda: _canonical_column(file),
        lambda: max(max(map(_width, rows), default=0), 0),
    )


def _plan(file: syntax.ListFile, options: FmtOptions, canonical: bool = False) -> tuple[Style, list[_Row]]:
    rows = _rows(file)
    style = Style(None) if canonical else _alignments(_evidence(file, rows), options)
    target = style.values or Alignment(LEFT, _canonical_column(file))
    kept = {target, *style.blocks}
    tabs = style.values is not None and _uses_tabs(_vote(row, target, kept) for row in rows)
    for row in rows:
        _place_value(row, target, kept, tabs)
    comments = None if canonical else _comment_column(map(_mark, rows), style, options)
    for row in rows:
        _place_comment(row, comments, style.values is None, tabs)
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
    if end is not None and _drops_tail([line.kind for line in lines], end):
        lines = lines[: end + 1]
    usual = _usual_newline(line.newline for line in file.lines)
    out = []
    previous = ""
    for position, line in enumerate(lines):
        newline = line.newline
        if position == len(lines) - 1 and end is not None and position == end and not newline:
            newline = usual
        out.append(_unjoined(bodies[position], line.body, previous, newline) + newline)
        previous = newline
    return "".join(out)


def _drops_tail(kinds: Sequence[str], end: int) -> bool:
    """Whether the lines after the end marker go: all of them blank."""
    return kinds[end + 1 :].count(syntax.BLANK) == len(kinds) - end - 1


def _usual_newline(newlines: Iterable[str]) -> str:
    """The line break most lines end with (the end marker gets it when it has none)."""
    counted = Counter(newline for newline in newlines if newline)
    return counted.most_common(1)[0][0] if counted else "\n"


def _unjoined(body: str, original: str, previous: str, newline: str) -> str:
    """A formatted body, unless emptied its line's LF would join the CR before it into one CRLF."""
    return original if not body and previous.endswith("\r") and newline.startswith("\n") else body


Block = tuple[int, int, str]  # lines [first, stop) of the text are replaced by this text


class _Decision(NamedTuple):
    """What fmt decided about a whole file; every line's formatted text follows from these and the line."""

    style: Style  # its values and blocks
    target: Alignment
    kept: frozenset[Alignment]
    tabs: bool
    comments: int | None
    lefts: frozenset[int]  # the columns of the kept left alignments
    rights: frozenset[int]  # ... and of the kept right ones


# What LiveFormat keeps of a value line, worked out once from its text (a plain tuple: a 50,000-line list has
# tens of thousands of them, and a tuple is made and read far faster than an object with attributes):
# - 0: its `_Row.alignments()`, None when it is indented (it then stands in no alignment);
# - 1, 2: the columns of these alignments (where the value starts, where its extent ends);
# - 3: its `_width`;
# - 4: its `_vote` when its value stays where it is;
# - 5: its `_mark` when its value stays where it is;
# - 6: what becomes of it when its value stays where it is, blanks separate and its comment (if any) keeps its
#   column: 0 work it out (a tab between path and value or before the comment), 1 it stays byte for byte, 2
#   it only loses the blanks at its end;
# - 7: where its comment after the value starts (-1: it has none that fmt may move);
# - 8: where its value ends.
_Facts = tuple[tuple[Alignment, Alignment] | None, int, int, int, bool | None, int | None, int, int, int]
_ENDS_BLANK = (" ", "\t")


def _stays(facts: _Facts, lefts: Set[int], rights: Set[int]) -> bool:
    """Whether the value line's value stands in one of the kept alignments (`_Row.fits`)."""
    return facts[0] is not None and (facts[1] in lefts or facts[2] in rights)


def _comment_stays(facts: _Facts, decision: _Decision) -> bool:
    """Whether `_place_comment` leaves the comment of a line whose value stays where it was (and whose blanks
    are plain) as it is."""
    start, end = facts[7], facts[8]
    if start < 0:
        return True  # no comment fmt moves
    column = decision.comments
    if column is not None:
        return start == column or (column <= end and start == end + 1)
    return decision.style.values is not None or start == end + 1


class LiveFormat:
    """`format_file` of a list that is edited over and over (the language server answers formatting within a
    keystroke of an edit of a 50,000-line list): each `update` reads only the lines changed since the one
    before, and `changes` says which lines the formatting rewrites.

    fmt decides about the whole file (the alignments most value lines share, the runs of value lines that
    make a block, tabs or blanks, the comment column) from counts to which each line adds: an edit takes out
    what the lines it replaces added and adds what the new ones do. A run of `MIN_BLOCK` value lines in an
    alignment is counted as the windows of `MIN_BLOCK` consecutive value lines that share it (there is such a
    run exactly when there is such a window), so an edit recounts only the windows around it. Each line's
    formatted text is kept while the decisions stand; when an edit changes one, every line is formatted
    again. The result is `format_file`'s, byte for byte (tests compare them over random edits).

    What a value line adds to the counts is worked out once from its text (`_facts_of`); so is what it
    becomes when its value already stands in a kept alignment, as most values of a list in a layout do: such a
    line is only worked through `_Row` (the way `format_file` places it) when it has tabs, blanks at its end or
    a comment to move. Each line costs a few microseconds at first, not tens.
    """

    PAUSE_EVERY = 256  # lines between two pause points of the language server's worker (a few milliseconds)
    LOCAL_LINES = 2000  # changed lines an `update` that may not format every line reads at most

    def __init__(
        self, options: FmtOptions | None = None, parse_line: Callable[[str], syntax.Line] | None = None
    ) -> None:
        self.options = options or FmtOptions()
        self._parse_line = parse_line or _line_parser()
        self._raw: list[str] = []  # the lines as the parser reads them, with their breaks
        self._extra = False  # the last of them is the empty one the parser reads after a final line break
        self._lines: list[syntax.Line] = []
        self._kinds: list[str] = []
        self._facts: list[_Facts | None] = []  # each value line's `_facts_of` (None: not a line fmt aligns)
        self._lengths: list[int] = []  # each line's `_path_length`
        self._votes: list[bool | None] = []  # each line's say in tabs or blanks (`_vote`)
        # where each line's comment starts once its value is placed (`_mark`)
        self._marks: list[int | None] = []
        self._out: list[str] = []  # each line formatted, with its break (the line itself if unchanged)
        self._row_count = 0
        self._counts: Counter[Alignment] = Counter()  # alignments of value lines without indent
        self._pairs: Counter[tuple[Alignment, Alignment]] = Counter()  # ... both ways at once
        self._paths: Counter[int] = Counter()  # lengths of parameter paths (the canonical column)
        self._widths: Counter[int] = Counter()  # `_width` of value lines
        self._main: Alignment | None = None  # the main alignment `_runs` are counted beside
        self._runs: Counter[Alignment] = Counter()  # windows of MIN_BLOCK value lines sharing an alignment
        self._tab_votes: Counter[bool] = Counter()
        self._starts: Counter[int] = Counter()  # comment starts showing a column
        self._commented = 0  # value lines with a comment after the value
        self._decision: _Decision | None = None  # None: every line's formatting is to be worked out again
        # one Alignment object per column and kind (the counts and the facts share them: made once, and
        # compared by identity before by value)
        self._left_at: dict[int, Alignment] = {}
        self._right_at: dict[int, Alignment] = {}

    def update(self, raw_lines: Sequence[str], full: bool = True) -> bool:
        """Take the list's lines as they are now (with their breaks, as `syntax.split_lines` keeps them).
        Returns False, having formatted nothing, when the edit changes a decision about the whole file and
        `full` is false: formatting every line again is left to a call that allows it (as is an edit of
        more than `LOCAL_LINES` lines, or a first one)."""
        raw = list(raw_lines)
        extra = not raw or raw[-1].endswith(("\n", "\r"))
        if extra:
            raw.append("")  # as the parser reads the text
        old = self._raw
        first = _common_prefix(old, raw)
        same = _common_suffix(old, raw, first)
        old_stop, new_stop = len(old) - same, len(raw) - same
        if not full and (self._decision is None or max(old_stop, new_stop) - first > self.LOCAL_LINES):
            return False
        self._extra = extra
        if first == old_stop == new_stop and self._decision is not None:
            return True
        window = self._window(first, old_stop)
        self._count_runs(*window, -1)
        self._tally(first, old_stop, -1)
        decision = self._decision
        new = raw[first:new_stop]
        lines, facts, lengths = self._read(new)
        if decision is None:  # worked out with every other line
            votes: list[bool | None] = [None] * len(new)
            marks: list[int | None] = [None] * len(new)
        else:
            votes, marks = [], []
            for line, found in zip(lines, facts, strict=True):
                if found is None:
                    votes.append(None)
                    marks.append(None)
                elif _stays(found, decision.lefts, decision.rights):
                    votes.append(found[4])
                    marks.append(found[5])
                else:
                    row = _row(line)
                    votes.append(_vote(row, decision.target, decision.kept))
                    marks.append(self._placed(row, decision))
        self._raw[first:old_stop] = new
        self._lines[first:old_stop] = lines
        self._kinds[first:old_stop] = [line.kind for line in lines]
        self._facts[first:old_stop] = facts
        self._lengths[first:old_stop] = lengths
        self._votes[first:old_stop] = votes
        self._marks[first:old_stop] = marks
        self._out[first:old_stop] = [""] * len(new)
        self._tally(first, new_stop, 1)
        self._count_runs(window[0], window[1] + new_stop - old_stop, 1)
        return self._decide(first, new_stop, full)

    def _read(self, texts: Sequence[str]) -> tuple[list[syntax.Line], list[_Facts | None], list[int]]:
        """The lines of `texts` parsed, their facts (value lines) and their `_path_length`."""
        parse, facts_of = self._parse_line, self._facts_of
        lines: list[syntax.Line] = []
        facts: list[_Facts | None] = []
        # The facts of each line read here: a line that repeats another (lists joined from several exports
        # repeat thousands) is parsed into the same Line, and its facts are the same.
        known: dict[syntax.Line, _Facts | None] = {}

        def first_read(line: syntax.Line, body: str) -> _Facts | None:
            found = known[line] = (
                facts_of(line, body)
                if line.kind == syntax.ASSIGNMENT
                and line.path_ok
                and line.value is not None
                and line.value_kind != syntax.BAD_STRING
                else None
            )
            return found

        for begin in range(0, len(texts), self.PAUSE_EVERY):
            if begin:
                pause()
            bodies = [text.rstrip("\r\n") for text in texts[begin : begin + self.PAUSE_EVERY]]
            parsed = list(map(parse, bodies))
            lines += parsed
            facts += [
                known[line] if line in known else first_read(line, body)
                for line, body in zip(parsed, bodies, strict=True)
            ]
        lengths = [
            len(line.path) if line.kind == syntax.ASSIGNMENT and line.path_ok and line.path else -1
            for line in lines
        ]
        return lines, facts, lengths

    def _facts_of(self, line: syntax.Line, body: str) -> _Facts:
        """What LiveFormat keeps of a line fmt aligns (see `_Facts`), as `_Row` works it out."""
        indent, sep, sep2, rest = line.indent, line.sep, line.sep2, line.rest
        path, value = line.path or "", line.value or ""
        free = rest is not None and (line.value_kind in NUMERIC_OR_REFERENCE or rest.startswith("("))
        tail = value if rest is None or free else value + sep2 + rest.rstrip(BLANKS)
        if "\t" in body:
            path_end = _advance(0, indent) + len(path)
            tab = "\t" in sep
            start = _advance(path_end, sep)
            end = _advance(start, value)
            right = _advance(start, tail)
            comment = _advance(end, sep2) if free else -1
            plain = 0 if tab or (free and "\t" in sep2) else 2 if body.endswith(_ENDS_BLANK) else 1
            width = -1 if "\t" in tail else len(path) + 2 + len(tail)
        else:  # (most lines: every column is a length)
            path_end = len(indent) + len(path)
            tab = False
            start = path_end + len(sep)
            end = start + len(value)
            right = start + len(tail)
            comment = end + len(sep2) if free else -1
            plain = 2 if body.endswith(" ") else 1
            width = len(path) + 2 + len(tail)
        aligned = None
        if not indent:
            left_at, right_at = self._left_at, self._right_at
            aligned = (
                left_at.get(start) or left_at.setdefault(start, Alignment(LEFT, start)),
                right_at.get(right) or right_at.setdefault(right, Alignment(RIGHT, right)),
            )
        return (
            aligned,
            start,
            right,
            width,
            tab if (path_end // TAB_WIDTH + 1) * TAB_WIDTH <= start else None,
            (comment if comment - end >= 2 else -1) if free else None,
            plain,
            comment,
            end,
        )

    def changes(self) -> list[Block]:
        """The stretches of lines formatting rewrites, in order (lines after the end marker dropped: replaced
        by nothing)."""
        raw, out = self._raw, self._out
        end, last, usual = self._ending()
        changed = list(compress(range(last), map(ne, out[:last], raw[:last])))
        if usual is not None and (not changed or changed[-1] != last - 1):
            changed.append(last - 1)
        starts: list[int] = []  # the stretches: starts[k] up to stops[k], with texts[k]
        stops: list[int] = []
        texts: list[list[str]] = []
        for index in changed:
            text = out[index] + (usual if usual is not None and index == end else "")
            if stops and stops[-1] == index:
                stops[-1] = index + 1
                texts[-1].append(text)
            else:
                starts.append(index)
                stops.append(index + 1)
                texts.append([text])
        lines = len(raw) - self._extra
        if last < lines:  # the blank lines after the end marker
            if stops and stops[-1] == last:
                stops[-1] = lines
            else:
                starts.append(last)
                stops.append(lines)
                texts.append([])
        return [(first, stop, "".join(text)) for first, stop, text in zip(starts, stops, texts, strict=True)]

    def formatted(self, first: int, stop: int) -> list[str]:
        """Lines [first, stop) formatted, each with its break (lines after the end marker as well: `changes`
        drops them)."""
        return self._out[first:stop]

    def text(self) -> str:
        """The formatted text."""
        _, last, usual = self._ending()
        text = "".join(self._out[:last])
        return text + usual if usual is not None else text

    # -- the decisions -------------------------------------------------------------------------------
    def _decide(self, first: int, stop: int, full: bool) -> bool:
        main = _most_common(self._counts, (LEFT, RIGHT))
        if main != self._main:
            self._main, self._runs = main, Counter()
            self._count_runs(0, len(self._facts), 1)
        evidence = _Evidence(
            self._counts, self._row_count, self._blocks, self._fitting, self._canonical, self._widest
        )
        style = _alignments(evidence, self.options)
        target = style.values or Alignment(LEFT, self._canonical())
        kept = frozenset({target, *style.blocks})
        old = self._decision
        again = old is None or (old.target, old.kept) != (target, kept)
        if again and not full:
            self._decision = None
            return False
        lefts = frozenset(alignment.column for alignment in kept if alignment.kind == LEFT)
        rights = frozenset(alignment.column for alignment in kept if alignment.kind == RIGHT)
        stays: list[bool] | None = None  # (`_staying`, worked out once the first line is formatted again)
        if again:
            stays = self._staying(lefts, rights)
            self._vote_all(target, kept, stays)
        tabs = style.values is not None and self._tab_votes[True] > self._tab_votes[False]
        again = again or old is None or tabs != old.tabs
        if again and not full:
            self._decision = None
            return False
        decision = _Decision(style, target, kept, tabs, None, lefts, rights)
        placed: dict[int, _Row] = {}
        if again:
            stays = stays if stays is not None else self._staying(lefts, rights)
            placed = self._mark_all(decision, stays)
        if self.options.comment_column is not None:
            comments: int | None = self.options.comment_column - 1
        else:
            comments = None if style.values is None else _chosen_column(self._starts, self._commented)
        decision = decision._replace(comments=comments)
        again = (
            again
            or old is None
            or comments != old.comments
            or (style.values is None) != (old.style.values is None)
        )
        if again and not full:
            self._decision = None
            return False
        self._decision = decision
        if again:
            self._format_all(decision, placed, stays if stays is not None else self._staying(lefts, rights))
        else:
            for index in range(first, min(stop + 1, len(self._raw))):
                self._out[index] = self._formatted(index, decision)
        return True

    def _blocks(self, main: Alignment) -> tuple[Alignment, ...]:
        assert main == self._main  # the runs are counted beside it
        return tuple(sorted(self._runs))

    def _fitting(self, kept: set[Alignment]) -> int:
        return sum(count for (left, right), count in self._pairs.items() if left in kept or right in kept)

    def _canonical(self) -> int:
        return max(self._paths, default=0) + 2

    def _widest(self) -> int:
        return max(self._widths, default=0)

    # -- each line's part ----------------------------------------------------------------------------
    def _tally(self, first: int, stop: int, sign: int) -> None:
        """Add (sign 1) or take out (-1) what lines [first, stop) count for."""
        lengths = Counter(self._lengths[first:stop])
        lengths.pop(-1, None)
        _add(self._paths, lengths, sign)
        facts = [found for found in self._facts[first:stop] if found is not None]
        if not facts:
            return
        self._row_count += sign * len(facts)
        pairs = Counter([found[0] for found in facts if found[0] is not None])
        counts: Counter[Alignment] = Counter()
        for (left, right), count in pairs.items():
            counts[left] += count
            counts[right] += count
        _add(self._pairs, pairs, sign)
        _add(self._counts, counts, sign)
        widths = Counter([found[3] for found in facts])
        widths.pop(-1, None)
        _add(self._widths, widths, sign)
        if self._decision is None:
            return
        _add(self._tab_votes, Counter([vote for vote in self._votes[first:stop] if vote is not None]), sign)
        marks = [mark for mark in self._marks[first:stop] if mark is not None]
        self._commented += sign * len(marks)
        _add(self._starts, Counter([mark for mark in marks if mark >= 0]), sign)

    def _window(self, first: int, stop: int) -> tuple[int, int]:
        """The lines that hold every window of MIN_BLOCK value lines with a value line of [first, stop): from
        the MIN_BLOCK - 1st value line before `first` to the MIN_BLOCK - 1st from `stop` on."""
        facts = self._facts
        start, found = first, 0
        while start > 0 and found < MIN_BLOCK - 1:
            start -= 1
            found += facts[start] is not None
        end, found = stop, 0
        while end < len(facts) and found < MIN_BLOCK - 1:
            found += facts[end] is not None
            end += 1
        return start, end

    def _count_runs(self, first: int, stop: int, sign: int) -> None:
        """Count (or take out) the windows of MIN_BLOCK value lines within lines [first, stop) that share an
        alignment beside the main one."""
        main = self._main
        if main is None:
            return  # no main alignment, no blocks: counted once there is one
        # each value line's alignments it can make a block with (`_here`): none when it is indented or in the
        # main alignment
        here = [
            () if aligned is None or main in aligned else aligned
            for aligned in (found[0] for found in self._facts[first:stop] if found is not None)
        ]
        starts = range(len(here) - MIN_BLOCK + 1)
        for begin in range(0, len(starts), self.PAUSE_EVERY):
            if begin:
                pause()
            stop = begin + self.PAUSE_EVERY
            for start in compress(starts[begin:stop], here[begin:stop]):  # (the lines that can start a run)
                for alignment in set(here[start]).intersection(*here[start + 1 : start + MIN_BLOCK]):
                    _bump(self._runs, alignment, sign)

    def _staying(self, lefts: frozenset[int], rights: frozenset[int]) -> list[bool]:
        """For each line, whether it is a value line whose value stands in a kept alignment (`_stays`)."""
        return [
            found is not None and found[0] is not None and (found[1] in lefts or found[2] in rights)
            for found in self._facts
        ]

    def _vote_all(self, target: Alignment, kept: frozenset[Alignment], stays: list[bool]) -> None:
        votes: list[bool | None] = []
        facts, lines = self._facts, self._lines
        for begin in range(0, len(facts), self.PAUSE_EVERY):
            if begin:
                pause()
            stop = begin + self.PAUSE_EVERY
            votes += [
                None if found is None else found[4] if stay else _vote(_row(line), target, kept)
                for found, stay, line in zip(
                    facts[begin:stop], stays[begin:stop], lines[begin:stop], strict=True
                )
            ]
        self._votes = votes
        self._tab_votes = Counter([vote for vote in votes if vote is not None])

    def _mark_all(self, decision: _Decision, stays: list[bool]) -> dict[int, _Row]:
        """Every line's `_mark`; the value lines whose values move, placed (for `_formatted`)."""
        marks: list[int | None] = []
        placed: dict[int, _Row] = {}
        facts, lines = self._facts, self._lines

        def place(index: int) -> int | None:
            moved = placed[index] = _row(lines[index])
            _place_value(moved, decision.target, decision.kept, decision.tabs)
            return _mark(moved)

        for begin in range(0, len(facts), self.PAUSE_EVERY):
            if begin:
                pause()
            stop = begin + self.PAUSE_EVERY
            marks += [
                None if found is None else found[5] if stay else place(index)
                for (index, found), stay in zip(
                    enumerate(facts[begin:stop], begin), stays[begin:stop], strict=True
                )
            ]
        self._marks = marks
        commented = [mark for mark in marks if mark is not None]
        self._commented = len(commented)
        self._starts = Counter([mark for mark in commented if mark >= 0])
        return placed

    def _format_all(self, decision: _Decision, placed: dict[int, _Row], stays: list[bool]) -> None:
        """Every line formatted (`_formatted`); a plain line whose value and comment stay is found without
        `_Row`."""
        raw, facts, out, formatted = self._raw, self._facts, self._out, self._formatted
        plain = not decision.tabs  # (with tabs, a gap may change to tabs)
        column = decision.comments
        kept = column is None and decision.style.values is not None  # (every comment stays where it is)
        for begin in range(0, len(raw), self.PAUSE_EVERY):
            if begin:
                pause()
            stop = begin + self.PAUSE_EVERY
            out[begin:stop] = [
                (text if found[6] == 1 else _stripped(text))
                if plain
                and stay
                and found is not None
                and found[6]
                and (kept or found[7] < 0 or found[7] == column or _comment_stays(found, decision))
                else formatted(index, decision, placed.get(index))
                for (index, text), found, stay in zip(
                    enumerate(raw[begin:stop], begin), facts[begin:stop], stays[begin:stop], strict=True
                )
            ]

    @staticmethod
    def _placed(row: _Row, decision: _Decision) -> int | None:
        """`_mark` of the row with its value placed."""
        placed = row.copy()
        _place_value(placed, decision.target, decision.kept, decision.tabs)
        return _mark(placed)

    def _formatted(self, index: int, decision: _Decision, placed: _Row | None = None) -> str:
        """Line `index` formatted (`placed`: the line with its value placed already), with its break."""
        raw, line, found = self._raw[index], self._lines[index], self._facts[index]
        if found is None:
            body = _other_line(line)
        else:
            if placed is None:
                if (
                    not decision.tabs
                    and found[6]
                    and _stays(found, decision.lefts, decision.rights)
                    and _comment_stays(found, decision)
                ):
                    return raw if found[6] == 1 else _stripped(raw)
                placed = _row(line)
                _place_value(placed, decision.target, decision.kept, decision.tabs)
            _place_comment(placed, decision.comments, decision.style.values is None, decision.tabs)
            body = placed.body()
        text = raw.rstrip("\r\n")
        newline = raw[len(text) :]
        formatted = _unjoined(body, text, self._raw[index - 1] if index else "", newline) + newline
        return raw if formatted == raw else formatted

    def _ending(self) -> tuple[int | None, int, str | None]:
        """Where the end marker is, how many lines are kept, and the line break the end marker gets (None:
        it keeps its own)."""
        kinds, raw = self._kinds, self._raw
        end = kinds.index(syntax.END) if syntax.END in kinds else None
        if end is None or not _drops_tail(kinds, end):
            return end, len(raw), None
        if raw[end].endswith(("\n", "\r")):
            return end, end + 1, None
        return end, end + 1, _usual_newline(text[len(text.rstrip("\r\n")) :] for text in raw)


def _stripped(raw: str) -> str:
    """A line without the blanks at its end (its break kept)."""
    text = raw.rstrip("\r\n")
    return text.rstrip(BLANKS) + raw[len(text) :]


def _add(counts: Counter[_Key], counted: Counter[_Key], sign: int) -> None:
    """Add (sign 1) or take out (-1) `counted` from `counts` (`_bump` for each key)."""
    for key, count in counted.items():
        _bump(counts, key, sign * count)


def _bump(counts: Counter[_Key], key: _Key, sign: int) -> None:
    """Add `sign` to a count, forgetting counts that reach 0 (the decisions look at the keys)."""
    count = counts[key] + sign
    if count:
        counts[key] = count
    else:
        del counts[key]


def _line_parser() -> Callable[[str], syntax.Line]:
    """A parser of single lines that remembers the lines it read."""
    parsed: dict[str, syntax.Line] = {}

    def parse(body: str) -> syntax.Line:
        line = parsed.get(body)
        if line is None:
            line = parsed[body] = syntax.parse_text(body).lines[0]
        return line

    return parse


def _common_prefix(old: Sequence[str], new: Sequence[str]) -> int:
    """How many lines both start with (compared in stretches: unchanged lines are the same strings)."""
    low, high = 0, min(len(old), len(new))
    while low < high:
        middle = (low + high + 1) // 2
        if old[low:middle] == new[low:middle]:
            low = middle
        else:
            high = middle - 1
    return low


def _common_suffix(old: Sequence[str], new: Sequence[str], prefix: int) -> int:
    """How many lines both end with, not counting into the first `prefix` lines."""
    low, high = 0, min(len(old), len(new)) - prefix
    while low < high:
        middle = (low + high + 1) // 2
        if old[len(old) - middle : len(old) - low] == new[len(new) - middle : len(new) - low]:
            low = middle
        else:
            high = middle - 1
    return low


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
        if is_program(
            target.name
        ):  # its blocks are no `parameter value` lines: aligned, they would be garbled
            outcome.errors.append(f"{target.name}: fmt rewrites lists only, not NC programs")
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
