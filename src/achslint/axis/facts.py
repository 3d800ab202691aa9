"""What the conversion stage found wrong with a written value, as plain facts.

`analysis.py` converts every value to its parameter's type and records one of these when it cannot;
it never decides how a problem is reported. Each rule module lists the facts it reports (`FACTS`) and
turns them into its message and fix. A fact says where on the line it is (`span`: "value", "rest", or
explicit columns).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..syntax.numbers import NumberProblem, Reference

Span = str | tuple[int, int]


@dataclass(frozen=True)
class ValueFact:
    """Base of every fact; `span` is the part of the line at fault."""

    @property
    def span(self) -> Span:
        return "value"


# Array indices -------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class IndexOutOfBounds(ValueFact):
    """A written index outside the array's bounds (`written` as in the list, `index` None if unreadable)."""

    array: str
    index: int | None
    written: str
    low: int
    high: int
    columns: tuple[int, int]

    @property
    def span(self) -> Span:
        return self.columns


# Data types ----------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class MissingValue(ValueFact):
    """Nothing after the name, or only a comment (`comment` is the text that starts it)."""

    comment: str | None = None


@dataclass(frozen=True)
class NotBoolean(ValueFact):
    """A BOOLEAN parameter written with something other than 0/1 (`replacement` when a number was written)."""

    text: str
    replacement: str | None = None


@dataclass(frozen=True)
class RealForInteger(ValueFact):
    """A real number for an integer parameter (`replacement` when it is a whole number)."""

    text: str
    replacement: str | None = None


@dataclass(frozen=True)
class TextForNumber(ValueFact):
    """Text where a number is expected."""

    text: str


# Ranges --------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class UnusableNumber(ValueFact):
    """A number that cannot be held at all (too many digits, beyond the float range, hex too long)."""

    text: str
    problem: NumberProblem


@dataclass(frozen=True)
class NotAccepted(ValueFact):
    """A number that is not one of the listed codes."""

    number: float
    accepted: tuple[int, ...]


@dataclass(frozen=True)
class NotPositive(ValueFact):
    """Zero or less for a parameter that must be greater than 0."""

    number: float
    unit: str | None


@dataclass(frozen=True)
class OutOfRange(ValueFact):
    """A number below `low` or above `high` (the bound that was crossed is the one not None)."""

    number: float
    low: float | None
    high: float | None
    unit: str | None

    @property
    def bound(self) -> float:
        """The bound that was crossed."""
        bound = self.low if self.low is not None else self.high
        if bound is None:
            raise ValueError("an OutOfRange fact names the bound the number crosses")
        return bound


# Symbols, strings, references ----------------------------------------------------------------------------


@dataclass(frozen=True)
class UnknownSymbol(ValueFact):
    """A word that is not one of the parameter's symbols (`codes`: their numbers, where they have some)."""

    text: str
    accepted: tuple[str, ...]
    codes: tuple[int, ...] = ()


@dataclass(frozen=True)
class TooLong(ValueFact):
    """A string longer than the CNC stores for the parameter."""

    length: int
    max_length: int


@dataclass(frozen=True)
class CommentReadAsValue(ValueFact):
    """`name  # text` on a string parameter: the CNC reads the whole rest as the value."""

    text: str


@dataclass(frozen=True)
class TextAfterString(ValueFact):
    """Text after a string value that does not start with `(`."""

    text: str

    @property
    def span(self) -> Span:
        return "rest"


@dataclass(frozen=True)
class BadReference(ValueFact):
    """A `P-AXIS-nnnnn[.i]` value the CNC cannot use.

    `reason` is one of: "unreadable" (`problem` says why), "unknown" (no such parameter), "itself",
    "kind" (a number refers to text or the other way round), "unit" (different units), "index"
    (the index is outside the target's array: `low`..`high`)."""

    reason: str
    written: str
    reference: Reference | None = None
    problem: NumberProblem | None = None
    target_path: str = ""
    target_type: str = ""
    own_unit: str | None = None
    target_unit: str | None = None
    low: int = 0
    high: int = 0
