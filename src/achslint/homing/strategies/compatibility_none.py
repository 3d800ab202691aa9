"""Compatibility mode `NONE` (P-AXIS-00299, §4.3): the reference position is adopted as the axis position."""

from __future__ import annotations

from ...axis.drives import DriveType
from ..base import StrategyDef, Use
from ..parameters import EVERYWHERE
from ..sequences import adopt

STRATEGY = StrategyDef(
    id="none",
    title="reference position adopted (compatibility mode NONE)",
    controlled_by="cnc",
    matches=lambda axis: axis.homing_type == "NONE",
    describe=lambda axis: (
        "When homing is commanded, pos_refpkt is taken over as the axis position; a simulated axis first moves a "
        "short distance, a DSE axis does not move (§4.3)."
    ),
    parameters={
        **EVERYWHERE,
        "getriebe[i].pos_refpkt": Use("adopted as the axis position"),
        "antr.simu.rpf_weg_bis_nip": Use(
            "the short move of a simulated axis before pos_refpkt is adopted (assumed; "
            "§4.3 does not name the parameter)",
            when=lambda axis: axis.drive_type == DriveType.SIMULATION,
            otherwise="only a simulated axis moves before it adopts pos_refpkt",
        ),
    },
    example="kenngr.homing.homing_type NONE\n",
    unused="compatibility mode NONE only adopts pos_refpkt",
    simulate=adopt.run,
)
