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
kenngr.antr_typ                 1          ( conventional drive
kenngr.ref_ohne_nocken          1          ( zero pulse only
kenngr.ref_ohne_rev             1
kenngr.fast_from_cam            0
getriebe[0].vb_refmax           200000
```

Use instead
-----------
```
kenngr.antr_typ                 1
kenngr.ref_ohne_nocken          1
kenngr.ref_ohne_rev             1
```

Reference
---------
TF5200 homing manual §3.5 (effectiveness of parameters), §3.1.1.2 (drive-controlled: only P-AXIS-00014/00015
matter), §3.4 (simulation: only P-AXIS-00161).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..homing import HOMING_PARAMETERS, is_homing_parameter
from ._common import known_settings

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS401"
NAME = "parameter-without-effect"
FIX = "none"
PARAMETERS = tuple(HOMING_PARAMETERS)  # parameters this rule reads
SUMMARY = "Homing parameter set but without effect under the configured strategy"


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    for setting, parameter, canonical in known_settings(ctx.settings):
        if setting.problems:
            continue  # a value the CNC rejects is reported by the value rules
        if not is_homing_parameter(canonical) or values.in_list(canonical) is not setting:
            continue
        if setting.value == parameter.typed_default:
            continue
        effect = ctx.effect(canonical)
        if effect.effective or effect.cause != "strategy":
            continue  # a parameter of another drive or axis type is LIS105's
        start, end = ctx.path_span(setting.line)
        yield ctx.report(
            CODE,
            setting.line,
            f"`{canonical}` has no effect here: {effect.reason} (the CNC runs: {ctx.strategy.title})",
            column=start,
            end_column=end,
            setting=setting,
        )
