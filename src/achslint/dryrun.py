"""`achslint dry-run`: simulate the configured homing of a list in a scenario.

Builds the effective values and the strategy, completes the scenario, runs the
engine, adds the analyses (LIS317 soft limits, LIS405 from the engine) and
renders the trace as a table, as JSON (schema below) or as a plot.

JSON (version 1): {"version", "axis", "strategy": {"id", "description"}, "scenario",
"phases": [{"name", "direction", "velocity", "start_position", "end_position",
"start_time", "end_time", "ended_by"}], "events": [{"time", "position", "kind"}],
"reference": {"kind", "position", "value"} | null, "final_position", "total_time",
"total_distance", "outcome", "failure", "warnings": [{"code", "message"}], "units"}.
Positions are mm (degrees for rotary axes and spindles), velocities per second,
times in seconds; phase and event positions are in the scenario frame (actual
values before homing), `reference.value` and `final_position` in the homed frame.
"""

from __future__ import annotations

import random
from collections import Counter
from dataclasses import dataclass

from .engine import Simulator, Trace
from .homing import classify
from .resolved import ResolvedAxis, resolve_bytes
from .scenario import default_scenario


@dataclass
class DryRun:
    values: ResolvedAxis
    simulator: Simulator
    trace: Trace


def prepare(data: bytes, name: str, given=None, *, gear: int = 0,
            cycle_time_us: int = 1000, defaults: bytes | None = None) -> Simulator:
    values = resolve_bytes(data, name, defaults)
    strategy = classify(values, gear)
    return Simulator(values, strategy, default_scenario(strategy, given, cycle_time_us))


def dry_run(data: bytes, name: str, given=None, *, gear: int = 0,
            cycle_time_us: int = 1000, defaults: bytes | None = None) -> DryRun:
    simulator = prepare(data, name, given, gear=gear, cycle_time_us=cycle_time_us, defaults=defaults)
    trace = simulator.run()
    simulator.check_soft_limits(trace)
    return DryRun(simulator.values, simulator, trace)


def trace_json(run: DryRun) -> dict:
    trace = run.trace
    values = run.values
    r = lambda v: None if v is None else round(v, 9)  # noqa: E731 - keep JSON free of float noise
    return {
        "version": 1,
        "units": {"position": trace.unit, "velocity": f"{trace.unit}/s", "time": "s",
                  "acceleration": f"{trace.unit}/s^2"},
        "axis": {
            "name": values.get("kopf.log_achs_name"),
            "axis_type": values.axis_type,
            "drive_type": values.drive_type,
            "homing_type": values.homing_type,
            "acceleration": r(trace.acceleration),
        },
        "strategy": {"id": trace.strategy.id, "description": trace.strategy.title},
        "scenario": trace.scenario.as_dict(),
        "phases": [
            {"name": p.name, "direction": p.direction, "velocity": r(p.velocity),
             "start_position": r(p.start_position), "end_position": r(p.end_position),
             "start_time": r(p.start_time), "end_time": r(p.end_time), "ended_by": p.ended_by}
            for p in trace.phases
        ],
        "events": [{"time": r(e.time), "position": r(e.position), "kind": e.kind} for e in trace.events],
        "reference": None if trace.reference is None else {
            "kind": trace.reference["kind"], "position": r(trace.reference["position"]),
            "value": r(trace.reference["value"]), "speed": r(trace.reference["speed"])},
        "final_position": r(trace.final_position),
        "total_time": r(trace.total_time),
        "total_distance": r(trace.total_distance),
        "outcome": trace.outcome,
        "failure": trace.failure,
        "warnings": trace.warnings,
        "corrections": [c.as_dict() for c in values.corrections],
    }


