"""`achslint explain hochlauf.lis [--program rfp.nc]`: the axes of a machine and the order they home in.

`explain_machine` returns plain data (output/explain.py renders it as text or JSON): per axis its programmed name, its
logical number, its axis and drive type, the homing strategy the CNC runs at power-up and the one a G74 that
names it runs (from the homing registry, after the CNC's load-time corrections) and its part in a gantry; with a program, the homing order block by block
and the program findings (LIS6xx). A gantry slave the channel does not name is among the other axes, shown
as its master's slave (with where the program homes it), never as an axis a program may name.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..catalogue import AXIS_TYPE_NAMES
from ..homing import classify
from ..linting.program import check_program
from ..rules.programcontext import g74_words, homed_from_start, homes_with_master, named_words
from .model import ChannelView, HomingBlock, MachineAxis, MoveBlock, Program, SkippedBlock

VERSION = 1


def _gantry(axis: MachineAxis, machine: ChannelView) -> dict[str, Any] | None:
    slaves = [slave for master, slave in machine.gantry_pairs if master == axis.name]
    if axis.gantry_master is not None:
        return {
            "role": "slave",
            "master": axis.gantry_master,
            "homes_with_master": homes_with_master(axis),
        }
    if slaves:
        return {"role": "master", "slaves": slaves}
    return None


def _axis(axis: MachineAxis, machine: ChannelView, gear: int) -> dict[str, Any]:
    values = axis.resolved
    strategy = classify(values, gear)
    commanded = classify(values, gear, commanded=True)
    log_name = values.get("kopf.log_achs_name")
    return {
        "name": axis.name,
        "log_achs_name": log_name,
        "logical_number": axis.logical_number,
        "channel": axis.channel,
        "list": str(axis.list_path) if axis.list_path else None,
        "name_defined_at": (
            {"path": axis.defined_at.path, "line": axis.defined_at.line} if axis.defined_at else None
        ),
        "axis_type": "spindle" if axis.spindle else AXIS_TYPE_NAMES[values.axis_type],
        "drive_type": values.drive_type,
        "drive": values.drive_name(),
        "homing_type": values.homing_type,
        "homing_type_set": not values.homing_type_is_default,
        "strategy": {"id": strategy.id, "title": strategy.title},
        "commanded": {"id": commanded.id, "title": commanded.title},  # what a G74 that names the axis runs
        "absolute": bool(values.get("kenngr.abs_pos_gueltig")),
        "gantry": _gantry(axis, machine),
        "corrections": [c.as_dict() for c in values.corrections],
    }


def _order(
    program: Program, machine: ChannelView
) -> tuple[list[dict[str, Any]], dict[str, str], str | None, SkippedBlock | None]:
    """The program's blocks as the homing order, for each axis where it is homed (in words), where the CNC
    stops the program (None when it runs to its end), and the first block the reader does not follow.

    The CNC stops at a block naming an axis the channel does not have (LIS602: nothing of that block runs), at a
    G74 naming an axis twice (LIS603: nothing of it runs either) and at the sequence step of a DISABLED axis
    (LIS604, P-ERR-50686: the steps before it have run); nothing is homed from there on, as in the dry-run.
    An IGNORE_ABS_POS axis a G74 names is passed over, not homed (P-AXIS-00299, LIS607). After a block the reader does not follow (a subroutine call, `$IF`, `$GOTO`, …)
    a later G74 homes its axes only perhaps: whether the program gets there is not known (as in LIS606)."""
    blocks: list[dict[str, Any]] = []
    homed_by: dict[str, str] = {}
    stopped: str | None = None
    halted = False  # a block that stops the program, perhaps after a part not followed
    unfollowed: SkippedBlock | None = None
    followers = machine.followers()

    def home(name: str, at: str) -> None:
        def said(where: str) -> str:
            if unfollowed is None:
                return where
            return f"perhaps: {where} (the program is not followed past {_shown(unfollowed)})"

        if classify(machine.axes[name].resolved, commanded=True).definition.skipped_by_g74:
            return  # passed over: its position comes from its absolute encoder
        homed_by.setdefault(name, said(at))
        for axis in [*machine.axes.values(), *followers]:
            if axis.gantry_master != name:
                continue
            if homes_with_master(axis):
                homed_by.setdefault(axis.name, said(f"{at}, with its master {name}"))
            elif axis.name not in machine.axes:  # outside the channel: its own homing follows
                homed_by.setdefault(axis.name, said(f"{at}, after its master {name}"))

    def stop(where: str) -> None:
        nonlocal stopped, halted
        if not halted and unfollowed is None:
            stopped = where
        halted = True

    for block in program.blocks:
        label = f"N{block.number}" if not isinstance(block, SkippedBlock) and block.number is not None else ""
        where = f"line {block.at.line}" + (f" ({label})" if label else "")
        named = named_words(block)
        if any(word.name not in machine.axes for word in named):
            stop(where)
        if isinstance(block, (HomingBlock, SkippedBlock)):  # an axis named twice in a G74 (LIS603)
            homes = block.words if isinstance(block, HomingBlock) else block.homes
            if len({word.name for word in homes}) < len(homes):
                stop(where)
        if isinstance(block, HomingBlock):
            groups = []
            for step, (number, words) in enumerate(block.groups(), 1):
                names = [word.name for word in words]
                groups.append({"sequence": number, "axes": names})
                if not halted and any(_refuses_g74(machine.axes[name]) for name in names):
                    stop(f"{where}, step {step}")
                if halted:
                    continue
                for name in names:
                    home(name, f"{where}, step {step}")
            blocks.append({"line": block.at.line, "number": block.number, "kind": "homing", "groups": groups})
        elif isinstance(block, MoveBlock):
            blocks.append(
                {
                    "line": block.at.line,
                    "number": block.number,
                    "kind": "move",
                    "rapid": block.rapid,
                    "absolute": block.absolute,
                    "feed_mm_min": block.feed_mm_min,
                    "targets": {word.name: word.value for word in block.targets},
                }
            )
        else:
            if block.homes and not halted:  # a G74 whose order is computed: it homes its axes all the same
                if any(_refuses_g74(machine.axes[word.name]) for word in block.homes):
                    stop(where)
                else:
                    for word in block.homes:
                        home(word.name, f"{where}, in an order computed when the program runs")
            if block.unfollowed and unfollowed is None:
                unfollowed = block
            blocks.append(
                {"line": block.at.line, "kind": "skipped", "text": block.text, "reason": block.reason}
            )
    return blocks, homed_by, stopped, unfollowed


def _shown(block: SkippedBlock) -> str:
    """A block the reader does not follow, as the homing order names it: line 6: `N45 LL SUB`."""
    text = block.text if len(block.text) <= 40 else f"{block.text[:37]}…"
    return f"line {block.at.line}: `{text}`"


def _refuses_g74(axis: MachineAxis) -> bool:
    """Whether a G74 naming the axis ends with an error (homing DISABLED)."""
    return classify(axis.resolved, commanded=True).definition.refuses_g74


def explain_machine(machine: ChannelView, program: Program | None = None, gear: int = 0) -> dict[str, Any]:
    """Everything `explain hochlauf.lis` shows, as JSON-ready data."""
    axes = [_axis(axis, machine, gear) for axis in machine.axes.values()]
    report: dict[str, Any] = {
        "version": VERSION,
        "startup": str(machine.startup) if machine.startup else None,
        "channel": machine.channel,
        "channel_list": str(machine.channel_list) if machine.channel_list else None,
        "axes": axes,
        "other_axes": [_axis(axis, machine, gear) for axis in machine.other_axes],
        "gantry_pairs": [{"master": master, "slave": slave} for master, slave in machine.gantry_pairs],
        "notes": list(machine.notes),
        "program": None,
    }
    if program is not None:
        blocks, homed_by, stopped, unfollowed = _order(program, machine)
        named = {word.name for words in g74_words(program) for word in words}
        # After a call any axis may be homed; after a branch or jump only one that some G74 homes.
        anything = any(isinstance(b, SkippedBlock) and b.unfollowed == "any" for b in program.blocks)
        rows = [*zip(axes, machine.axes.values(), strict=True)]
        others = zip(report["other_axes"], machine.other_axes, strict=True)
        rows += [(row, axis) for row, axis in others if axis.gantry_master is not None]  # moved by a master
        for row, axis in rows:
            if axis.name in homed_by:
                row["homed"] = homed_by[axis.name]
            elif homed_from_start(axis):
                row["homed"] = "not needed: absolute position from power-up"
            elif stopped is not None and (axis.name in named or axis.gantry_master in named):
                row["homed"] = f"not: the CNC stops the program at {stopped} first"
            elif unfollowed is not None and (anything or axis.name in named or axis.gantry_master in named):
                row["homed"] = f"not known: the program is not followed past {_shown(unfollowed)}"
            else:
                row["homed"] = "not by this program"
        report["program"] = {
            "name": program.name,
            "blocks": blocks,
            "end_line": program.end.line if program.end else None,
            # the first block the reader does not follow (a call, `$IF`, …), from which on the order is not known
            "unfollowed": None
            if unfollowed is None
            else {"line": unfollowed.at.line, "text": unfollowed.text, "reason": unfollowed.reason},
            "findings": [
                {
                    "line": d.line,
                    "column": d.column,
                    "code": d.code,
                    "severity": d.severity.value,
                    "message": d.message,
                }
                for d in check_program(program, machine)
            ],
        }
    return report


def explain_startup(
    startup: Path,
    *,
    program: Path | None = None,
    cnc_root: Path | None = None,
    channel: int = 1,
    gear: int = 0,
) -> dict[str, Any]:
    """`explain_machine` from files. Raises `MachineError` for the machine, `OSError` for the program."""
    from ..core.files import Refused, not_a_list_file, read_program_file
    from .build import build_machine
    from .program import read_program

    machine = build_machine(startup, cnc_root=cnc_root, channel=channel)
    read = None
    if program is not None:
        problem = not_a_list_file(program)
        if problem is not None:
            raise Refused(f"{program}: {problem}")
        read = read_program(read_program_file(program), str(program))
    return explain_machine(machine, read, gear)
