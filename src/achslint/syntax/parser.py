"""Text to a lossless syntax tree, using the Lark grammar in grammars/achsmds.lark.

The tree is flat because the format is: a list of `Line` objects, each holding
the exact text of its parts (indent, path, separators, value, trailing text,
line break). Joining the parts of every line gives back the input, character
for character; columns are derived from the part lengths, so they are exact
for tabs and for any line-break style.
"""

from __future__ import annotations

import re
import sys
import threading
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field, fields
from functools import lru_cache
from operator import attrgetter
from pathlib import Path
from typing import TYPE_CHECKING, Any, cast

from .numbers import parse_int

if TYPE_CHECKING:
    from lark import Lark, Token

BLANK = "blank"
COMMENT = "comment"
END = "end"
ASSIGNMENT = "assignment"

# Value kinds, as named by the grammar's value alternatives.
INT, HEX, REAL, REFERENCE, STRING, BAD_STRING, SYMBOL = (
    "int",
    "hex",
    "real",
    "reference",
    "string",
    "bad_string",
    "symbol",
)

GRAMMAR_NAME = "achsmds.lark"

# Separators, line breaks and parameter paths repeat on every line of a list:
# sharing one string object per spelling keeps large lists small in memory.
_intern = sys.intern


@dataclass(slots=True, eq=False)
class Line:
    """One physical line. Text parts are kept verbatim; `None` means absent."""

    kind: str
    indent: str = ""
    path: str | None = None
    path_ok: bool = True
    sep: str = ""
    value: str | None = None
    value_kind: str | None = None
    sep2: str = ""
    rest: str | None = None
    comment: str | None = None
    newline: str = ""
    number: int = 0

    @property
    def body(self) -> str:
        """The line without its line break."""
        if self.kind == COMMENT:
            return self.indent + (self.comment or "")
        parts = [self.indent, self.path or "", self.sep, self.value or "", self.sep2, self.rest or ""]
        return "".join(parts)

    @property
    def text(self) -> str:
        return self.body + self.newline

    @property
    def path_column(self) -> int:
        return len(self.indent) + 1

    @property
    def value_column(self) -> int:
        return self.path_column + len(self.path or "") + len(self.sep)

    @property
    def rest_column(self) -> int:
        return self.value_column + len(self.value or "") + len(self.sep2)

    @property
    def end_column(self) -> int:
        """Column just after the last character of the line (before the break)."""
        return len(self.body) + 1


@dataclass(slots=True, eq=False)
class ListFile:
    """A parsed list: the lines plus where the text came from."""

    name: str
    lines: list[Line]
    encoding: str = "utf-8"
    bom: bool = False
    end_index: int | None = field(default=None)

    def unparse(self) -> str:
        return "".join(line.text for line in self.lines)

    def offsets(self) -> list[int]:
        """Character offset of the start of every line."""
        result: list[int] = []
        offset = 0
        for line in self.lines:
            result.append(offset)
            offset += len(line.body) + len(line.newline)
        return result

    def assignments(self) -> Iterator[Line]:
        """Assignments the CNC reads: those before the end marker."""
        stop = self.end_index if self.end_index is not None else len(self.lines)
        for line in self.lines[:stop]:
            if line.kind == ASSIGNMENT:
                yield line


def _grammar_text() -> str:
    here = Path(__file__).resolve().parent
    packaged = here / "grammars" / GRAMMAR_NAME
    if packaged.is_file():  # installed wheel: the grammar ships inside the package
        text = packaged.read_text(encoding="utf-8")
    else:  # source checkout / editable install: the grammar lives at the repository root
        text = (here.parents[2] / "grammars" / GRAMMAR_NAME).read_text(encoding="utf-8")
    return text if sys.version_info >= (3, 11) else _without_possessive(text)


def _without_possessive(grammar: str) -> str:
    """The grammar for Python 3.10, whose regular expressions have no possessive repeats: the PATH
    terminal's `*+` / `++` as `*` / `+` (the same text matches: see the grammar)."""
    lines = grammar.split("\n")
    for index, line in enumerate(lines):
        if line.startswith("PATH."):
            lines[index] = line.replace("*+", "*").replace("++", "+")
    return "\n".join(lines)


# A value alternative reduced: (kind, blanks before the value, value text).
_ValueParts = tuple[str, str, str]


def _value(kind: str) -> Callable[[_Builder, list[Token]], _ValueParts]:
    """The builder method of one value alternative."""

    def build(self: _Builder, children: list[Token]) -> _ValueParts:
        text = str(children[0])
        value = text.lstrip(" \t")
        return (kind, _intern(text[: len(text) - len(value)]), value)

    return build


