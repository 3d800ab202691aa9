"""
What
----
A gantry coupling (`kenngr.gantry_ax_nr`) that has no master to lead it:
an axis that names its own logical axis number as its master, axes that name
each other as master (1 → 2 → 1, or longer circles), or a slave whose master
is itself the slave of a third axis.

Why
---
A gantry is one master and the slaves that follow it: `kenngr.gantry_ax_nr`
(P-AXIS-00070) of each slave holds the `kopf.achs_nr` (P-AXIS-00016) of the
master, and the master's own list has no `kenngr.gantry_ax_nr`. An axis that
follows itself, or axes that follow each other, leave the gantry without an
axis that moves on its own, and a slave of a slave is not a gantry the CNC
couples. No CNC message is documented for these settings, so what the
controller makes of them is not known; `dry-run` of the machine does not
simulate such axes and says why when a block names one of them.

Example
-------
```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X1
kenngr.gantry_ax_nr   2          ( the master is X2 ...
kenngr.achs_mode      0x20001
```

```
# file: achsmds2.lis
kopf.achs_nr          2
kopf.log_achs_name    X2
kenngr.gantry_ax_nr   1          ( ... and X2 names X1 back
kenngr.achs_mode      0x20001
```

Use instead
-----------
X1 leads: its list names no master, and X2 follows it (achsmds2.lis stays as
it is):

```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X1
```

Reference
---------
P-AXIS-00070 (logical axis number of the gantry master), P-AXIS-00016; TF5200
gantry manual (a gantry combination: one master axis, one or more slave axes).
No CNC error id is documented for a coupling without a master.
"""

from __future__ import annotations

from collections.abc import Hashable, Iterator, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Generic, TypeVar

from ..core.diagnostics import Diagnostic, Related, Severity
from ..machine.startup import diagnostic

if TYPE_CHECKING:
    from ..machine.resolved import Machine
    from ..machine.startup import Member

CODE = "LIS507"
NAME = "gantry-master-chain"
FIX = "none"
PARAMETERS = ("kenngr.gantry_ax_nr", "kopf.achs_nr")  # parameters this rule reads
SUMMARY = "Gantry slave that is its own master, masters that name each other, or a slave of a slave"

Axis = TypeVar("Axis", bound=Hashable)


@dataclass(frozen=True)
class CouplingFault(Generic[Axis]):
    """Why the coupling of one gantry slave has no master: `kind` "itself" (it names itself), "circle"
    (masters name each other) or "chain" (its master is a slave too). `members` are the axes involved: the
    circle (one tuple shared by all its axes, this slave at `first`), or the slave, its master and that
    master's master."""

    kind: str
    members: tuple[Axis, ...]
    first: int = 0

    def axes(self, limit: int) -> tuple[Axis, ...]:
        """At most `limit` axes from this slave on, each master after its slave (a circle does not come back
        to the slave)."""
        ahead = self.members[self.first : self.first + limit]
        return ahead + self.members[: max(limit - len(ahead), 0)][: self.first]


def coupling_faults(master_of: Mapping[Axis, Axis]) -> dict[Axis, CouplingFault[Axis]]:
    """The faults of a machine's gantry couplings, by slave, from each slave's master. Linear in the number
    of slaves, however long the circles (the machine dry-run asks the same about its programmed names)."""
    on_circle: dict[Axis, CouplingFault[Axis]] = {}
    done: set[Axis] = set()
    for start in master_of:
        path: list[Axis] = []
        where: dict[Axis, int] = {}
        axis = start
        while axis in master_of and axis not in done and axis not in where:
            where[axis] = len(path)
            path.append(axis)
            axis = master_of[axis]
        if axis in where:  # the walk came back to itself: the axes from there on form a circle
            circle = tuple(path[where[axis] :])
            for position, member in enumerate(circle):
                on_circle[member] = CouplingFault("circle", circle, position)
        done.update(path)
    faults: dict[Axis, CouplingFault[Axis]] = {}
    for slave, master in master_of.items():
        if master == slave:
            faults[slave] = CouplingFault("itself", (slave,))
        elif slave in on_circle:
            faults[slave] = on_circle[slave]
        elif master in master_of:
            faults[slave] = CouplingFault("chain", (slave, master, master_of[master]))
    return faults


SHOWN_AXES = 6  # a longer circle is shortened in messages


def circle_words(fault: CouplingFault[Axis]) -> str:
    """A circle of masters as words, from its slave back to it: `1 → 2 → 1`, `1 → 2 → … → 1 (20,000 axes)`."""
    slave = fault.members[fault.first]
    shown = [str(axis) for axis in fault.axes(SHOWN_AXES)]
    if len(fault.members) > SHOWN_AXES:
        return f"{' → '.join(shown)} → … → {slave} ({len(fault.members):,} axes)"
    return " → ".join([*shown, str(slave)])


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    members = machine.numbered()  # not by a template number TwinCAT repeats in every export
    by_number: dict[int, Member] = {}
    for member in members:
        if isinstance(member[1]["achs_nr"], int):
            by_number.setdefault(member[1]["achs_nr"], member)  # a repeated number is LIS501's
    master_of = {
        number: member[1]["gantry_ax_nr"]
        for number, member in by_number.items()
        if isinstance(member[1]["gantry_ax_nr"], int) and member[1]["gantry_ax_nr"] > 0
    }
    for number, fault in coupling_faults(master_of).items():
        member = by_number[number]
        master = master_of[number]
        if fault.kind == "itself":
            message = (
                f"kenngr.gantry_ax_nr {master} is this axis's own kopf.achs_nr: an axis cannot be its own gantry "
                "master; write the master's logical axis number, or remove the entry if the axis is no "
                "gantry slave"
            )
        elif fault.kind == "circle":
            message = (
                f"kenngr.gantry_ax_nr {master} makes axis {master} the gantry master of this axis, but the "
                f"masters name each other in a circle ({circle_words(fault)}), so no axis "
                "leads the gantry: remove kenngr.gantry_ax_nr from the list of the axis that is the master"
            )
        else:
            message = (
                f"kenngr.gantry_ax_nr {master} makes axis {master} the gantry master of this axis, but axis "
                f"{master} is itself the gantry slave of axis {fault.members[2]}: a master must not be a slave; "
                "name the axis that leads the gantry (the one whose list has no kenngr.gantry_ax_nr)"
            )
        related = []
        if fault.kind != "itself" and master in by_number:
            other = by_number[master]
            line, column = other[1]["gantry_at"] or other[1]["achs_nr_at"] or (1, 1)
            related.append(Related(other[0], line, column, "kenngr.gantry_ax_nr", "its master's coupling"))
        yield diagnostic(CODE, member, "gantry_at", message, Severity.ERROR, related)
