"""Plausibility bounds of scenario numbers, in human units (mm or °, seconds).

Both the scenario (which fills in the default geometry) and the pydantic models that validate scenario input
check against these numbers; they sit below both so that the models need not import the scenario.
Positions and distances are first checked against ±1e9, then against the unit's own bound (±1e6 mm, ±1e9 °)
once the axis type is known.
"""

from __future__ import annotations

POSITION_BOUND = {"mm": 1e6, "deg": 1e9}
ANY_POSITION = 1e9
MIN_PERIOD = 0.001  # 1 µm (or 0.001°)
CYCLE_TIME_US = (50, 100_000)  # the CNC cycle: 0.05 ms to 100 ms (the configuration's cycle-time bounds too)
CYCLE_MS = (CYCLE_TIME_US[0] / 1000, CYCLE_TIME_US[1] / 1000)
MAX_RATE = 1e9  # velocities and accelerations per second
