"""
What
----
A `noqa` suppression that suppresses nothing: an end-of-line `# noqa: CODE`
on a line without such a diagnostic, or a file-level `# achslint: noqa: CODE`
in a file without one. The same holds in NC homing programs checked against a
machine (`lint rfp.nc --machine hochlauf.lis`): a `(noqa: CODE)` or
`; noqa: CODE` in a block's comment that suppresses no finding of that block,
or a comment line `; achslint: noqa: CODE` with no such finding in the
program. Codes of rules that are not selected in this run are not counted as
unused. A code that is no rule code at all (`LIS3O2` with a letter O,
`LIS9999`) is reported as unknown, with the closest codes.

Why
---
Stale suppressions hide the next real problem on that line and make readers
think something is wrong there. Remove them once the finding is fixed.

Example
-------
```
getriebe[0].vb_refmax        80000     ( noqa: LIS303
```
(when vb_refmax is below vb_max, nothing is suppressed)

Use instead
-----------
```
getriebe[0].vb_refmax        80000
```

Reference
---------
achslint suppression comments (README, Suppressions).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from ..core.diagnostics import Diagnostic, Directive
from .codes import known_codes, selector_problem, severity

CODE = "LIS009"
NAME = "unused-noqa"
FIX = "none"
SUMMARY = "Suppression comment that suppresses nothing"


def check_after(
    path: str, directives: list[Directive], enabled: Callable[[str], bool]
) -> Iterator[Diagnostic]:
    """Runs after the other rules and the suppressions, with every `noqa` directive of the list or program
    (`path`: its name in findings)."""
    known = known_codes()
    for directive in directives:
        if directive.codes is None:
            if not directive.used:
                yield _report(path, directive, "this `noqa` suppresses no diagnostic; remove it")
            continue
        for code in directive.codes:
            if code not in known:
                problem = selector_problem(code)
                # The did-you-mean part; a prefix (`LIS3`) picks rules elsewhere but is no code for noqa.
                hint = problem.split("; ", 1)[1] if problem else "noqa takes full codes such as LIS302"
                yield _report(
                    path,
                    directive,
                    f"`noqa` names the unknown code `{code}`, which suppresses nothing; {hint}",
                )
        unused = [
            code for code in directive.codes if code in known and code not in directive.used and enabled(code)
        ]
        if unused:
            where = "in this file" if directive.file_level else "on this line"
            yield _report(
                path,
                directive,
                f"`noqa` for {', '.join(unused)} suppresses nothing {where}; remove "
                f"{'it' if len(unused) == len(directive.codes) else 'those codes'}",
            )


def _report(path: str, directive: Directive, message: str) -> Diagnostic:
    return Diagnostic(
        path,
        directive.line,
        directive.column,
        directive.line,
        directive.end_column,
        CODE,
        severity(CODE),
        message,
    )