def render(run: DryRun, console) -> None:
    from rich.table import Table
    from rich.text import Text

    trace = run.trace
    unit = trace.unit
    console.print(Text(f"Homing: {trace.strategy.title}", style="bold"))
    scenario = trace.scenario
    assumed = ", ".join(scenario.assumed) or "nothing"
    cam = f"[{scenario.cam[0]:g}, {scenario.cam[1]:g}]" if scenario.cam else "none"
    console.print(f"Scenario: start {scenario.start_position:g} {unit}, cam {cam}, zero pulse every "
                  f"{scenario.zero_pulse_period:g} {unit} (one at {scenario.zero_pulse_phase:g}), "
                  f"{'hardware latch' if scenario.hardware_latch else 'no latch'}, cycle {scenario.cycle_time * 1000:g} ms, "
                  f"limit switches [{scenario.limit_switches[0]:g}, {scenario.limit_switches[1]:g}]; assumed: {assumed}")
    console.print(f"Homing acceleration {trace.acceleration:g} {unit}/s²")
    for correction in run.values.corrections:
        console.print(Text(f"CNC correction {correction.error}: ", style="yellow")
                      + Text(f"{correction.parameter} {correction.written} -> {correction.used}: {correction.reason}"))
    table = Table(title="Phases", title_justify="left")
    for column in ("#", "phase", "direction", f"speed {unit}/s", f"from {unit}", f"to {unit}", "t start s", "t end s", "ended by"):
        table.add_column(column)
    for number, p in enumerate(trace.phases, 1):
        table.add_row(str(number), p.name, p.direction or "", f"{p.velocity:g}", f"{p.start_position:.4f}",
                      f"{p.end_position:.4f}", f"{p.start_time:.4f}", f"{p.end_time:.4f}", p.ended_by)
    if trace.phases:
        console.print(table)
    if trace.events:
        events = Table(title="Events", title_justify="left")
        for column in ("t s", f"position {unit}", "event"):
            events.add_column(column)
        for e in trace.events:
            events.add_row(f"{e.time:.4f}", f"{e.position:.4f}", e.kind)
        console.print(events)
    if trace.reference:
        ref = trace.reference
        console.print(f"Reference: {ref['kind']} at {ref['position']:.4f} {unit} (actual value before homing) "
                      f"becomes {ref['value']:g} {unit}")
    if trace.final_position is not None:
        console.print(f"Final position: {trace.final_position:.4f} {unit} (homed); total {trace.total_time:.3f} s, "
                      f"{trace.total_distance:.3f} {unit} travelled")
    style = {"homed": "green", "failed": "red"}.get(trace.outcome, "yellow")
    console.print(Text(f"Outcome: {trace.outcome}", style=f"bold {style}") +
                  Text(f" — {trace.failure}" if trace.failure else ""))
    for warning in trace.warnings:
        console.print(Text(f"{warning['code']}: ", style="yellow") + Text(warning["message"]))


# --- sweeps -----------------------------------------------------------------------------------

def sweep(simulator: Simulator, runs: int, seed: int = 1) -> dict:
    """Simulate many start positions and cam jitters; summarise the spread of the reference."""
    scenario = simulator.scenario
    rng = random.Random(seed)
    low, high = scenario.limit_switches
    jitter = scenario.cam_jitter
    references: list[float] = []
    outcomes: Counter = Counter()
    for _ in range(runs):
        start = rng.uniform(low, high)
        shift = rng.uniform(-jitter, jitter) if jitter else 0.0
        trace = simulator.run(start=start, cam_shift=shift)
        outcomes[trace.outcome] += 1
        if trace.reference is not None and trace.outcome == "homed":
            references.append(trace.reference["position"])
    period = scenario.zero_pulse_period
    summary = {"runs": runs, "outcomes": dict(outcomes), "unit": simulator.unit}
    if references:
        spread = max(references) - min(references)
        pulses = Counter(round((ref - scenario.zero_pulse_phase) / period) for ref in references)
        usual = pulses.most_common(1)[0][1]
        summary.update({
            "reference_min": min(references), "reference_max": max(references), "spread": spread,
            "distinct_pulses": len(pulses), "one_revolution_jumps": len(references) - usual,
        })
    return summary
