"""Helpers shared by several rules."""

from __future__ import annotations

from ..diagnostics import Edit, Fix


def value_problems(ctx, code: str, fix_applicability: str | None = None):
    """Report every problem of kind `code` that the analysis stage found in a value.

    With `fix_applicability`, a problem that carries a replacement value gets a
    fix that writes it in place of the old value.
    """
    for setting in ctx.settings:
        for problem in setting.problems:
            if problem.code != code:
                continue
            line = setting.line
            start, end = ctx.problem_span(line, problem.span)
            fix = None
            if fix_applicability and problem.replacement is not None and line.value is not None:
                fix = Fix(
                    fix_applicability,
                    f"replace `{line.value}` with `{problem.replacement}`",
                    (Edit(line.number, start, line.number, start + len(line.value), problem.replacement),),
                )
            yield ctx.report(code, line, problem.message, column=start, end_column=end, setting=setting, fix=fix)


def replace_path_fix(line, new_path: str, applicability: str) -> Fix:
    start = line.path_column
    return Fix(
        applicability,
        f"rename `{line.path}` to `{new_path}`",
        (Edit(line.number, start, line.number, start + len(line.path), new_path),),
    )
