"""Default homing in three phases, referencing on the cam edge without zero pulse (type I, §2.3.1.3)."""

from __future__ import annotations

from ..base import StrategyDef
from ..parameters import CAM, CAM_EDGE, SEQUENCE
from ..sequences import cam
from . import _sequence
from ._three_phases import THREE_PHASE_SPEEDS, describe, phases

STRATEGY = StrategyDef(
    id="cam_only",
    title="three-phase homing on the cam only (type I)",
    controlled_by="cnc",
    matches=lambda axis: True,
    describe=describe,
    parameters={**SEQUENCE, **CAM, **CAM_EDGE, **THREE_PHASE_SPEEDS},
    example=(
        "kenngr.antr_typ 1\nkenngr.ref_ohne_nocken 0\nkenngr.ref_ohne_rev 0\nkenngr.homing_without_zero_pulse 1\n"
    ),
    phases=phases,
    manual_type="I",
    with_cam=True,
    reference_speed="vb_reflow",
    variants=_sequence.variants,
    unused="there is no zero pulse: the cam edge is the reference (§3.5, type I)",
    simulate=cam.three_phases,
)
