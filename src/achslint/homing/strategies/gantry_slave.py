"""Gantry slave whose own homing is suppressed (P-AXIS-00074): it takes its reference with the master."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..base import StrategyDef, Use
from ..parameters import EVERYWHERE

if TYPE_CHECKING:
    from ...axis.resolved import ResolvedAxis


def _matches(axis: ResolvedAxis) -> bool:
    return (
        bool(axis.get("kenngr.gantry_ax_nr"))
        and bool(axis.get("kenngr.gantry_slave_no_homing"))
        and axis.axis_type != "S"
    )


STRATEGY = StrategyDef(
    id="gantry_slave",
    title="gantry slave homed with its master",
    controlled_by="none",
    matches=_matches,
    describe=lambda axis: (
        f"The axis is the gantry slave of axis {axis.get('kenngr.gantry_ax_nr')} and its own homing is suppressed "
        "(gantry_slave_no_homing = 1): it moves with the master, takes the reference position of its own list when "
        "the master is homed, and the gantry difference is monitored from then on (§2.3.3.4.5)."
    ),
    parameters={
        **EVERYWHERE,
        "getriebe[i].pos_refpkt": Use("taken over when the master is homed (P-AXIS-00074)"),
    },
    example="kenngr.gantry_ax_nr 1\nkenngr.gantry_slave_no_homing 1\n",
    unused="the gantry master's homing references this slave; its own sequence parameters are not used",
    homed_with_master=True,
    simulate=lambda sim, trace, x, cam_shift: sim.stand_still(
        trace, "skipped", note="the gantry master's homing references this slave; simulate the master"
    ),
)
