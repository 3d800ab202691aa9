"""Compatibility mode `NONE` (§4.3): the reference position is adopted where the axis stands."""

from __future__ import annotations

from ..motion import Simulator, Trace


def run(sim: Simulator, trace: Trace, x: float, cam_shift: float) -> Trace:
    """pos_refpkt becomes the axis position where it stands (no move is simulated)."""
    trace.outcome = "homed"
    trace.reference = {"kind": "adopted", "position": x, "value": sim.refpkt, "speed": 0.0, "time": 0.0}
    trace.final_position = sim.refpkt
    return trace
