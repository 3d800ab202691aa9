"""Axis lists inside XML: TwinCAT tree items / projects and the ISG XML list format.

* TwinCAT (`.xml`, `.xti`, `.tsproj`): each `<AchsMds>` element holds a complete
  axis list as text (usually CDATA); `<DriveType>` and `<Spindle>` of the same
  `<IsgAxisDef>` describe the drive type and whether the axis is a spindle.
* ISG XML lists: `<AX_MDS>` with one element per parameter, named by id and
  index (`<P-AXIS-00152.0 Value="0"/>`), inside optional grouping elements.

Both become ordinary list text, linted by the same rules; diagnostics are moved
back to the line and column of the XML file. The XML is read with defusedxml:
a DTD, entity declarations and external references are refused.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .decode import UnreadableInput

XML_SUFFIXES = (".xml", ".xti", ".tsproj")


@dataclass
class EmbeddedList:
    """One axis list found in an XML file, with what is needed to map positions back."""

    text: str
    label: str  # e.g. "AchsMds of Achse_1" or "AX_MDS"
    first_line: int  # XML line of the list's first line
    first_column: int  # XML column of the list's first character
    line_map: list[tuple[int, int]] | None = None  # ISG: XML (line, column) of every synthetic line
    drive_type: int | None = None
    drive_type_line: int | None = None
    spindle: bool | None = None
    spindle_line: int | None = None

    def position(self, line: int, column: int) -> tuple[int, int]:
        if self.line_map is not None:
            return self.line_map[min(line, len(self.line_map)) - 1]
        if line == 1:
            return self.first_line, self.first_column + column - 1
        return self.first_line + line - 1, column


def is_xml(name: str) -> bool:
    return name.lower().endswith(XML_SUFFIXES)


def _text_of(data: bytes) -> str:
    match = re.match(rb'<\?xml[^>]*encoding=["\']([A-Za-z0-9_.-]+)["\']', data)
    encoding = match.group(1).decode("ascii") if match else "utf-8"
    try:
        text = data.decode(encoding)
    except (LookupError, UnicodeDecodeError):
        text = data.decode("latin-1")
    return text[1:] if text.startswith("\ufeff") else text


def _check_safely(data: bytes, name: str) -> None:
    import xml.etree.ElementTree as StdET

    import defusedxml
    import defusedxml.ElementTree as SafeET

    try:
        SafeET.fromstring(data, forbid_dtd=True)
    except (defusedxml.DTDForbidden, defusedxml.EntitiesForbidden, defusedxml.ExternalReferenceForbidden) as exc:
        raise UnreadableInput(
            f"refusing to read {name}: it declares a DTD or entities ({type(exc).__name__}), which can expand or "
            "load external content"
        ) from None
    except StdET.ParseError as exc:
        raise UnreadableInput(f"{name} is not well-formed XML: {exc}") from None


def _line_col(text: str, offset: int) -> tuple[int, int]:
    line = text.count("\n", 0, offset) + 1
    start = text.rfind("\n", 0, offset) + 1
    return line, offset - start + 1


_ACHSMDS = re.compile(r"<AchsMds>(?P<body><!\[CDATA\[(?P<cdata>.*?)\]\]>|(?P<plain>[^<]*))</AchsMds>", re.S)
_ELEMENT = re.compile(r"<(?P<id>P-AXIS-\d{5})(?P<index>(?:\.\d+)*)(?P<attrs>[^>]*?)/?>")
_VALUE = re.compile(r'\bValue\s*=\s*"(?P<value>[^"]*)"')


def _unescape(text: str) -> str:
    return (text.replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", '"')
            .replace("&apos;", "'").replace("&amp;", "&"))


def extract(data: bytes, name: str) -> list[EmbeddedList]:
    """Every axis list in an XML file. Raises `UnreadableInput` for unsafe or broken XML, or XML without lists."""
    _check_safely(data, name)
    text = _text_of(data)
    found = [_twincat(text, match) for match in _ACHSMDS.finditer(text)]
    if not found and re.search(r"<AX_MDS[\s>]", text):
        found.append(_isg(text))
    if not found:
        raise UnreadableInput(f"{name} contains no axis list (no <AchsMds> element and no <AX_MDS> list)")
    return found


def _twincat(text: str, match: re.Match) -> EmbeddedList:
    if match.group("cdata") is not None:
        body, start = match.group("cdata"), match.start("cdata")
    else:
        body, start = _unescape(match.group("plain")), match.start("plain")
    line, column = _line_col(text, start)
    # The surrounding <IsgAxisDef> (TwinCAT tree item) names the drive type and the spindle flag.
    owner_start = text.rfind("<IsgAxisDef", 0, match.start())
    owner = text[owner_start:match.start()] if owner_start >= 0 else ""
    embedded = EmbeddedList(body, "AchsMds", line, column)
    drive = re.search(r"<DriveType>\s*(\d+)\s*</DriveType>", owner)
    if drive:
        embedded.drive_type = int(drive.group(1))
        embedded.drive_type_line = _line_col(text, owner_start + drive.start())[0]
    spindle = re.search(r"<Spindle>\s*(true|false)\s*</Spindle>", owner, re.I)
    if spindle:
        embedded.spindle = spindle.group(1).lower() == "true"
        embedded.spindle_line = _line_col(text, owner_start + spindle.start())[0]
    return embedded


def _isg(text: str) -> EmbeddedList:
    from .catalogue import catalogue, fill_indices

    cat = catalogue()
    lines: list[str] = []
    positions: list[tuple[int, int]] = []
    for match in _ELEMENT.finditer(text):
        pid = match.group("id")
        indices = tuple(int(i) for i in match.group("index").split(".") if i)
        value_match = _VALUE.search(match.group("attrs"))
        value = _unescape(value_match.group("value")) if value_match else ""
        parameter = cat.by_id.get(pid)
        if parameter is None:
            path = pid + match.group("index").replace(".", "_")  # reported as an unknown parameter
        else:
            count = parameter.path.count("[i]")
            wanted = (indices + (0,) * count)[:count]
            path = fill_indices(parameter.path, wanted)
        if value and (re.search(r"\s|\(", value) or value.startswith('"')):
            value = '"' + value.strip('"') + '"'
        lines.append(f"{path} {value}".rstrip())
        positions.append(_line_col(text, match.start()))
    close = text.rfind("</AX_MDS>")
    lines.append("Ende")
    positions.append(_line_col(text, close if close >= 0 else len(text)))
    return EmbeddedList("\n".join(lines) + "\n", "AX_MDS", positions[0][0], positions[0][1], line_map=positions)
