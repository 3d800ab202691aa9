"""`achslint dry-run`: simulate the configured homing of a list in a scenario.

Builds the resolved axis and the strategy, completes the scenario (the
configuration's `scenario` table, then the scenario file, then the
command-line options; `cycle-time-us` of the configuration as the cycle),
refuses what the CNC would not run (LIS306, LIS319) and scenarios that do not
fit the axis (a `[drive]` table on an axis that does not home drive-controlled),
runs the engine, adds the analyses (LIS317 soft limits, LIS405 from the engine,
every CNC correction as a warning with its P-ERR id) and renders the trace as a
table, as JSON (schema below) or as a plot.

JSON (version 1): {"version", "axis": {..., "acceleration", "acceleration_source"},
"strategy": {"id", "description"}, "scenario", "phases": [{"name", "direction",
"velocity", "start_position", "end_position", "start_time", "end_time",
"ended_by"}], "events": [{"time", "position", "kind"}], "reference": {"kind",
"position", "value", "speed"} | null, "final_position", "ends_moving",
"total_time", "total_distance", "outcome", "failure", "warnings": [{"code",
"message"}], "corrections", "units"}. Positions are mm (degrees for rotary
axes and spindles), velocities per second, times in seconds; phase and event
positions are in the scenario frame (actual values before homing, continuous:
on a modulo axis they keep counting past the modulo range so a revolution
shows as 360°), `reference.position` (wrapped into the modulo range),
`reference.value` and `final_position` in the homed frame. Numbers are always
finite: the JSON never contains NaN or Infinity.
"""

from __future__ import annotations

import importlib
import math
import random
from collections import Counter
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .engine import Simulator, Trace
from .homing import classify
from .resolved import ResolvedAxis, plain, resolve_bytes
from .scenario import ScenarioError, default_scenario, parse_input

if TYPE_CHECKING:
    from rich.console import Console

    from .catalogue import Value
    from .context import Context
    from .scenario_input import ScenarioInput

# Rules whose finding means the CNC does not run the homing at all: the dry-run refuses with their text.
REFUSING_RULES = ("lis306_torq_drive_type", "lis319_spindle_homing_direction")


class DryRunRefused(Exception):
    """The CNC would not run this homing (exit code 2, one line)."""


@dataclass
class DryRun:
    values: ResolvedAxis
    simulator: Simulator
    trace: Trace


def scenario_input(
    file: Path, scenario: Path | None, options: Mapping[str, object], config: Path | None = None
) -> tuple[ScenarioInput, int]:
    """The scenario a dry run uses and the cycle time: the configuration's `scenario` table (found next to the
    list, or `config`), then the scenario file, then the command-line options (each later source wins, key by
    key; a `[drive]` table as a whole). Each source is validated on its own, so errors name it."""
    from .config import ConfigError, discover, load_file
    from .tomlfile import read_toml

    try:
        resolved = load_file(config) if config else discover(file)
    except ConfigError as exc:
        raise ScenarioError(str(exc)) from None
    base: dict[str, object] = dict(resolved.settings.scenario)
    if base:
        parse_input(base, f"{resolved.path}: [scenario]")
    from_file = read_toml(scenario, "scenario", ScenarioError) if scenario else {}
    if scenario:
        parse_input(from_file, str(scenario))
    given = {k: v for k, v in options.items() if v is not None}
    if given:
        parse_input(given, "command-line scenario")
    merged = {**base, **from_file, **given}
    return parse_input(merged, "scenario"), resolved.settings.cycle_time_us


def prepare(
    data: bytes,
    name: str,
    given: ScenarioInput | None = None,
    *,
    gear: int = 0,
    cycle_time_us: int = 1000,
    defaults: bytes | None = None,
) -> Simulator:
    return _simulator(resolve_bytes(data, name, defaults), name, given, gear, cycle_time_us)


