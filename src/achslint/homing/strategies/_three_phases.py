"""The three phases of default homing (§2.3.1), shared by types I and III."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..base import Phase, Use, opposite
from . import _sequence

if TYPE_CHECKING:
    from ...axis.resolved import ResolvedAxis
    from ..setup import HomingSetup

THREE_PHASE_SPEEDS = {
    "getriebe[i].vb_refmax": Use("speed of phase 1 (to the cam), and of phase 2 with fast_from_cam = 1"),
    "kenngr.fast_from_cam": Use("speed of phase 2 (off the cam)"),
}


def describe(axis: ResolvedAxis) -> str:
    from ..setup import HomingSetup

    event = _sequence.reference_event(HomingSetup(axis))
    return (
        "Default homing in three phases: to the reference cam at the fast speed, back off the cam, and slowly "
        f"onto the cam again, referencing on {event} (§2.3.1)."
    )


def phases(setup: HomingSetup) -> list[Phase]:
    way = _sequence.direction(setup)
    fast, slow = setup.stage("vb_refmax"), setup.stage("vb_reflow")
    off = fast if setup.fast_from_cam else slow
    return [
        Phase(
            "to the reference cam",
            way,
            fast,
            setup.speed("vb_refmax"),
            "the cam is reached (skipped when starting on the cam)",
        ),
        Phase(
            "off the reference cam", opposite(way), off, setup.speed(off.split(".", 1)[1]), "the cam is left"
        ),
        Phase(
            "onto the cam and reference",
            way,
            slow,
            setup.speed("vb_reflow"),
            f"the cam is reached and {_sequence.reference_event(setup)} is detected",
        ),
    ]
