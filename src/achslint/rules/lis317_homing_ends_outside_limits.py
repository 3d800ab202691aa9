"""
What
----
Homing ends outside the software limits: after the reference event the axis
brakes and stands beyond the reference position by its braking distance
(v²/2a with the referencing speed and the homing acceleration); with fixed-stop
homing it backs off by the retraction distance from `torq_homing_position`.
The check runs the dry-run engine with its default scenario — the braking
distance does not depend on where cam and zero pulse are. On a short axis,
where the default cam (100 mm from the start) lies beyond the limit switches,
the scenario moves the cam closer and makes it narrower until homing completes
between them, so short axes are checked too. When no such cam exists (no room
between the start and the software limit in the homing direction, or braking
longer than the axis) the rule says so with an info finding ("not checked")
instead of passing silently; describe the real geometry in a scenario and run
`achslint dry-run --scenario`.

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
kenngr.swe_neg                 -500000         ( -50 mm: a short axis
kenngr.swe_pos                 500000          ( 50 mm
kenngr.ref_richt               1
getriebe[0].vb_reflow          50000           ( 50 mm/s
getriebe[0].a_ref              100             ( brakes 12.5 mm
getriebe[0].pos_refpkt         450000          ( 45 mm: stands at 57.5 mm
```
(The default cam 100 mm away would lie beyond the limit switch at 60 mm; the
check assumes the cam at [12.5, 50] mm instead, as `achslint dry-run` shows.)

Use instead
-----------
```
kenngr.antr_typ                1
kenngr.swe_neg                 -500000
kenngr.swe_pos                 500000
kenngr.ref_richt               1
getriebe[0].vb_reflow          50000
getriebe[0].a_ref              100
getriebe[0].pos_refpkt         350000          ( 35 mm: stands at 47.5 mm, inside
lr_hw[0].cam_direct_access     0               ( cam signal from the PLC
```

Reference
---------
TF5200 homing manual §2 (axis position after homing: the deceleration distance away from the reference
position; software limits monitored once homing is complete) and §2.3.3.4 (retraction after the fixed stop);
P-AXIS-00152 (`pos_refpkt`), P-AXIS-00158 (`ref_richt`). The assumed geometry and how the cam is fitted to a
short axis: `achslint dry-run` ("Assumed"), scenario.py.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..catalogue.units import unit_label

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from ..homing.motion import SoftLimitOvershoot
    from ..homing.scenario import Scenario
    from .context import Context

CODE = "LIS317"
NAME = "homing-ends-outside-limits"
FIX = "none"
INFO_WHEN_UNCHECKED = True  # the assumed cam does not fit between the limits: said, not passed
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
    unit = unit_label(fact.unit)  # degrees as every other message writes them
    if fact.reference_outside:
        return f"the reference value {fact.value:g} {unit} lies outside the software limits [{low:g}, {high:g}] {unit}"
    what = "after retracting from the stop" if fact.retracted else "after braking"
    return (
        f"{what} the axis stands at {fact.final:.6g} {unit}, outside the software limits "
        f"[{low:g}, {high:g}] {unit}: move the reference position inside by at least "
        f"{abs(fact.final - fact.value):.4g} {unit}"
    )


def check(ctx: Context) -> Iterator[Diagnostic]:
    from ..core.diagnostics import Severity
    from ..homing.base import geometry_failure
    from ..homing.motion import Simulator

    values, strategy = ctx.values, ctx.strategy
    if not strategy.moves or strategy.controlled_by != "cnc" or values.axis_type == "S":
        return
    probe = Simulator(values, strategy, strategy.default_scenario(cycle_time_us=ctx.options.cycle_time_us))
    # Only the distances matter: a fixed stop (read by fixed-stop homing alone) where detection is certain.
    low = values.number("kenngr.homing.torq_min_distance") * 1e-4
    probe.scenario.fixed_stop = probe.scenario.start_position + strategy.direction * (low + 1.0)
    trace = probe.run()
    reference = strategy.definition.reference_parameter.replace("[i]", f"[{strategy.gear}]")
    limits = [reference, "kenngr.swe_neg", "kenngr.swe_pos"]
    if trace.reference is None and strategy.cam_may_move(probe.scenario) and geometry_failure(trace.failure):
        yield ctx.cross(
            CODE, unchecked(probe.scenario, trace.failure or "", probe.unit), limits, severity=Severity.INFO
        )
        return
    fact = probe.check_soft_limits(trace)
    if fact is not None:
        yield ctx.cross(CODE, message(fact), limits)


def unchecked(scenario: Scenario, failure: str, unit: str) -> str:
    """No assumed cam lets homing complete on this axis, so the check could not run: said, not passed."""
    low, high = scenario.cam or (0.0, 0.0)
    unit = unit_label(unit)
    return (
        f"not checked: homing with the assumed cam at [{low:g}, {high:g}] {unit} fails ({failure}), and no "
        f"closer, narrower cam between the start {scenario.start_position:g} {unit} and the software limit "
        "lets it complete; describe the cam and the limit switches in a scenario and run "
        "`achslint dry-run --scenario`"
    )
