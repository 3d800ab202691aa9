"""
What
----
A homing parameter set in the list (to something other than its default) that
has no effect under the homing strategy the axis is configured for: for
example `vb_refmax` or `fast_from_cam` when there is no reference cam, cam
parameters on a zero-pulse-only axis, any CNC sequence parameter when the
drive homes itself (`DRIVE_CONTROLLED`) or the axis is absolute, or
`rpf_weg_bis_nip` on a real drive. `achslint explain FILE` shows the whole
table with the reason for each parameter.

Why
---
Such values mislead whoever reads or tunes the list: changing them does
nothing. Often they show that the strategy is not the one intended (a
forgotten `ref_ohne_nocken`, a homing type left at the drive default).

Example
-------
```
kenngr.ref_ohne_nocken          1          ( zero pulse only
kenngr.ref_ohne_rev             1
kenngr.fast_from_cam            0
getriebe[0].vb_refmax           200000
```

Use instead
-----------
```
kenngr.ref_ohne_nocken          1
kenngr.ref_ohne_rev             1
```

Reference
---------
TF5200 homing manual §3.5 (effectiveness of parameters), §3.1.1.2 (drive-controlled: only P-AXIS-00014/00015
matter), §3.4 (simulation: only P-AXIS-00161).
"""

from __future__ import annotations

import re
from functools import lru_cache

from ..strategy import HOMING_PARAMETERS, effectiveness

CODE = "LIS401"
NAME = "parameter-without-effect"
SEVERITY = "info"
FIX = "none"
PARAMETERS = tuple(HOMING_PARAMETERS)  # parameters this rule reads
SUMMARY = "Homing parameter set but without effect under the configured strategy"

_GENERIC = set(HOMING_PARAMETERS)
_GEAR_INDEX = re.compile(r"getriebe\[\d+\]")


@lru_cache(maxsize=4096)
def _generic(canonical: str) -> str:
    """`getriebe[2].vb_reflow` -> `getriebe[i].vb_reflow` (and the second cam input as the first)."""
    return _GEAR_INDEX.sub("getriebe[i]", canonical).replace("lr_hw[1]", "lr_hw[0]")


def check(ctx):
    strategy = ctx.strategy
    values = ctx.values
    for setting in ctx.settings:
        if not setting.known or setting.problems:
            continue
        canonical = setting.canonical
        generic = _generic(canonical)
        if generic not in _GENERIC or values.in_list(canonical) is not setting:
            continue
        if setting.value == setting.parameter.typed_default:
            continue
        group = setting.parameter.drive_group
        if group and values.drive_type_known and values.drive_type not in group:
            continue  # LIS105 already says this parameter belongs to another drive
        gear_path = canonical
        effective, reason = effectiveness(strategy, values, gear_path)
        if not effective:
            start, end = ctx.path_span(setting.line)
            yield ctx.report(
                CODE, setting.line,
                f"`{canonical}` has no effect here: {reason} (configured strategy: {strategy.title})",
                column=start, end_column=end, setting=setting,
            )
