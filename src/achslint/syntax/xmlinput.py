"""Axis lists inside XML: TwinCAT tree items / projects and the ISG XML list format.

* TwinCAT (`.xml`, `.xti`, `.tsproj`): each `<AchsMds>` element holds a complete
  axis list as text (CDATA, plain text with character references, or both);
  `<DriveType>` and `<Spindle>` of the same `<IsgAxisDef>` describe the drive
  type and whether the axis is a spindle. The element around the `<IsgAxisDef>`
  is the axis's tree item: its `<ItemName>`, `<PathName>`
  (`TICC^CNC^Axes^<name>`), `<ItemId>` and `<ObjectId>`, with the
  `<DefaultChannel>` / `<DefaultIndex>` / `<DefaultProgName>` of the
  `<IsgAxisDef>`, are the identity TwinCAT gives the axis (`TreeItem`).
  The channel's tree item holds `<IsgChannelDef>` with the channel's other lists
  as text the same way (`_CHANNEL_ITEM_LISTS`: `<SdaMds>` the channel list,
  `<NullpD>` zero offsets, `<WerkzD>` tool data, `<PzvD>` clamp position
  offsets, `<VeD>` external variables; each with its list kind).
* ISG XML lists: `<AX_MDS>` with one element per parameter, named by id and
  index (`<P-AXIS-00152.0 Value="0"/>`), inside optional grouping elements.

Both become ordinary list text, linted by the same rules; diagnostics are moved
back to the line and column of the XML file. The file is read in one pass by
defusedxml's expat parser, which refuses a DTD, entity declarations and
external references, reads any encoding expat knows (UTF-16 included), skips
comments and takes positions from the parser itself, so the time is linear in
the size of the file.

The one syntax module above the catalogue: an ISG XML list names parameters by
id, and the catalogue turns an id into the path a list writes.
"""

from __future__ import annotations

import codecs
import re
from bisect import bisect_right
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING, Any
from xml.sax import SAXException
from xml.sax.handler import ContentHandler

from ..catalogue import catalogue, fill_indices
from ..core.decode import UnreadableInput
from .numbers import parse_int
from .parser import split_lines

if TYPE_CHECKING:
    from xml.sax.expatreader import ExpatParser
    from xml.sax.xmlreader import AttributesImpl

_ISG_ELEMENT = re.compile(r"(P-AXIS-[0-9]+)((?:\.[0-9]+)*)")
# Elements of the <IsgAxisDef> itself, and those of the tree item around it (children of its parent element)
_AXIS_FIELDS = frozenset(("DriveType", "Spindle", "DefaultChannel", "DefaultIndex", "DefaultProgName"))
_ITEM_FIELDS = frozenset(("ItemName", "PathName", "ItemId", "ObjectId"))
# The lists a TwinCAT channel item (<IsgChannelDef>) holds as text, with the kind of each (`catalogue.kinds` ids)
_CHANNEL_ITEM_LISTS = {
    "SdaMds": "channel",
    "NullpD": "zero_offsets",
    "WerkzD": "tools",
    "PzvD": "clamp_offsets",
    "VeD": "external_variables",
}
# (text, XML line, XML column) of one such element, by element name
Fields = dict[str, tuple[str, int, int]]


@dataclass
class TreeItem:
    """The TwinCAT tree item an axis list is embedded in: how TwinCAT itself names and numbers the axis.

    Every export of one project may embed the same template header (`kopf.achs_nr 1`, `X_Achse`), while the
    tree items differ: `path` (`TICC^CNC^Axes^Axis_X`) is unique in the project tree, `item_id` is the running
    number of the axis items (1, 2, ...) and `object_id` is derived from it. `channel`, `index` and
    `program_name` (`DefaultChannel`, `DefaultIndex`, `DefaultProgName` of the `<IsgAxisDef>`) place the axis
    in a channel. `positions` holds the XML (line, column) of every element read, by element name.
    """

    name: str | None = None
    path: str | None = None
    item_id: int | None = None
    object_id: str | None = None
    channel: int | None = None
    index: int | None = None
    program_name: str | None = None
    positions: dict[str, tuple[int, int]] = field(default_factory=dict)

    @property
    def label(self) -> str:
        """How messages name the item: its path in the tree, else its name, else its ItemId."""
        return self.path or self.name or f"ItemId {self.item_id}"

    def identity(self) -> dict[str, Any]:
        """The item as the machine summary carries it (`identity`; a plain dict, see `machine.startup.summary`)."""
        return {
            "source": "TwinCAT tree item",
            "item": self.label,
            "name": self.name,
            "path": self.path,
            "item_id": self.item_id,
            "object_id": self.object_id,
            "channel": self.channel,
            "index": self.index,
            "program_name": self.program_name,
            "positions": dict(self.positions),
        }

    @classmethod
    def of(cls, item: Fields, axis: Fields) -> TreeItem | None:
        """The tree item from the elements around an <IsgAxisDef> and in it; None when there is no tree item
        (an <IsgAxisDef> written without one names no identity, whatever its Default* elements say)."""
        if not item:
            return None

        def number(fields: Fields, key: str) -> int | None:
            value = parse_int(fields[key][0]) if key in fields else None
            return value if isinstance(value, int) else None

        def text(fields: Fields, key: str) -> str | None:
            return fields[key][0] or None if key in fields else None

        positions = {key: (line, column) for key, (_, line, column) in (*item.items(), *axis.items())}
        return cls(
            text(item, "ItemName"),
            text(item, "PathName"),
            number(item, "ItemId"),
            text(item, "ObjectId"),
            number(axis, "DefaultChannel"),
            number(axis, "DefaultIndex"),
            text(axis, "DefaultProgName"),
            positions,
        )


