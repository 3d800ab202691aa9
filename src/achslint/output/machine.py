"""`dry-run hochlauf.lis --program rfp.nc` as JSON or text: a summary table per block and group, then each
axis's phases, then the sweep when `--sweep` asked for one.

The JSON document (`"version": 1, "kind": "machine dry-run"`) is described in docs/dry-run/machine.md.
Times are seconds from the program start; positions are per axis in its own unit (`axes[].unit`: mm, or
degrees on rotary axes and spindles); phase positions and `reference.position` are actual values before
homing (the scenario's frame), `final_position` is in the homed frame. On modulo axes (spindles, modulo
rotary axes) every position is shown within the modulo range, so a move's way is its `direction`, not the
difference of its positions. Numbers are always finite.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ..catalogue.units import unit_label
from ..dryrun import finite_document as _finite
from . import Screen, write_json
from .dryrun import json_number as _round
from .dryrun import number_text as _num
from .plot import write_plot

if TYPE_CHECKING:
    from rich.console import Console

    from ..machine.run import AxisPhase, AxisRun, BlockRun, MachineRun
    from . import Registry


@dataclass(frozen=True)
class MachineDryRun:
    """What the machine dry-run reports: the run, and the summary of `--sweep` when one was asked for."""

    run: MachineRun
    sweep: dict[str, Any] | None = None


OUTCOME_WORDS = {
    "homed": "homed",
    "failed": "FAILED",
    "aborted": "stopped (another axis failed)",
    "not_run": "not run",
    "skipped": "skipped by G74",
    "not_simulated": "not simulated",
    "not_commanded": "not commanded",
}


def _phase_json(phase: AxisPhase, axis: AxisRun) -> dict[str, Any]:
    r = _round
    shown = axis.shown
    return {
        "name": phase.name,
        "kind": phase.kind,
        "block": phase.block,
        "start_time": r(phase.start_time),
        "end_time": r(phase.end_time),
        "start_position": r(shown(phase.start_position)),
        "end_position": r(shown(phase.end_position)),
        "velocity": r(phase.velocity),
        "direction": phase.direction,
        "ended_by": phase.ended_by,
    }


def _axis_json(axis: AxisRun) -> dict[str, Any]:
    r = _round
    reference = axis.reference
    return {
        "name": axis.name,
        "logical_number": axis.logical_number,
        "unit": axis.unit,
        "spindle": axis.spindle,
        "strategy": {"id": axis.strategy.id, "description": axis.strategy.title},
        "gantry": None if axis.gantry is None else {"role": axis.gantry[0], "partner": axis.gantry[1]},
        "scenario": axis.scenario.as_dict(),
        "start_position": r(axis.shown(axis.start_position)),
        "position": r(axis.shown(axis.position)),
        "final_position": r(axis.final_position),
        "homed": axis.homed,
        "ends_moving": axis.ends_moving,
        "outcome": axis.outcome,
        "failure": axis.failure,
        "reference": None
        if reference is None
        else {
            "kind": reference["kind"],
            "position": r(axis.shown(reference["position"])),
            "value": r(reference["value"]),
            "time": r(reference["time"]),
        },
        "phases": [_phase_json(p, axis) for p in axis.phases],
        "warnings": axis.warnings,
    }


def _block_json(block: BlockRun) -> dict[str, Any]:
    r = _round
    return {
        "index": block.index,
        "line": block.at.line,
        "number": block.number,
        "kind": block.kind,
        "text": block.text,
        "axes": block.axes,
        "start_time": r(block.start_time),
        "end_time": r(block.end_time),
        "outcome": block.outcome,
        "note": block.note,
        "groups": [
            {
                "sequence": g.sequence,
                "axes": g.axes,
                "moving": g.moving,
                "still": g.still,
                "following": g.following,
                "start_time": r(g.start_time),
                "end_time": r(g.end_time),
                "outcome": g.outcome,
            }
            for g in block.groups
        ],
    }


def machine_json(run: MachineRun, sweep: dict[str, Any] | None = None) -> dict[str, Any]:
    failure = run.failure
    machine = run.machine
    document: dict[str, Any] = {
        "version": 1,
        "kind": "machine dry-run",
        "units": {"time": "s", "position": "per axis (axes[].unit)", "velocity": "per axis, unit/s"},
        "startup": str(machine.startup) if machine.startup else None,
        "channel": getattr(machine, "channel", None),
        "program": run.program.name,
        "cycle_time_ms": _round(run.cycle_time * 1000),
        "blocks": [_block_json(b) for b in run.blocks],
        "axes": [_axis_json(a) for a in run.axes.values()],
        "total_time": _round(run.total_time),
        "outcome": run.outcome,
        "failure": None
        if failure is None
        else {
            "axis": failure.axis,
            "reason": failure.reason,
            "cause": failure.cause,
            "code": failure.code,
            "time": _round(failure.time),
            "block": failure.block,
            "line": failure.at.line,
            "column": failure.at.column,
        },
        "warnings": run.warnings,
        "notes": list(getattr(machine, "notes", [])),  # what the machine left out or assumed (as explain)
    }
    if sweep is not None:
        document["sweep"] = sweep
    return _finite(document)


def as_json(report: MachineDryRun, screen: Screen) -> None:
    write_json(machine_json(report.run, report.sweep), screen, strict=True)


def plot(report: MachineDryRun, target: str) -> None:
    """The run's timeline (a lane per axis) and positions, written to `target` (PNG or SVG)."""
    from .plot import plot_machine

    write_plot(lambda file: plot_machine(report.run, file), target)


