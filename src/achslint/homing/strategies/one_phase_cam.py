"""One-phase homing on the cam edge without zero pulse (type I without reversal, §2.3.3.2)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..base import Phase, StrategyDef, Use
from ..parameters import CAM, CAM_EDGE, SEQUENCE
from ..sequences import cam
from . import _sequence

if TYPE_CHECKING:
    from ..setup import HomingSetup


def _phases(setup: HomingSetup) -> list[Phase]:
    return [
        Phase(
            "to the cam and reference",
            _sequence.direction(setup),
            setup.stage("vb_refmax"),
            setup.speed("vb_refmax"),
            "the cam edge is detected (sampled each cycle)",
            "there is no move on the cam, so the cam edge is taken at the approach speed vb_refmax "
            "(assumed; §3.5 marks vb_refmax effective for type I)",
        )
    ]


STRATEGY = StrategyDef(
    id="one_phase_cam",
    title="one-phase homing on the cam only (type I)",
    controlled_by="cnc",
    matches=lambda axis: bool(axis.get("kenngr.ref_ohne_rev")),
    describe=lambda axis: (
        "Homing without reversal and without zero pulse: the axis moves in the homing direction and references on "
        "the cam edge. It must not start on the cam, which the PLC has to ensure (§2.3.3.2)."
    ),
    parameters={
        **{k: v for k, v in SEQUENCE.items() if k != "getriebe[i].vb_reflow"},
        **{k: v for k, v in CAM.items() if k != "lr_hw[0].move_from_cam_max_dist"},
        **CAM_EDGE,
        "getriebe[i].vb_refmax": Use("speed towards the cam, at which its edge is taken (§3.5)"),
    },
    example=(
        "kenngr.antr_typ 1\nkenngr.ref_ohne_rev 1\nkenngr.ref_ohne_nocken 0\nkenngr.homing_without_zero_pulse 1\n"
        "getriebe[0].vb_refmax 20000\n"
    ),
    phases=_phases,
    manual_type="I",
    with_cam=True,
    one_phase=True,
    reference_speed="vb_refmax",
    variants=_sequence.variants,
    unused="one-phase homing on the cam edge has no slow phase and no move off the cam",
    simulate=cam.one_phase,
)
