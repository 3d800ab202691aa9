"""Referencing on the zero pulse without reference cam (type II, §2.3.3.3)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..base import Phase, StrategyDef, Use
from ..parameters import SEQUENCE, ZERO_PULSE
from ..sequences import zero_pulse
from . import _sequence

if TYPE_CHECKING:
    from ..setup import HomingSetup


def _phases(setup: HomingSetup) -> list[Phase]:
    return [
        Phase(
            "to the zero pulse",
            _sequence.direction(setup),
            setup.stage("vb_reflow"),
            setup.speed("vb_reflow"),
            f"{_sequence.reference_event(setup)} is detected",
        )
    ]


STRATEGY = StrategyDef(
    id="zero_pulse_only",
    title="zero pulse without reference cam (type II)",
    controlled_by="cnc",
    matches=lambda axis: bool(axis.get("kenngr.ref_ohne_nocken")),
    describe=lambda axis: (
        "There is no reference cam: the axis moves at vb_reflow in the homing direction and takes the first zero "
        "pulse as the reference (§2.3.3.3); the pulse must occur only once in the travel range to be unique."
    ),
    parameters={
        **SEQUENCE,
        **ZERO_PULSE,
        "lr_hw[0].zero_pulse_search_max_dist": Use(
            "bounds the zero-pulse search, counted from the start (without a cam the zero-pulse logic is armed at "
            "once)"
        ),
    },
    example="kenngr.antr_typ 1\nkenngr.ref_ohne_nocken 1\nkenngr.ref_ohne_rev 1\n",
    phases=_phases,
    manual_type="II",
    with_zero_pulse=True,
    one_phase=True,
    reference_speed="vb_reflow",
    needs_zero_pulse=True,
    variants=_sequence.variants,
    unused="there is no reference cam and no fast search phase (§3.5, type II)",
    simulate=zero_pulse.run,
)
