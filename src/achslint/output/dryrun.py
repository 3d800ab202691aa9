"""`achslint dry-run LIST` as text or JSON: the simulated homing of one axis, then the sweep when `--sweep`
asked for one; `--plot` draws the same run.

JSON (version 1): {"version", "axis": {..., "acceleration", "acceleration_source"},
"strategy": {"id", "description"}, "scenario", "phases": [{"name", "direction",
"velocity", "start_position", "end_position", "start_time", "end_time",
"ended_by"}], "events": [{"time", "position", "kind"}], "reference": {"kind",
"position", "value", "speed", "time", "armed_at", "cam_zero_pulse_offset"} |
null, "final_position", "ends_moving",
"total_time", "total_distance", "outcome" ("homed", "failed", "not_required",
"skipped" or "not_simulated": a mode the simulator does not cover, with a note),
"failure" (a failed search names the bound with its value and what it searched
for, and where), "warnings": [{"code", "message"}], "corrections", "units"}. Positions are mm (degrees for rotary
axes and spindles), velocities per second, times in seconds; phase and event
positions are in the scenario frame (actual values before homing, continuous:
on a modulo axis they keep counting past the modulo range so a revolution
shows as 360°), `reference.position` (wrapped into the modulo range),
`reference.value` and `final_position` in the homed frame. The engineering
numbers of the reference: `time` (seconds after the homing start), `armed_at`
(where the zero-pulse logic of §2.6 was armed, wrapped like `position`; null
when the reference is no zero pulse) and `cam_zero_pulse_offset` (the distance
from where the cam was operated to that zero pulse along the homing direction,
shift included: what the CNC object "reference cam - zero pulse offset" reads
after homing, §2.6; null without a cam). Numbers are always finite: the JSON
never contains NaN or Infinity.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ..axis.resolved import plain
from ..catalogue.units import unit_label
from ..dryrun import finite_document
from . import Screen, write_json
from .plot import write_plot

if TYPE_CHECKING:
    from rich.console import Console

    from ..dryrun import DryRun
    from . import Registry


@dataclass(frozen=True)
class AxisDryRun:
    """What the dry-run of one axis reports: the run, and the summary of `--sweep` when one was asked for."""

    run: DryRun
    sweep: dict[str, Any] | None = None


def as_text(report: AxisDryRun, screen: Screen) -> None:
    """The scenario, the phases and events as tables, the outcome; the sweep in words after them."""
    render(report.run, screen.console)
    if report.sweep is not None:
        screen.console.print(sweep_words(report.sweep), markup=False, highlight=False)


def as_json(report: AxisDryRun, screen: Screen) -> None:
    """The trace document (its keys in the module docstring), with the sweep under `sweep`."""
    document = trace_json(report.run)
    if report.sweep is not None:
        document["sweep"] = report.sweep
    write_json(document, screen, strict=True)


def plot(report: AxisDryRun, target: str) -> None:
    """The run's position and velocity over time, written to `target` (PNG or SVG)."""
    from .plot import plot_trace

    write_plot(lambda file: plot_trace(report.run.trace, file), target)


# --- JSON ------------------------------------------------------------------------------------


def json_number(value: float | None) -> float | None:
    return None if value is None or not math.isfinite(value) else round(value, 9)


def trace_json(run: DryRun) -> dict[str, Any]:
    """The dry-run as JSON (the schema is in the module docstring)."""
    trace = run.trace
    values = run.values
    r = json_number  # keep JSON free of float noise
    return finite_document(
        {
            "version": 1,
            "units": {
                "position": trace.unit,
                "velocity": f"{trace.unit}/s",
                "time": "s",
                "acceleration": f"{trace.unit}/s^2",
            },
            "axis": {
                "name": values.get("kopf.log_achs_name"),
                "axis_type": values.axis_type,
                "drive_type": values.drive_type,
                "homing_type": values.homing_type,
                "acceleration": r(trace.acceleration),
                "acceleration_source": trace.acceleration_source,
            },
            "strategy": {"id": trace.strategy.id, "description": trace.strategy.title},
            "scenario": trace.scenario.as_dict(),
            "phases": [
                {
                    "name": p.name,
                    "direction": p.direction,
                    "velocity": r(p.velocity),
                    "start_position": r(p.start_position),
                    "end_position": r(p.end_position),
                    "start_time": r(p.start_time),
                    "end_time": r(p.end_time),
                    "ended_by": p.ended_by,
                }
                for p in trace.phases
            ],
            "events": [{"time": r(e.time), "position": r(e.position), "kind": e.kind} for e in trace.events],
            "reference": None
            if trace.reference is None
            else {
                "kind": trace.reference["kind"],
                "position": r(trace.reference["position"]),
                "value": r(trace.reference["value"]),
                "speed": r(trace.reference["speed"]),
                "time": r(trace.reference["time"]),
                "armed_at": None if trace.arming is None else r(run.simulator.wrap(trace.arming.armed)),
                "cam_zero_pulse_offset": r(trace.cam_zero_pulse_offset),
            },
            "final_position": r(trace.final_position),
            "ends_moving": trace.ends_moving,
            "total_time": r(trace.total_time),
            "total_distance": r(trace.total_distance),
            "outcome": trace.outcome,
            "failure": trace.failure,
            "warnings": trace.warnings,
            "corrections": [c.as_dict() for c in values.corrections],
        }
    )


