"""Axis skipped by G74 (`IGNORE_ABS_POS`, P-AXIS-00299)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..base import StrategyDef
from ..parameters import EVERYWHERE

if TYPE_CHECKING:
    from ...axis.resolved import ResolvedAxis


def _describe(axis: ResolvedAxis) -> str:
    text = "G74 skips the axis without an error; its absolute encoder supplies the position."
    if not axis.get("kenngr.abs_pos_gueltig"):
        text += " Without an absolute encoder (abs_pos_gueltig = 0) the CNC warns (P-ERR-110584) and the axis is never homed."
    return text


STRATEGY = StrategyDef(
    id="ignore_abs_pos",
    title="homing skipped (IGNORE_ABS_POS)",
    controlled_by="none",
    matches=lambda axis: axis.homing_type == "IGNORE_ABS_POS",
    describe=_describe,
    parameters=EVERYWHERE,
    manual_type=None,
    skipped_by_g74=True,
    referenced_at_power_up=True,
    example="kenngr.abs_pos_gueltig 1\nkenngr.homing.homing_type IGNORE_ABS_POS\n",
    unused="G74 skips this axis (IGNORE_ABS_POS)",
    simulate=lambda sim, trace, x, cam_shift: sim.stand_still(trace, "skipped"),
)
