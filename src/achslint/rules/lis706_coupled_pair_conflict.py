"""
What
----
Coupled pairs of a channel list (`synchro_data.koppel_gruppe[g].paar[i]`,
master `log_achs_nr_master` P-CHAN-00037, slave `log_achs_nr_slave`
P-CHAN-00038, kind `mode` P-CHAN-00061) that cannot all hold:

* a pair couples an axis to itself;
* a slave that an earlier pair of the same coupling group already couples to
  another master;
* pairs of one coupling group that close a circle (A leads B, B leads A; or
  longer);
* a pair whose `mode` says path axes (0) or spindles (1) while the channel
  list defines its master or slave as the other kind.

Why
---
A coupled pair makes its slave follow its master in synchronous operation.
An axis follows one master, and a master that in the end follows its own
slave has no axis leading the group, so in each of the first three cases at
least one pair is not what the machine does. Each coupling group
`koppel_gruppe[g]` is a coupling specification of its own, so two groups may
couple one axis to different masters. `mode` tells the CNC whether the
pair joins path axes of the axis group or spindles of the channel
(P-CHAN-00061); a pair of the other kind of slot joins axes the mode does not
describe. Which pair is meant only the machine builder knows, and the CNC's
reaction is not documented: a warning. (Pairs that contradict the static
gantry couplings of the axis lists are LIS515's.)

Example
-------
```
# file: sda_mds1.lis
gruppe[0].achse[0].bezeichnung                            X
gruppe[0].achse[0].log_achs_nr                            1
gruppe[0].achse[1].bezeichnung                            Y
gruppe[0].achse[1].log_achs_nr                            2
gruppe[0].achse[2].bezeichnung                            Z
gruppe[0].achse[2].log_achs_nr                            3
synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_master  1
synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_slave   2
synchro_data.koppel_gruppe[0].paar[1].log_achs_nr_master  3   ( Y follows X already
synchro_data.koppel_gruppe[0].paar[1].log_achs_nr_slave   2
```

Use instead
-----------
One master per slave:

```
# file: sda_mds1.lis
gruppe[0].achse[0].bezeichnung                            X
gruppe[0].achse[0].log_achs_nr                            1
gruppe[0].achse[1].bezeichnung                            Y
gruppe[0].achse[1].log_achs_nr                            2
gruppe[0].achse[2].bezeichnung                            Z
gruppe[0].achse[2].log_achs_nr                            3
synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_master  1
synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_slave   2
```

Reference
---------
P-CHAN-00037 / P-CHAN-00038 (master and slave of a coupled pair, synchronous
operation), P-CHAN-00061 (mode: 0 a pair of path axes, 1 a pair of spindle
axes), P-CHAN-00035 / P-CHAN-00036 (logical axis numbers of the path axes and
spindles). No CNC error id is documented for these contradictions.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ._kindvalues import entries, slots, whole, written

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS706"
NAME = "coupled-pair-conflict"
FIX = "none"
SUMMARY = "Coupled pairs of a channel list that cannot all hold (two masters, a circle, the wrong mode)"

_PAIRS = "synchro_data.koppel_gruppe[i].paar[i]."


@dataclass(frozen=True)
class _Pair:
    slot: str  # synchro_data.koppel_gruppe[0].paar[1]
    group: int  # the coupling group (koppel_gruppe[g]) the pair belongs to
    master: int
    slave: int
    master_at: Setting
    slave_at: Setting
    mode: Setting | None


def _pairs(ctx: Context) -> list[_Pair]:
    """The pairs the list writes with a master and a slave (0, the default, leaves a pair unused)."""
    found = []
    for indices, members in sorted(entries(written(ctx.settings), _PAIRS).items()):
        master_at, slave_at = members.get("log_achs_nr_master"), members.get("log_achs_nr_slave")
        master, slave = whole(master_at), whole(slave_at)
        if master_at is None or slave_at is None or not master or not slave:
            continue
        slot = "synchro_data.koppel_gruppe[{}].paar[{}]".format(*indices)
        found.append(_Pair(slot, indices[0], master, slave, master_at, slave_at, members.get("mode")))
    return found


def check(ctx: Context) -> Iterator[Diagnostic]:
    pairs = _pairs(ctx)
    # each coupling group is a coupling specification of its own (switched on as a whole): the masters, and
    # so the circles, are compared within a group
    masters: dict[int, dict[int, _Pair]] = {}
    for pair in pairs:
        master_of = masters.setdefault(pair.group, {})
        if pair.master == pair.slave:
            yield _report(
                ctx,
                pair.slave_at,
                f"{pair.slot} couples logical axis {pair.slave} to itself: a pair joins two axes; give the "
                "slave's logical axis number, or remove the pair",
            )
            continue
        earlier = master_of.get(pair.slave)
        if earlier is not None and earlier.master != pair.master:
            yield _report(
                ctx,
                pair.slave_at,
                f"{pair.slot} makes logical axis {pair.slave} follow axis {pair.master}, but {earlier.slot} "
                f"already couples it to axis {earlier.master}: an axis follows one master; remove one of the "
                "pairs",
                earlier.slave_at,
                "the earlier pair",
            )
            continue
        master_of.setdefault(pair.slave, pair)
        circle = _circle(pair, master_of)
        if circle:
            yield _report(
                ctx,
                pair.slave_at,
                f"{pair.slot} closes a circle of coupled pairs (logical axes {' → '.join(str(n) for n in circle)}, "
                "each leading the next): every axis of it follows another, so none leads the group; remove the "
                "pair that makes a master a follower",
            )
    yield from _modes(ctx, pairs)


def _circle(pair: _Pair, master_of: dict[int, _Pair]) -> list[int]:
    """The logical axis numbers of the circle the pair closes, from its master, each leading the next and the
    last the first again (`[2, 1, 2]`: 2 leads 1, 1 leads 2), or [] when it closes none."""
    chain = [pair.slave, pair.master]
    number = pair.master
    while number in master_of:
        number = master_of[number].master
        if number == pair.slave:  # chain: the slave, its new master, that master's master ...
            leads = [pair.master, pair.slave, *reversed(chain[2:])]
            return [*leads, pair.master]
        if number in chain:
            return []  # a circle this pair is not part of (reported when it was closed)
        chain.append(number)
    return []


def _modes(ctx: Context, pairs: list[_Pair]) -> Iterator[Diagnostic]:
    """Pairs whose mode (P-CHAN-00061) says path axes or spindles while a coupled axis is a slot of the
    other kind in this channel list."""
    kinds: dict[int, bool] = {}
    for slot in slots(written(ctx.settings)):
        if slot.logical_number is not None:
            kinds.setdefault(slot.logical_number, slot.spindle)  # both kinds: LIS701's finding
    for pair in pairs:
        spindles = whole(pair.mode) == 1
        said = "spindles (mode 1)" if spindles else "path axes (mode 0)"
        if pair.mode is None:
            said = "path axes (mode 0, its default)"
        roles = (("master", pair.master, pair.master_at), ("slave", pair.slave, pair.slave_at))
        wrong = [
            (role, number, at) for role, number, at in roles if kinds.get(number) not in (None, spindles)
        ]
        if not wrong:
            continue
        what = "path axes" if spindles else "spindles"
        remedy = f"set {pair.slot}.mode to {0 if spindles else 1}, or couple axes of the kind the mode names"
        if len(wrong) == 2:
            whose = f"its master and slave, logical axes {pair.master} and {pair.slave}, are {what}"
        else:
            role, number, _ = wrong[0]
            whose = f"its {role}, logical axis {number}, is {'a path axis' if spindles else 'a spindle'}"
            other = pair.slave if role == "master" else pair.master
            if kinds.get(other) == spindles:  # the other axis is of the mode's kind: no mode fits both
                remedy = "a pair joins two path axes or two spindles, so couple axes of one kind"
        yield _report(
            ctx,
            wrong[0][2],
            f"{pair.slot} is a pair of {said}, but {whose} of this channel list: {remedy}",
            pair.mode,
            "the mode",
        )


def _report(
    ctx: Context, at: Setting, message: str, other: Setting | None = None, note: str = ""
) -> Diagnostic:
    start, end = ctx.value_span(at.line)
    related = [ctx.related(other, note)] if other is not None and note else []
    return ctx.report(CODE, at.line, message, column=start, end_column=end, setting=at, related=related)