# --- text ------------------------------------------------------------------------------------


def number_text(value: float, digits: int = 4, fixed: bool = False) -> str:
    """A number for the text output: `digits` decimals (trailing zeros dropped unless `fixed`, for columns).
    Rounded to 9 decimals first, as `--format json` and the report round: 6.30249999… shows as 6.3025 does."""
    text = f"{round(value, 9):.{digits}f}"
    if text.startswith("-") and float(text) == 0:
        text = text[1:]
    return text if fixed or "." not in text else text.rstrip("0").rstrip(".")


def header_lines(run: DryRun) -> list[str]:
    """The scenario as far as the run reads it (an absolute axis: its valid position instead), what was
    assumed, and the homing acceleration of an axis that moves."""
    trace = run.trace
    unit = unit_label(trace.unit)
    scenario = trace.scenario
    uses = scenario.uses
    parts = [f"start {number_text(scenario.start_position)} {unit}"]
    if scenario.start_velocity:
        parts[0] += f" turning at {scenario.start_velocity:+g} {unit}/s (endless rotation)"
    if scenario.cam is not None:
        parts.append(f"cam [{number_text(scenario.cam[0])}, {number_text(scenario.cam[1])}]")
    elif "cam" in uses:
        parts.append("cam none")
    if "zero_pulse" in uses:
        parts.append(
            f"zero pulse every {number_text(scenario.zero_pulse_period)} {unit} "
            f"(one at {number_text(scenario.zero_pulse_phase)})"
        )
    if "hardware_latch" in uses:
        parts.append("hardware latch" if scenario.hardware_latch else "no latch")
    if "cycle_time" in uses:
        parts.append(f"cycle {number_text(scenario.cycle_time * 1000)} ms")
    if scenario.limit_switches is not None:
        parts.append(
            f"limit switches [{number_text(scenario.limit_switches[0])}, {number_text(scenario.limit_switches[1])}]"
        )
    elif "limit_switches" in uses:
        parts.append("limit switches none")
    if "fixed_stop" in uses and scenario.fixed_stop is not None:
        parts.append(f"fixed stop {number_text(scenario.fixed_stop)}")
    if scenario.modulo:
        parts.append(f"modulo [{number_text(scenario.modulo[0])}, {number_text(scenario.modulo[1])}) {unit}")
    lines = ["Scenario: " + ", ".join(parts)]
    lines.append(f"Assumed (not given): {', '.join(scenario.assumed) or 'nothing'}")
    strategy = trace.strategy
    if strategy.setup.absolute:
        lines.append(
            "Absolute, position valid: the absolute measuring system gives the position at power-up "
            "(kenngr.abs_pos_gueltig 1, P-AXIS-00014)"
        )
    if not strategy.moves and strategy.controlled_by != "drive":
        return lines  # no homing move: no acceleration to speak of
    if trace.acceleration is None:
        lines.append(f"Homing acceleration: {trace.acceleration_source}")
    else:
        lines.append(
            f"Homing acceleration {number_text(trace.acceleration)} {unit}/s² from {trace.acceleration_source}"
        )
    return lines


