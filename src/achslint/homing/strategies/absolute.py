"""Absolute measuring system (P-AXIS-00014 = 1): no homing move needed (type IV of §3.5)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..base import StrategyDef
from ..parameters import EVERYWHERE

if TYPE_CHECKING:
    from ...axis.resolved import ResolvedAxis


def _describe(axis: ResolvedAxis) -> str:
    return (
        "The axis has an absolute measuring system (abs_pos_gueltig = 1): its position is known at power-up, so "
        f"it needs no homing move. Its homing type is {axis.homing_type}, not IGNORE_ABS_POS or DISABLED: a G74 "
        "that names this axis would still run that homing type (P-AXIS-00299 remark); set IGNORE_ABS_POS to "
        "have G74 skip it."
    )


STRATEGY = StrategyDef(
    id="absolute",
    title="no homing move (absolute measuring system)",
    controlled_by="none",
    matches=lambda axis: bool(axis.get("kenngr.abs_pos_gueltig")),
    describe=_describe,
    parameters=EVERYWHERE,
    manual_type="IV",
    power_up_only=True,
    referenced_at_power_up=True,
    example="kenngr.abs_pos_gueltig 1\n",
    unused="an axis with an absolute measuring system needs no homing move (§3.5, type IV); only a G74 that "
    "names it would run its homing type",
    simulate=lambda sim, trace, x, cam_shift: sim.stand_still(trace, "not_required"),
)
