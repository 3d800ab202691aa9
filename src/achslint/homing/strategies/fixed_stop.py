"""Homing to a fixed stop (`TORQ`, §2.3.3.4): move with limited torque until the stop is detected, then retract."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...axis.drives import DriveType
from ...axis.resolved import ResolvedAxis
from ...catalogue.units import describe
from ..base import NEGATIVE, POSITIVE, Phase, StrategyDef, Use, opposite
from ..parameters import CNC_MOVES
from ..sequences import fixed_stop

if TYPE_CHECKING:
    from ..setup import HomingSetup

_MASTER_RETRACTS = "a gantry slave retracts by its master's torq_retraction_distance (§2.3.3.4.5)"


def _not_gantry_slave(axis: ResolvedAxis) -> bool:
    return not axis.get("kenngr.gantry_ax_nr")


def _simulated(axis: ResolvedAxis) -> bool:
    return axis.drive_type == DriveType.SIMULATION


def _phases(setup: HomingSetup) -> list[Phase]:
    direction = POSITIVE if setup.torq_direction > 0 else NEGATIVE
    path = setup.stage("homing.torq_move_velocity")
    speed = setup.speed("homing.torq_move_velocity")
    retraction = setup.axis.get("kenngr.homing.torq_retraction_distance")
    unit = setup.axis.parameter("kenngr.homing.torq_retraction_distance").unit(setup.axis_type)
    missing = "" if speed else "torq_move_velocity is not set (0): the axis does not move (LIS315)"
    # No retraction distance: the axis stays at the stop and there is no second move (§2.3.3.4.1); a gantry
    # slave retracts by its master's distance (§2.3.3.4.5), which its own list does not show.
    stays = not retraction and _not_gantry_slave(setup.axis)
    approach = Phase(
        "to the fixed stop",
        direction,
        path,
        speed,
        "the stop is detected (armed after torq_min_distance; homing aborts after torq_max_distance)",
        "; ".join(
            note
            for note in (
                missing,
                "torq_retraction_distance is 0: no retraction, the axis stays at the stop" * stays,
            )
            if note
        ),
    )
    if stays:
        return [approach]
    return [
        approach,
        Phase(
            "retract from the stop",
            opposite(direction),
            path,
            speed,
            f"torq_retraction_distance = {describe(retraction, unit)} is travelled",
        ),
    ]


_TORQ = "parameter of homing to a fixed stop"

STRATEGY = StrategyDef(
    id="fixed_stop",
    title="homing to a fixed stop (TORQ)",
    controlled_by="cnc",
    matches=lambda axis: axis.homing_type == "TORQ",
    describe=lambda axis: (
        "The axis moves with limited torque towards a mechanical stop; once the stop is detected the position "
        "torq_homing_position is set and the axis backs off by the retraction distance, so it ends that far from "
        "the stop (§2.3.3.4)."
    ),
    parameters={
        **{k: v for k, v in CNC_MOVES.items() if k not in ("getriebe[i].pos_refpkt",)},
        "kenngr.homing.torq_homing_dir": Use("direction towards the stop"),
        "getriebe[i].homing.torq_move_velocity": Use("speed towards the stop and of the retraction"),
        "getriebe[i].homing.torq_move_acceleration": Use("acceleration of the fixed-stop moves"),
        "getriebe[i].homing.torq_move_torque_limit": Use("torque limit while moving to the stop"),
        "kenngr.homing.torq_min_distance": Use("travel before stop detection is armed"),
        "kenngr.homing.torq_max_distance": Use("travel after which homing aborts"),
        "kenngr.homing.torq_detect_time": Use(_TORQ + ": detection criterion"),
        "kenngr.homing.torq_detect_velocity_limit": Use(_TORQ + ": detection criterion"),
        "kenngr.homing.torq_detect_pos_lag_limit": Use(_TORQ + ": detection criterion"),
        "kenngr.homing.torq_detect_torque_limit": Use(_TORQ + ": detection criterion"),
        "kenngr.homing.torq_retraction_distance": Use(
            "distance backed off after the stop", when=_not_gantry_slave, otherwise=_MASTER_RETRACTS
        ),
        "kenngr.homing.torq_homing_position": Use("the position set at the stop"),
        "kenngr.homing.torq_distance_to_block": Use(
            "distance to the simulated stop (P-AXIS-00822)",
            when=_simulated,
            otherwise="distance to the simulated stop, simulated drives only",
        ),
    },
    example=(
        "kenngr.antr_typ 2\nkenngr.homing.homing_type TORQ\nkenngr.homing.torq_homing_dir POSITIVE\n"
        "kenngr.homing.torq_max_distance 200000\nkenngr.homing.torq_detect_time 25000\n"
        "getriebe[0].homing.torq_move_velocity 2000\ngetriebe[0].homing.torq_move_acceleration 50\n"
        # the drive's torque limit, written while homing (without it the CNC stops the homing: LIS328)
        "antr.fixed_stop.drive_ident[0].id TORQUE_LIMIT\nantr.fixed_stop.drive_ident[0].commu ACYCLIC\n"
        "antr.fixed_stop.drive_ident[0].wr_ident S_0_0092\n"
    ),
    phases=_phases,
    unused="fixed-stop homing uses only its own torq_* parameters",
    retracts=True,
    reference_parameter="kenngr.homing.torq_homing_position",
    direction=lambda setup: setup.torq_direction,
    acceleration=lambda setup: setup.torq_ramp,
    simulate=fixed_stop.run,
)
