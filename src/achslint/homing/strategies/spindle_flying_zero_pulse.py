"""Flying homing of a spindle without cam (§2.3.2.1, ref_ohne_rev 1, ref_ohne_nocken 1)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..base import Phase, StrategyDef, Use
from ..parameters import SEQUENCE
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
            "the zero pulse arrives (one per spindle revolution); the spindle keeps turning",
            _sequence.ROTATION,
        )
    ]


STRATEGY = StrategyDef(
    id="spindle_flying_zero_pulse",
    title="flying homing of a spindle without cam",
    controlled_by="cnc",
    matches=lambda axis: axis.axis_type == "S" and bool(axis.get("kenngr.ref_ohne_rev")),
    describe=lambda axis: (
        "The spindle references while it turns, without stopping or reversing: it runs at vb_reflow in the homing "
        "direction (from standstill or from endless rotation) and takes the first zero pulse as the reference "
        "(§2.3.2.1)."
    ),
    parameters={
        **SEQUENCE,
        "getriebe[i].vb_reflow": Use("speed at which the spindle references"),
        "lr_hw[0].zero_pulse_search_max_dist": Use(
            "bounds the zero-pulse search, counted from the start (without a cam the zero-pulse logic is armed at once)"
        ),
    },
    example="kenngr.antr_typ 1\nkenngr.achs_typ 4\nkenngr.achs_mode 0x4\nkenngr.ref_ohne_rev 1\nkenngr.ref_ohne_nocken 1\n",
    phases=_phases,
    with_zero_pulse=True,
    one_phase=True,
    reference_speed="vb_reflow",
    flying=True,
    needs_zero_pulse=True,
    variants=_sequence.variants,
    unused="flying spindle homing without cam reads only the zero pulse and vb_reflow",
    simulate=flying.run,
)
