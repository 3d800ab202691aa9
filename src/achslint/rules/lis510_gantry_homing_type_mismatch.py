"""
What
----
A gantry slave (`kenngr.gantry_ax_nr`) whose homing type differs from its
master's, both taken as the CNC runs them: the written
`kenngr.homing.homing_type` after the CNC's corrections, or the drive type's
default when it is not set.

Why
---
Master and slave of a gantry are one mechanical axis and must home the same
way; `kenngr.homing.homing_type` is among the parameters the two lists must
agree on. When they differ the CNC warns at start-up, homes the pair with the
master's value and reports P-ERR-70263 — the slave's own setting is not what
runs. `dry-run` of the slave's list alone cannot know its master and simulates
the slave's own type; this finding says which type the CNC uses.

Example
-------
```
# file: achsmds1.lis
kopf.achs_nr                  1
kopf.log_achs_name            X1
kenngr.antr_typ               1          ( conventional drive
kenngr.homing.homing_type     CNC_CONTROLLED
lr_hw[0].cam_direct_access    0
```

```
# file: achsmds2.lis
kopf.achs_nr                  2
kopf.log_achs_name            X2
kenngr.antr_typ               1
kenngr.achs_mode              0x20001    ( LINEAR, gantry slave
kenngr.gantry_ax_nr           1          ( slave of X1
kenngr.homing.homing_type     TORQ
```

Use instead
-----------
With achsmds1.lis as it is, the slave homes as its master does:

```
# file: achsmds2.lis
kopf.achs_nr                  2
kopf.log_achs_name            X2
kenngr.antr_typ               1
kenngr.achs_mode              0x20001
kenngr.gantry_ax_nr           1
kenngr.homing.homing_type     CNC_CONTROLLED
lr_hw[0].cam_direct_access    0
```

Reference
---------
P-AXIS-00070 (master and slave must agree in P-AXIS-00299 among others; otherwise a start-up warning and
the master's values), P-AXIS-00299; CNC message P-ERR-70263; TF5200 homing manual §2.3.3.4.5 (gantry coupling).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Related, Severity
from ..machine.startup import diagnostic, gantry_pairs

if TYPE_CHECKING:
    from ..machine.resolved import Machine
    from ..machine.startup import Member

CODE = "LIS510"
NAME = "gantry-homing-type-mismatch"
FIX = "none"
PARAMETERS = (
    "kenngr.homing.homing_type",
    "kenngr.gantry_ax_nr",
    "kopf.achs_nr",
)  # parameters this rule reads
SUMMARY = "Gantry master and slave with different homing types"


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    members = machine.numbered()  # not by a template number TwinCAT repeats in every export
    for slave, master in gantry_pairs(members):
        if master is None or slave[1]["homing_type"] == master[1]["homing_type"]:
            continue
        line, column = master[1]["homing_type_at"] or master[1]["achs_nr_at"] or (1, 1)
        yield diagnostic(
            CODE,
            slave,
            "homing_type_at" if slave[1]["homing_type_at"] else "gantry_at",
            f"this gantry slave homes {homing(slave)}, its master {master[0]} (kopf.achs_nr "
            f"{master[1]['achs_nr']}) {homing(master)}: master and slave must use the same homing type "
            f"(P-AXIS-00070); the CNC homes the pair with the master's type and reports P-ERR-70263. {advice(master)}",
            Severity.ERROR,
            [Related(master[0], line, column, "kenngr.homing.homing_type", "master")],
        )


def advice(master: Member) -> str:
    kind = master[1]["homing_type"]
    if kind == "DRIVE_CONTROLLED":  # what the master runs is itself refused for a gantry (LIS511)
        return "Choose one homing type other than DRIVE_CONTROLLED for both lists (P-ERR-50429, LIS511)"
    return f"Use {kind} in both lists"


def homing(member: Member) -> str:
    """`with TORQ`, or `with DRIVE_CONTROLLED (kenngr.homing.homing_type not written in its list)`."""
    info = member[1]
    unset = "" if info["homing_type_at"] else " (kenngr.homing.homing_type not written in its list)"
    return f"with {info['homing_type']}{unset}"
