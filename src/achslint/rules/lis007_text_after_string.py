"""
What
----
Text after the value of a string parameter that does not start with `(`,
including `name   # comment` written to mean "empty string".

Why
---
After a numeric value anything after a blank is a comment, but after a string
value only `(` starts a comment. The CNC reads `# text` or `/* text` as part of
the string (or rejects the line), so the parameter gets a value nobody meant.

Example
-------
```
kopf.log_achs_name                      X_Achse   # main axis
antr.fixed_stop.drive_ident[0].rd_ident           # empty string
```

Use instead
-----------
```
kopf.log_achs_name                      X_Achse   ( main axis
antr.fixed_stop.drive_ident[0].rd_ident           ( empty string
```

Reference
---------
TF5200 external variables / tool data manuals, comment rules for string values;
documented inconsistency E.49.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..axis.facts import CommentReadAsValue, TextAfterString
from ._common import value_facts

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from ..catalogue import Parameter
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS007"
NAME = "text-after-string"
FIX = "none"
SUMMARY = "Text after a string value that is not a `(` comment"

Fact = CommentReadAsValue | TextAfterString
FACTS: tuple[type[Fact], ...] = (CommentReadAsValue, TextAfterString)


def message(fact: Fact, setting: Setting, parameter: Parameter) -> str:
    name = setting.canonical
    if isinstance(fact, CommentReadAsValue):
        return (
            f"`{name}` is a string parameter: the CNC reads `{fact.text}` as its value, not as a comment "
            f"(after a string only `(` starts a comment); to leave it empty write nothing after the name "
            f"or start the comment with `(`"
        )
    return (
        f"text `{fact.text}` after the string value of `{name}` is not a `(` comment; the CNC reads it "
        f"as part of the value or rejects the line; start the comment with `(`"
    )


def check(ctx: Context) -> Iterator[Diagnostic]:
    yield from value_facts(ctx, CODE, FACTS, message, to_line_end=True)
