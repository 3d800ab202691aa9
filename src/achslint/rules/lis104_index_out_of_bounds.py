"""
What
----
An array index outside the array: `getriebe[6]` (gear stages are 0..5),
`lr_hw[2]` (0..1), `antr.fixed_stop.drive_ident[4]` (0..3).

Why
---
The CNC rejects the line while reading the list; the value you wrote is lost.
Indices are zero-based, so the sixth gear stage is `getriebe[5]`.

Example
-------
```
getriebe[6].vb_refmax          100000
```

Use instead
-----------
```
getriebe[5].vb_refmax          100000
```

Reference
---------
Array bounds of the parameter metadata (catalogue `index_bounds`).
"""

from __future__ import annotations

import re

CODE = "LIS104"
NAME = "index-out-of-bounds"
SEVERITY = "error"
FIX = "none"
SUMMARY = "Array index out of bounds"


def check(ctx):
    for setting in ctx.settings:
        if not setting.known or setting.resolution.alias is not None:
            continue
        parameter = setting.parameter
        arrays = re.findall(r"(\w+)\[i\]", parameter.path)
        for position, (index, (low, high)) in enumerate(zip(setting.resolution.indices, parameter.index_bounds)):
            if low <= index <= high:
                continue
            array = arrays[position]
            line = setting.line
            column = line.path_column + _index_offset(line.path, position)
            yield ctx.report(
                CODE, line,
                f"index {index} of `{array}` in `{line.path}` is out of bounds: {parameter.id} allows "
                f"{array}[{low}]..{array}[{high}] (indices are zero-based)",
                column=column, end_column=column + len(str(index)) + 2, setting=setting,
            )


def _index_offset(path: str, position: int) -> int:
    matches = list(re.finditer(r"\[[0-9]+\]", path))
    return matches[position].start() if position < len(matches) else 0
