"""The one axis list a file holds, for the commands that read a single list (explain, dry-run, diff, the
machine build), and the check that a file is an axis list at all."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from ..core.decode import UnreadableInput
from ..core.files import Refused, is_xml, not_a_list_file, read_list
from ..syntax.parser import ASSIGNMENT, END, ListFile, parse_bytes

NOT_A_LIST = (
    "not an axis list (no line is a `parameter value` assignment and there is no `Ende`); "
    "nothing of its content is shown"
)


def looks_like_a_list(file: ListFile) -> bool:
    """Whether a file is an axis list at all: some line assigns a well-formed name, or it has the end marker.

    Anything else (a password file, the process environment, a binary) is reported once instead of line by
    line, so none of its lines end up in a report or a CI log.
    """
    content = False
    for line in file.lines:
        if line.kind == END or (line.kind == ASSIGNMENT and line.path_ok):
            return True
        content = content or line.kind == ASSIGNMENT
    return not content


def read_one_list(path: Path, name: str, read: Callable[[Path], bytes] = read_list) -> bytes:
    """The one axis list a file holds, for the commands that read a single list (explain, dry-run, diff).

    The same checks as for lint: a regular file only (never a FIFO or /proc), XML through the one XML
    parser (DTDs and entities refused; the file's only `<AchsMds>` / `<AX_MDS>` list), and a file that is
    not an axis list refused without showing it. `read` reads the file (the editor: its open buffer).
    Raises `OSError` or `UnreadableInput` with a message.
    """
    problem = not_a_list_file(path)
    if problem is not None:
        raise Refused(f"{name}: {problem}")
    data = read(path)
    if is_xml(name):
        from ..syntax.xmlinput import single_list

        return single_list(data, name)
    if not looks_like_a_list(parse_bytes(data, name)):
        raise UnreadableInput(f"{name}: {NOT_A_LIST}")
    return data