@dataclass
class EmbeddedList:
    """One list found in an XML file, with what is needed to map positions back."""

    text: str
    label: str  # "AchsMds" or "AX_MDS"; "SdaMds", "NullpD" ... for the lists of a channel item
    first_line: int  # XML line of the element that holds the list
    first_column: int
    line_map: list[tuple[int, int]] | None = None  # ISG: XML (line, column) of every synthetic line
    drive_type: int | None = None
    drive_type_line: int | None = None
    spindle: bool | None = None
    spindle_line: int | None = None
    tree_item: TreeItem | None = None  # TwinCAT: the tree item around the <IsgAxisDef>, when there is one
    # TwinCAT: where each piece of the text starts in the XML file, as the parser reported it:
    # text offsets (ascending) and the XML (line, column) of each.
    pieces: list[int] = field(default_factory=list)
    piece_positions: list[tuple[int, int]] = field(default_factory=list)
    kind: str = "axis"  # the list kind (`catalogue.kinds` id): the lists of a channel item are of others

    @cached_property
    def _line_starts(self) -> list[int]:
        starts, offset = [0], 0
        for line in split_lines(self.text, keepends=True):
            offset += len(line)
            starts.append(offset)
        return starts

    def position(self, line: int, column: int) -> tuple[int, int]:
        """The XML (line, column) of a 1-based (line, column) of the list text."""
        if self.line_map is not None:
            return self.line_map[max(1, min(line, len(self.line_map))) - 1]
        if not self.pieces:
            return self.first_line, self.first_column
        starts = self._line_starts
        offset = starts[max(1, min(line, len(starts))) - 1] + max(column, 1) - 1
        index = max(bisect_right(self.pieces, offset) - 1, 0)
        start = self.pieces[index]
        xml_line, xml_column = self.piece_positions[index]
        between = self.text[start:offset]
        breaks = between.count("\n")
        if not breaks:
            return xml_line, xml_column + len(between)
        return xml_line + breaks, len(between) - between.rindex("\n")


class NoAxisList(UnreadableInput):
    """Well-formed XML that holds no axis list (a channel list, zero offsets, tools, ...)."""


_MARKERS = tuple(
    marker.encode(encoding)
    for marker in ("<AchsMds", "<AX_MDS", ":AchsMds", ":AX_MDS")
    for encoding in ("ascii", "utf-16-le", "utf-16-be")
)
_CHANNEL_MARKERS = tuple(
    marker.encode(encoding)
    for marker in ("<IsgChannelDef", ":IsgChannelDef")
    for encoding in ("ascii", "utf-16-le", "utf-16-be")
)


def may_hold_axis_list(data: bytes) -> bool:
    """Whether an XML file can hold an axis list at all: it names `<AchsMds>` or `<AX_MDS>` somewhere.

    Folder discovery goes by content, not by file name: TwinCAT names its exports after the axis
    (`Axis_X.xti`), and the same folder holds channel lists and zero-offset tables.
    """
    return any(marker in data for marker in _MARKERS)


def may_hold_list(data: bytes) -> bool:
    """Whether an XML file can hold any list achslint reads: an axis list, or a TwinCAT channel item."""
    return may_hold_axis_list(data) or any(marker in data for marker in _CHANNEL_MARKERS)


def root_element(data: bytes) -> str:
    """The name of the document element (for the note about a skipped XML file), or "?"."""
    match = re.search(r"<(?![?!])([A-Za-z_][\w.:-]*)", source_text(data))
    return match.group(1) if match else "?"


