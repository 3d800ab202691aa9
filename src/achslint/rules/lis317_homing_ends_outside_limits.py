"""
What
----
Homing ends outside the software limits: after the reference event the axis
brakes and stands beyond the reference position by its braking distance
(v²/2a with the referencing speed and the homing acceleration); with fixed-stop
homing it backs off by the retraction distance from `torq_homing_position`.
The check runs the dry-run engine with its default scenario — the braking
distance does not depend on where cam and zero pulse are.

Why
---
Software limits become active as soon as the axis is homed. An axis that
stands outside them after homing cannot move back in one direction without a
manual override. A reference position close to a limit, approached at a high
referencing speed, is the usual cause.

Example
-------
```
kenngr.antr_typ                1               ( conventional drive, cam and zero pulse
kenngr.swe_neg                 -10000000       ( -1000 mm
kenngr.ref_richt               0
getriebe[0].vb_reflow          50000           ( 50 mm/s
getriebe[0].a_ref              100             ( brakes 12.5 mm
getriebe[0].pos_refpkt         -9950000        ( -995 mm
```

Use instead
-----------
```
kenngr.antr_typ                1
kenngr.swe_neg                 -10000000
kenngr.ref_richt               0
getriebe[0].vb_reflow          50000
getriebe[0].a_ref              100
getriebe[0].pos_refpkt         -9800000        ( -980 mm: 20 mm inside the limit
lr_hw[0].cam_direct_access     0               ( cam signal from the PLC
```

Reference
---------
TF5200 homing manual §2 (axis position after homing: the deceleration distance away from the reference
position; software limits monitored once homing is complete) and §2.3.3.4 (retraction after the fixed stop).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..context import Context
    from ..diagnostics import Diagnostic
    from ..homing.motion import SoftLimitOvershoot

CODE = "LIS317"
NAME = "homing-ends-outside-limits"
SEVERITY = "warning"
FIX = "none"
PARAMETERS = (
    "getriebe[i].pos_refpkt",
    "kenngr.swe_neg",
    "kenngr.swe_pos",
    "getriebe[i].vb_reflow",
    "getriebe[i].a_ref",
    "kenngr.homing.torq_homing_position",
    "kenngr.homing.torq_retraction_distance",
)  # parameters this rule reads
SUMMARY = "Homing ends outside the software limits (braking or retraction)"


def message(fact: SoftLimitOvershoot) -> str:
    """The finding in words, for lint and the dry-run alike."""
    low, high = fact.limits
    unit = fact.unit
    if fact.reference_outside:
        return f"the reference value {fact.value:g} {unit} lies outside the software limits [{low:g}, {high:g}] {unit}"
    what = "after retracting from the stop" if fact.retracted else "after braking"
    return (
        f"{what} the axis stands at {fact.final:.6g} {unit}, outside the software limits "
        f"[{low:g}, {high:g}] {unit}: move the reference position inside by at least "
        f"{abs(fact.final - fact.value):.4g} {unit}"
    )


def check(ctx: Context) -> Iterator[Diagnostic]:
    from ..homing.motion import Simulator

    values, strategy = ctx.values, ctx.strategy
    if not strategy.moves or strategy.controlled_by != "cnc" or values.axis_type == "S":
        return
    probe = Simulator(values, strategy, strategy.default_scenario(cycle_time_us=ctx.options.cycle_time_us))
    # Only the distances matter: a fixed stop (read by fixed-stop homing alone) where detection is certain.
    low = values.number("kenngr.homing.torq_min_distance") * 1e-4
    probe.scenario.fixed_stop = probe.scenario.start_position + strategy.direction * (low + 1.0)
    fact = probe.check_soft_limits(probe.run())
    if fact is not None:
        reference = strategy.definition.reference_parameter.replace("[i]", f"[{strategy.gear}]")
        yield ctx.cross(CODE, message(fact), [reference, "kenngr.swe_neg", "kenngr.swe_pos"])
