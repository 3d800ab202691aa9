"""One-phase homing with cam and zero pulse (type III without reversal, §2.3.3.2)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...catalogue.units import unit_label
from ..base import Phase, StrategyDef, Use
from ..parameters import CAM, CAM_AND_ZERO_PULSE, SEQUENCE, ZERO_PULSE
from ..sequences import cam
from . import _sequence

if TYPE_CHECKING:
    from ...axis.resolved import ResolvedAxis
    from ..setup import HomingSetup

_SPEEDS = (
    "the manual marks vb_refmax and vb_reflow effective for this type (§3.5) without naming the phase of "
    "each; achslint assumes the cam is approached at vb_refmax and the pulse searched at vb_reflow"
)


def _phases(setup: HomingSetup) -> list[Phase]:
    way = _sequence.direction(setup)
    armed = (
        f"{setup.shift:g} {unit_label(setup.unit)} after the cam edge (shift_offset_zero_pulse_activation, P-AXIS-00494)"
        if setup.shift
        else "at the cam edge"
    )
    event = _sequence.reference_event(setup).replace("the next ", "the first ")
    return [
        Phase(
            "to the reference cam",
            way,
            setup.stage("vb_refmax"),
            setup.speed("vb_refmax"),
            f"the cam is reached; the zero-pulse logic is armed {armed}, whatever the speed (§2.6)",
            _SPEEDS,
        ),
        Phase(
            "on to the reference",
            way,
            setup.stage("vb_reflow"),
            setup.speed("vb_reflow"),
            f"{event} after the arming point is detected (no reversal). One passed while the axis still brakes "
            "after the cam is the reference too: homing then ends with that braking, without this phase",
        ),
    ]


STRATEGY = StrategyDef(
    id="one_phase_cam_zero_pulse",
    title="one-phase homing on the cam and the zero pulse (type III)",
    controlled_by="cnc",
    matches=lambda axis: bool(axis.get("kenngr.ref_ohne_rev")) and _zero_pulse(axis),
    describe=lambda axis: (
        "Homing without reversal: the axis moves in the homing direction to the cam, where the zero-pulse logic "
        "is armed (§2.6), and references on the first zero pulse after that point, even while it brakes after "
        "the cam. It must not start on the cam, which the PLC has to ensure (§2.3.3.2)."
    ),
    parameters={
        **SEQUENCE,
        **{k: v for k, v in CAM.items() if k != "lr_hw[0].move_from_cam_max_dist"},
        **ZERO_PULSE,
        **CAM_AND_ZERO_PULSE,
        "getriebe[i].vb_refmax": Use("speed towards the cam (§3.5; assumed for the approach)"),
    },
    example=(
        "kenngr.antr_typ 1\nkenngr.ref_ohne_rev 1\nkenngr.ref_ohne_nocken 0\nkenngr.homing_without_zero_pulse 0\n"
    ),
    phases=_phases,
    manual_type="III",
    with_cam=True,
    with_zero_pulse=True,
    one_phase=True,
    reference_speed="vb_reflow",
    variants=_sequence.variants,
    unused="one-phase homing never reverses, so it has no move off the cam",
    simulate=cam.one_phase,
)


def _zero_pulse(axis: ResolvedAxis) -> bool:
    from ..setup import HomingSetup

    return HomingSetup(axis).zero_pulse