def _simulator(
    values: ResolvedAxis, name: str, given: ScenarioInput | None, gear: int, cycle_time_us: int
) -> Simulator:
    strategy = classify(values, gear)
    if given is not None and given.drive is not None and strategy.controlled_by != "drive":
        raise ScenarioError(
            f"scenario: the [drive] table describes drive-controlled homing, but {name} homes "
            f"{strategy.title} (homing type {values.homing_type}): remove the [drive] table"
        )
    return Simulator(values, strategy, default_scenario(strategy, given, cycle_time_us))


def refusal(data: bytes, name: str, defaults: bytes | None = None) -> str | None:
    """The lint finding that makes the CNC refuse this homing (drive type, spindle direction), if any."""
    return _refused(_context(data, name, defaults))


def _context(data: bytes, name: str, defaults: bytes | None) -> Context:
    """The list read once, as the rules see it; its `values` are the resolved axis (as resolve_bytes)."""
    from .context import Context
    from .syntax import parse_bytes

    return Context(
        name,
        parse_bytes(data, name),
        default_file=parse_bytes(defaults, "default list") if defaults is not None else None,
    )


def _refused(context: Context) -> str | None:
    for module in REFUSING_RULES:
        rule = importlib.import_module(f"{__package__}.rules.{module}")
        for diagnostic in rule.check(context):
            return (
                f"{context.name}: dry-run refused, the CNC does not run this homing: "
                f"{rule.CODE} {diagnostic.message}"
            )
    return None


def dry_run(
    data: bytes,
    name: str,
    given: ScenarioInput | None = None,
    *,
    gear: int = 0,
    cycle_time_us: int = 1000,
    defaults: bytes | None = None,
) -> DryRun:
    context = _context(data, name, defaults)  # one read for the simulation and the refusal check
    simulator = _simulator(context.values, name, given, gear, cycle_time_us)
    refused = _refused(context)
    if refused:
        raise DryRunRefused(refused)
    trace = run(simulator)
    simulator.check_soft_limits(trace)
    annotate(simulator, trace)
    return DryRun(simulator.values, simulator, trace)


def run(simulator: Simulator, start: float | None = None, cam_shift: float = 0.0) -> Trace:
    """One G74 of the axis as the CNC answers it: the strategy's sequence (with homing DISABLED the G74 is
    refused, whatever the encoder)."""
    return simulator.run(start=start, cam_shift=cam_shift)


def annotate(simulator: Simulator, trace: Trace) -> None:
    """Warnings about what the simulation takes from the CNC's corrections and from stand-ins."""
    for correction in simulator.values.corrections:
        trace.warn(
            correction.error,
            f"the CNC corrects {correction.parameter} {_plain(correction.written)} -> "
            f"{_plain(correction.used)}: {correction.reason}; the dry-run uses the "
            "corrected value",
        )
    setup = simulator.strategy.setup
    if simulator.overflow and setup.overflow_period is None and simulator.strategy.moves:
        given = "zero_pulse_period" not in trace.scenario.assumed
        trace.warn(
            None,
            (
                "antr.encoder_bit_range is 0, so the distance between encoder overflows is unknown; the dry-run uses "
                f"the scenario's zero_pulse_period ({trace.scenario.zero_pulse_period:g} {trace.unit}"
                f"{'' if given else ', assumed'}) instead. Set encoder_bit_range to the encoder's bits per revolution"
            ),
        )


def _plain(value: Value | None) -> str:
    return str(plain(value))