class _Builder:
    """Inline transformer: builds `Line` objects while Lark reduces the rules.

    The rules that combine reduced parts (`assignment`, `line`, `body`) receive children of mixed kinds
    (tokens, the tuples and lines built here), hence their `list[Any]`.
    """

    int = _value(INT)
    hex = _value(HEX)
    real = _value(REAL)
    reference = _value(REFERENCE)
    string = _value(STRING)
    bad_string = _value(BAD_STRING)
    symbol = _value(SYMBOL)

    def valid_path(self, children: list[Token]) -> tuple[bool, str]:
        return (True, _intern(str(children[0])))

    def bad_path(self, children: list[Token]) -> tuple[bool, str]:
        return (False, str(children[0]))

    def comment(self, children: list[Token]) -> Line:
        return Line(COMMENT, comment=str(children[0]))

    @staticmethod
    def _trailer(line: Line, token: Token) -> None:
        """Split a trailer token into the blanks (sep2 or sep) and the text after them (rest)."""
        text = str(token)
        rest = text.lstrip(" \t")
        blanks = _intern(text[: len(text) - len(rest)])
        if line.value is None and line.kind == ASSIGNMENT:
            line.sep = blanks
        else:
            line.sep2 = blanks
        if rest:
            line.rest = rest

    def end_marker(self, children: list[Token]) -> Line:
        line = Line(END, path=str(children[0]))
        if len(children) > 1:
            text = str(children[1])
            rest = text.lstrip(" \t")
            line.sep = text[: len(text) - len(rest)]
            line.rest = rest or None
        return line

    def assignment(self, children: list[Any]) -> Line:
        ok, path = children[0]
        line = Line(ASSIGNMENT, path=path, path_ok=ok)
        for child in children[1:]:
            if isinstance(child, tuple):
                line.value_kind, line.sep, line.value = child
            else:
                self._trailer(line, child)
        return line

    def line(self, children: list[Any]) -> Line:
        if not children:
            return Line(BLANK)
        first = children[0]
        if isinstance(first, Line):
            return first
        indent = _intern(str(first))
        if len(children) == 1:
            return Line(BLANK, indent=indent)
        stmt: Line = children[1]
        stmt.indent = indent
        return stmt

    def body(self, children: list[Any]) -> list[Line]:
        if len(children) == 1:
            return [children[0]]
        lines: list[Line] = children[0]
        newline, line = children[1], children[2]
        lines[-1].newline = _intern(str(newline))
        lines.append(line)
        return lines

    def start(self, children: list[list[Line]]) -> list[Line]:
        return children[0]


def _cache_file(grammar: str) -> str | bool:
    """Where Lark may keep its analysed grammar: a regular file (or none yet) in the private per-user cache
    folder (`codecache.private_folder`: a relative XDG_CACHE_HOME is ignored), else no cache.

    Lark's cache is a pickle, so it is only kept in a folder that belongs to the user and that no one else
    can write to (not a shared temporary folder); and Lark opens it blocking and reads it whole, so a FIFO or
    a link to a device there (which would hang or exhaust every run) is no cache.
    """
    import hashlib
    import os
    import stat

    from ..core.codecache import private_folder

    folder = private_folder()
    if folder is None:
        return False
    digest = hashlib.sha256(grammar.encode("utf-8")).hexdigest()[:16]
    path = os.path.join(folder, f"grammar-{digest}.lark-cache")
    try:
        info = os.lstat(path)
    except FileNotFoundError:
        return path  # Lark writes it
    except OSError:
        return False
    return path if stat.S_ISREG(info.st_mode) else False


@lru_cache(maxsize=1)
def parser() -> Lark:
    """The Lark LALR parser, built once per process (the analysed grammar is cached on disk)."""
    from lark import Lark

    grammar = _grammar_text()
    options = dict(parser="lalr", lexer="contextual", transformer=_Builder(), maybe_placeholders=False)
    cache = _cache_file(grammar)
    if cache:
        try:
            return Lark(grammar, cache=cache, **options)
        except Exception:
            pass
    return Lark(grammar, **options)


class _RecentParses:
    """The lines of the last small texts parsed, so that parsing one again costs copies of them.

    One process often parses the same text again: a start-up list is read for its entries and then
    linted, a folder's lists are read for the machine rules and linted, the editor lints an unchanged
    buffer again. Texts up to `text_limit` characters are kept, `total_limit` characters in all (the
    least recently used go first); each line as the tuple of its fields, from which every parse gets new
    `Line` objects (about fifty times cheaper than parsing), which the caller may change as before.
    """

    text_limit = 1 << 16
    total_limit = 1 << 20
    _fields = attrgetter(*(f.name for f in fields(Line)))

    def __init__(self) -> None:
        self._kept: dict[str, list[tuple[Any, ...]]] = {}
        self._total = 0
        self._lock = threading.Lock()  # the language server parses on more than one thread

    def lines(self, text: str) -> list[Line] | None:
        with self._lock:
            kept = self._kept.pop(text, None)
            if kept is None:
                return None
            self._kept[text] = kept  # now the most recently used
        return [Line(*values) for values in kept]

    def keep(self, text: str, lines: list[Line]) -> None:
        if len(text) > self.text_limit:
            return
        kept = [self._fields(line) for line in lines]
        with self._lock:
            if text not in self._kept:
                self._total += len(text)
            self._kept[text] = kept
            while self._total > self.total_limit:
                oldest = next(iter(self._kept))
                del self._kept[oldest]
                self._total -= len(oldest)


