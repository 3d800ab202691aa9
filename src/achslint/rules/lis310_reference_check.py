"""
What
----
Reference monitoring (`antr.reference_check.element_name` and
`antr.reference_check.bit_nr`) configured wrongly: on a drive other than
SERCOS, with a bit number beyond the telegram element (0..15 for a 2-byte
element such as the status word `S-0-0135`, 0..31 for 4 bytes), or with only
one of the two parameters set.

Why
---
The CNC switches monitoring off with P-ERR-110548 (drive type) or
P-ERR-110549 (bit number), so a lost reference — an exhausted encoder battery,
changed drive parameters — goes unnoticed.

Example
-------
```
kenngr.antr_typ                        8          ( CANopen
antr.reference_check.element_name      S-0-0135
antr.reference_check.bit_nr            17
```

Use instead
-----------
```
kenngr.antr_typ                        2          ( SERCOS
antr.reference_check.element_name      S-0-0135
antr.reference_check.bit_nr            6          ( real-time status bit 1
```

Reference
---------
TF5200 homing manual §2.5.1; P-AXIS-00425, P-AXIS-00426; CNC messages P-ERR-110548, P-ERR-110549.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import TYPE_CHECKING

from ._common import known_settings

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS310"
NAME = "reference-check"
FIX = "none"
PARAMETERS = (
    "antr.reference_check.element_name",
    "antr.reference_check.bit_nr",
    "kenngr.antr_typ",
)  # parameters this rule reads
SUMMARY = "Reference monitoring on a non-SERCOS drive or with an invalid bit"

NAME_PATH, BIT_PATH = "antr.reference_check.element_name", "antr.reference_check.bit_nr"
STATUS_WORD = "S-0-0135"


def _element_bytes(ctx: Context, element: str) -> int | None:
    """Length in bytes of the telegram element that carries the signal, if the list says."""
    if element.upper().replace("_", "-") == STATUS_WORD:
        return 2
    values = ctx.values
    for setting, _, canonical in known_settings(ctx.settings):
        if re.fullmatch(r"antr\.sercos\.at\[\d+\]\.nc_ref", canonical) and setting.value == element:
            length_path = canonical.replace(".nc_ref", ".ident_len")
            return int(values.number(length_path)) or None
    return None


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    element = str(values.written(NAME_PATH) or "")  # a string parameter
    bit = values.number(BIT_PATH)
    if not element and bit == -1:
        return
    paths = [NAME_PATH, BIT_PATH]
    correction = ctx.correction(NAME_PATH)
    if correction is not None:
        yield ctx.report_correction(CODE, correction, f"{ctx.show(NAME_PATH)}", [*paths, "kenngr.antr_typ"])
        return
    if not element:
        yield ctx.cross(
            CODE,
            f"{ctx.show(BIT_PATH)} is set but no element name: name the telegram element "
            f"(`{STATUS_WORD}` for the status word) in {NAME_PATH}",
            paths,
        )
        return
    if bit == -1:
        yield ctx.cross(
            CODE,
            f"{ctx.show(NAME_PATH)} switches reference monitoring on, but {BIT_PATH} is not set; "
            "give the bit number of the 'drive is referenced' signal (P-ERR-110549)",
            paths,
        )
        return
    size = _element_bytes(ctx, element)
    if size and not 0 <= bit <= size * 8 - 1:
        yield ctx.cross(
            CODE,
            f"{ctx.show(BIT_PATH)} does not exist in the {size}-byte element `{element}` (bits 0..{size * 8 - 1}); "
            "the CNC switches monitoring off (P-ERR-110549)",
            [BIT_PATH, NAME_PATH],
        )