def render(run: DryRun, console: Console) -> None:
    from rich import box
    from rich.table import Table
    from rich.text import Text

    trace = run.trace
    unit = unit_label(trace.unit)
    console.print(Text(f"Homing: {trace.strategy.title}", style="bold"))
    for line in header_lines(run):
        console.print(Text(line))
    for correction in run.values.corrections:
        console.print(
            Text(f"CNC correction {correction.error}: ", style="yellow")
            + Text(
                f"{correction.parameter} {plain(correction.written)} -> {plain(correction.used)}: "
                f"{correction.reason}"
            )
        )
    if trace.phases:
        # Numbers never wrap or shrink; the phase name and what ended it wrap instead (fits 80 columns).
        table = Table(title="Phases", title_justify="left", box=box.SIMPLE_HEAD, pad_edge=False)
        table.add_column("#", no_wrap=True)
        table.add_column("phase / ended by", ratio=1, overflow="fold")
        table.add_column("dir", no_wrap=True)
        for column in (f"{unit}/s", f"from {unit}", f"to {unit}", "t end s"):
            table.add_column(column, no_wrap=True, justify="right")
        for number, p in enumerate(trace.phases, 1):
            table.add_row(
                str(number),
                Text(p.name) + Text(f"\n{p.ended_by}", style="dim"),
                {"positive": "+", "negative": "-"}.get(p.direction or "", ""),
                number_text(p.velocity, 3),
                number_text(p.start_position, fixed=True),
                number_text(p.end_position, fixed=True),
                number_text(p.end_time, fixed=True),
            )
        console.print(table)
    if trace.events:
        events = Table(title="Events", title_justify="left", box=box.SIMPLE_HEAD, pad_edge=False)
        events.add_column("t s", no_wrap=True, justify="right")
        events.add_column(f"at {unit}", no_wrap=True, justify="right")
        events.add_column("event", ratio=1, overflow="fold")
        for e in trace.events:
            events.add_row(number_text(e.time, fixed=True), number_text(e.position, fixed=True), e.kind)
        console.print(events)
    if trace.reference:
        ref = trace.reference
        console.print(
            Text(
                f"Reference: {ref['kind']} at {number_text(ref['position'])} {unit} (actual value before "
                f"homing) becomes {number_text(ref['value'])} {unit}, at {number_text(ref['time'], 3)} s"
            )
        )
        offset = trace.cam_zero_pulse_offset
        if trace.arming is not None and offset is not None:
            console.print(
                Text(
                    f"Zero-pulse logic armed at {number_text(run.simulator.wrap(trace.arming.armed))} {unit}; "
                    f"reference cam - zero pulse offset {number_text(offset)} {unit} (what the CNC reports "
                    "after homing, §2.6)"
                )
            )
    if trace.final_position is not None:
        where = (
            "the spindle turns on at " + number_text(trace.reference["speed"], 3) + f" {unit}/s"
            if trace.ends_moving and trace.reference
            else "at standstill"
        )
        console.print(
            Text(
                f"Final position: {number_text(trace.final_position)} {unit} (homed, {where}); total "
                f"{number_text(trace.total_time, 3)} s, {number_text(trace.total_distance, 3)} {unit} travelled"
            )
        )
    style = {"homed": "green", "failed": "red"}.get(trace.outcome, "yellow")
    console.print(
        Text(f"Outcome: {trace.outcome}", style=f"bold {style}")
        + Text(f" — {trace.failure}" if trace.failure else "")
    )
    for warning in trace.warnings:
        if warning["code"] and warning["code"].startswith("P-ERR"):
            continue  # shown above as a CNC correction
        prefix = (
            Text(f"{warning['code']}: ", style="yellow")
            if warning["code"]
            else Text("note: ", style="yellow")
        )
        console.print(prefix + Text(warning["message"]))


def sweep_words(summary: dict[str, Any]) -> str:
    """The sweep in words: counts per outcome with the reasons, the spread, and a loud note on assumed geometry."""
    unit = unit_label(summary["unit"])
    lines = []
    if summary["assumed_geometry"]:
        lines.append(
            f"NOTE: the sweep runs in an ASSUMED geometry ({', '.join(summary['assumed_geometry'])} not "
            "given): its failures and spread describe the default scenario, not your machine. Give the "
            "real geometry with --scenario or --cam/--zero-pulse-period/--zero-pulse-phase/--limit-switches."
        )
    low, high = summary["start_range"]
    outcomes = ", ".join(f"{name} ×{count}" for name, count in sorted(summary["outcomes"].items()))
    lines.append(
        f"Sweep of {summary['runs']} runs (start between {number_text(low)} and {number_text(high)} {unit}): {outcomes}."
    )
    for item in summary["reasons"]:
        lines.append(f"  {item['outcome']}: {item['reason']} ×{item['count']}")
    if "spread" in summary:
        lines.append(
            f"Reference between {number_text(summary['reference_min'])} and {number_text(summary['reference_max'])} "
            f"{unit} (spread {summary['spread']:.4g} {unit}); {summary['distinct_pulses']} distinct zero "
            f"pulse(s), {summary['one_revolution_jumps']} run(s) jumped by one or more encoder revolutions."
        )
    return "\n".join(lines)


RENDERERS: Registry[AxisDryRun] = {"text": as_text, "json": as_json}