# --- text ---------------------------------------------------------------------------------------


def _time(value: float | None) -> str:
    return "" if value is None else _num(value, 3, fixed=True)


def _group_axes(axes: list[str], following: list[str], still: list[str]) -> str:
    shown = [f"{name} (still)" if name in still else name for name in axes]
    shown += [f"+{name}" for name in following if name not in axes]
    return " ".join(shown)


def as_text(report: MachineDryRun, screen: Screen) -> None:
    """The run as tables and lines for people, the sweep in words after it."""
    render_machine(report.run, screen.console)
    if report.sweep is not None:
        screen.console.print(sweep_words(report.sweep), markup=False, highlight=False)


def render_machine(run: MachineRun, console: Console) -> None:
    from rich import box
    from rich.table import Table
    from rich.text import Text

    machine = run.machine
    where = str(machine.startup) if machine.startup else "machine"
    channel = getattr(machine, "channel", None)
    console.print(
        Text(f"Machine {where}" + (f", channel {channel}" if channel else ""), style="bold")
        + Text(f" — program {run.program.name}, cycle {_num(run.cycle_time * 1000)} ms")
    )
    for note in getattr(machine, "notes", []):  # what the machine left out or assumed, as explain says it
        console.print(Text("note: ", style="yellow") + Text(note))
    assumed = sorted(
        {
            name
            for axis in run.axes.values()
            if any(p.kind == "homing" for p in axis.phases)
            for name in axis.scenario.assumed
            if name in ("cam", "zero_pulse_period", "zero_pulse_phase", "limit_switches", "start_position")
        }
    )
    if assumed:
        console.print(
            Text(
                f"Assumed (not given) for some axes: {', '.join(assumed)} — see each axis below, "
                "or give them in the machine scenario"
            )
        )
    table = Table(title="Program", title_justify="left", box=box.SIMPLE_HEAD, pad_edge=False)
    table.add_column("block", ratio=1, overflow="fold")
    table.add_column("line", no_wrap=True, justify="right")
    table.add_column("grp", no_wrap=True, justify="right")
    table.add_column("axes", overflow="fold")
    table.add_column("start s", no_wrap=True, justify="right")
    table.add_column("end s", no_wrap=True, justify="right")
    table.add_column("outcome", no_wrap=True)
    for block in run.blocks:
        style = {"failed": "red", "not_run": "dim", "not_simulated": "yellow"}.get(block.outcome, "")
        outcome = block.outcome.replace("_", " ")
        if not block.groups:
            table.add_row(
                Text(block.text),
                str(block.at.line),
                "",
                " ".join(block.axes),
                _time(block.start_time if block.outcome != "not_run" else None),
                _time(block.end_time if block.outcome != "not_run" else None),
                Text(outcome, style=style),
            )
            continue
        for number, group in enumerate(block.groups):
            group_style = {"failed": "red", "not_run": "dim"}.get(group.outcome, "")
            table.add_row(
                Text(block.text if number == 0 else ""),
                str(block.at.line) if number == 0 else "",
                str(group.sequence),
                _group_axes(group.axes, group.following, group.still),
                _time(group.start_time),
                _time(group.end_time),
                Text(group.outcome.replace("_", " "), style=group_style),
            )
    console.print(table)
    failure = run.failure
    if failure is None:
        console.print(Text(f"Total time {_num(run.total_time, 3)} s", style="bold green"))
    else:
        console.print(
            Text(f"FAILED at {_num(failure.time, 3)} s (line {failure.at.line}): ", style="bold red")
            + Text(failure.reason)
            + Text(f"; the program stops, total time {_num(run.total_time, 3)} s")
        )
    console.print(Text("Axes", style="bold"))
    for axis in run.axes.values():
        _render_axis(axis, console)
    shown = {w["message"] for axis in run.axes.values() for w in axis.warnings}
    for warning in run.warnings:
        if warning["message"] in shown:
            continue
        prefix = f"{warning['code']}: " if warning["code"] else "note: "
        line = f"line {warning['line']}: " if warning.get("line") else ""
        console.print(Text(prefix, style="yellow") + Text(line + warning["message"]))


