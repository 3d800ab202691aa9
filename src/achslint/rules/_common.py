"""Helpers shared by several rules."""

from __future__ import annotations

from ..catalogue import BOOL, INTEGER, REAL, SYMBOL
from ..diagnostics import Edit, Fix


def value_facts(
    ctx,
    code: str,
    kinds: tuple[type, ...],
    message,
    replacement=None,
    applicability: str = "safe",
    to_line_end: bool = False,
):
    """Report every fact of the given kinds that the conversion stage recorded for a value.

    `message(fact, setting)` words the finding; `replacement(fact)`, when given and not None, is a value
    written in place of the old one as a fix of the given applicability. With `to_line_end` the finding
    reaches from the fact's start to the end of the line.
    """
    for setting in ctx.settings:
        for fact in setting.problems:
            if not isinstance(fact, kinds):
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
                code, line, message(fact, setting), column=start, end_column=end, setting=setting, fix=fix
            )


def expected(parameter) -> str:
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


def replace_path_fix(line, new_path: str, applicability: str) -> Fix:
    start = line.path_column
    return Fix(
        applicability,
        f"rename `{line.path}` to `{new_path}`",
        (Edit(line.number, start, line.number, start + len(line.path), new_path),),
    )
