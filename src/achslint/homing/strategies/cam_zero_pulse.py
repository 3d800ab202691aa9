"""Default homing in three phases, referencing on the zero pulse (type III, §2.3.1)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..base import StrategyDef
from ..parameters import CAM, CAM_AND_ZERO_PULSE, SEQUENCE, ZERO_PULSE
from ..sequences import cam
from . import _sequence
from ._three_phases import THREE_PHASE_SPEEDS, describe, phases

if TYPE_CHECKING:
    from ...axis.resolved import ResolvedAxis

STRATEGY = StrategyDef(
    id="cam_zero_pulse",
    title="three-phase homing on the cam and the zero pulse (type III)",
    controlled_by="cnc",
    matches=lambda axis: _zero_pulse(axis),
    describe=describe,
    parameters={**SEQUENCE, **CAM, **ZERO_PULSE, **CAM_AND_ZERO_PULSE, **THREE_PHASE_SPEEDS},
    example=(
        "kenngr.antr_typ 1\nkenngr.ref_ohne_nocken 0\nkenngr.ref_ohne_rev 0\nkenngr.homing_without_zero_pulse 0\n"
    ),
    phases=phases,
    manual_type="III",
    with_cam=True,
    with_zero_pulse=True,
    reference_speed="vb_reflow",
    variants=_sequence.variants,
    unused="not part of three-phase homing on the cam and the zero pulse",
    simulate=cam.three_phases,
)


def _zero_pulse(axis: ResolvedAxis) -> bool:
    from ..setup import HomingSetup

    return HomingSetup(axis).zero_pulse
