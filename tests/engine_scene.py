"""The axis and the scene the dry-run engine tests work their numbers out on (test_engine.py,
test_engine_facts.py, test_dryrun_fidelity.py), and the drive-side homing set-up: one copy, so a hand-computed
figure in one file means the same axis as in the others.

AXIS: a conventional drive (antr_typ 1), linear, homing negative (ref_richt 0), fast off the cam; fast
100 mm/s (vb_refmax), slow 10 mm/s (vb_reflow), 500 mm/s² (a_ref), pos_refpkt -950 mm. Ramps are
trapezoidal: t_acc = v/a, d_acc = v²/2a, so at full speed 0.2 s and 10 mm, at slow speed 0.02 s and 0.1 mm.
SCENE: the cam from -120 to -100 mm, a zero pulse every 5 mm with one at -102.5, a hardware latch, a 1 ms
cycle, limit switches at ±1010 mm.
"""

from __future__ import annotations

from typing import Any

import pytest

from achslint.dryrun import dry_run
from achslint.homing.motion import Trace
from achslint.homing.scenario import ScenarioInput

AXIS = (
    "kenngr.antr_typ 1\nkenngr.ref_richt 0\nkenngr.fast_from_cam 1\n"
    "getriebe[0].vb_refmax 100000\ngetriebe[0].vb_reflow 10000\ngetriebe[0].a_ref 500\n"
    "getriebe[0].pos_refpkt -9500000\n"
)
SCENE: dict[str, Any] = {
    "start_position": 0.0,
    "cam": (-120.0, -100.0),
    "zero_pulse_period": 5.0,
    "zero_pulse_phase": -102.5,
    "hardware_latch": True,
    "cycle_time_ms": 1.0,
    "limit_switches": (-1010.0, 1010.0),
}

# A SERCOS drive that homes itself; the scene of drive_run puts the cam at [40, 50] mm.
SERCOS_DRIVE = b"kenngr.antr_typ 2\nkenngr.homing.homing_type DRIVE_CONTROLLED\nEnde\n"


def listed(extra: str = "") -> bytes:
    """AXIS with `extra` lines, ended by `Ende`, as the bytes of a list."""
    return (AXIS + extra + "Ende\n").encode()


def run(extra: str = "", **scene: Any) -> Trace:
    """The dry-run trace of AXIS plus `extra` lines in SCENE changed by `scene`."""
    return dry_run(listed(extra), "axis.lis", ScenarioInput(**{**SCENE, **scene})).trace


def approx(value: float, expected: float, tolerance: float = 1e-9) -> bool:
    return value == pytest.approx(expected, abs=tolerance)


def drive_run(
    start: float,
    drive: dict[str, Any],
    cam: tuple[float, float] = (40.0, 50.0),
    fixed_stop: float | None = None,
) -> Trace:
    """The dry-run trace of SERCOS_DRIVE homing with the drive method `drive`, from `start`."""
    scenario = ScenarioInput(
        start_position=start,
        cam=cam,
        zero_pulse_period=5.0,
        zero_pulse_phase=1.0,
        limit_switches=(-100.0, 100.0),
        fixed_stop=fixed_stop,
        drive=drive,
    )
    return dry_run(SERCOS_DRIVE, "drive.lis", scenario).trace
