"""
What
----
A coupled pair of the channel list
(`synchro_data.koppel_gruppe[g].paar[i].log_achs_nr_master` and
`.log_achs_nr_slave`, P-CHAN-00037 / P-CHAN-00038) that contradicts the static
gantry couplings of the axis lists (`kenngr.gantry_ax_nr`, P-AXIS-00070) in one
of three ways:

* the pair repeats a static gantry: its slave's axis list already couples it
  to the pair's master;
* the pair gives its slave another master than the slave's axis list does;
* the pair's master is itself the slave of a static gantry.

Why
---
The two couplings are different things. A static gantry
(`kenngr.gantry_ax_nr`) is made at start-up in the position controller; its
slave belongs to no channel and moves when its master moves. A coupled pair
of the channel list joins two axes of the channel's axis group (or two
spindles of the channel) for synchronous operation. An axis cannot be both a
static gantry slave and a channel axis that a pair couples, and an axis
follows one master, so one of the two settings is not what the machine does.
Which one is meant only the machine builder knows; the CNC's reaction is not
documented, hence a warning.

Example
-------
```
# file: hochlauf.lis
zahl_mds          3
achs_mds[0]       ./achsmds1.lis
achs_mds[1]       ./achsmds2.lis
achs_mds[2]       ./achsmds3.lis
sda_mds[0]        ./sda_mds1.lis
```

```
# file: achsmds1.lis
kopf.achs_nr          1
kopf.log_achs_name    X
```

```
# file: achsmds2.lis
kopf.achs_nr          2
kopf.log_achs_name    Y
kenngr.achs_mode      0x10001    ( LINEAR | GANTRY_MASTER
```

```
# file: achsmds3.lis
kopf.achs_nr          3
kopf.log_achs_name    Y2
kenngr.achs_mode      0x20001    ( LINEAR | GANTRY_SLAVE
kenngr.gantry_ax_nr   2
```

```
# file: sda_mds1.lis
gruppe[0].achse[0].bezeichnung                          X
gruppe[0].achse[0].log_achs_nr                          1
gruppe[0].achse[1].bezeichnung                          Y
gruppe[0].achse[1].log_achs_nr                          2
synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_master  1   ( X leads axis 3 here,
synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_slave   3   ( but axis 3 follows Y
```

Use instead
-----------
The static gantry alone: its slave needs no pair (remove the pair):

```
# file: sda_mds1.lis
gruppe[0].achse[0].bezeichnung                          X
gruppe[0].achse[0].log_achs_nr                          1
gruppe[0].achse[1].bezeichnung                          Y
gruppe[0].achse[1].log_achs_nr                          2
```

Reference
---------
P-CHAN-00037 / P-CHAN-00038 (master and slave of a coupled pair; synchronous
operation joins axes of the channel's axis group or spindles of the channel),
P-CHAN-00061 (mode of the pair), P-AXIS-00070 (kenngr.gantry_ax_nr: static
gantry coupling, the slave is not known in the channel), P-AXIS-00016; TF5200
gantry manual. No CNC error id is documented for these contradictions.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..core.diagnostics import Diagnostic, Related, Severity
from ._crosslist import at_member, by_number
from .lis507_gantry_master_chain import coupling_faults

if TYPE_CHECKING:
    from ..machine.channel import CoupledPair
    from ..machine.resolved import Machine
    from ..machine.startup import Member

CODE = "LIS515"
NAME = "coupled-pair-vs-gantry"
FIX = "none"
PARAMETERS = ("kenngr.gantry_ax_nr", "kopf.achs_nr")  # parameters this rule reads
SUMMARY = "Coupled pair of the channel list that contradicts the axis lists' gantry coupling"


def _master_of(member: Member | None) -> int:
    """The static gantry master an axis list names (0: none)."""
    if member is None:
        return 0
    number = member[1].get("gantry_ax_nr")
    return number if isinstance(number, int) and not isinstance(number, bool) and number > 0 else 0


def _contradiction(
    pair: CoupledPair, numbers: dict[int, Member], names: dict[int, str]
) -> tuple[str, Member] | None:
    """What the pair contradicts, in words, with the axis list that says otherwise; None when nothing.
    `names` are the channel's names of logical axes, shown beside the numbers."""

    def axis(number: int) -> str:
        return f"axis {number} (`{names[number]}`)" if number in names else f"axis {number}"

    pair_words = f"{pair.slot} couples {axis(pair.slave)} to master {axis(pair.master)}"
    slave, master = numbers.get(pair.slave), numbers.get(pair.master)
    static = _master_of(slave)
    if slave is not None and static == pair.master:
        return (
            f"{pair_words}, which {slave[0]} already makes a static gantry (kenngr.gantry_ax_nr "
            f"{static}): a static gantry's slave is in no channel, while a coupled pair joins axes of the "
            "channel, so the two couplings contradict each other; remove the pair (a static gantry needs "
            "none), or remove kenngr.gantry_ax_nr if the channel is to couple the axes",
            slave,
        )
    if slave is not None and static and static != pair.slave:
        return (
            f"{pair_words}, but {slave[0]} couples it to {axis(static)} as a static gantry "
            f"(kenngr.gantry_ax_nr {static}): an axis follows one master; make the pair and the axis list "
            "name the same master, or remove one of the two couplings",
            slave,
        )
    leader = _master_of(master)
    if master is not None and leader and leader != pair.master:
        return (
            f"{pair_words}, but {master[0]} makes that master the static gantry slave of {axis(leader)} "
            f"(kenngr.gantry_ax_nr {leader}): a static gantry slave is in no channel and follows its "
            "own master, so it cannot lead a pair; make the pair's master a channel axis of its own",
            master,
        )
    return None


def check_machine(machine: Machine) -> Iterator[Diagnostic]:
    members = machine.members
    numbers = by_number(members)
    # An axis whose static coupling is in a circle or a chain is LIS507's (as in LIS514): that finding says no
    # axis leads it, so "already a static gantry" or "its own master" would contradict it.
    tangled = set(
        coupling_faults({number: master for number in numbers if (master := _master_of(numbers[number]))})
    )
    for _, channel in machine.channel_lists():
        names = {axis.logical_number: axis.name for axis in reversed(channel.axes)}
        master_of: dict[int, int] = {}  # by the channel's pairs so far
        for pair in channel.pairs:
            if pair.master == pair.slave or tangled & {pair.master, pair.slave}:
                continue  # a pair of one axis (not about the axis lists), or a coupling LIS507 reports
            if master_of.setdefault(pair.slave, pair.master) != pair.master:
                continue  # the channel gives the slave a second master itself: LIS706's finding
            found = _contradiction(pair, numbers, names)
            if found is None:
                continue
            message, member = found
            related: list[Related] = [at_member(member, "gantry_at", "kenngr.gantry_ax_nr", "static gantry")]
            end = pair.at.end_column or pair.at.column + 1
            yield Diagnostic(
                pair.at.path,
                pair.at.line,
                pair.at.column,
                pair.at.line,
                end,
                CODE,
                Severity.WARNING,
                message,
                related=tuple(related),
            )
