"""One-phase homing with cam and zero pulse (type III without reversal, §2.3.3.2)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..base import Phase, StrategyDef, Use
from ..parameters import CAM, CAM_AND_ZERO_PULSE, SEQUENCE, ZERO_PULSE
from . import _sequence

if TYPE_CHECKING:
    from ...resolved import ResolvedAxis
    from ..setup import HomingSetup

_SPEEDS = (
    "the manual marks vb_refmax and vb_reflow effective for this type (§3.5) without naming the phase of "
    "each; achslint assumes the cam is approached at vb_refmax and the pulse searched at vb_reflow"
)


def _phases(setup: HomingSetup) -> list[Phase]:
    way = _sequence.direction(setup)
    return [
        Phase(
            "to the reference cam",
            way,
            setup.stage("vb_refmax"),
            setup.speed("vb_refmax"),
            "the cam is reached",
            _SPEEDS,
        ),
        Phase(
            "on to the reference",
            way,
            setup.stage("vb_reflow"),
            setup.speed("vb_reflow"),
            f"{_sequence.reference_event(setup)} after the cam edge is detected (no reversal)",
        ),
    ]


STRATEGY = StrategyDef(
    id="one_phase_cam_zero_pulse",
    title="one-phase homing on the cam and the zero pulse (type III)",
    controlled_by="cnc",
    matches=lambda axis: bool(axis.get("kenngr.ref_ohne_rev")) and _zero_pulse(axis),
    describe=lambda axis: (
        "Homing without reversal: the axis moves in the homing direction to the cam and references on the next "
        "zero pulse after it. It must not start on the cam, which the PLC has to ensure (§2.3.3.2)."
    ),
    parameters={
        **SEQUENCE,
        **CAM,
        **ZERO_PULSE,
        **CAM_AND_ZERO_PULSE,
        "getriebe[i].vb_refmax": Use("speed towards the cam (§3.5; assumed for the approach)"),
    },
    example="kenngr.ref_ohne_rev 1\nkenngr.ref_ohne_nocken 0\nkenngr.homing_without_zero_pulse 0\n",
    phases=_phases,
    manual_type="III",
    with_cam=True,
    with_zero_pulse=True,
    one_phase=True,
    reference_speed="vb_reflow",
    variants=_sequence.variants,
    unused="one-phase homing never reverses, so it has no move off the cam",
    simulate=lambda sim, trace, x, cam_shift: sim.cam_sequence(trace, x, cam_shift),
)


def _zero_pulse(axis: ResolvedAxis) -> bool:
    from ..setup import HomingSetup

    return HomingSetup(axis).zero_pulse