_BOMS = (b"\xef\xbb\xbf", b"\xff\xfe", b"\xfe\xff")
_UTF32_BOMS = (b"\xff\xfe\x00\x00", b"\x00\x00\xfe\xff")
_DECLARATION = re.compile(rb'(?:\xef\xbb\xbf)?<\?xml[^>]*encoding\s*=\s*["\']([A-Za-z0-9_.-]+)["\']')
_SURROGATE = re.compile("[\ud800-\udfff]")


def declared_encoding(data: bytes) -> str | None:
    """The encoding the XML declaration names (`<?xml version="1.0" encoding="cp1252"?>`), if any."""
    match = _DECLARATION.match(data)
    return match.group(1).decode("ascii") if match else None


def source_text(data: bytes) -> str:
    """The XML file as text, for code frames: by its byte-order mark or declared encoding, else Latin-1.

    Latin-1 too when the declared codec fails or yields lone surrogates (UTF-7 and the escape codecs can),
    which no output format could show."""
    bom = data.startswith((b"\xff\xfe", b"\xfe\xff"))
    encoding = "utf-16" if bom else declared_encoding(data) or "utf-8"
    try:
        text = data.decode(encoding)
    except (LookupError, ValueError):  # UnicodeError is a ValueError; IDNA raises a plain UnicodeError
        text = data.decode("latin-1")
    if _SURROGATE.search(text):
        text = data.decode("latin-1")
    return text[1:] if text.startswith("\ufeff") else text


def _local(name: str) -> str:
    """An element name without its namespace prefix."""
    return name.rsplit(":", 1)[-1]


