"""
What
----
The file mixes line-break styles (CRLF, LF, CR) or separates names from values
with tabs on some lines and with spaces on others.

Why
---
Mixed styles are a sign of hand edits with different editors or of merged
exports. They make diffs noisy and alignment break in some viewers.
`achslint fmt` normalises the alignment.

Example
-------
A list exported on Windows (CRLF) with lines appended on Linux (LF), or one
edited in different editors, so that some lines separate name and value with
a tab and the others with spaces:

```
kopf.achs_nr\t1                   ( tab
kopf.log_achs_name\tX           ( tab
kenngr.swe_pos            10000000  ( spaces
```

Use instead
-----------
One line-break style and one separator style per file:

```
kopf.achs_nr              1
kopf.log_achs_name        X
kenngr.swe_pos            10000000
```

Reference
---------
List format facts §2 and §8.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..syntax import parser as syntax

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS008"
NAME = "mixed-style"
FIX = "none"
SUMMARY = "Mixed line endings or tab/space separators"

_NAMES = {"\r\n": "CRLF", "\n": "LF", "\r": "CR"}


def check(ctx: Context) -> Iterator[Diagnostic]:
    lines = ctx.file.lines
    endings = Counter(line.newline for line in lines if line.newline)
    if len(endings) > 1:
        usual = endings.most_common(1)[0][0]
        odd = next(line for line in lines if line.newline and line.newline != usual)
        summary = ", ".join(f"{count} {_NAMES[nl]}" for nl, count in endings.most_common())
        yield ctx.report(
            CODE,
            odd,
            f"mixed line endings ({summary}); this line ends with {_NAMES[odd.newline]}",
            column=odd.end_column,
            end_column=odd.end_column + 1,
        )
    styles: dict[str, list[syntax.Line]] = {"tab": [], "space": []}
    for line in lines:
        if line.kind == syntax.ASSIGNMENT and line.sep and line.value is not None:
            styles["tab" if "\t" in line.sep else "space"].append(line)
    if styles["tab"] and styles["space"]:
        minority = min(styles.values(), key=len)
        kind = "tabs" if minority is styles["tab"] else "spaces"
        odd = minority[0]
        yield ctx.report(
            CODE,
            odd,
            f"{len(styles['tab'])} lines separate name and value with tabs, {len(styles['space'])} with spaces; "
            f"this line uses {kind}",
            column=odd.path_column + len(odd.path or ""),
            end_column=odd.value_column,
        )
