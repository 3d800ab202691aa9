"""
What
----
Homing to a fixed stop (`TORQ`) without what it needs: no detection criterion
at all (neither a homing-specific one — `torq_detect_time`,
`torq_detect_pos_lag_limit`, `torq_detect_velocity_limit`,
`torq_detect_torque_limit` — nor a general one under
`antr.fixed_stop.detect.*`), a simulated drive without
`kenngr.homing.torq_distance_to_block`, or a move speed / acceleration that is
not set (0) or above the axis's `vb_max` / `a_max`. Not reported for an axis
with an absolute measuring system: it makes no homing move at power-up, and
LIS401 says its fixed-stop values have no effect there.

Why
---
Without a criterion the stop is never recognised and the axis pushes against
it until the maximum distance aborts homing. The simulated drive needs the
distance at which its simulated stop sits. The move speed and acceleration must
be set (at least 1) and must not exceed the axis limits `vb_max` / `a_max`.

Example
-------
```
kenngr.antr_typ                             2          ( SERCOS
kenngr.homing.homing_type                   TORQ
kenngr.homing.torq_max_distance             200000     ( 20 mm
getriebe[0].homing.torq_move_velocity       5000       ( 5 mm/s
getriebe[0].homing.torq_move_acceleration   100
```

Use instead
-----------
```
kenngr.antr_typ                             2
kenngr.homing.homing_type                   TORQ
kenngr.homing.torq_max_distance             200000
getriebe[0].homing.torq_move_velocity       5000
getriebe[0].homing.torq_move_acceleration   100
kenngr.homing.torq_detect_time              25000      ( 25 ms at the torque limit
kenngr.homing.torq_detect_velocity_limit    300        ( 30 % residual speed
antr.fixed_stop.drive_ident[0].id           TORQUE_LIMIT ( torque limited while homing
antr.fixed_stop.drive_ident[0].wr_ident     S_0_0092
antr.fixed_stop.drive_ident[0].active_value 50
```

Reference
---------
TF5200 homing manual §2.3.3.4.2 (at least one criterion; general detection parameters P-AXIS-00769/00817/00818)
and §2.3.3.4.4 (P-AXIS-00822 for simulation); ranges of P-AXIS-00333 and P-AXIS-00334 (1 ≤ …);
§2.3.3.5 (torq_move_velocity ≤ vb_max, torq_move_acceleration ≤ a_max).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..catalogue import Value
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS315"
NAME = "fixed-stop-setup"
FIX = "none"
PARAMETERS = (
    "kenngr.homing.torq_detect_time",
    "kenngr.homing.torq_detect_pos_lag_limit",
    "kenngr.homing.torq_detect_velocity_limit",
    "kenngr.homing.torq_detect_torque_limit",
    "kenngr.homing.torq_distance_to_block",
    "getriebe[i].homing.torq_move_velocity",
    "getriebe[i].homing.torq_move_acceleration",
)  # parameters this rule reads
SUMMARY = "Fixed-stop homing without a detection criterion or with impossible move values"

SPECIFIC = [
    "kenngr.homing.torq_detect_time",
    "kenngr.homing.torq_detect_pos_lag_limit",
    "kenngr.homing.torq_detect_velocity_limit",
    "kenngr.homing.torq_detect_torque_limit",
]
GENERAL = [
    "antr.fixed_stop.detect.pos_lag_limit",
    "antr.fixed_stop.detect.detect_velocity_limit",
    "antr.fixed_stop.detect.detect_torque_limit",
]


def _active(path: str, value: Value | None) -> bool:
    if not isinstance(value, (int, float)):
        return False  # no value
    if path.endswith("detect.detect_velocity_limit"):
        return value < 1000  # 1000 = not active
    return value > 0


def check(ctx: Context) -> Iterator[Diagnostic]:
    values = ctx.values
    # Silent unless fixed-stop homing is what runs: an absolute axis whose homing type is TORQ needs no homing
    # move at power-up, and LIS401 says its fixed-stop values have no effect there, as for other strategies.
    if values.homing_type != "TORQ" or not ctx.effective("getriebe[0].homing.torq_move_velocity"):
        return
    stage_criteria = [
        f"getriebe[{g}].homing.torq_detect_torque_limit"
        for g in values.gear_stages_set("homing.torq_detect_torque_limit")
    ]
    criteria = SPECIFIC + stage_criteria + GENERAL
    if not any(_active(p, values.get(p)) for p in criteria):
        yield ctx.cross(
            CODE,
            "fixed-stop homing (TORQ) has no detection criterion: set at least one of torq_detect_time, "
            "torq_detect_pos_lag_limit, torq_detect_velocity_limit, torq_detect_torque_limit "
            "(or the general antr.fixed_stop.detect.* values); otherwise the stop is never recognised",
            ["kenngr.homing.homing_type"],
        )
    if ctx.strategy.setup.simulated and not values.get("kenngr.homing.torq_distance_to_block"):
        yield ctx.cross(
            CODE,
            "a simulated drive homing to a fixed stop needs `kenngr.homing.torq_distance_to_block` "
            "(P-AXIS-00822), the distance at which the simulated stop is hit",
            ["kenngr.homing.torq_distance_to_block", "kenngr.antr_typ", "kenngr.homing.homing_type"],
        )
    for gear in sorted(
        {0}
        | set(
            values.gear_stages_set(
                "homing.torq_move_velocity",
                "homing.torq_move_acceleration",
                "dynamik.vb_max",
                "dynamik.a_max",
            )
        )
    ):
        speed, vmax = f"getriebe[{gear}].homing.torq_move_velocity", f"getriebe[{gear}].dynamik.vb_max"
        accel, amax = f"getriebe[{gear}].homing.torq_move_acceleration", f"getriebe[{gear}].dynamik.a_max"
        for path, limit, what, pid in (
            (speed, vmax, "speed", "P-AXIS-00333"),
            (accel, amax, "acceleration", "P-AXIS-00334"),
        ):
            value = values.written_number(path)
            if not value:
                if gear == 0 or values.is_set(path):
                    yield ctx.cross(
                        CODE,
                        f"gear stage {gear}: {ctx.show(path)}: fixed-stop homing needs a move {what} "
                        f"of at least 1 ({pid}); without it the axis does not move",
                        [path],
                    )
            elif value > values.number(limit):
                yield ctx.cross(
                    CODE,
                    f"gear stage {gear}: {ctx.show(path)} must not exceed {ctx.show(limit)} (§2.3.3.5)",
                    [path, limit],
                )
