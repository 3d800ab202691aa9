"""Drive-controlled homing (P-AXIS-00299 `DRIVE_CONTROLLED`, §3.1.1.2): the drive runs its own sequence."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..base import StrategyDef, Use
from ..parameters import EVERYWHERE
from ..sequences import drive

if TYPE_CHECKING:
    from ...axis.resolved import ResolvedAxis


def _writes_position(axis: ResolvedAxis) -> bool:
    return bool(axis.get("kenngr.write_reference_position_to_drive"))


STRATEGY = StrategyDef(
    id="drive_controlled",
    title="drive-controlled homing",
    controlled_by="drive",
    matches=lambda axis: axis.homing_type == "DRIVE_CONTROLLED",
    describe=lambda axis: (
        f"The drive ({axis.drive_name()}) runs its own homing sequence (SERCOS command S-0-148 or the CANopen "
        "homing mode); the cam must be wired to the drive, and apart from abs_pos_gueltig and achs_mode the CNC's "
        "homing parameters are not used (§2.2, §3.1.1.2)."
    ),
    parameters={
        **EVERYWHERE,
        "getriebe[i].vb_not_referenced": Use("caps every move while the axis is not homed"),
        "kenngr.write_reference_position_to_drive": Use("sends pos_refpkt to the drive for its homing"),
        "getriebe[i].pos_refpkt": Use(
            "sent to the drive as its reference position",
            when=_writes_position,
            otherwise="sent to the drive only with write_reference_position_to_drive = 1",
        ),
    },
    example="kenngr.antr_typ 2\nkenngr.homing.homing_type DRIVE_CONTROLLED\n",
    unused="drive-controlled homing: the drive's own parameters define the sequence (§2.2)",
    acceleration=lambda setup: None,  # the drive's own (the scenario's [drive] table describes it)
    simulate=drive.run,
)
