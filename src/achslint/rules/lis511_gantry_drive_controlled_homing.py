"""
What
----
A gantry pair homed drive-controlled: the master of a gantry slave
(`kenngr.gantry_ax_nr`) whose homing type in force is `DRIVE_CONTROLLED` —
written, or the default of a SERCOS drive when `kenngr.homing.homing_type` is
not set. A slave whose master is not in the machine (LIS503) is judged by its
own homing type. A slave that differs from its master is LIS510's: the CNC
homes the pair with the master's type.

Why
---
In drive-controlled homing each drive references itself; the CNC cannot keep
the two drives of a gantry together while they do. It refuses homing of a
gantry axis with P-ERR-50429, so the pair cannot be homed as configured.

Example
-------
```
# file: achsmds1.lis
kopf.achs_nr                  1
kopf.log_achs_name            X1
kenngr.antr_typ               2          ( SERCOS: drive-controlled by default
```

```
# file: achsmds2.lis
kopf.achs_nr                  2
kopf.log_achs_name            X2
kenngr.antr_typ               2
kenngr.achs_mode              0x20001    ( LINEAR, gantry slave
kenngr.gantry_ax_nr           1          ( slave of X1
```

Use instead
-----------
Both lists home CNC-controlled, the zero pulse latched by the drive:

```
# file: achsmds1.lis
kopf.achs_nr                            1
kopf.log_achs_name                      X1
kenngr.antr_typ                         2
kenngr.homing.homing_type               CNC_CONTROLLED
antr.sercos.drive_supports_cnc_homing   1
antr.cnc_homing_encoder                 1
antr.sercos.cnc_homing_rt_bit_layout    16
```

```
# file: achsmds2.lis
kopf.achs_nr                            2
kopf.log_achs_name                      X2
kenngr.antr_typ                         2
kenngr.achs_mode                        0x20001
kenngr.gantry_ax_nr                     1
kenngr.homing.homing_type               CNC_CONTROLLED
antr.sercos.drive_supports_cnc_homing   1
antr.cnc_homing_encoder                 1
antr.sercos.cnc_homing_rt_bit_layout    16
```

Reference
---------
P-AXIS-00299 (homing types; SERCOS default DRIVE_CONTROLLED); CNC message P-ERR-50429; P-AXIS-00070
(gantry master axis number); TF5200 homing manual §2.3.3.4.5 (gantry coupling).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from ..core.diagnostics import Diagnostic, Related, Severity
from ..machine.startup import diagnostic, gantry_pairs

if TYPE_CHECKING:
    from ..machine.resolved import Machine
    from ..machine.startup import Member

CODE = "LIS511"
NAME = "gantry-drive-controlled-homing"
FIX = "none"
PARAMETERS = (
    "kenngr.homing.homing_type",
    "kenngr.gantry_ax_nr",
    "kopf.achs_nr",
)  # parameters this rule reads
SUMMARY = "Drive-controlled homing on a gantry pair"

DRIVE = "DRIVE_CONTROLLED"


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    members = machine.numbered()  # not by a template number TwinCAT repeats in every export
    slaves: dict[int, tuple[Member, list[Member]]] = {}  # by id of the master's summary
    for slave, master in gantry_pairs(members):
        if master is not None:
            slaves.setdefault(id(master[1]), (master, []))[1].append(slave)
        elif slave[1]["homing_type"] == DRIVE:
            yield _finding(
                slave,
                f"this gantry slave (its master kopf.achs_nr {slave[1]['gantry_ax_nr']} is not in "
                "the machine, so its own type counts)",
                [],
            )
    for master, coupled in slaves.values():
        if master[1]["homing_type"] == DRIVE:
            names = ", ".join(name for name, _ in coupled)
            related = [_slave(name, info) for name, info in coupled]
            yield _finding(master, f"this gantry master (slaves: {names})", related)


def _slave(name: str, info: dict[str, Any]) -> Related:
    line, column = info["gantry_at"] or (1, 1)
    return Related(name, line, column, "kenngr.gantry_ax_nr", "slave")


def _finding(member: Member, who: str, related: list[Related]) -> Diagnostic:
    written = member[1]["homing_type_at"]
    how = "" if written else " (kenngr.homing.homing_type not written in this list)"
    return diagnostic(
        CODE,
        member,
        "homing_type_at" if written else "achs_nr_at",
        f"{who} homes {DRIVE}{how}: the CNC refuses drive-controlled homing on a gantry axis (P-ERR-50429); "
        "home the pair CNC-controlled (or to a fixed stop), the same type in both lists",
        Severity.ERROR,
        related,
    )
