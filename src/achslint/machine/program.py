"""A homing program (`rfp.nc`) read as far as the machine dry-run and LIS6xx need it.

Read: the `%` header line, `N` numbers, comments (`( … )`, nested, `(` left open and `;`, both to the end of the line), `G74`
with axis words whose values give the homing order, straight moves `G00`/`G01` with `G90`/`G91` and `F`
(mm/min; the modal state is carried from block to block), and the program end `M30`/`M02`. Every other
block becomes a `SkippedBlock` with the reason: nothing the reader does not understand is guessed.
Defects of the text (an unclosed `[`, `G74` without axes, a sequence number that
is not a whole number from 1 up) become `ProgramProblem`s with line and column. The reader never raises:
random bytes give problems, not a traceback.

The ISG decoder reads more than addresses with numbers (TF5200 programming manual, "Structure of NC
programs", "Arithmetical expressions", "Parameters", "Subroutines", "Control block statements"), and so
does the reader, without evaluating any of it:

* a value computed when the program runs: `X[-2*P1+3]`, `X P1*SIN[P2*30]`, `XP1`, `Y2=[P1]`, `X"POS"`:
  such a word is read with its expression, and its block is passed over (a G74 with a computed order or a
  move to a computed position still names its axes, for the findings that need only the names);
* assignments: `P1 = 2`, `PP1 = P2 + P3 * [P4 - 1]`, `P[P1+5] = 0`, `V.P.NAME = …`, `"NAME" = "5 * 12"`;
* calls the reader does not follow: `L name` (a global subroutine), `LL name` (a local one), `"NAME"` (a
  macro); `%L name` … `M17`/`M29` defines a local subroutine, whose blocks run only where they are called;
* `$IF`, `$FOR`, `$GOTO` and the other control statements: the reader does not follow the program's course
  from there; `#` commands are passed over (`#COMMENT BEGIN` … `#COMMENT END` is a comment, `#VAR` …
  `#ENDVAR` declares variables).

After a block it does not follow, the reader says so on the block (`SkippedBlock.unfollowed`) and forgets
the modal state (G00/G01, G90/G91, F), which the part it did not follow may have changed.

Axis words are read without knowing the machine: an address is a run of letters (`X`, `Z`, `SPOS`) with
a value after it (`X1`, `Z-20.5`, `X 10`), or an extended name with `=` (`Z1=200`, `S1=3`), so that axes
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
    NamedAxis,
    Program,
    ProgramProblem,
    SkippedBlock,
    Unfollowed,
)

# The highest sequence number read as a homing order; larger numbers are a typing slip, not an order.
MAX_SEQUENCE = 32767
# Addresses that are never axis names in a block the dry-run reads.
NOT_AXES = frozenset({"N", "G", "F", "M", "S", "T", "D", "H", "E", "L", "P", "O", "I", "J", "K", "R"})
# G codes that change nothing the dry-run simulates (plane selection, cutter compensation off, cycles off).
NEUTRAL_G = frozenset({17, 18, 19, 40, 80})
# Program end: the CNC stops reading here.
END_M = frozenset({2, 30})
# The end of a local subroutine (`%L name` … M17 or M29).
SUBROUTINE_END_M = frozenset({17, 29})
# Control statements that only ever go forward (a branch, or leaving a loop): the blocks after them may be
# passed by, but none runs twice. The others loop or jump back (`$FOR`, `$ENDWHILE`, `$GOTO`, …).
FORWARD_STATEMENTS = frozenset(
    {"$IF", "$ELSEIF", "$ELSE", "$ENDIF", "$SWITCH", "$CASE", "$DEFAULT", "$ENDSWITCH", "$BREAK"}
)

_NUMBER = r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)"
_SIGNED_NUMBER = re.compile(_NUMBER)
_UNSIGNED_NUMBER = re.compile(r"[0-9]+(?:\.[0-9]*)?|\.[0-9]+")
_LETTER_RUN = re.compile(r"[A-Za-z_]+")
# An extended name (`Z1=200`, `S1=3`) is a run of letters, digits and `_` that starts with a letter and is
# followed by `=` and a value. The run is found once and shared by every position inside it: matching it
# again from each word of `X1Y1Y1…=` would take time quadratic in the length of the run.
_NOT_IN_NAME = re.compile(r"[^A-Za-z0-9_]")
_BLANKS = " \t\f\v"
# A block number at the start of a block, with the blanks after it.
_BLOCK_NUMBER = re.compile(r"[Nn]\+?([0-9]+)[ \t\f\v]*")
_LETTERS = re.compile(r"[A-Z_]*")
# A parameter (`P1`, `PP12`, `P[P1+5]`, `R3` in the DIN mode of parameters) or a variable (`V.P.NAME`,
# `V.A.ABS.X`), up to an index in brackets, which the reader takes as brackets.
_PARAMETER = re.compile(r"[Pp]+(?:[0-9]+|(?=\[))|[Rr][0-9]+")
_VARIABLE = re.compile(r"[Vv]\.[A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z0-9_]+)*")
_VARIABLE_PART = re.compile(r"\.[A-Za-z0-9_]+")
# Binary operators of an expression written without brackets (`P1 = P2 + 3`, `X P1*SIN[P2*30]`), longest
# first so that `**` is not read as `*`.
_OPERATORS = ("**", "==", "!=", "<>", "<=", ">=", "*", "/", "+", "-", "<", ">", "&", "|", "^")
_WORD_OPERATORS = frozenset({"MOD", "AND", "OR", "XOR"})
# What ends the name of a subroutine in a call (`L gup_1.nc`, `LL UP1`): the decoder's separators.
_NAME_END = frozenset(_BLANKS + '(;"],#$')
# `%L name` begins a local subroutine (a separator between `L` and the name is required).
_LOCAL_SUBROUTINE = re.compile(r"%[Ll][ \t]+([^ \t(;]+)")
_COMMENT_BEGIN = re.compile(r"#COMMENT[ \t]+BEGIN\b", re.IGNORECASE)
_COMMENT_END = re.compile(r"#COMMENT[ \t]+END\b", re.IGNORECASE)
# `#VAR` … `#ENDVAR` declares variables, one a line (`V.P.NAME`, `V.L.NAME : UNS32 = 200`).
_VAR_BEGIN = re.compile(r"#VAR\b", re.IGNORECASE)
_VAR_END = re.compile(r"#ENDVAR\b", re.IGNORECASE)
_STATEMENT = re.compile(r"\$[A-Za-z]*")
_GOTO = re.compile(r"\$GOTO\b[ \t]*(?:[Nn]\+?([0-9]+)\b)?", re.IGNORECASE)


def _letters(address: str) -> str:
    """The letters an address starts with: `P` of the extended `P1`, the address itself otherwise."""
    match = _LETTERS.match(address)
    return match.group(0) if match else address


# -- expressions -----------------------------------------------------------------------------------------
# The reader only finds where an expression ends; it never evaluates one. Inside brackets anything the
# decoder may take (functions, variables, strings, comparisons) is passed over, as long as the brackets
# pair; outside brackets an expression is operands joined by operators. Every scan moves forward only, so
# a line is read in time linear in its length.


class _Unreadable(Exception):
    """Text the decoder cannot read, from `start` to `end` (indices into a part), and why."""

    def __init__(self, start: int, end: int, why: str):
        super().__init__(why)
        self.start, self.end, self.why = start, end, why


def _skip(text: str, i: int) -> int:
    """The first index at or after `i` that is no blank."""
    n = len(text)
    while i < n and text[i] in _BLANKS:
        i += 1
    return i


def _string_end(text: str, i: int) -> int:
    """The index after the `"` that closes the string opened at `i` (`\\"` does not close it); -1 if none."""
    n = len(text)
    j = i + 1
    while j < n:
        char = text[j]
        if char == "\\":
            j += 2
            continue
        if char == '"':
            return j + 1
        j += 1
    return -1


def _brackets_end(text: str, i: int) -> int:
    """The index after the `]` that pairs with the `[` at `i`. Raises _Unreadable when none does, or when
    the brackets hold nothing."""
    depth = 0
    j, n = i, len(text)
    while j < n:
        char = text[j]
        if char == '"':
            close = _string_end(text, j)
            if close < 0:
                break
            j = close
            continue
        if char == "[":
            depth += 1
        elif char == "]":
            depth -= 1
            if depth == 0:
                if not text[i + 1 : j].strip(_BLANKS):
                    raise _Unreadable(i, j + 1, "nothing between `[` and `]`")
                return j + 1
        j += 1
    raise _Unreadable(i, n, "the `[` is not closed with `]`")


def _reference_end(text: str, i: int) -> tuple[int, str] | None:
    """Where a parameter or variable that starts at `i` ends, with its kind ("parameter", "variable")."""
    match = _VARIABLE.match(text, i)
    kind = "variable"
    if match is None:
        match = _PARAMETER.match(text, i)
        kind = "parameter"
    if match is None:
        return None
    end, n = match.end(), len(text)
    while end < n and text[end] == "[":  # `P100[50]`, `V.L.ARR[2].ELEM`
        end = _brackets_end(text, end)
        part = _VARIABLE_PART.match(text, end) if kind == "variable" else None
        if part is not None:
            end = part.end()
    return end, kind


def _operand_end(text: str, i: int, names: bool) -> int | None:
    """Where an operand of an expression that starts at `i` ends (None when none starts there): a number,
    a parameter or variable, a macro (`"NAME"`), brackets, a function (`SIN[…]`, `ABS [ … ]`), after any
    signs; with `names`, also a name (`TRUE`), which only the right side of an assignment may hold."""
    n = len(text)
    while i < n and text[i] in "+-":
        i = _skip(text, i + 1)
    if i >= n:
        return None
    char = text[i]
    if char == "[":
        return _brackets_end(text, i)
    if char == '"':
        close = _string_end(text, i)
        return None if close < 0 else close
    if char.isdigit() or char == ".":
        number = _UNSIGNED_NUMBER.match(text, i)
        return None if number is None else number.end()
    if not (char.isascii() and char.isalpha()):
        return None
    reference = _reference_end(text, i)
    if reference is not None:
        return reference[0]
    run = _LETTER_RUN.match(text, i)
    end = run.end() if run else i + 1
    if end < n and text[end].isdigit():
        return None  # an NC word (`X10`), not an operand
    after = _skip(text, end)
    if after < n and text[after] == "[":
        return _brackets_end(text, after)
    if not names or text[i:end].upper() in _WORD_OPERATORS:
        return None
    return end


def _operator_length(text: str, i: int) -> int:
    """The length of the binary operator at `i`; 0 if there is none."""
    for operator in _OPERATORS:
        if text.startswith(operator, i):
            return len(operator)
    run = _LETTER_RUN.match(text, i)
    if run is not None and run.group().upper() in _WORD_OPERATORS:
        end = run.end()
        if end >= len(text) or not text[end].isdigit():
            return end - i
    return 0


def _expression_end(text: str, i: int, names: bool = False) -> int | None:
    """Where an expression that starts at `i` ends: operands joined by operators, blanks between them
    allowed. An operator with no operand after it is not part of the expression."""
    end = _operand_end(text, i, names)
    if end is None:
        return None
    while True:
        at = _skip(text, end)
        length = _operator_length(text, at)
        if not length:
            return end
        after = _operand_end(text, _skip(text, at + length), names)
        if after is None:
            return end
        end = after


def _assignment_at(text: str, i: int) -> int | None:
    """The index after the `=` of an assignment when the next text after blanks is `=` (not `==`)."""
    at = _skip(text, i)
    if at < len(text) and text[at] == "=" and not text.startswith("==", at):
        return at + 1
    return None


@dataclass
class _Word:
    address: str  # upper case
    text: str  # the value as written: a number, or an expression when `computed`
    column: int
    end_column: int
    extended: bool = False
    computed: bool = False  # the value is an expression the CNC evaluates when the program runs

    @property
    def number(self) -> float:
        return math.nan if self.computed else float(self.text)

    @property
    def written(self) -> str:
        """The word as written, for messages (shortened when long)."""
        gap = "=" if self.extended else " " if self.computed and self.text[:1].isalpha() else ""
        return _short(f"{self.address}{gap}{self.text}")


@dataclass
class _Line:
    """What a line's code holds: words, text that cannot be read, assignments and calls."""

    words: list[_Word] = field(default_factory=list)
    junk: list[tuple[int, int, str, str | None]] = field(default_factory=list)  # column, end, text, why
    assignments: list[tuple[int, str]] = field(default_factory=list)  # column, kind
    calls: list[tuple[int, str, str]] = field(default_factory=list)  # column, text, kind

    @property
    def first_column(self) -> int:
        columns = [w.column for w in self.words] + [c for c, _ in self.assignments]
        columns += [c for c, _, _ in self.calls]
        return min(columns, default=1)


