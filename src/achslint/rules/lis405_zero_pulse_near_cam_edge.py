"""
What
----
The zero pulse that ends homing lies so close to the point where the CNC starts
looking for it that the spread of the cam switch and the sampling of one control
cycle can put that point on either side of the pulse. The zero-pulse logic is
armed where the cam edge is detected, moved on by
`kenngr.shift_offset_zero_pulse_activation` (§2.6), in three-phase homing
(taken at `vb_reflow`) and in one-phase homing (taken at the approach speed
`vb_refmax`, so its sampling spread is larger) alike. Only `achslint dry-run`
reports this: it needs the machine's geometry (cam position, zero-pulse phase,
cam jitter) from a scenario, which an axis list does not hold.

Why
---
When the arming falls just behind the pulse, the CNC takes the next pulse one
encoder revolution later: the machine's zero point then moves by a whole revolution
(for example 5 mm on a 5 mm ball screw) from one homing to the next, without any
message. Moving the arming point about half a revolution away from the pulse
makes the choice of pulse insensitive to the cam's spread. That shift usually
makes the CNC take a different pulse for good, typically the next one, one pulse
period further: the message says by how much the reference moves, and
`pos_refpkt` must move by the same amount so the axis keeps its coordinates.

Example
-------
```
kenngr.antr_typ             1
kenngr.ref_richt            0
getriebe[0].vb_refmax       100000
getriebe[0].vb_reflow       10000
getriebe[0].a_ref           500
```
```
# file: scenario.toml
start_position = 0.0
cam = [-120.0, -100.0]
zero_pulse_period = 5.0
zero_pulse_phase = -100.005
cam_jitter = 0.02
limit_switches = [-1010.0, 1010.0]
```

Use instead
-----------
```
kenngr.antr_typ                            1
kenngr.ref_richt                           0
getriebe[0].vb_refmax                      100000
getriebe[0].vb_reflow                      10000
getriebe[0].a_ref                          500
kenngr.shift_offset_zero_pulse_activation  25050
getriebe[0].pos_refpkt                     -50000
```
```
# file: scenario.toml
start_position = 0.0
cam = [-120.0, -100.0]
zero_pulse_period = 5.0
zero_pulse_phase = -100.005
cam_jitter = 0.02
limit_switches = [-1010.0, 1010.0]
```
The dry-run's message names the shift that puts the pulse half a revolution
away (here 25050 × 0.1 µm = 2.505 mm). Armed there, the CNC takes the pulse at
-105.005 instead of -100.005: the reference moves 5 mm in the (negative) homing
direction, so `pos_refpkt` goes from 0 to -5 mm (-50000 × 0.1 µm) and the axis
keeps its coordinates.

Reference
---------
TF5200 homing manual §2.3.1.3 (phase 3: zero pulse after the cam edge), §2.3.3.2
(one-phase homing) and §2.6 with P-AXIS-00494 (`shift_offset_zero_pulse_activation`:
the zero-pulse logic is enabled as soon as the cam is operated, or that much
later); P-AXIS-00152 (`pos_refpkt`). The margin is the distance travelled in one
control cycle at the speed the cam is crossed plus the scenario's `cam_jitter`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..catalogue.units import unit_label
from ..homing.setup import POSITION

if TYPE_CHECKING:
    from ..homing.motion import PulseMargin

CODE = "LIS405"
NAME = "zero-pulse-near-cam-edge"
FIX = "none"
SUMMARY = "Zero pulse too close to the cam edge: the reference can jump by one revolution (dry-run)"

# Found by the homing simulation (a PulseMargin fact of the trace), not by linting a list: `achslint dry-run`
# reports it in these words.
PRODUCED_BY = "dry-run"


def message(fact: PulseMargin) -> str:
    unit = unit_label(fact.unit)
    side = (
        f"{fact.ahead:.4g} {unit} after" if fact.ahead < fact.margin else f"{fact.behind:.4g} {unit} before"
    )
    return (
        f"a zero pulse lies {side} the point where the zero-pulse logic is armed (one encoder revolution = "
        f"{fact.period:g} {unit}); the cam jitter and the sampling of the cam edge ({fact.margin:.4g} {unit}) can "
        f"arm it on either side, so the reference can jump by one revolution. Set "
        f"kenngr.shift_offset_zero_pulse_activation to about {round(fact.wanted / POSITION)} "
        f"(= {fact.wanted:.4g} {unit}) to put the pulse half a revolution away; {_reference_moves(fact)}"
    )


def _reference_moves(fact: PulseMargin) -> str:
    """What that shift does to the reference, and the pos_refpkt that keeps the axis's coordinates."""
    unit = unit_label(fact.unit)
    if not fact.periods:
        return "the reference stays on the same zero pulse, so pos_refpkt keeps its value"
    if fact.modulo and abs(fact.moved) < 1e-9 * fact.period:
        return (
            f"the reference moves by whole revolutions only, to the same position within "
            f"[{fact.modulo[0]:g}, {fact.modulo[1]:g}) {unit}, so pos_refpkt keeps its value"
        )
    count = abs(fact.periods)
    how_many = "one zero-pulse period" if count == 1 else f"{count} zero-pulse periods"
    way = "in" if fact.periods > 0 else "against"
    value = fact.reference_value
    return (
        f"the reference then moves {abs(fact.moved):.6g} {unit} ({how_many}) {way} the homing direction: correct "
        f"getriebe[{fact.gear}].pos_refpkt by {fact.moved:+.6g} {unit}, to about "
        f"{round(value / POSITION)} (= {value:.6g} {unit}), so the axis keeps its coordinates"
    )
