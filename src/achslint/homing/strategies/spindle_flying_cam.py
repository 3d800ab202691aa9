"""Flying homing of a spindle with cam (§2.3.2.1, ref_ohne_rev 1, ref_ohne_nocken 0)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..base import Phase, StrategyDef, Use
from ..parameters import CAM, SEQUENCE
from ..sequences import flying
from . import _sequence

if TYPE_CHECKING:
    from ..setup import HomingSetup


def _phases(setup: HomingSetup) -> list[Phase]:
    return [
        Phase(
            "reference on the fly",
            _sequence.direction(setup),
            setup.stage("vb_reflow"),
            setup.speed("vb_reflow"),
            "the cam changes from operated to not operated (a spindle on the cam first turns until it is "
            "left) and the next zero pulse arrives; the spindle keeps turning",
            _sequence.ROTATION,
        )
    ]


STRATEGY = StrategyDef(
    id="spindle_flying_cam",
    title="flying homing of a spindle with cam",
    controlled_by="cnc",
    matches=lambda axis: (
        axis.axis_type == "S"
        and bool(axis.get("kenngr.ref_ohne_rev"))
        and not axis.get("kenngr.ref_ohne_nocken")
    ),
    describe=lambda axis: (
        "The spindle references while it turns, without stopping or reversing: it runs at vb_reflow in the homing "
        "direction (from standstill or from endless rotation) and takes the reference on the fly (§2.3.2.1)."
    ),
    parameters={
        **SEQUENCE,
        **CAM,
        "getriebe[i].vb_reflow": Use("speed at which the spindle references"),
        "kenngr.shift_offset_zero_pulse_activation": Use(
            "delays the zero-pulse detection after the cam edge (§2.6)"
        ),
        "lr_hw[0].zero_pulse_search_max_dist": Use(
            "bounds the zero-pulse search, counted from where the zero-pulse logic is armed (the cam edge plus shift_offset_zero_pulse_activation; the manual does not say, this is the tool's reading)"
        ),
    },
    example="kenngr.antr_typ 1\nkenngr.achs_typ 4\nkenngr.achs_mode 0x4\nkenngr.ref_ohne_rev 1\nkenngr.ref_ohne_nocken 0\n",
    phases=_phases,
    with_cam=True,
    with_zero_pulse=True,
    one_phase=True,
    reference_speed="vb_reflow",
    flying=True,
    arms_on_cam_exit=True,
    variants=_sequence.variants,
    unused="flying spindle homing reads only the cam, the zero pulse and vb_reflow",
    simulate=flying.run,
)