@dataclass
class _Modal:
    motion: int | None = None  # 0 (G00) or 1 (G01) once programmed; no motion mode is assumed before
    absolute: bool | None = True  # G90 is the CNC's default; None when not known
    feed: float | None = None
    # Where the modal values stopped being known (" after line 6 (`LL SUB`)"), until programmed again; the
    # feed rate alone is also not known after a computed `F[…]`.
    lost: str = ""
    feed_lost: str = ""

    def lose(self, where: str) -> None:
        self.motion, self.absolute, self.feed = None, None, None
        self.lost = self.feed_lost = where


@dataclass
class _Reader:
    name: str
    # Block numbers a `$GOTO` jumps to; None when some jump's target cannot be read (any block may be one).
    targets: set[int] | None = field(default_factory=set)
    program: Program = field(init=False)
    modal: _Modal = field(default_factory=_Modal)
    ended: bool = False
    in_comment: Location | None = None
    flowed: bool = False  # a block was passed that branches, loops or jumps ($IF, $GOTO, …)
    subroutine: tuple[str, int] | None = None  # the local subroutine being defined: name, line of `%L`
    comment_lines: bool = False  # between #COMMENT BEGIN and #COMMENT END
    declaring: bool = False  # between #VAR and #ENDVAR

    def __post_init__(self) -> None:
        self.program = Program(self.name)

    def at(self, line: int, column: int, end_column: int | None = None) -> Location:
        return Location(self.name, line, column, end_column)

    def problem(self, line: int, column: int, end_column: int | None, message: str) -> None:
        self.program.problems.append(ProgramProblem(self.at(line, column, end_column), message))

    # -- text to words ---------------------------------------------------------------------------
    def code_parts(self, number: int, text: str, found: _Line) -> list[tuple[int, str]]:
        """The parts of a line outside comments, as (0-based start, text). A comment may hold comments
        (`(a (b) c)`); a string (`"…"`) holds no comment."""
        parts: list[tuple[int, str]] = []
        start = position = 0
        n = len(text)
        while position < n:
            char = text[position]
            if char == ";":
                break
            if char == '"':
                close = _string_end(text, position)
                if close < 0:
                    parts.append((start, text[start:position]))
                    found.junk.append(
                        (position + 1, n + 1, text[position:], 'the text opened here with `"` is not closed')
                    )
                    return parts
                position = close
                continue
            if char != "(":
                position += 1
                continue
            if start < position:
                parts.append((start, text[start:position]))
            depth, close = 0, -1
            for index in range(position, n):
                if text[index] == "(":
                    depth += 1
                elif text[index] == ")":
                    depth -= 1
                    if depth == 0:
                        close = index + 1
                        break
            if close < 0:
                # The end of the block ends a comment too (ISG programming manual, "Structure of NC
                # programs": a comment left open runs to the end of its block), so this is no defect.
                return parts
            start = position = close
        if start < position:
            parts.append((start, text[start:position]))
        return parts

    def words(self, number: int, text: str) -> _Line:
        """The words of a line, and what could not be read as a word."""
        found = _Line()
        for start, part in self.code_parts(number, text, found):
            position = 0
            run_end = 0  # where the letter/digit run around `position` ends
            run_value: int | None = None  # where the value after `=` behind that run starts
            while position < len(part):
                if part[position] in _BLANKS:
                    position += 1
                    continue
                if position >= run_end:
                    stop = _NOT_IN_NAME.search(part, position)
                    run_end = stop.start() if stop else len(part)
                    run_value = _assignment_at(part, run_end)
                try:
                    position = self.item(start, part, position, run_end, run_value, found)
                except _Unreadable as exc:
                    end = max(exc.end, position + 1)
                    found.junk.append((start + position + 1, start + end + 1, part[position:end], exc.why))
                    position = end
                    run_end = 0
        return found

    def item(
        self, start: int, part: str, position: int, run_end: int, run_value: int | None, found: _Line
    ) -> int:
        """Read what starts at `position` of a part into `found`; return where the next item may start."""
        column = start + position + 1
        char = part[position]
        n = len(part)
        if char == '"':  # a macro: defined (`"NAME" = "…"`) or called
            close = _string_end(part, position)  # the line's strings are closed (code_parts)
            value = _assignment_at(part, close)
            if value is None:
                found.calls.append((column, part[position:close], "macro"))
                return close
            return self.assignment(part, position, value, "macro", column, found)
        if not (char.isascii() and char.isalpha()):
            end = position
            while end < n and part[end] not in _BLANKS and not part[end].isalpha():
                end += 1
            end = max(end, position + 1)
            found.junk.append((column, start + end + 1, part[position:end], None))
            return end
        reference = _reference_end(part, position)
        if reference is not None:
            end, kind = reference
            value = _assignment_at(part, end)
            if value is not None:
                return self.assignment(part, position, value, kind, column, found)
            if kind == "variable":
                raise _Unreadable(
                    position, end, "a variable outside an expression must be assigned (`V.… = …`)"
                )
        run = _LETTER_RUN.match(part, position)
        letters = run.end() if run else position + 1
        head = part[position:letters].upper()
        if head.startswith("L"):
            return self.call(start, part, position, head, found)
        if run_value is not None:  # an extended name: `Y2=1`, `S1 = 3`, `Z1=[P1]`
            value_start = _skip(part, run_value)
            value_end = _expression_end(part, value_start)
            if value_end is None:
                raise _Unreadable(position, run_value, "nothing after `=`")
            text = part[value_start:value_end]
            computed = _SIGNED_NUMBER.fullmatch(text) is None
            word = _Word(part[position:run_end].upper(), text, column, start + value_end + 1, True, computed)
            self.word(word, part[position:value_end], found)
            return value_end
        address, address_end = head, letters
        # `XP1`, `ZPP2*3`: an address and a parameter written together.
        together = len(head) > 1 and head[0] != "P" and head[1:] == "P" * (len(head) - 1)
        if together and letters < n and (part[letters].isdigit() or part[letters] == "["):
            address, address_end = head[0], position + 1
        elif len(head) > 1 and head[-1] == "V" and _VARIABLE.match(part, letters - 1):
            address, address_end = head[:-1], letters - 1  # `XV.P.POS`: an address and a variable together
        value_start = _skip(part, address_end)
        value_end = _expression_end(part, value_start)
        if value_end is None:
            found.junk.append((column, start + letters + 1, part[position:letters], None))
            return letters
        text = part[value_start:value_end]
        computed = _SIGNED_NUMBER.fullmatch(text) is None
        self.word(
            _Word(address, text, column, start + value_end + 1, False, computed),
            part[position:value_end],
            found,
        )
        return value_end

    @staticmethod
    def assignment(part: str, position: int, value: int, kind: str, column: int, found: _Line) -> int:
        """An assignment whose `=` ends at `value`: its right side is an expression."""
        end = _expression_end(part, _skip(part, value), names=True)
        if end is None:
            raise _Unreadable(position, value, "nothing to assign after `=`")
        found.assignments.append((column, kind))
        return end

    @staticmethod
    def call(start: int, part: str, position: int, head: str, found: _Line) -> int:
        """`L name` (a global subroutine, also `Lname`, `L4712`, `LV.E.NAME`) or `LL name` (a local one)."""
        n = len(part)
        named = position + (2 if head.startswith("LL") else 1)
        begin = _skip(part, named)
        if begin < n and part[begin] == '"':
            end = _string_end(part, begin)
        else:
            end = begin
            while end < n and part[end] not in _NAME_END:
                end += 1
        if end <= begin:
            raise _Unreadable(
                position,
                named,
                "a subroutine call names no subroutine: `L name` calls a global one, `LL name` a local one",
            )
        found.calls.append((start + position + 1, part[position:end], "subroutine"))
        return end

    @staticmethod
    def word(word: _Word, written: str, found: _Line) -> None:
        """Keep a word, or report it as junk when its number is too large for a float."""
        if word.computed or math.isfinite(word.number):
            found.words.append(word)
        else:
            found.junk.append((word.column, word.end_column, written, None))

    # -- blocks ------------------------------------------------------------------------------------
    def line(self, number: int, text: str) -> None:
        body = text.lstrip(_BLANKS)
        indent = len(text) - len(body)
        if not body:
            return
        numbered = _BLOCK_NUMBER.match(body)
        rest = body[numbered.end() :] if numbered else body
        if self.comment_lines:  # between #COMMENT BEGIN and #COMMENT END: comment lines, no blocks
            if _COMMENT_END.match(rest):
                self.comment_lines = False
            return
        if self.declaring:  # between #VAR and #ENDVAR: declarations, which the reader passes over
            if _VAR_END.match(rest):
                self.declaring = False
            if self.subroutine is not None:
                self.subroutine_line(number, text, indent, "#")  # passed over, as one of its blocks
            else:
                self.skip(number, indent + 1, text, "a declaration of variables (`#VAR`): not simulated")
            return
        if body.startswith("%"):
            local = _LOCAL_SUBROUTINE.match(body)
            if local is not None:
                name = _short(local.group(1))
                self.subroutine = (name, number)
                self.skip(
                    number,
                    indent + 1,
                    text,
                    f"begins the local subroutine {name}: its blocks run where `LL {name}` calls it",
                )
                return
            self.subroutine = None  # a subroutine defined before ends here
            if number == 1:
                return  # the program name line (`%rfp.nc`)
            if not self.ended:  # after the local subroutines (`%L …`), the main program
                self.skip(number, indent + 1, text, "a program name (`%…`): the main program begins here")
                return
        if self.subroutine is not None:
            self.subroutine_line(number, text, indent, rest)
            return
        if self.ended:
            self.skip(number, indent + 1, text, "after the program end (M30/M02): the CNC does not read it")
            return
        if body.startswith("/"):
            self.skip(
                number,
                indent + 1,
                text,
                "an optional block (`/`): whether it runs depends on the CNC",
                "any",
            )
            return
        # A control command may follow a block number (`N10 #MSG[...]`); it is passed over all the same.
        if rest.startswith("#"):
            self.command(rest)
            self.skip(number, indent + 1, text, "a control command or statement: not simulated")
            return
        if rest.startswith("$"):
            statement = _STATEMENT.match(rest)
            keyword = statement.group(0).upper() if statement else "$"
            self.skip(
                number,
                indent + 1,
                text,
                f"{keyword}: a control statement; the program's branches, loops and jumps are not followed",
                "branch" if keyword in FORWARD_STATEMENTS else "flow",
            )
            return
        if self.flowed and numbered is not None:
            label = int(numbered.group(1))
            if self.targets is None or label in self.targets:
                self.modal.lose(f" at N{label} (a `$GOTO` may jump there)")
        found = self.words(number, text)
        for column, end_column, piece, why in found.junk:
            self.problem(number, column, end_column, _junk_message(piece, why))
        if not (found.words or found.junk or found.assignments or found.calls):
            return  # a comment line
        self.block(number, text, found)

    def command(self, rest: str) -> None:
        """A `#` command; `#COMMENT BEGIN` and `#VAR` open lines that are no blocks of their own."""
        if _COMMENT_BEGIN.match(rest):
            self.comment_lines = True
        elif _VAR_BEGIN.match(rest):
            self.declaring = True

    def subroutine_line(self, number: int, text: str, indent: int, rest: str) -> None:
        """A line of a local subroutine: its text is checked, its block runs only where it is called."""
        name, begins = self.subroutine or ("", 0)
        found = _Line()
        if rest.startswith("#"):
            self.command(rest)
        elif not rest.startswith("$"):
            found = self.words(number, text)
            for column, end_column, piece, why in found.junk:
                self.problem(number, column, end_column, _junk_message(piece, why))
            if not (found.words or found.junk or found.assignments or found.calls):
                return
        self.skip(
            number,
            indent + 1,
            text,
            f"in the local subroutine {name} (line {begins}): it runs where `LL {name}` calls it",
        )
        ends = [
            w for w in found.words if w.address == "M" and not w.computed and w.number in SUBROUTINE_END_M
        ]
        if ends:
            self.subroutine = None

    def skip(
        self, number: int, column: int, text: str, reason: str, unfollowed: Unfollowed | None = None
    ) -> None:
        block = SkippedBlock(self.at(number, column, len(text) + 1), text.strip(_BLANKS), reason)
        if unfollowed is not None:
            self.unfollowed(block, unfollowed)
        else:
            self.program.blocks.append(block)

    def unfollowed(self, block: SkippedBlock, kind: Unfollowed) -> None:
        """A block the reader does not follow: the modal state after it is not known."""
        self.program.blocks.append(
            SkippedBlock(block.at, block.text, block.reason, block.homes, block.moves, kind)
        )
        shown = _short(block.text)
        self.modal.lose(f" after line {block.at.line} (`{shown}`)")
        if kind != "any":
            self.flowed = True

    def block(self, number: int, text: str, found: _Line) -> None:
        words = found.words
        block_number = self.block_number(number, words)
        first = found.first_column
        words = [w for w in words if w.address != "N"]
        location = self.at(number, first, len(text) + 1)
        written = text.strip(_BLANKS)
        g_codes = [w for w in words if w.address == "G"]
        computed_g = [w for w in g_codes if w.computed]
        g_codes = [w for w in g_codes if not w.computed]
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
        others = [w for w in words if w.address not in ("G", "F", "M")]
        if found.junk:
            if 74 in codes:  # its sequence numbers are still checked, for the report
                self.homing(number, block_number, location, others, keep=False)
            self.program.blocks.append(
                SkippedBlock(location, written, "it holds text that is not an NC word")
            )
            return
        if found.calls:
            _, call, kind = found.calls[0]
            what = "a subroutine call" if kind == "subroutine" else "a macro call"
            self.unfollowed(SkippedBlock(location, written, f"{_short(call)}: {what} is not followed"), "any")
            return
        if computed_g:
            reason = f"{computed_g[0].written}: a computed G code is not followed"
            self.unfollowed(SkippedBlock(location, written, reason), "any")
            return
        m_words = [w for w in words if w.address == "M"]
        computed_m = [w for w in m_words if w.computed]
        if computed_m:  # it may end the program (M30) or a subroutine
            reason = f"{computed_m[0].written}: a computed M code is not followed"
            self.unfollowed(SkippedBlock(location, written, reason), "branch")
            return
        # The modal words count even in a block that is skipped for other reasons.
        if 90 in codes and 91 in codes:
            self.problem(number, first, len(text) + 1, "G90 and G91 in one block: the later one wins")
        for word in g_codes:
            if word.number in (90.0, 91.0):
                self.modal.absolute = word.number == 90.0
        feed = [w for w in words if w.address == "F"]
        for word in feed:
            if word.computed:
                self.modal.feed, self.modal.feed_lost = None, f" ({word.written} is computed)"
            elif word.number <= 0:
                self.problem(
                    number,
                    word.column,
                    word.end_column,
                    f"{word.written}: a feed rate must be above 0 mm/min",
                )
            else:
                self.modal.feed, self.modal.feed_lost = word.number, ""
        motion = [int(w.number) for w in g_codes if w.number in (0.0, 1.0)]
        ends = [w for w in m_words if w.number in END_M]
        # In a G74 block every other address names an axis (the spindle `S` too); in a move block the
        # spindle speed, tools and the like are not simulated.
        # `S1=1000` (the speed of spindle S1) names no axis either.
        not_read = [] if 74 in codes else [w for w in others if _letters(w.address) in NOT_AXES]
        axes = [w for w in others if w not in not_read]
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
            self.program.blocks.append(SkippedBlock(location, written, "; ".join(reasons)))
        elif 74 in codes:
            if any(w.computed for w in others):
                self.homing(number, block_number, location, others, keep=False)
                computed = ", ".join(w.written for w in others if w.computed)
                self.program.blocks.append(
                    SkippedBlock(
                        location,
                        written,
                        f"G74 {computed}: a computed homing order is not simulated",
                        homes=self.named(number, others),
                    )
                )
            else:
                self.homing(number, block_number, location, others)
        else:
            if motion:
                self.modal.motion = motion[-1]
            if axes:
                self.move(number, block_number, location, axes, written)
            elif found.assignments:
                self.program.blocks.append(SkippedBlock(location, written, _assignment_reason(found)))
        if ends:
            if self.flowed:  # the program may end here, or a branch may pass the end by
                if self.program.end is None:
                    self.program.end = self.at(number, ends[0].column, ends[0].end_column)
            else:
                self.ended = True
                self.program.end = self.at(number, ends[0].column, ends[0].end_column)

    def named(self, number: int, words: list[_Word]) -> tuple[NamedAxis, ...]:
        return tuple(NamedAxis(w.address, w.written, self.at(number, w.column, w.end_column)) for w in words)

    def block_number(self, number: int, words: list[_Word]) -> int | None:
        numbers = [w for w in words if w.address == "N"]
        for word in numbers[1:]:
            self.problem(number, word.column, word.end_column, "a second block number in one block")
        if not numbers:
            return None
        word = numbers[0]
        if word.computed:
            return None  # `N[P1]`: a block number the CNC computes
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
            if word.computed:
                continue  # its order is known when the program runs
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
        modal = self.modal
        lost = modal.lost
        computed = [w for w in words if w.computed]
        if computed:  # the block moves its axes, to positions known only when the program runs
            why = f"{', '.join(w.written for w in computed)}: a computed position is not simulated"
        elif modal.motion is None:
            why = (
                f"an axis position: the motion mode (G00/G01) in force{lost} is not known"
                if lost
                else "an axis position without G00 or G01 programmed before it: the motion mode in force "
                "is not known"
            )
            self.program.blocks.append(SkippedBlock(location, text, why))
            return
        elif modal.absolute is None:
            why = f"whether G90 or G91 is in force{lost} is not known"
        elif modal.motion == 1 and modal.feed is None and modal.feed_lost:
            why = f"the feed rate in force{modal.feed_lost} is not known"
        else:
            why = ""
        if modal.motion == 1 and modal.feed is None and not modal.feed_lost:
            self.problem(
                number, location.column, location.end_column, "G01 without a feed rate: program F (mm/min)"
            )
        if why:
            self.program.blocks.append(SkippedBlock(location, text, why, moves=self.named(number, words)))
            return
        targets = tuple(AxisWord(w.address, w.number, self.at(number, w.column, w.end_column)) for w in words)
        self.program.blocks.append(
            MoveBlock(location, block_number, modal.motion == 0, bool(modal.absolute), modal.feed, targets)
        )


