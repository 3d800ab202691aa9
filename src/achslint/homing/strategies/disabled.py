"""Homing disabled (`DISABLED`, P-AXIS-00299): G74 for the axis ends with an error."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..base import StrategyDef
from ..parameters import EVERYWHERE

if TYPE_CHECKING:
    from ...axis.resolved import ResolvedAxis
    from ..setup import HomingSetup


def _describe(axis: ResolvedAxis) -> str:
    text = (
        "Homing is disabled: a G74 that names this axis ends with an error (P-ERR-50686 / P-ERR-60313). "
        "The setting is meant for axes with an absolute measuring system."
    )
    if not axis.get("kenngr.abs_pos_gueltig"):
        text += " This axis is incremental (abs_pos_gueltig = 0), so it can never be homed."
    return text


def _refused(setup: HomingSetup) -> str:
    """Why a G74 naming the axis fails: the CNC refuses it whatever the encoder; an absolute axis keeps a valid
    position all the same (the machine run stops the program there too, LIS604)."""
    why = (
        "its absolute position is valid without homing: leave it out of G74"
        if setup.absolute
        else "the axis is incremental (kenngr.abs_pos_gueltig 0), so it can never be homed (LIS308)"
    )
    return (
        "homing is DISABLED (kenngr.homing.homing_type): the CNC refuses a G74 that names this axis "
        f"(P-ERR-50686 / P-ERR-60313); {why}"
    )


STRATEGY = StrategyDef(
    id="disabled",
    title="homing disabled",
    controlled_by="none",
    matches=lambda axis: axis.homing_type == "DISABLED",
    describe=_describe,
    parameters=EVERYWHERE,
    example="kenngr.abs_pos_gueltig 1\nkenngr.homing.homing_type DISABLED\n",
    unused="homing is disabled for this axis",
    refuses_g74=True,
    referenced_at_power_up=True,
    simulate=lambda sim, trace, x, cam_shift: sim.stand_still(trace, "failed", _refused(sim.strategy.setup)),
)
