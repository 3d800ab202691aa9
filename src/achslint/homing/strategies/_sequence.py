"""Pieces shared by the CNC-controlled sequences of §2.3 (types I, II, III and flying spindle homing)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...catalogue.units import unit_label
from ..base import NEGATIVE, POSITIVE

if TYPE_CHECKING:
    from ..setup import HomingSetup


ROTATION = (
    "From endless rotation (before M19 or a gear change) the spindle keeps its rotation direction and first "
    "decelerates or accelerates to vb_reflow; the referencing starts once it runs at vb_reflow (§2.3.2.1; "
    "the tool's reading of 'before being referenced')"
)


def direction(setup: HomingSetup) -> str:
    return POSITIVE if setup.direction > 0 else NEGATIVE


def reference_event(setup: HomingSetup) -> str:
    if setup.overflow:
        return "the encoder overflow"
    return "the next zero pulse" if setup.zero_pulse else "the cam edge"


def variants(setup: HomingSetup) -> list[str]:
    found = []
    if setup.overflow:
        found.append("reference on the encoder overflow instead of the zero pulse (P-AXIS-00294)")
    if setup.falling_edge and not setup.spindle:
        found.append(
            "cam_level 0: the CNC takes a 0-signal as 'on the cam'. With a 0-active switch that is ordinary "
            "wiring; with a 1-active switch it inverts the cam, and together with an inverted ref_richt the "
            "axis references on the falling edge while moving off the cam (§2.3.3.1)"
        )
    if setup.zero_pulse and setup.with_cam and setup.shift:
        found.append(
            f"zero-pulse detection switched on only {setup.shift:g} {unit_label(setup.unit)} after the cam edge "
            "(P-AXIS-00494, §2.6)"
        )
    return found