def _assignment_reason(found: _Line) -> str:
    kinds = {kind for _, kind in found.assignments}
    if kinds == {"parameter"}:
        return "a parameter assignment: not simulated"
    if kinds == {"variable"}:
        return "a variable assignment: not simulated"
    if kinds == {"macro"}:
        return "a macro definition: not simulated"
    return "assignments of parameters, variables or macros: not simulated"


# Longer words are shortened in messages: a 5,000-digit number is not worth repeating.
SHOWN_CHARACTERS = 40


def _short(text: str) -> str:
    return shortened(text, SHOWN_CHARACTERS, SHOWN_CHARACTERS // 2)


def _junk_message(piece: str, why: str | None = None) -> str:
    if why is not None:
        shown = _short(piece if piece.isprintable() else repr(piece))
        return f"`{shown}`: {why}, so the block cannot be read"
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
    reader.targets = _jump_targets(lines)
    for number, line in enumerate(lines, 1):
        reader.line(number, line)
    return reader.program


def _jump_targets(lines: list[str]) -> set[int] | None:
    """The block numbers `$GOTO N…` jumps to; None when a jump's target is not a plain block number."""
    targets: set[int] = set()
    for line in lines:
        if "$" not in line:
            continue
        for match in _GOTO.finditer(line):
            if match.group(1) is None:
                return None
            targets.add(int(match.group(1)))
    return targets


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