class _Collector(ContentHandler):
    """Gathers the axis lists while expat reads the file once."""

    def __init__(self, locator: ExpatParser, bom: bool = False) -> None:
        super().__init__()
        self.locator = locator
        self.bom = bom  # the file starts with a byte-order mark, which expat counts as a column of line 1
        self.twincat: list[EmbeddedList] = []
        # ISG lists: the list, its lines, and the XML (line, column) of each line (the list's line_map)
        self.isg: list[tuple[EmbeddedList, list[str], list[tuple[int, int]]]] = []
        self.isg_depth = 0  # how many <AX_MDS> elements we are inside
        self.axis_defs: list[list[EmbeddedList]] = []  # the <IsgAxisDef> elements we are inside
        self.current: EmbeddedList | None = None  # the <AchsMds> (or list of a channel item) being read
        self.channel_defs = 0  # how many <IsgChannelDef> elements we are inside
        self.others: list[EmbeddedList] = []  # the lists of channel items
        self.chunks: list[str] = []
        self.offset = 0
        self.field: tuple[str, int, int] | None = None  # an element of _AXIS_FIELDS / _ITEM_FIELDS being read
        self.field_text: list[str] = []
        self.axis_fields: list[Fields] = []  # the _AXIS_FIELDS of each <IsgAxisDef> we are inside
        self.elements = 0  # elements started so far
        self.depth = 0  # elements open now
        # By the depth of an open element: the _ITEM_FIELDS among its children, and the lists of the
        # <IsgAxisDef> children it holds with that <IsgAxisDef>'s fields (they get the tree item when it ends).
        self.item_fields: dict[int, Fields] = {}
        self.in_item: dict[int, list[tuple[list[EmbeddedList], Fields]]] = {}

    def _here(self) -> tuple[int, int]:
        line = self.locator.getLineNumber()
        return line, _column(line, self.locator.getColumnNumber(), self.bom)

    def startElement(self, name: str, attrs: AttributesImpl) -> None:
        self.elements += 1
        self.depth += 1
        local = _local(name)
        line, column = self._here()
        if local == "IsgAxisDef":
            self.axis_defs.append([])
            self.axis_fields.append({})
        elif local == "AchsMds" and self.current is None:
            self.current = EmbeddedList("", "AchsMds", line, column)
            self.chunks, self.offset = [], 0
        elif local == "IsgChannelDef":
            self.channel_defs += 1
        elif self.channel_defs and local in _CHANNEL_ITEM_LISTS and self.current is None:
            self.current = EmbeddedList("", local, line, column, kind=_CHANNEL_ITEM_LISTS[local])
            self.chunks, self.offset = [], 0
        elif (local in _AXIS_FIELDS and self.axis_defs) or local in _ITEM_FIELDS:
            self.field, self.field_text = (local, line, column), []
        elif local == "AX_MDS":
            self.isg_depth += 1
            if self.isg_depth == 1:
                line_map: list[tuple[int, int]] = []
                self.isg.append((EmbeddedList("", "AX_MDS", line, column, line_map=line_map), [], line_map))
        elif self.isg_depth and (element := _ISG_ELEMENT.fullmatch(local)):
            self._isg_line(element, attrs.get("Value", ""), (line, column))

    def characters(self, content: str) -> None:
        if self.current is not None:
            self.current.pieces.append(self.offset)
            self.current.piece_positions.append(self._here())
            self.chunks.append(content)
            self.offset += len(content)
        elif self.field is not None:
            self.field_text.append(content)

    def endElement(self, name: str) -> None:
        local = _local(name)
        if local == "AchsMds" and self.current is not None:
            self.current.text = "".join(self.chunks)
            self.twincat.append(self.current)
            if self.axis_defs:
                self.axis_defs[-1].append(self.current)
            self.current = None
        elif self.current is not None and local == self.current.label:  # a list of a channel item
            self.current.text = "".join(self.chunks)
            self.others.append(self.current)
            self.current = None
        elif local == "IsgChannelDef" and self.channel_defs:
            self.channel_defs -= 1
        elif self.field is not None and local == self.field[0]:
            read = ("".join(self.field_text).strip(), *self.field[1:])
            if local in _ITEM_FIELDS:
                self.item_fields.setdefault(self.depth - 1, {})[local] = read
            else:
                self.axis_fields[-1][local] = read
            self.field = None
        elif local == "IsgAxisDef" and self.axis_defs:
            lists, fields = self.axis_defs.pop(), self.axis_fields.pop()
            self._describe(lists, fields)
            self.in_item.setdefault(self.depth - 1, []).append((lists, fields))
        elif local == "AX_MDS" and self.isg_depth:
            self.isg_depth -= 1
            if not self.isg_depth:
                _, lines, line_map = self.isg[-1]
                lines.append("Ende")
                line_map.append(self._here())
        item = self.item_fields.pop(self.depth, {})
        for lists, fields in self.in_item.pop(self.depth, ()):
            tree_item = TreeItem.of(item, fields)
            for embedded in lists:
                embedded.tree_item = tree_item
        self.depth -= 1

    @staticmethod
    def _describe(lists: list[EmbeddedList], fields: Fields) -> None:
        """Give the lists of one <IsgAxisDef> its drive type and spindle flag."""
        for embedded in lists:
            if "DriveType" in fields:
                number = parse_int(fields["DriveType"][0])
                if isinstance(number, int):
                    embedded.drive_type, embedded.drive_type_line = number, fields["DriveType"][1]
            if "Spindle" in fields and fields["Spindle"][0].lower() in ("true", "false"):
                embedded.spindle = fields["Spindle"][0].lower() == "true"
                embedded.spindle_line = fields["Spindle"][1]

    def _isg_line(self, element: re.Match[str], value: str, where: tuple[int, int]) -> None:
        """One `<P-AXIS-nnnnn.i Value="..."/>` element (its name matched by `_ISG_ELEMENT`) as a list line."""
        _, lines, line_map = self.isg[-1]
        pid, written = element.group(1), element.group(2)
        indices = tuple(written.split(".")[1:])
        parameter = catalogue().by_id.get(pid)
        if parameter is None:
            path = pid + written.replace(".", "_")  # reported as an unknown parameter
        else:
            count = parameter.path.count("[i]")
            path = fill_indices(parameter.path, (indices + ("0",) * count)[:count])
        value = value.replace("\r", " ").replace("\n", " ")  # a character reference must not split the line
        if value and (re.search(r"[ \t(]", value) or value.startswith('"')):
            value = '"' + value.strip('"') + '"'
        lines.append(f"{path} {value}".rstrip(" \t"))
        line_map.append(where)


def _parse(data: bytes, name: str) -> _Collector:
    import defusedxml
    from defusedxml.expatreader import create_parser

    parser = create_parser(forbid_dtd=True)
    collector = _Collector(parser, data.startswith(_BOMS))
    parser.setContentHandler(collector)
    try:
        parser.feed(data)
        parser.close()
    except (
        defusedxml.DTDForbidden,
        defusedxml.EntitiesForbidden,
        defusedxml.ExternalReferenceForbidden,
    ) as exc:
        raise UnreadableInput(
            f"refusing to read {name}: it declares a DTD or entities ({type(exc).__name__}), which can expand or "
            "load external content"
        ) from None
    except SAXException as exc:
        raise UnreadableInput(_not_well_formed(exc, data, name)) from None
    except (LookupError, ValueError):  # after the defusedxml errors, which are ValueErrors too
        if collector.elements:  # raised by our own handler, not by the encoding: a bug, not the file
            raise
        # expat decodes UTF-8, UTF-16, ISO-8859-1 and ASCII itself and asks Python for any other declared
        # encoding as a table of 256 single characters: multi-byte encodings (Shift_JIS, GB2312, EUC-KR,
        # Big5), UTF-7 and codecs that are no text encoding (IDNA, punycode, rot13) fail there, before
        # the first element is read.
        declared = declared_encoding(data) or "?"
        try:
            codecs.lookup(declared)
        except LookupError:
            raise UnreadableInput(
                f"refusing to read {name}: it declares the unknown encoding `{declared}`; save it as UTF-8"
            ) from None
        raise UnreadableInput(
            f"refusing to read {name}: it declares the encoding `{declared}`, which achslint cannot read XML "
            "in (UTF-8, UTF-16, ASCII and one-byte code pages such as Latin-1 or cp1252 only); save it as UTF-8"
        ) from None
    return collector