_recent = _RecentParses()


# The fields of a `Line` before its line break and number, as `_LineParses` keeps them (`_LineParses._head`).
_Head = tuple[str, str, str | None, bool, str, str | None, str | None, str, str | None, str | None]


class _LineParses:
    """The lines parsed before, by their text, so that a text sharing most of its lines with earlier ones
    costs a Lark parse of its new lines only: a list after a fix or an edit, the same settings in many
    lists of a folder (the test suite parsed 165,000 lines this way, 16,000 of them distinct).

    The grammar reads every line on its own: no token crosses a line break, and after a break the parser
    is where it is at the start of a text. So the new lines joined by line breaks and parsed together give,
    line for line, what the parse of the whole text gives (a test compares the two on generated texts).
    Each line is kept as the fields before its line break and number; a parse gets new `Line` objects.
    Lines up to `line_limit` characters of texts up to `text_limit` are kept, at most `count_limit` of
    them and `total_limit` characters in all (all are forgotten when full).
    """

    text_limit = 1 << 20  # (a longer text is parsed whole: splitting it and keeping its lines cost ~8 %)
    line_limit = 1 << 12
    count_limit = 1 << 16
    total_limit = 1 << 22
    _head = attrgetter(*(f.name for f in fields(Line) if f.name not in ("newline", "number")))

    def __init__(self) -> None:
        self._kept: dict[str, _Head] = {}
        self._total = 0
        self._lock = threading.Lock()  # the language server parses on more than one thread

    def lines(self, text: str) -> list[Line]:
        if len(text) > self.text_limit:
            return self._parse(text)
        bodies, breaks = _bodies(text)
        kept = self._kept  # (entries are only ever added to this dict: `_keep` replaces a full one)
        distinct = dict.fromkeys(bodies)
        missing = [body for body in distinct if body not in kept]
        if len(missing) == len(distinct):  # no line seen before: the whole text parsed as it is
            parsed = self._parse(text)
            self._keep({body: self._head(line) for body, line in zip(bodies, parsed, strict=True)})
            return parsed
        heads: dict[str, _Head] = kept
        if missing:
            parsed = cast("list[Line]", parser().parse("\n".join(missing)))
            new = {body: self._head(line) for body, line in zip(missing, parsed, strict=True)}
            self._keep(new)
            heads = {body: kept[body] if body in kept else new[body] for body in distinct}
        if isinstance(breaks, str):  # every line ends with that break, the last one with none
            lines = [Line(*heads[body], breaks, number) for number, body in enumerate(bodies, 1)]
            lines[-1].newline = ""
            return lines
        return [
            Line(*heads[body], newline, number)
            for number, (body, newline) in enumerate(zip(bodies, breaks, strict=True), 1)
        ]

    @staticmethod
    def _parse(text: str) -> list[Line]:
        # The inline transformer builds the result while parsing: `_Builder.start` returns the lines.
        parsed = cast("list[Line]", parser().parse(text))
        for number, line in enumerate(parsed, 1):
            line.number = number
        return parsed

    def _keep(self, new: dict[str, _Head]) -> None:
        kept = {body: head for body, head in new.items() if len(body) <= self.line_limit}
        size = sum(map(len, kept))
        with self._lock:
            if len(self._kept) + len(kept) > self.count_limit or self._total + size > self.total_limit:
                self._kept = {}
                self._total = 0
            self._kept.update(kept)
            self._total += size


_by_line = _LineParses()
_CRLF = _intern("\r\n")


