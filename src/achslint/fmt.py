"""`achslint fmt`: the canonical layout of a list, changing whitespace only.

* assignments start in column 1 and their values start in one common column
  (two blanks after the longest parameter path of the file), separated by
  blanks, not tabs;
* one blank before the comment that follows a value — unless the value is a
  string followed by text that is not a `(` comment, where the blanks may be
  part of what the CNC reads (LIS007), so they are left alone;
* no trailing blanks, and blank-only lines become empty lines;
* the end marker stands alone in column 1 and is the last line: blank lines
  after it are dropped and the file ends with a line break after `Ende`.

"Blank" means the space and the tab, nothing else: a no-break space, a form
feed or U+2028 is content to the CNC and to fmt. Names, values and comment text
are never touched, nor are lines the parser could not read (LIS001). Each line
keeps its own line break (no two lines are ever joined), the file keeps its
encoding and byte-order mark, and formatting twice changes nothing.
"""

from __future__ import annotations

import difflib
from collections import Counter

from . import syntax
from .decode import decode

NUMERIC_OR_REFERENCE = {syntax.INT, syntax.HEX, syntax.REAL, syntax.REFERENCE}
BLANKS = " \t"


def value_column(file: syntax.ListFile) -> int:
    """0-based column where every value starts."""
    lengths = [len(line.path) for line in file.lines if line.kind == syntax.ASSIGNMENT and line.path_ok]
    return max(lengths, default=0) + 2


def _comment_is_free(line: syntax.Line) -> bool:
    """Whether the blanks before the trailing text are plain separators the CNC ignores."""
    return line.value_kind in NUMERIC_OR_REFERENCE or (line.rest or "").startswith("(")


def format_line(line: syntax.Line, column: int) -> str:
    """The canonical body of one line (without its line break)."""
    if line.kind == syntax.BLANK:
        return ""
    if line.kind == syntax.COMMENT:
        return (line.indent + (line.comment or "")).rstrip(BLANKS)
    if line.kind == syntax.END:
        rest = f" {line.rest.rstrip(BLANKS)}" if line.rest else ""
        return (line.path or "") + rest
    if not line.path_ok or line.value_kind == syntax.BAD_STRING:
        return line.body.rstrip(BLANKS)
    if line.value is None:
        return line.path
    text = line.path.ljust(column - 1) + " " + line.value
    if line.rest is not None:
        separator = " " if _comment_is_free(line) else line.sep2
        text += separator + line.rest
    return text.rstrip(BLANKS)


def format_file(file: syntax.ListFile) -> str:
    """The formatted text of a parsed list."""
    column = value_column(file)
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
        body = format_line(line, column)
        if not body and previous.endswith("\r") and newline.startswith("\n"):
            body = line.body  # emptied, this line's LF would join the CR before it into one CRLF
        out.append(body + newline)
        previous = newline
    return "".join(out)


def format_text(text: str, name: str = "<string>") -> str:
    """The formatted version of a list's text."""
    return format_file(syntax.parse_text(text, name))


def format_bytes(data: bytes, name: str = "<bytes>") -> tuple[bytes, bool]:
    """(formatted bytes, changed). Raises `decode.UnreadableInput` for UTF-16/32 input."""
    source = decode(data)
    file = syntax.parse_text(source.text, name, encoding=source.encoding, bom=source.bom)
    formatted = source.encode(format_file(file))
    return formatted, formatted != data


NO_NEWLINE = "\\ No newline at end of file\n"


def unified_diff(before: bytes, after: bytes, name: str, label: str = "formatted") -> str:
    """A unified diff of two versions of a list; a last line without a line break is marked as `diff` marks it."""
    old = syntax.split_lines(decode(before).text, keepends=True)
    new = syntax.split_lines(decode(after).text, keepends=True)
    out = []
    for row in difflib.unified_diff(old, new, f"{name} (original)", f"{name} ({label})"):
        out.append(row)
        if not row.endswith(("\n", "\r")):
            out.append("\n" + NO_NEWLINE)
    return "".join(out)
