"""`achslint explain hochlauf.lis [--program rfp.nc]`: the axes of a machine and the order they home in.

`explain_machine` returns plain data (the CLI prints it as text or JSON): per axis its programmed name, its
logical number, its axis and drive type, the homing strategy the CNC runs (from the homing registry, after
the CNC's load-time corrections) and its part in a gantry; with a program, the homing order block by block
and the program findings (LIS6xx).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from .catalogue import AXIS_TYPE_NAMES
from .homing import classify
from .machinemodel import HomingBlock, Machine, MachineAxis, MoveBlock, Program, SkippedBlock
from .programlint import check_program, homed_from_start, homes_with_master

VERSION = 1


def _gantry(axis: MachineAxis, machine: Machine) -> dict[str, Any] | None:
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


def _axis(axis: MachineAxis, machine: Machine, gear: int) -> dict[str, Any]:
    values = axis.resolved
    strategy = classify(values, gear)
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
        "absolute": bool(values.get("kenngr.abs_pos_gueltig")),
        "gantry": _gantry(axis, machine),
        "corrections": [c.as_dict() for c in values.corrections],
    }


def _order(program: Program, machine: Machine) -> tuple[list[dict[str, Any]], dict[str, str]]:
    """The program's blocks as the homing order, and for each axis where it is homed (in words)."""
    blocks: list[dict[str, Any]] = []
    homed_by: dict[str, str] = {}
    for block in program.blocks:
        label = f"N{block.number}" if not isinstance(block, SkippedBlock) and block.number is not None else ""
        where = f"line {block.at.line}" + (f" ({label})" if label else "")
        if isinstance(block, HomingBlock):
            groups = []
            for step, (number, words) in enumerate(block.groups(), 1):
                names = [word.name for word in words]
                groups.append({"sequence": number, "axes": names})
                for name in names:
                    homed_by.setdefault(name, f"{where}, step {step}")
                    for axis in machine.axes.values():
                        if axis.gantry_master == name and homes_with_master(axis):
                            homed_by.setdefault(axis.name, f"{where}, step {step}, with its master {name}")
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
            blocks.append(
                {"line": block.at.line, "kind": "skipped", "text": block.text, "reason": block.reason}
            )
    return blocks, homed_by


def explain_machine(machine: Machine, program: Program | None = None, gear: int = 0) -> dict[str, Any]:
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
        blocks, homed_by = _order(program, machine)
        for row, axis in zip(axes, machine.axes.values(), strict=True):
            if axis.name in homed_by:
                row["homed"] = homed_by[axis.name]
            elif homed_from_start(axis):
                row["homed"] = "not needed: absolute position from power-up"
            else:
                row["homed"] = "not by this program"
        report["program"] = {
            "name": program.name,
            "blocks": blocks,
            "end_line": program.end.line if program.end else None,
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


def render_machine(report: dict[str, Any], console: Any) -> None:
    """The report as text: a table of the axes, then the homing order of the program."""
    from rich.table import Table
    from rich.text import Text

    where = (
        f"channel {report['channel']} ({report['channel_list']})" if report["channel_list"] else "axis lists"
    )
    console.print(Text(f"{report['startup']}", style="bold") + Text(f" — names from {where}"))
    program = report["program"]
    table = Table(show_lines=False)
    columns = ["name", "no.", "axis", "drive", "homing", "gantry"] + (["homed"] if program else [])
    for column in columns:
        table.add_column(column, overflow="fold")
    for row in report["axes"]:
        names = row["name"] + (
            f" ({row['log_achs_name']})"
            if row["log_achs_name"] and row["log_achs_name"].upper() != row["name"]
            else ""
        )
        cells = [
            names,
            str(row["logical_number"]),
            row["axis_type"],
            f"{row['drive_type']} {row['drive']}",
            f"{row['strategy']['title']} ({row['homing_type']})",
            _gantry_words(row["gantry"]),
        ]
        if program:
            cells.append(row.get("homed", ""))
        table.add_row(*cells)
    console.print(table)
    for row in report["other_axes"]:
        console.print(
            f"Not named in this channel: {row['list']} (logical axis {row['logical_number']}, "
            f"kopf.log_achs_name {row['log_achs_name']})"
        )
    for note in report["notes"]:
        console.print(Text("note: ", style="yellow") + Text(note))
    if program is None:
        return
    console.print(Text(f"Homing order of {program['name']}:", style="bold"))
    for block in program["blocks"]:
        label = f"line {block['line']}" + (f" N{block['number']}" if block.get("number") is not None else "")
        if block["kind"] == "homing":
            steps = "; then ".join(", ".join(group["axes"]) for group in block["groups"]) or "no axis"
            console.print(f"  {label}: G74 homes {steps}")
        elif block["kind"] == "move":
            targets = " ".join(f"{name}{value:g}" for name, value in block["targets"].items())
            mode = (
                "G00"
                if block["rapid"]
                else f"G01 F{block['feed_mm_min']:g}"
                if block["feed_mm_min"]
                else "G01"
            )
            console.print(f"  {label}: {mode} {'G90' if block['absolute'] else 'G91'} {targets}")
        else:
            console.print(f"  {label}: not simulated — {block['reason']}")
    for finding in program["findings"]:
        style = {"error": "red", "warning": "yellow"}.get(finding["severity"], "")
        console.print(
            Text(f"  {finding['code']} {finding['severity']}", style=style)
            + Text(f" line {finding['line']}:{finding['column']}: {finding['message']}")
        )


def _gantry_words(gantry: dict[str, Any] | None) -> str:
    if gantry is None:
        return ""
    if gantry["role"] == "master":
        return "master of " + ", ".join(gantry["slaves"])
    return f"slave of {gantry['master']}" + (" (homed with it)" if gantry["homes_with_master"] else "")


def explain_startup(
    startup: Path,
    *,
    program: Path | None = None,
    cnc_root: Path | None = None,
    channel: int = 1,
    gear: int = 0,
) -> dict[str, Any]:
    """`explain_machine` from files. Raises `MachineError` for the machine, `OSError` for the program."""
    from .files import Refused, not_a_list_file, read_program_file
    from .machinebuild import build_machine
    from .ncprogram import read_program

    machine = build_machine(startup, cnc_root=cnc_root, channel=channel)
    read = None
    if program is not None:
        problem = not_a_list_file(program)
        if problem is not None:
            raise Refused(f"{program}: {problem}")
        read = read_program(read_program_file(program), str(program))
    return explain_machine(machine, read, gear)
