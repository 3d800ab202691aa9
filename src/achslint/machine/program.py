"""A homing program (`rfp.nc`) read as far as the machine dry-run and LIS6xx need it.

Read: the `%` header line, `N` numbers, comments (`( … )` and `;` to the end of the line), `G74` with
axis words whose values give the homing order, straight moves `G00`/`G01` with `G90`/`G91` and `F`
(mm/min; the modal state is carried from block to block), and the program end `M30`/`M02`. Every other
block becomes a `SkippedBlock` with the reason: nothing the reader does not understand is guessed.
Defects of the text (an unterminated comment, `G74` without axes, a sequence number that is not a whole
number from 1 up) become `ProgramProblem`s with line and column. The reader never raises: random bytes
give problems, not a traceback.

Axis words are read without knowing the machine: an address is a run of letters (`X`, `Z`, `SPOS`) with
a number right after it (`X1`, `Z-20.5`), or an extended name with `=` (`Z1=200`, `S1=3`), so that axes
named with digits can be written. Whether the name is an axis of the machine is for LIS6xx to say.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from ..core.display import shortened
from ..syntax.parser import split_lines
from .model import (
    AxisWord,
    HomingBlock,
    Location,
    MoveBlock,
    Program,
    ProgramProblem,
    SkippedBlock,
)

# The highest sequence number read as a homing order; larger numbers are a typing slip, not an order.
MAX_SEQUENCE = 32767
# Addresses that are never axis names in a block the dry-run reads.
NOT_AXES = frozenset({"N", "G", "F", "M", "S", "T", "D", "H", "E", "L", "P", "O", "I", "J", "K", "R"})
# G codes that change nothing the dry-run simulates (plane selection, cutter compensation off, cycles off).
NEUTRAL_G = frozenset({17, 18, 19, 40, 80})
# Program end: the CNC stops reading here.
END_M = frozenset({2, 30})

_NUMBER = r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)"
# `Z200` / `G01` / `N10` (letters, then a number); `bare` catches a letter run without a number. Every part
# is matched in time linear in what it takes, whatever follows.
_WORD = re.compile(rf"(?P<addr>[A-Za-z][A-Za-z_]*)(?P<value>{_NUMBER})|(?P<bare>[A-Za-z][A-Za-z_]*)")
# An extended name (`Z1=200`, `S1=3`) is a run of letters, digits and `_` that starts with a letter and is
# followed by `=` and a number. The run is found once and shared by every position inside it: matching it
# again from each word of `X1Y1Y1…=` would take time quadratic in the length of the run.
_NOT_IN_NAME = re.compile(r"[^A-Za-z0-9_]")
_EXTENDED_VALUE = re.compile(rf"=(?P<evalue>{_NUMBER})")
_BLANKS = " \t\f\v"
# A block number at the start of a block, with the blanks after it.
_BLOCK_NUMBER = re.compile(r"[Nn]\+?[0-9]+[ \t\f\v]*")
_LETTERS = re.compile(r"[A-Z_]*")


def _letters(address: str) -> str:
    """The letters an address starts with: `P` of the extended `P1`, the address itself otherwise."""
    match = _LETTERS.match(address)
    return match.group(0) if match else address


@dataclass
class _Word:
    address: str  # upper case
    text: str  # the number as written
    column: int
    end_column: int
    extended: bool = False

    @property
    def number(self) -> float:
        return float(self.text)

    @property
    def written(self) -> str:
        """The word as written, for messages (shortened when long)."""
        return _short(f"{self.address}{'=' if self.extended else ''}{self.text}")


@dataclass
class _Modal:
    motion: int | None = None  # 0 (G00) or 1 (G01) once programmed; no motion mode is assumed before
    absolute: bool = True  # G90 is the CNC's default
    feed: float | None = None


@dataclass
class _Reader:
    name: str
    program: Program = field(init=False)
    modal: _Modal = field(default_factory=_Modal)
    ended: bool = False
    in_comment: Location | None = None

    def __post_init__(self) -> None:
        self.program = Program(self.name)

    def at(self, line: int, column: int, end_column: int | None = None) -> Location:
        return Location(self.name, line, column, end_column)

    def problem(self, line: int, column: int, end_column: int | None, message: str) -> None:
        self.program.problems.append(ProgramProblem(self.at(line, column, end_column), message))

    # -- text to words ---------------------------------------------------------------------------
    def code_parts(self, number: int, text: str) -> list[tuple[int, str]]:
        """The parts of a line outside comments, as (0-based start, text)."""
        parts: list[tuple[int, str]] = []
        position = 0
        while position < len(text):
            char = text[position]
            if char == ";":
                break
            if char == "(":
                close = text.find(")", position + 1)
                if close < 0:
                    self.problem(
                        number,
                        position + 1,
                        len(text) + 1,
                        "the comment opened here is not closed with `)` on this line; "
                        "the rest of the line is read as a comment",
                    )
                    break
                position = close + 1
                continue
            start = position
            while position < len(text) and text[position] not in "(;":
                position += 1
            parts.append((start, text[start:position]))
        return parts

    def words(self, number: int, text: str) -> tuple[list[_Word], list[tuple[int, int, str]]]:
        """The words of a line, and what could not be read as a word: (column, end column, text)."""
        words: list[_Word] = []
        junk: list[tuple[int, int, str]] = []
        for start, part in self.code_parts(number, text):
            position = 0
            run_end = 0  # where the letter/digit run around `position` ends
            while position < len(part):
                if part[position] in _BLANKS:
                    position += 1
                    continue
                column = start + position + 1
                if position >= run_end:
                    stop = _NOT_IN_NAME.search(part, position)
                    run_end = stop.start() if stop else len(part)
                letter = part[position].isascii() and part[position].isalpha()
                extended = _EXTENDED_VALUE.match(part, run_end) if letter else None
                if extended is not None:
                    end = extended.end()
                    name = part[position:run_end].upper()
                    word = _Word(name, extended.group("evalue"), column, start + end + 1, True)
                    self.word(word, part[position:end], words, junk)
                    position = run_end = end
                    continue
                match = _WORD.match(part, position)
                if match is None:
                    end = position
                    while end < len(part) and part[end] not in _BLANKS and not part[end].isalpha():
                        end += 1
                    end = max(end, position + 1)
                    junk.append((column, start + end + 1, part[position:end]))
                    position = end
                    continue
                end_column = start + match.end() + 1
                if match.group("addr"):
                    word = _Word(match.group("addr").upper(), match.group("value"), column, end_column)
                    self.word(word, match.group(0), words, junk)
                else:
                    junk.append((column, end_column, match.group("bare")))
                position = match.end()
        return words, junk

    @staticmethod
    def word(word: _Word, written: str, words: list[_Word], junk: list[tuple[int, int, str]]) -> None:
        """Keep a word, or report it as junk when its number is too large for a float."""
        if math.isfinite(word.number):
            words.append(word)
        else:
            junk.append((word.column, word.end_column, written))

    # -- blocks ------------------------------------------------------------------------------------
    def line(self, number: int, text: str) -> None:
        body = text.lstrip(_BLANKS)
        indent = len(text) - len(body)
        if not body:
            return
        if number == 1 and body.startswith("%"):
            return  # the program name line (`%rfp.nc`)
        if self.ended:
            self.skip(number, indent + 1, text, "after the program end (M30/M02): the CNC does not read it")
            return
        if body.startswith("/"):
            self.skip(number, indent + 1, text, "an optional block (`/`): whether it runs depends on the CNC")
            return
        # A control command may follow a block number (`N10 #MSG[...]`); it is passed over all the same.
        numbered = _BLOCK_NUMBER.match(body)
        if body.startswith(("#", "$", "%")) or (numbered and body[numbered.end() :].startswith(("#", "$"))):
            self.skip(number, indent + 1, text, "a control command or statement: not simulated")
            return
        words, junk = self.words(number, text)
        for column, end_column, piece in junk:
            self.problem(number, column, end_column, _junk_message(piece))
        if not words and not junk:
            return  # a comment line
        self.block(number, text, words, bool(junk))

    def skip(self, number: int, column: int, text: str, reason: str) -> None:
        self.program.blocks.append(
            SkippedBlock(self.at(number, column, len(text) + 1), text.strip(_BLANKS), reason)
        )

    def block(self, number: int, text: str, words: list[_Word], unreadable: bool) -> None:
        block_number = self.block_number(number, words)
        first = min((w.column for w in words), default=1)
        words = [w for w in words if w.address != "N"]
        g_codes = [w for w in words if w.address == "G"]
        codes = set()
        other_g = []
        for word in g_codes:
            value = word.number
            if value != int(value):
                other_g.append(word)
                continue
            codes.add(int(value))
            if int(value) not in (0, 1, 74, 90, 91) and int(value) not in NEUTRAL_G:
                other_g.append(word)
        # The modal words count even in a block that is skipped for other reasons.
        if 90 in codes and 91 in codes:
            self.problem(number, first, len(text) + 1, "G90 and G91 in one block: the later one wins")
        for word in g_codes:
            if word.number in (90.0, 91.0):
                self.modal.absolute = word.number == 90.0
        feed = [w for w in words if w.address == "F"]
        for word in feed:
            if word.number <= 0:
                self.problem(
                    number,
                    word.column,
                    word.end_column,
                    f"{word.written}: a feed rate must be above 0 mm/min",
                )
            else:
                self.modal.feed = word.number
        motion = [int(w.number) for w in g_codes if w.number in (0.0, 1.0)]
        m_words = [w for w in words if w.address == "M"]
        ends = [w for w in m_words if w.number in END_M]
        # In a G74 block every other address names an axis (the spindle `S` too); in a move block the
        # spindle speed, tools and the like are not simulated.
        others = [w for w in words if w.address not in ("G", "F", "M")]
        # `P1=2` (a parameter) and `S1=1000` (the speed of spindle S1) name no axis either.
        not_read = [] if 74 in codes else [w for w in others if _letters(w.address) in NOT_AXES]
        location = self.at(number, first, len(text) + 1)
        if unreadable:
            if 74 in codes:  # its sequence numbers are still checked, for the report
                self.homing(number, block_number, location, others, keep=False)
            self.program.blocks.append(
                SkippedBlock(location, text.strip(_BLANKS), "it holds text that is not an NC word")
            )
            return
        reasons = []
        if other_g:
            reasons.append(", ".join(w.written for w in other_g) + " is not simulated")
        if not_read:
            reasons.append(", ".join(w.written for w in not_read) + " is not simulated")
        extra_m = [w for w in m_words if w.number not in END_M]
        if extra_m:
            reasons.append(", ".join(w.written for w in extra_m) + " is not simulated")
        if 74 in codes and motion:
            reasons.append("G74 and a motion command (G00/G01) in one block")
        if reasons:
            self.modal.motion = motion[-1] if motion else self.modal.motion
            self.program.blocks.append(SkippedBlock(location, text.strip(_BLANKS), "; ".join(reasons)))
        elif 74 in codes:
            self.homing(number, block_number, location, others)
        else:
            if motion:
                self.modal.motion = motion[-1]
            if others:
                self.move(number, block_number, location, others, text.strip(_BLANKS))
        if ends:
            self.ended = True
            self.program.end = self.at(number, ends[0].column, ends[0].end_column)

    def block_number(self, number: int, words: list[_Word]) -> int | None:
        numbers = [w for w in words if w.address == "N"]
        for word in numbers[1:]:
            self.problem(number, word.column, word.end_column, "a second block number in one block")
        if not numbers:
            return None
        word = numbers[0]
        if not re.fullmatch(r"\+?[0-9]+", word.text) or len(word.text) > 9:
            self.problem(number, word.column, word.end_column, f"{word.written} is not a block number")
            return None
        return int(word.text)

    def homing(
        self,
        number: int,
        block_number: int | None,
        location: Location,
        words: list[_Word],
        keep: bool = True,
    ) -> None:
        axis_words = []
        for word in words:
            value = word.text
            if not re.fullmatch(r"\+?[0-9]+", value) or not value.strip("+0"):
                self.problem(
                    number,
                    word.column,
                    word.end_column,
                    f"G74 {word.written}: the homing order of an axis is "
                    "a whole number from 1 up (axes with the same number home together)",
                )
                continue
            if len(value.lstrip("+0")) > 5 or int(value) > MAX_SEQUENCE:
                self.problem(
                    number,
                    word.column,
                    word.end_column,
                    f"G74 {word.written}: a homing order above "
                    f"{MAX_SEQUENCE} is not read; number the steps 1, 2, 3, …",
                )
                continue
            axis_words.append(
                AxisWord(word.address, float(int(value)), self.at(number, word.column, word.end_column))
            )
        if not words and keep:  # (a block that cannot be read has its own problem)
            self.problem(
                number,
                location.column,
                location.end_column,
                "G74 names no axis to home: write the axes with their homing order, e.g. `G74 X1 Y1 Z2`",
            )
        if keep:
            self.program.blocks.append(HomingBlock(location, block_number, tuple(axis_words)))

    def move(
        self, number: int, block_number: int | None, location: Location, words: list[_Word], text: str
    ) -> None:
        if self.modal.motion is None:
            self.program.blocks.append(
                SkippedBlock(
                    location,
                    text,
                    "an axis position without G00 or G01 programmed before it: the motion mode in force "
                    "is not known",
                )
            )
            return
        rapid = self.modal.motion == 0
        if not rapid and self.modal.feed is None:
            self.problem(
                number, location.column, location.end_column, "G01 without a feed rate: program F (mm/min)"
            )
        targets = tuple(AxisWord(w.address, w.number, self.at(number, w.column, w.end_column)) for w in words)
        self.program.blocks.append(
            MoveBlock(location, block_number, rapid, self.modal.absolute, self.modal.feed, targets)
        )


# Longer words are shortened in messages: a 5,000-digit number is not worth repeating.
SHOWN_CHARACTERS = 40


def _short(text: str) -> str:
    return shortened(text, SHOWN_CHARACTERS, SHOWN_CHARACTERS // 2)


def _junk_message(piece: str) -> str:
    if piece[:1].isalpha() and piece.isascii():
        if re.fullmatch(r"[A-Za-z_]+", piece):
            return f"`{_short(piece)}` has no number after it, so the block cannot be read"
        return f"`{_short(piece)}`: the number is too large to use, so the block cannot be read"
    shown = _short(piece if piece.isprintable() else repr(piece))
    return f"`{shown}` is not an NC word (an address followed by a number), so the block cannot be read"


def read_program(data: bytes, name: str) -> Program:
    """The blocks of a homing program, with the problems of its text. Never raises."""
    reader = _Reader(name)
    text = program_text(data)
    if text is None:
        reader.problem(
            1,
            1,
            None,
            "this is not an NC program as text (it holds NUL bytes or is UTF-16/32): "
            "save it as ASCII/Latin-1",
        )
        return reader.program
    lines = split_lines(text)
    if _is_parameter_list(lines):
        reader.problem(
            1,
            1,
            None,
            "this is a parameter list (`name value` lines closed by `Ende`), not an NC program: give the "
            "homing program (rfp.nc) here, and the start-up list as the machine",
        )
        return reader.program
    for number, line in enumerate(lines, 1):
        reader.line(number, line)
    return reader.program


# A parameter-list line: a name with a `.` or an index (`kenngr.achs_typ`, `achs_mds[0]`), blanks, a value.
_LIST_ENTRY = re.compile(r"[ \t]*[A-Za-z_][A-Za-z0-9_]*(?:\[[0-9]+\]|\.[A-Za-z_][A-Za-z0-9_]*)+[ \t]+\S")


def _is_parameter_list(lines: list[str]) -> bool:
    """Whether the text is a parameter list (an axis, channel or start-up list) rather than an NC program: a
    line `Ende` ends it, and it has entries. Neither is an NC block (`Ende` has no number after its letters)."""
    if not any(line.strip() == "Ende" for line in lines):
        return False
    return any(_LIST_ENTRY.match(line) for line in lines)


def program_text(data: bytes) -> str | None:
    """The program as text (UTF-8, else Latin-1); None for a binary or UTF-16/32 file."""
    if data.startswith((b"\xff\xfe", b"\xfe\xff")) or b"\x00" in data:
        return None
    body = data[3:] if data.startswith(b"\xef\xbb\xbf") else data
    try:
        return body.decode("utf-8")
    except UnicodeDecodeError:
        return body.decode("latin-1")