def _render_axis(axis: AxisRun, console: Console) -> None:
    from rich.text import Text

    unit = unit_label(axis.unit)
    style = {"homed": "green", "failed": "red", "aborted": "red"}.get(axis.outcome, "yellow")
    role = f", gantry {axis.gantry[0]} of {axis.gantry[1]}" if axis.gantry else ""
    head = Text(f"{axis.name}", style="bold") + Text(
        f" (logical {axis.logical_number}{role}; {axis.strategy.title}): "
    )
    head += Text(OUTCOME_WORDS.get(axis.outcome, axis.outcome), style=style)
    if axis.reference is not None:
        ref = axis.reference
        head += Text(
            f" — reference {ref['kind']} at {_num(axis.shown(ref['position']))} {unit} becomes {_num(ref['value'])} {unit} "
            f"at {_num(ref['time'], 3)} s"
        )
    if axis.final_position is not None:
        moving = ", turning on" if axis.ends_moving else ""
        head += Text(f"; stands at {_num(axis.final_position)} {unit}{moving}")
    elif axis.outcome != "not_commanded" or axis.phases:
        head += Text(f"; stands at {_num(axis.shown(axis.position))} {unit} (actual value, not homed)")
    if axis.failure and axis.outcome in ("failed", "aborted"):
        head += Text(f" — {axis.failure}", style="red")
    console.print(head)
    for phase in axis.phases:
        sign = {"positive": "+", "negative": "-"}.get(phase.direction or "", " ")
        console.print(
            Text(
                f"  {_num(phase.start_time, 3, fixed=True):>9} - {_num(phase.end_time, 3, fixed=True):>9} s  "
                f"{sign} {_speed(phase.velocity):>8} {unit}/s  "
                f"{_num(axis.shown(phase.start_position), fixed=True)} -> "
                f"{_num(axis.shown(phase.end_position), fixed=True)} {unit}  "
            )
            + Text(phase.name)
            + Text(f"; {phase.ended_by}", style="dim")
        )
    for warning in axis.warnings:
        prefix = f"{warning['code']}: " if warning["code"] else "note: "
        console.print(Text("  ") + Text(prefix, style="yellow") + Text(warning["message"]))


def _speed(value: float) -> str:
    """A phase's speed to three decimals; one too slow for them keeps three significant digits (a move at
    F0.00001 runs at 1.67e-07 mm/s, not at 0)."""
    text = _num(value, 3)
    return f"{value:.3g}" if text == "0" and value else text


def sweep_words(summary: dict[str, Any]) -> str:
    """A machine sweep in words: completed and failed runs, the spread of the total time, failures per axis."""
    lines = []
    if summary["assumed_geometry"]:
        assumed = "; ".join(
            f"{axis}: {', '.join(names)}" for axis, names in summary["assumed_geometry"].items()
        )
        lines.append(
            f"NOTE: the sweep runs in an ASSUMED geometry ({assumed} not given): its failures and times describe "
            "the default scenario, not your machine. Give the real geometry in the machine scenario."
        )
    lines.append(
        f"Sweep of {summary['runs']} runs (every axis starts anywhere in its range): "
        f"{summary['completed']} completed, {summary['failed']} failed."
    )
    if "total_time" in summary:
        spread = summary["total_time"]
        lines.append(
            f"Total time between {_num(spread['min'], 3)} and {_num(spread['max'], 3)} s "
            f"(median {_num(spread['median'], 3)} s, spread {_num(spread['spread'], 3)} s)."
        )
    for entry in summary["failures"]:
        lines.append(f"  {entry['axis']} failed ×{entry['failed']}:")
        for reason in entry["reasons"]:
            lines.append(f"    {reason['reason']} ×{reason['count']}")
    return "\n".join(lines)


RENDERERS: Registry[MachineDryRun] = {"text": as_text, "json": as_json}
