"""Drive types (P-AXIS-00020) and what each one allows: the homing type it uses when none is set, and which
drives support CNC-controlled homing only or encoder-overflow homing. Both the corrections and the resolved
axis read these tables, so they sit below both."""

from __future__ import annotations

from enum import IntEnum


class DriveType(IntEnum):
    """P-AXIS-00020 drive type codes (compare equal to the numbers written in lists)."""

    CONVENTIONAL = 1
    SERCOS = 2
    PROFIDRIVE = 3
    SIMULATION = 4
    LIGHTBUS = 5
    TERMINAL = 6
    REALTIME_ETHERNET = 7
    CANOPEN = 8
    GENERIC = 9
    VIRTUAL = 16
    DSE = 17
    CAN_BUS = 32


SERCOS, SIMULATION, LIGHTBUS, CANOPEN = (
    DriveType.SERCOS,
    DriveType.SIMULATION,
    DriveType.LIGHTBUS,
    DriveType.CANOPEN,
)


def default_homing_type(drive_type: int) -> str:
    """The homing type a drive type uses when none is configured (P-AXIS-00299 table)."""
    return "DRIVE_CONTROLLED" if drive_type == SERCOS else "CNC_CONTROLLED"


# Drive types that only home CNC-controlled (P-AXIS-00299 table, plus the conventional drive).
CNC_ONLY_DRIVES = frozenset(
    {
        DriveType.CONVENTIONAL,
        DriveType.PROFIDRIVE,
        SIMULATION,
        LIGHTBUS,
        DriveType.TERMINAL,
        DriveType.REALTIME_ETHERNET,
    }
)
# Drive types with encoder-overflow homing (P-AXIS-00354/00355 drive types; §3.1.1.2).
OVERFLOW_DRIVES = frozenset({SERCOS, LIGHTBUS, CANOPEN})
