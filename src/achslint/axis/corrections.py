"""The CNC's load-time corrections: values it replaces while it reads an axis list.

Each function below is one correction the manual or the parameter table describes; it records on the axis
the parameter, the value used instead and the CNC message. Rules report these corrections, `explain` lists
them, and the dry-run simulates the corrected axis, so all three agree on what the CNC actually runs.

The functions see the axis through `CorrectableAxis`, the few lookups they need, so this module sits below
`resolved`, which applies them while it builds an axis.
"""

from __future__ import annotations

from typing import Protocol

from ..catalogue import Parameter, Value
from ..catalogue.units import describe
from .drives import CNC_ONLY_DRIVES, OVERFLOW_DRIVES, SERCOS, default_homing_type


class CorrectableAxis(Protocol):
    """What a correction reads and writes on an axis (`resolved.ResolvedAxis` is one)."""

    @property
    def axis_type(self) -> str: ...

    @property
    def drive_type(self) -> int: ...

    def drive_name(self, code: int | None = None) -> str: ...

    def parameter(self, path: str) -> Parameter: ...

    def get(self, path: str) -> Value | None: ...

    def number(self, path: str) -> float: ...

    def written(self, path: str, _depth: int = 0) -> Value | None: ...

    def written_number(self, path: str) -> float: ...

    def gear_stages_set(self, *members: str) -> list[int]: ...

    def correct(self, path: str, used: Value, error: str, reason: str) -> None: ...


HOMING_TYPE = "kenngr.homing.homing_type"
OVERFLOW, BITS, OFFSET = (
    "kenngr.homing_overflow_evaluation",
    "antr.encoder_bit_range",
    "antr.encoder_overflow_offset",
)
LATCH, LAYOUT, ENCODER = (
    "antr.sercos.drive_supports_cnc_homing",
    "antr.sercos.cnc_homing_rt_bit_layout",
    "antr.cnc_homing_encoder",
)
MAX_DIST = "kenngr.homing_max_movement_dist"
CHECK_NAME, CHECK_BIT = "antr.reference_check.element_name", "antr.reference_check.bit_nr"


def homing_type(axis: CorrectableAxis) -> None:
    """P-AXIS-00299: a homing type the drive cannot run is replaced by the drive's default (P-ERR-110384)."""
    if axis.written(HOMING_TYPE) == "DRIVE_CONTROLLED" and axis.drive_type in CNC_ONLY_DRIVES:
        fallback = default_homing_type(axis.drive_type)
        axis.correct(
            HOMING_TYPE,
            fallback,
            "P-ERR-110384",
            f"drive-controlled homing is not available for kenngr.antr_typ {axis.drive_type} "
            f"({axis.drive_name()}); the CNC uses the drive type's default {fallback}",
        )


def encoder_overflow(axis: CorrectableAxis) -> None:
    """P-AXIS-00294 on a drive without encoder-overflow homing is switched off (P-ERR-110416);
    P-AXIS-00354 beyond one encoder revolution is reset to 0 (P-ERR-70310)."""
    if not axis.written(OVERFLOW):
        return
    if axis.drive_type not in OVERFLOW_DRIVES:
        axis.correct(
            OVERFLOW,
            False,
            "P-ERR-110416",
            f"encoder-overflow homing is not available for kenngr.antr_typ {axis.drive_type} "
            f"({axis.drive_name()}); only SERCOS, Lightbus and CANopen drives support it",
        )
        return
    revolution = encoder_revolution(axis, 0)
    offset = axis.written_number(OFFSET)
    if revolution and abs(offset) >= revolution:
        unit = axis.parameter(OFFSET).unit(axis.axis_type)
        axis.correct(
            OFFSET,
            0,
            "P-ERR-70310",
            f"the offset is beyond one encoder revolution (2^{axis.get(BITS)} increments = "
            f"{describe(revolution, unit)} with getriebe[0].wegaufz/wegaufn); the CNC resets it to 0",
        )


def encoder_revolution(axis: CorrectableAxis, gear: int) -> float | None:
    """One encoder revolution (2^encoder_bit_range increments) in list units of the gear stage, if known."""
    bits = axis.number(BITS)
    numerator, denominator = (
        axis.number(f"getriebe[{gear}].wegaufz"),
        axis.number(f"getriebe[{gear}].wegaufn"),
    )
    _, most = axis.parameter(BITS).limits
    if not bits or not numerator or (most is not None and bits > most):
        # A reference can bring a number beyond encoder_bit_range's range (its value is not range-checked);
        # it describes no encoder, and 2 to its power may not even fit a float.
        return None
    return (2**bits) * denominator / numerator


# (member of getriebe[i], CNC message) for the speeds the limit for unreferenced axes caps.
CAPPED_SPEEDS = (
    ("vb_refmax", "P-ERR-110421"),
    ("vb_reflow", "P-ERR-110422"),
    ("homing.torq_move_velocity", "P-ERR-110413"),
)


