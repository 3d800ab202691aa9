"""
What
----
A parameter that has no effect for the axis's drive type (`kenngr.antr_typ`)
or axis type (`kenngr.achs_typ`): a parameter of a drive interface group
(`antr.sercos.*`, `antr.canopen.*`, `antr.profibus.*`, `antr.simu.*`,
`antr.terminal.*`, `antr.dse.*`, `antr.generic.*`) on an axis with another
drive, or a parameter documented for linear and rotary axes only set on a
spindle. The check only runs when the list sets the drive or axis type itself,
and a parameter set to its default value is not reported (it changes nothing
either way).

Why
---
The value is ignored by the CNC. Often it is left over from a copied list of
another axis, and someone reading the list believes it matters.

Example
-------
```
kenngr.antr_typ                  8      ( CANopen
antr.sercos.drive_supports_cnc_homing 1
```

Use instead
-----------
Remove the parameter, or check that the drive type is the one you meant:

```
kenngr.antr_typ                  8      ( CANopen
```

Reference
---------
P-AXIS-00020 drive type codes; "Axis types" rows of the P-AXIS parameter
pages (catalogue `axis_types`). The per-parameter drive-type rows are
incomplete (documented inconsistency C.36: P-AXIS-00219 omits the drives with
CNC-controlled homing), so only the drive interface groups are used here; which
homing parameters matter for the configured strategy is LIS401's job.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..catalogue import AXIS_TYPE_NAMES

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS105"
NAME = "not-effective-for-drive"
FIX = "none"
SUMMARY = "Parameter has no effect for this drive type or axis type"

# Parameters that describe the drive or axis itself are never "not effective".
_DEFINING = {"P-AXIS-00018", "P-AXIS-00020"}
# Wrong axis type reported at error by another rule: the CNC does not support it (LIS316).
_REPORTED_ELSEWHERE = {"P-AXIS-00074"}
_NEVER = frozenset(_DEFINING | _REPORTED_ELSEWHERE)


def check(ctx: Context) -> Iterator[Diagnostic]:
    analysis = ctx.analysis
    drive = analysis.drive_type
    axis_type = analysis.axis_type if analysis.axis_type_known else None
    names = ctx.catalogue.drive_type_names
    for setting, parameter, canonical in ctx.known:
        # Whether the parameter misses the drive type or the axis type comes first: it is a look at the
        # parameter's metadata, and false for almost every setting of a list.
        drive_group = parameter.drive_group
        wrong_drive = drive is not None and bool(drive_group) and drive not in drive_group
        if not wrong_drive and (
            axis_type is None or not parameter.axis_types or axis_type in parameter.axis_types
        ):
            continue
        if setting.problems or parameter.id in _NEVER:
            continue  # a rejected value is reported by the value rules
        if ctx.values.correction(canonical) is not None:
            continue  # the CNC corrects it at load: the rule reporting the correction says more
        if setting.value is not None and setting.value == parameter.typed_default:
            continue  # writing the default changes nothing, effective or not
        line = setting.line
        start, end = ctx.path_span(line)
        if drive is not None and wrong_drive:
            wanted = ", ".join(names.get(code, str(code)) for code in drive_group)
            yield ctx.report(
                CODE,
                line,
                f"`{setting.canonical}` only takes effect with drive type {wanted}; this axis has "
                f"kenngr.antr_typ {drive} ({names.get(drive, 'unknown')})",
                column=start,
                end_column=end,
                setting=setting,
            )
        else:
            wanted = ", ".join(AXIS_TYPE_NAMES[a] for a in parameter.axis_types)
            yield ctx.report(
                CODE,
                line,
                f"`{setting.canonical}` only takes effect on {wanted} axes; this axis is a "
                f"{AXIS_TYPE_NAMES[analysis.axis_type]} axis (kenngr.achs_typ)",
                column=start,
                end_column=end,
                setting=setting,
            )
