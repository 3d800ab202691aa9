"""
What
----
A number outside the range the parameter accepts: outside its data type
(a negative value for an unsigned parameter, 300 for UNS08) or outside the
literal bounds the manual gives (`encoder_bit_range` 1..31,
`torq_detect_velocity_limit` 0..1000 per mille), or not one of the listed codes
(`kenngr.antr_typ`).

In a list of another kind (channel, tool data, start-up ...) the bounds come
from that kind's catalogue: the range text of its reference table where it
states bounds (`m_h_pre_outp_nbr_block` 50..200, P-CHAN-00274; `zahl_mds`
1..32, P-STUP-00014), else the data type's range.

Bounds that depend on other parameters (such as vb_refmax ≤ vb_max) are checked
by the cross-parameter rules, not here. A parameter's documented default is
always accepted, because several parameters use an out-of-range default
(0 or -1) to mean "not set".

Why
---
The CNC corrects or rejects out-of-range values while it reads the list, with
a warning that is easy to miss; the axis then runs with a value nobody wrote.

Example
-------
```
antr.encoder_bit_range                    40
kenngr.homing.torq_detect_velocity_limit  1500
```

Use instead
-----------
```
antr.encoder_bit_range                    20
kenngr.homing.torq_detect_velocity_limit  500
```

Reference
---------
Value ranges of the P-AXIS parameter pages (catalogue `range`); P-AXIS-00355, P-AXIS-00347.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..axis.facts import NotAccepted, NotPositive, OutOfRange, UnusableNumber
from ..catalogue.units import describe
from ._common import expected, value_facts

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from ..catalogue import Parameter
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS202"
NAME = "out-of-range"
FIX = "none"
SUMMARY = "Value outside the parameter's range"

Fact = UnusableNumber | NotAccepted | NotPositive | OutOfRange
FACTS: tuple[type[Fact], ...] = (UnusableNumber, NotAccepted, NotPositive, OutOfRange)


def message(fact: Fact, setting: Setting, parameter: Parameter) -> str:
    name = setting.canonical
    if isinstance(fact, UnusableNumber):
        holds = f", far more than a {parameter.type} holds" if fact.problem.reason == "digits" else ""
        return f"`{name}` = `{fact.text}` {fact.problem}{holds}; {expected(parameter)} is expected"
    if isinstance(fact, NotAccepted):
        return f"`{name}` = {fact.number} is not an accepted value; accepted: {', '.join(map(str, fact.accepted))}"
    if isinstance(fact, NotPositive):
        return f"`{name}` = {describe(fact.number, fact.unit)} must be greater than 0"
    side, least = (
        ("below the minimum", "at least") if fact.low is not None else ("above the maximum", "at most")
    )
    return (
        f"`{name}` = {describe(fact.number, fact.unit)} is {side} {describe(fact.bound, fact.unit)}"
        f"{_range_hint(parameter)}; use a value of {least} {_plain(fact.bound)}"
    )


def _plain(value: float) -> str:
    return str(int(value)) if float(value).is_integer() else f"{value:g}"


def _range_hint(parameter: Parameter) -> str:
    text = parameter.range_text.split(";")[0].strip()
    if not text or text.startswith("("):
        return f" of {parameter.type}"
    return f" (manual range: {text})"


def _judged_by_lis506(fact: Fact, setting: Setting) -> bool:
    """In a default axis list `kopf.achs_nr` must be 0 (P-ERR-110300), which is outside its range for an
    axis: there LIS506 says what is wrong with a number (a value that is no number stays LIS202's)."""
    return setting.canonical == "kopf.achs_nr" and not isinstance(fact, UnusableNumber)


def check(ctx: Context) -> Iterator[Diagnostic]:
    yield from value_facts(ctx, CODE, FACTS, message, skip=_judged_by_lis506 if ctx.default_list else None)