def speed_caps(axis: CorrectableAxis) -> None:
    """P-AXIS-00268: homing speeds above the limit for unreferenced axes are lowered to it
    (P-ERR-110421 vb_refmax, P-ERR-110422 vb_reflow, P-ERR-110413 torq_move_velocity)."""
    unit = axis.parameter("getriebe[i].vb_not_referenced").unit(axis.axis_type)
    for gear in axis.gear_stages_set("vb_not_referenced"):
        cap = axis.number(f"getriebe[{gear}].vb_not_referenced")
        if not cap:
            continue  # 0: no limit
        for member, error in CAPPED_SPEEDS:
            path = f"getriebe[{gear}].{member}"
            if axis.written_number(path) > cap:
                axis.correct(
                    path,
                    cap,
                    error,
                    f"above the limit for unreferenced axes getriebe[{gear}].vb_not_referenced = "
                    f"{describe(cap, unit)}; the CNC lowers it to that limit",
                )


def sercos_latch(axis: CorrectableAxis) -> None:
    """P-AXIS-00386 on a spindle is switched off (P-ERR-110522); P-AXIS-00387 outside 1..16 becomes 1
    (P-ERR-110514); P-AXIS-00388 on a drive other than SERCOS becomes 0 (P-ERR-110516)."""
    if axis.written(ENCODER) and axis.drive_type != SERCOS:
        axis.correct(
            ENCODER,
            0,
            "P-ERR-110516",
            f"the homing encoder can only be chosen for SERCOS drives; kenngr.antr_typ {axis.drive_type} "
            f"({axis.drive_name()}) gets 0",
        )
    if not axis.written(LATCH) or axis.drive_type != SERCOS:
        return
    if axis.axis_type == "S":
        axis.correct(
            LATCH,
            False,
            "P-ERR-110522",
            "the drive's zero-pulse latch (S-0-146) is not available for spindles; the CNC switches it off",
        )
        return
    if not 1 <= axis.written_number(LAYOUT) <= 16:
        axis.correct(
            LAYOUT,
            1,
            "P-ERR-110514",
            "must be 1..16 while drive_supports_cnc_homing is 1; the CNC uses 1 (real-time bits 1 and 2 "
            "of the control and status word), which must match the drive's bit assignment",
        )


def path_monitoring(axis: CorrectableAxis) -> None:
    """P-AXIS-00412 other than 0 on a linear axis is set to 0 (P-ERR-110545)."""
    if axis.written(MAX_DIST) and axis.axis_type == "T":
        axis.correct(
            MAX_DIST,
            0,
            "P-ERR-110545",
            "homing path monitoring only works for rotary axes and spindles; on a linear axis the CNC "
            "sets it to 0",
        )


def reference_monitoring(axis: CorrectableAxis) -> None:
    """P-AXIS-00425/00426: reference monitoring on a drive other than SERCOS is switched off (P-ERR-110548)."""
    if axis.written(CHECK_NAME) and axis.drive_type != SERCOS:
        axis.correct(
            CHECK_NAME,
            "",
            "P-ERR-110548",
            f"reference monitoring only works with SERCOS drives; with kenngr.antr_typ {axis.drive_type} "
            f"({axis.drive_name()}) the CNC switches it off",
        )


def homing_dynamics(axis: CorrectableAxis) -> None:
    """P-AXIS-00285 above the gear stage's a_max (P-AXIS-00008) is lowered to it (P-ERR-110393); P-AXIS-00286
    other than 0 below the stage's tr_min (P-AXIS-00201) is raised to it (P-ERR-110394). 0 is no error: it
    selects the fallbacks of §3.2.4."""
    for gear in axis.gear_stages_set("a_ref"):
        path, limit = f"getriebe[{gear}].a_ref", f"getriebe[{gear}].dynamik.a_max"
        most = axis.number(limit)
        if axis.written_number(path) > most:
            axis.correct(
                path,
                most,
                "P-ERR-110393",
                f"the homing acceleration may be at most the axis's {limit}; the CNC homes with {limit}",
            )
    for gear in axis.gear_stages_set("tr_ref"):
        path, limit = f"getriebe[{gear}].tr_ref", f"getriebe[{gear}].dynamik.tr_min"
        least, written = axis.number(limit), axis.written_number(path)
        if 0 < written < least:
            axis.correct(
                path,
                least,
                "P-ERR-110394",
                f"the homing ramp time may not be shorter than the axis's {limit}; the CNC ramps with {limit}",
            )


LINEAR, MODULO = 0x1, 0x4  # kenngr.achs_mode bits (P-AXIS-00015)


def spindle_modulo(axis: CorrectableAxis) -> None:
    """P-AXIS-00015 of a spindle without the MODULO bit is corrected to modulo (P-ERR-110352)."""
    if axis.axis_type != "S":
        return
    mode = int(axis.written_number("kenngr.achs_mode"))
    if mode & MODULO:
        return
    used = (mode & ~LINEAR) | MODULO
    axis.correct(
        "kenngr.achs_mode",
        used,
        "P-ERR-110352",
        f"a spindle always counts modulo; the CNC uses {used:#x}, MODULO (0x4) in place of LINEAR (0x1) and the "
        "other bits as written (the manual names only the MODULO bit)",
    )


# In the order the CNC's checks depend on each other (the overflow offset needs the overflow switch).
CORRECTIONS = (
    homing_type,
    encoder_overflow,
    speed_caps,
    sercos_latch,
    path_monitoring,
    reference_monitoring,
    homing_dynamics,
    spindle_modulo,
)


def apply(axis: CorrectableAxis) -> None:
    for correction in CORRECTIONS:
        correction(axis)
