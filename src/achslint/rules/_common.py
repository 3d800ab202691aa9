"""Helpers shared by several rules."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from typing import TYPE_CHECKING, TypeVar

from ..axis.facts import ValueFact
from ..catalogue import BOOL, INTEGER, REAL, SYMBOL, Parameter
from ..core.diagnostics import Diagnostic, Edit, Fix

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from ..syntax.parser import Line
    from .context import Context

F = TypeVar("F", bound=ValueFact)


def known_settings(settings: Iterable[Setting]) -> Iterator[tuple[Setting, Parameter, str]]:
    """The assignments of catalogue parameters (not misspelt), each with its parameter and canonical path."""
    for setting in settings:
        if setting.canonical is not None and setting.resolution is not None:
            yield setting, setting.resolution.parameter, setting.canonical


def value_facts(
    ctx: Context,
    code: str,
    kinds: tuple[type[F], ...],
    message: Callable[[F, Setting, Parameter], str],
    replacement: Callable[[F], str | None] | None = None,
    applicability: str = "safe",
    to_line_end: bool = False,
    skip: Callable[[F, Setting], bool] | None = None,
) -> Iterator[Diagnostic]:
    """Report every fact of the given kinds that the conversion stage recorded for a value.

    `message(fact, setting, parameter)` words the finding; `replacement(fact)`, when given and not None,
    is a value written in place of the old one as a fix of the given applicability. With `to_line_end` the
    finding reaches from the fact's start to the end of the line. `skip(fact, setting)` leaves out facts
    another rule judges.
    """
    for setting, parameter in ctx.with_facts:  # the known settings with facts: most settings have none
        for fact in setting.problems:
            if not isinstance(fact, kinds) or (skip is not None and skip(fact, setting)):
                continue
            line = setting.line
            start, end = ctx.problem_span(line, fact.span)
            if to_line_end:
                end = line.end_column
            new = replacement(fact) if replacement is not None else None
            fix = None
            if new is not None and line.value is not None:
                fix = Fix(
                    applicability,
                    f"replace `{line.value}` with `{new}`",
                    (Edit(line.number, start, line.number, start + len(line.value), new),),
                )
            yield ctx.report(
                code,
                line,
                message(fact, setting, parameter),
                column=start,
                end_column=end,
                setting=setting,
                fix=fix,
            )


def expected(parameter: Parameter) -> str:
    """What a value of the parameter looks like, for messages."""
    kind = parameter.kind
    if kind == BOOL:
        return "0 or 1"
    if kind == INTEGER:
        return f"an integer ({parameter.type})"
    if kind == REAL:
        return "a number (REAL64)"
    if kind == SYMBOL:
        return "one of " + ", ".join(parameter.symbols)
    return "a string"


def replace_path_fix(line: Line, new_path: str, applicability: str) -> Fix:
    start = line.path_column
    path = line.path or ""
    return Fix(
        applicability,
        f"rename `{path}` to `{new_path}`",
        (Edit(line.number, start, line.number, start + len(path), new_path),),
    )