def _column(line: int, column: int | None, bom: bool) -> int:
    """The 1-based column of expat's 0-based one, without the byte-order mark it counts on line 1."""
    return (column or 0) + (0 if line == 1 and bom else 1)


def _not_well_formed(exc: SAXException, data: bytes, name: str) -> str:
    """One line for XML expat stops reading: the file, what is wrong, the column, what to do, the line."""
    line = getattr(exc, "getLineNumber", lambda: None)()
    column = getattr(exc, "getColumnNumber", lambda: None)()
    where = (
        f" at column {_column(line, column, data.startswith(_BOMS))}" if line and column is not None else ""
    )
    if data.startswith(_UTF32_BOMS):
        advice = "it is saved as UTF-32, which achslint cannot read XML in; save it as UTF-8"
    elif _undeclared_non_utf8(data):
        advice = (
            "its bytes are not UTF-8, which XML without an encoding declaration must be: declare the "
            'encoding it is saved in (<?xml version="1.0" encoding="ISO-8859-1"?> for Latin-1) or save it '
            "as UTF-8"
        )
    else:
        advice = "correct the XML there or export the file again from TwinCAT"
    return f"{name} is not well-formed XML: {exc.getMessage()}{where}; {advice}" + (
        f" (line {line})" if line else ""
    )


def _undeclared_non_utf8(data: bytes) -> bool:
    """Whether an XML file expat reads as UTF-8 (no UTF-16 byte-order mark, no other encoding declared)
    holds bytes that are no UTF-8."""
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        return False
    declared = (declared_encoding(data) or "utf-8").lower().replace("_", "-")
    if declared not in ("utf-8", "utf8"):
        return False
    try:
        data.decode("utf-8")
    except UnicodeDecodeError:
        return True
    return False


def extract(data: bytes, name: str) -> list[EmbeddedList]:
    """Every axis list in an XML file. Raises `UnreadableInput` for unsafe or broken XML, or XML without lists."""
    return _axis_lists(_parse(data, name), name)


def extract_lists(data: bytes, name: str) -> list[EmbeddedList]:
    """Every list in an XML file: its axis lists, then the lists of its TwinCAT channel items (their `kind`
    says which). Raises `UnreadableInput` for unsafe or broken XML, `NoAxisList` for XML without any list."""
    collected = _parse(data, name)
    try:
        return [*_axis_lists(collected, name), *collected.others]
    except NoAxisList:
        if collected.others:
            return list(collected.others)
        raise


def _axis_lists(collected: _Collector, name: str) -> list[EmbeddedList]:
    found = list(collected.twincat)
    if not found:
        for embedded, lines, _ in collected.isg:
            embedded.text = "\n".join(lines) + "\n"
            found.append(embedded)
    if not found:
        if collected.others:  # a TwinCAT channel item: its lists are of other kinds
            held = ", ".join(dict.fromkeys(f"<{embedded.label}>" for embedded in collected.others))
            raise NoAxisList(
                f"{name} is a TwinCAT channel item (<IsgChannelDef> with {held}), not an axis item: "
                "it contains no axis list"
            )
        raise NoAxisList(f"{name} contains no axis list (no <AchsMds> element and no <AX_MDS> list)")
    return found


def single_list(data: bytes, name: str) -> bytes:
    """The one axis list of an XML file as list bytes (for explain, dry-run and diff, which read one list)."""
    lists = extract(data, name)
    if len(lists) > 1:
        where = ", ".join(f"line {embedded.first_line}" for embedded in lists)
        raise UnreadableInput(
            f"{name} holds {len(lists)} axis lists (at {where}); this command reads one list, "
            "so export the axis you mean on its own"
        )
    return lists[0].text.encode("utf-8")
