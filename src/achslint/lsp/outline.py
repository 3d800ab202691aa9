"""The outline (`textDocument/documentSymbol`) as JSON, kept line by line between requests.

`features.document_symbols` says what the outline is: `Ende`, and each parameter under its group
(`kopf`, `getriebe[0]` ...). Built as lsprotocol objects and serialised by pygls, a 2,000-line list's
outline takes tens of milliseconds, and the editor asks for it after every keystroke. `Outline`
gives the same answer as JSON text: each line's symbol is written once and kept while the line is
the same object (the parse keeps the `Line` of a line an edit did not touch), so a keystroke writes
one line again. A list of more than `LIMIT` parameters is outlined by its groups alone (each with
the count of its parameters): tens of thousands of entries are no outline anybody reads, and their
JSON alone takes longer to read than the editor waits for an answer.

This module does not import pygls.
"""

from __future__ import annotations

import json

from lsprotocol import types as lsp

from ..syntax import parser as syntax
from .documents import Document
from .features import lsp_range

LIMIT = 5000  # parameters; beyond them the outline lists the groups without their members

_Position = tuple[int, int]


class _Symbol:
    """One line's part of the outline; its JSON written when first asked for (a list beyond `LIMIT` never
    asks for its members')."""

    __slots__ = ("child", "end", "head", "line", "name", "start", "text")

    def __init__(self, line: syntax.Line, head: str, child: bool, start: _Position, end: _Position) -> None:
        self.line = line
        self.head = head  # the group (`getriebe[0]`); "" for the end marker
        self.child = (
            child  # a member of the group `head` (else a symbol of its own: a path without a dot, `Ende`)
        )
        self.start, self.end = start, end  # its range
        self.name: str | None = None  # its selection range (JSON), the group's when the line opens it
        self.text: str | None = None  # the symbol (JSON)

    def selection(self, document: Document, plain: bool) -> str:
        if self.name is None:
            line = self.line
            if line.kind == syntax.END:
                self.name = _range(self.start, self.end)
            else:
                self.name = _range(
                    *_span(document, line, plain, line.path_column, line.path_column + len(line.path or ""))
                )
        return self.name

    def json(self, document: Document, plain: bool) -> str:
        if self.text is None:
            where, name = _range(self.start, self.end), self.selection(document, plain)
            line = self.line
            if line.kind == syntax.END:
                self.text = (
                    f'{{"name":"Ende","kind":{int(lsp.SymbolKind.Event)},"range":{where},'
                    f'"selectionRange":{name},"detail":"end marker"}}'
                )
            else:
                head, _, tail = (line.path or "").partition(".")
                self.text = (
                    f'{{"name":{json.dumps(tail or head)},"kind":{int(lsp.SymbolKind.Field)},'
                    f'"range":{where},"selectionRange":{name},"detail":{json.dumps(line.value or "")}}}'
                )
        return self.text


def _range(start: _Position, end: _Position) -> str:
    return (
        f'{{"start":{{"line":{start[0]},"character":{start[1]}}},'
        f'"end":{{"line":{end[0]},"character":{end[1]}}}}}'
    )


class Outline:
    """A document's outline, the symbols of its lines kept from one request to the next."""

    def __init__(self) -> None:
        self._kept: dict[int, tuple[syntax.Line, _Symbol | None]] = {}  # id(line) -> its symbol
        self._measure: tuple[bool, bool, str] | None = None  # how positions were counted for the kept lines

    def json(self, document: Document, file: syntax.ListFile) -> str:
        """The outline of `file` (the parse of `document`'s text) as a JSON array."""
        # Code points are the client's units when the text is ASCII (or the client counts code points).
        plain = document.encoding == "utf-32" or (not document.bom and document.text.isascii())
        measure = (plain, document.bom, document.encoding)  # a mark shifts the first line, not its `Line`
        if measure != self._measure:
            self._kept.clear()
            self._measure = measure
        kept, now = self._kept, {}
        symbols: list[_Symbol] = []
        members = 0
        for line in file.lines:
            found = kept.get(id(line))
            if found is None or found[0] is not line:
                found = (line, _symbol(document, line, plain))
            now[id(line)] = found
            symbol = found[1]
            if symbol is not None:
                symbols.append(symbol)
                members += symbol.child
        self._kept = now
        return _assemble(document, plain, symbols, members <= LIMIT)


def _span(
    document: Document, line: syntax.Line, plain: bool, start: int, end: int
) -> tuple[_Position, _Position]:
    number = line.number
    if plain:  # code points are the client's units: no line needs to be measured
        return (number - 1, start - 1), (number - 1, max(end, start) - 1)
    where = lsp_range(document, number, start, number, end)
    return (where.start.line, where.start.character), (where.end.line, where.end.character)


def _symbol(document: Document, line: syntax.Line, plain: bool) -> _Symbol | None:
    if line.kind == syntax.END:
        return _Symbol(line, "", False, *_span(document, line, plain, line.path_column, line.end_column))
    path = line.path
    if line.kind != syntax.ASSIGNMENT or not line.path_ok or not path:
        return None
    head, dot, _ = path.partition(".")
    return _Symbol(line, head, bool(dot), *_span(document, line, plain, 1, line.end_column))


def _assemble(document: Document, plain: bool, symbols: list[_Symbol], with_members: bool) -> str:
    """The outline: the symbols of their own and the groups in the order they first appear."""
    out: list[list[_Symbol] | _Symbol] = []
    groups: dict[str, list[_Symbol]] = {}
    for symbol in symbols:
        if not symbol.child:
            out.append(symbol)
        elif symbol.head in groups:
            groups[symbol.head].append(symbol)
        else:
            groups[symbol.head] = [symbol]
            out.append(groups[symbol.head])
    parts = []
    for entry in out:
        if isinstance(entry, _Symbol):
            parts.append(entry.json(document, plain))
            continue
        first, last = entry[0], entry[-1]
        kind = lsp.SymbolKind.Array if "[" in first.head else lsp.SymbolKind.Namespace
        text = (
            f'{{"name":{json.dumps(first.head)},"kind":{int(kind)},"range":{_range(first.start, last.end)},'
            f'"selectionRange":{first.selection(document, plain)}'
        )
        if with_members:
            text += f',"children":[{",".join(member.json(document, plain) for member in entry)}]}}'
        else:
            text += f',"detail":"{len(entry)} parameters (a list of more than {LIMIT:,} is outlined by its groups)"}}'
        parts.append(text)
    return f"[{','.join(parts)}]"
