"""
What
----
A line that is neither `path value [comment]`, a `#` comment, a blank line nor
the end marker `Ende`: a malformed parameter path (an index that is not a
number, a missing dot after `]`, an unbalanced bracket, dot leaders copied from
a manual) or a string whose double quote is never closed.

Why
---
The CNC stops reading the list, or drops the line, when it cannot parse it;
the axis then starts with whatever value was set before. achslint checks the
other lines all the same.

Example
-------
```
getriebe[i].vb_reflow                 20000
antr.fixed_stop.drive_ident[0]wr_ident S_0_0092
kopf.log_achs_name                    "X (left
```

Use instead
-----------
```
getriebe[0].vb_reflow                 20000
antr.fixed_stop.drive_ident[0].wr_ident S_0_0092
kopf.log_achs_name                    "X (left)"
```

Reference
---------
TF5200 axis parameter manual, "Syntax, interpretation and testing of ASCII-list file";
list format facts §2 and §5.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..syntax import parser as syntax

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS001"
NAME = "syntax-error"
FIX = "none"
SUMMARY = "Line is not a valid `path value [comment]` assignment"


def explain_bad_path(path: str) -> str:
    """Say in words what is wrong with a path the grammar rejected."""
    if path.startswith(";"):
        return "`;` does not start a comment in CNC lists; use `#` at the start of the line"
    if re.fullmatch(r"\.{3,}.*", path) or "...." in path:
        return "dot leaders or an elision (`...`) are not part of the list syntax; delete them"
    index = re.search(r"\[([^\[\]]*)\]", path)
    if index and not index.group(1).isdigit():
        return f"index `[{index.group(1)}]` is not a number; indices are zero-based numbers such as `[0]`"
    if path.count("[") != path.count("]"):
        return "unbalanced `[` `]` in the parameter path"
    missing_dot = re.search(r"\](\w)", path)
    if missing_dot:
        return f"missing `.` after `]` (before `{missing_dot.group(1)}`)"
    if ".." in path or path.endswith(".") or path.startswith("."):
        return "empty member name between dots"
    if path[0].isdigit():
        return "a parameter path starts with a letter"
    if path.startswith('"'):
        return "a line cannot start with a quoted string; the parameter path comes first"
    bad = re.search(r"[^A-Za-z0-9_.\[\]\-]", path)
    if bad:
        return f"character `{bad.group(0)}` is not allowed in a parameter path"
    return "not a valid parameter path"


def check(ctx: Context) -> Iterator[Diagnostic]:
    lines = ctx.file.lines
    stop = ctx.file.end_index if ctx.file.end_index is not None else len(lines)
    for line in lines[:stop]:
        if line.kind != syntax.ASSIGNMENT:
            continue
        if not line.path_ok:
            start, end = ctx.path_span(line)
            path = line.path or ""
            yield ctx.report(
                CODE,
                line,
                f"syntax error in `{path}`: {explain_bad_path(path)}",
                column=start,
                end_column=end,
            )
        elif line.value_kind == syntax.BAD_STRING and line.value is not None:
            start = line.value_column
            closing = line.value.find('"', 1)
            if closing < 0:
                reason = 'the double quote is never closed; add the closing `"`'
            else:
                reason = 'text follows the closing `"` without a blank; put a space or `(` before the comment'
            yield ctx.report(
                CODE,
                line,
                f"syntax error in the value of `{line.path}`: {reason}",
                column=start,
                end_column=start + len(line.value),
            )
