"""
What
----
A parameter reference (`P-AXIS-00212.0`, "take the value of that parameter")
that names a parameter that does not exist, names the parameter itself, names a
parameter of another kind (text for a number) or with another unit, or uses an
index outside the target's array.

A reference names an axis parameter (P-AXIS), which only the axis catalogue
holds: in a list of another kind (a channel list, tool data ...) achslint
reports only a reference it cannot read, and leaves the target unchecked.

Why
---
The CNC cannot resolve such a reference while it reads the list (loader errors
2049, 2051, 2052, 2062, 2065) and the parameter keeps its default.

Example
-------
```
handbetrieb.hb.vb_max          P-AXIS-00008.0
getriebe[0].vb_reflow          P-AXIS-00218.0
```

Use instead
-----------
```
handbetrieb.hb.vb_max          P-AXIS-00212.0
getriebe[0].vb_reflow          20000
```

Reference
---------
List format facts §6 (parameter references and their loader errors).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..axis.facts import BadReference
from ..catalogue.units import unit_label
from ._common import value_facts

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from ..catalogue import Parameter
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS205"
NAME = "bad-reference"
FIX = "none"
SUMMARY = "Parameter reference that cannot be resolved"

FACTS = (BadReference,)


def message(fact: BadReference, setting: Setting, parameter: Parameter) -> str:
    name, reference = setting.canonical, fact.reference
    target = reference.target if reference is not None else ""
    if fact.reason == "unreadable":
        return f"`{name}` refers to `{fact.written}`, which {fact.problem}"
    if fact.reason == "unknown":
        return f"`{name}` refers to {target}, which is not an axis parameter"
    if fact.reason == "itself":
        return f"`{name}` refers to itself ({reference}); write a value instead"
    if fact.reason == "kind":
        return (
            f"`{name}` ({parameter.type}) refers to {target} `{fact.target_path}`, which is {fact.target_type}; "
            f"a reference must name a parameter of the same kind"
        )
    if fact.reason == "unit":
        return (
            f"`{name}` is in {unit_label(fact.own_unit) or 'no unit'} but refers to {target} `{fact.target_path}` "
            f"in {unit_label(fact.target_unit) or 'no unit'}; the CNC rejects references with different units"
        )
    return f"`{name}` refers to {reference}, but {target} has indices {fact.low}..{fact.high} only"


def check(ctx: Context) -> Iterator[Diagnostic]:
    yield from value_facts(ctx, CODE, FACTS, message)