def _finite(value: object) -> object:
    """The value with every non-finite float replaced by None (strict JSON parsers reject NaN)."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(v) for v in value]
    return value


def finite_document(document: dict[str, Any]) -> dict[str, Any]:
    return {key: _finite(value) for key, value in document.items()}


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
    """A number for the text output: `digits` decimals (trailing zeros dropped unless `fixed`, for columns)."""
    text = f"{value:.{digits}f}"
    if text.startswith("-") and float(text) == 0:
        text = text[1:]
    return text if fixed or "." not in text else text.rstrip("0").rstrip(".")


def header_lines(run: DryRun) -> list[str]:
    trace = run.trace
    unit = trace.unit
    scenario = trace.scenario
    cam = f"[{number_text(scenario.cam[0])}, {number_text(scenario.cam[1])}]" if scenario.cam else "none"
    switches = (
        f"[{number_text(scenario.limit_switches[0])}, {number_text(scenario.limit_switches[1])}]"
        if scenario.limit_switches
        else "none"
    )
    lines = [
        f"Scenario: start {number_text(scenario.start_position)} {unit}, cam {cam}, zero pulse every "
        f"{number_text(scenario.zero_pulse_period)} {unit} (one at {number_text(scenario.zero_pulse_phase)}), "
        f"{'hardware latch' if scenario.hardware_latch else 'no latch'}, cycle {number_text(scenario.cycle_time * 1000)} ms, "
        f"limit switches {switches}"
        + (
            f", modulo [{number_text(scenario.modulo[0])}, {number_text(scenario.modulo[1])}) {unit}"
            if scenario.modulo
            else ""
        )
    ]
    lines.append(f"Assumed (not given): {', '.join(scenario.assumed) or 'nothing'}")
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
    unit = trace.unit
    console.print(Text(f"Homing: {trace.strategy.title}", style="bold"))
    for line in header_lines(run):
        console.print(Text(line))
    for correction in run.values.corrections:
        console.print(
            Text(f"CNC correction {correction.error}: ", style="yellow")
            + Text(
                f"{correction.parameter} {_plain(correction.written)} -> {_plain(correction.used)}: "
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
                f"homing) becomes {number_text(ref['value'])} {unit}"
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


# --- sweeps -----------------------------------------------------------------------------------

GEOMETRY = ("cam", "zero_pulse_period", "zero_pulse_phase", "limit_switches")


def sweep(simulator: Simulator, runs: int, seed: int = 1) -> dict[str, Any]:
    """Simulate many start positions and cam jitters; count the outcomes with their reasons and summarise the
    spread of the reference. Start positions are drawn between the limit switches, or over one revolution on a
    modulo axis without them."""
    scenario = simulator.scenario
    rng = random.Random(seed)
    if scenario.limit_switches is not None:
        low, high = scenario.limit_switches
    elif scenario.modulo is not None:
        low, high = scenario.modulo
    else:  # pragma: no cover - every non-modulo scenario has limit switches
        low, high = scenario.start_position - 100.0, scenario.start_position + 100.0
    jitter = scenario.cam_jitter
    references: list[float] = []
    outcomes: Counter[str] = Counter()
    reasons: Counter[tuple[str, str]] = Counter()
    for _ in range(runs):
        start = rng.uniform(low, high)
        shift = rng.uniform(-jitter, jitter) if jitter else 0.0
        trace = run(simulator, start, shift)
        outcomes[trace.outcome] += 1
        if trace.outcome != "homed":
            reason = (
                trace.phases[-1].ended_by if trace.phases and trace.outcome == "failed" else trace.failure
            )
            reasons[(trace.outcome, reason or trace.outcome)] += 1
        elif trace.reference is not None:
            references.append(trace.reference["position"])
    period = scenario.zero_pulse_period
    assumed = [
        name
        for name in GEOMETRY
        if name in scenario.assumed and not (name == "limit_switches" and scenario.modulo is not None)
    ]
    summary: dict[str, Any] = {
        "runs": runs,
        "outcomes": dict(outcomes),
        "unit": simulator.unit,
        "start_range": [low, high],
        "reasons": [
            {"outcome": outcome, "reason": reason, "count": count}
            for (outcome, reason), count in reasons.most_common()
        ],
        "assumed_geometry": assumed,
    }
    if references:
        spread = round(max(references) - min(references), 9)
        pulses = Counter(round((ref - scenario.zero_pulse_phase) / period) for ref in references)
        usual = pulses.most_common(1)[0][1]
        summary.update(
            {
                "reference_min": round(min(references), 9),
                "reference_max": round(max(references), 9),
                "spread": spread,
                "distinct_pulses": len(pulses),
                "one_revolution_jumps": len(references) - usual,
            }
        )
    return finite_document(summary)


def sweep_words(summary: dict[str, Any]) -> str:
    """The sweep in words: counts per outcome with the reasons, the spread, and a loud note on assumed geometry."""
    unit = summary["unit"]
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