def _bodies(text: str) -> tuple[list[str], str | list[str]]:
    """The lines of `text` as the parser reads them, without their line breaks, and those breaks: one string
    when every line but the last ends with it (the last one has none), else the break of each line. A text
    ending with a line break ends with an empty line, as the parser reads one there.

    A text without CR is split at LF. One with CR is split by `str.splitlines` when it holds none of the
    other characters that method breaks at (`split_lines`), and the lengths tell whether every break is a
    CRLF or every one a lone CR; a text with several kinds of break, or with such a character, is split by
    the pattern of line breaks, several times slower."""
    if "\r" not in text:
        return text.split("\n"), "\n"
    if _splitlines_alike(text):
        bodies = text.splitlines()
        if not text or text[-1] in "\r\n":
            bodies.append("")  # the parser reads an empty last line after a final line break
        breaks = len(bodies) - 1
        long_breaks = len(text) - sum(map(len, bodies)) - breaks  # the CRLFs: two characters, the others one
        if long_breaks == breaks:
            return bodies, _CRLF
        if not long_breaks and "\n" not in text:
            return bodies, "\r"
    raw = _LINE.findall(text)
    if not raw or raw[-1].endswith(("\n", "\r")):
        raw.append("")
    bodies = [line.rstrip("\r\n") for line in raw]
    return bodies, [_intern(line[len(body) :]) for line, body in zip(raw, bodies, strict=True)]


# What `str.splitlines` breaks at besides CR and LF: the five ASCII ones first (an ASCII text holds no other).
_OTHER_BREAKS = "\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029"


def _splitlines_alike(text: str) -> bool:
    """Whether `str.splitlines` breaks `text` only where the parser does (at CR, LF and CRLF)."""
    return not any(other in text for other in _OTHER_BREAKS[: 5 if text.isascii() else None])


def _parsed_lines(text: str) -> list[Line]:
    lines = _recent.lines(text)
    if lines is None:
        lines = _by_line.lines(text)
        _recent.keep(text, lines)
    return lines


def parse_text(text: str, name: str = "<string>", *, encoding: str = "utf-8", bom: bool = False) -> ListFile:
    """Parse list text (already decoded, without BOM) into a `ListFile`."""
    lines = _parsed_lines(text)
    end_index = next((index for index, line in enumerate(lines) if line.kind == END), None)
    return ListFile(name=name, lines=lines, encoding=encoding, bom=bom, end_index=end_index)


_LINE = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+")


def split_lines(text: str, keepends: bool = False) -> list[str]:
    """The lines of `text` as the parser numbers them: only CR, LF and CRLF end a line.

    `str.splitlines` also breaks at \\x0b, \\x0c, \\x1c-\\x1e, U+0085, U+2028 and U+2029,
    which are ordinary characters in a list; using it would shift every line number after them. A text
    without them is split by it all the same: then it breaks where the parser does, about six times faster
    than the pattern (the language server splits the whole text on every edit).
    """
    if _splitlines_alike(text):
        return text.splitlines(keepends)
    lines = _LINE.findall(text)
    return lines if keepends else [line.rstrip("\r\n") for line in lines]


def parse_bytes(data: bytes, name: str = "<bytes>") -> ListFile:
    """Decode and parse list bytes. Raises `decode.UnreadableInput` for UTF-16/32."""
    from ..core.decode import decode

    source = decode(data)
    return parse_text(source.text, name, encoding=source.encoding, bom=source.bom)


_SEGMENT = re.compile(r"([A-Za-z_][A-Za-z0-9_\-]*)((?:\[[0-9]+\])*)")


def split_path(path: str) -> list[tuple[str, tuple[int, ...]]]:
    """Split a valid path into (member, indices) pairs: `a[1].b` -> [("a", (1,)), ("b", ())]."""
    parts: list[tuple[str, tuple[int, ...]]] = []
    for segment in path.split("."):
        match = _SEGMENT.fullmatch(segment)
        if match is None:
            raise ValueError(f"not a valid path: {path!r}")
        indices = tuple(whole_number(i) for i in re.findall(r"\[([0-9]+)\]", match.group(2)))
        parts.append((match.group(1), indices))
    return parts


HUGE = 10**30  # stands for a number with more digits than any parameter type or index bound holds


def whole_number(text: str) -> int:
    """The decimal integer `text`; `±HUGE` when it has too many digits to be converted (see `numbers`)."""
    value = parse_int(text)
    if isinstance(value, int):
        return value
    return -HUGE if text.startswith("-") else HUGE


@lru_cache(maxsize=1 << 16)
def path_pattern(path: str) -> tuple[str, tuple[int, ...]]:
    """Replace every index by `[i]`: `getriebe[2].vb_reflow` -> (`getriebe[i].vb_reflow`, (2,))."""
    indices: list[int] = []

    def repl(match: re.Match[str]) -> str:
        indices.append(whole_number(match.group(1)))
        return "[i]"

    return _INDEX.sub(repl, path), tuple(indices)


_INDEX = re.compile(r"\[([0-9]+)\]")


def is_misspelt_end(line: Line) -> bool:
    """A line that was meant as the end marker: `End`, `END`, `ende` ... alone on the line."""
    return (
        line.kind == ASSIGNMENT
        and line.value is None
        and (line.path or "").lower() in ("end", "ende")
        and line.path != "Ende"
    )
