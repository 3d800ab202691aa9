"""`achslint dry-run`: simulate the configured homing of a list in a scenario.

Builds the resolved axis and the strategy, completes the scenario (the
configuration's `scenario` table, then the scenario file, then the
command-line options; `cycle-time-us` of the configuration as the cycle),
refuses what the CNC would not run (the findings of the rules that say so,
`CNC_REFUSES_HOMING` and an error: LIS306, LIS319, LIS328) and scenarios that do not
fit the axis (a `[drive]` table on an axis that does not home drive-controlled),
runs the strategy's sequence (homing/sequences/ over homing/motion.py), puts the
facts the simulation found in the words of their rules (LIS317 soft limits, LIS402
start on the cam, LIS405 zero pulse near the arming point), adds every CNC
correction as a warning with its P-ERR id, and sweeps start positions
and cam jitters. `output/dryrun.py` renders the run as a table or as JSON (its
schema is there), `plot.py` draws it.
"""

from __future__ import annotations

import math
import random
from collections import Counter
from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .axis.resolved import ResolvedAxis, plain, resolve_bytes
from .catalogue.units import unit_label
from .core.diagnostics import Severity
from .homing import classify
from .homing.motion import Fact, Simulator, SoftLimitOvershoot, StartOnCam, Trace, TraceWarning
from .homing.scenario import ScenarioError, parse_input
from .linting import engine
from .rules import Scope, registry
from .rules import lis317_homing_ends_outside_limits as lis317
from .rules import lis402_one_phase_with_cam as lis402
from .rules import lis405_zero_pulse_near_cam_edge as lis405

if TYPE_CHECKING:
    from .catalogue import Value
    from .homing.scenario_input import ScenarioInput
    from .rules.context import Context


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
    from .core.tomlfile import read_toml
    from .linting.config import ConfigError, discover, load_file

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
    return Simulator(values, strategy, strategy.default_scenario(given, cycle_time_us, name=name))


def refusal(data: bytes, name: str, defaults: bytes | None = None) -> str | None:
    """The lint finding that makes the CNC refuse this homing (drive type, spindle direction), if any."""
    return _refused(_context(data, name, defaults))


def _context(data: bytes, name: str, defaults: bytes | None) -> Context:
    """The list read once, as the rules see it; its `values` are the resolved axis (as resolve_bytes)."""
    from .rules.context import Context
    from .syntax.parser import parse_bytes

    return Context(
        name,
        parse_bytes(data, name),
        default_file=parse_bytes(defaults, "default list") if defaults is not None else None,
    )


@lru_cache(maxsize=1)
def _refusing() -> engine.Policy | None:
    """The selection of the rules whose finding means the CNC does not run the homing at all."""
    codes = [code for code, rule in registry().items() if rule.refuses_homing]
    return engine.Policy.of(select=codes) if codes else None


def _refused(context: Context) -> str | None:
    """The refusal with the first such finding (in code order), run by the lint engine; None if none."""
    policy = _refusing()
    found = engine.run(Scope.LIST, (context,), policy) if policy is not None else []
    # only an error refuses: LIS328 warns of an unsent torque limit, with which the homing does run
    found = [diagnostic for diagnostic in found if diagnostic.severity is Severity.ERROR]
    if not found:
        return None
    first = min(found, key=lambda diagnostic: diagnostic.code)
    return f"{context.name}: dry-run refused, the CNC does not run this homing: {first.code} {first.message}"


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
    finish(simulator, trace)
    return DryRun(simulator.values, simulator, trace)


def run(simulator: Simulator, start: float | None = None, cam_shift: float = 0.0) -> Trace:
    """One G74 of the axis as the CNC answers it: the strategy's sequence (with homing DISABLED the G74 is
    refused, whatever the encoder)."""
    return simulator.run(start=start, cam_shift=cam_shift)


def finish(simulator: Simulator, trace: Trace) -> None:
    """What a dry-run adds to a simulated trace, in this order: the soft-limit check, every fact of the trace in
    the words of the rule it belongs to, and the notes on the CNC's corrections and stand-ins."""
    simulator.check_soft_limits(trace)
    trace.warnings.extend(finding(fact) for fact in trace.facts)
    annotate(simulator, trace)


def finding(fact: Fact) -> TraceWarning:
    """A fact of the simulation as the finding of its rule."""
    if isinstance(fact, SoftLimitOvershoot):
        return {"code": lis317.CODE, "message": lis317.message(fact)}
    if isinstance(fact, StartOnCam):
        return {"code": lis402.CODE, "message": lis402.start_on_cam(fact)}
    return {"code": lis405.CODE, "message": lis405.message(fact)}


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
                f"the scenario's zero_pulse_period ({trace.scenario.zero_pulse_period:g} {unit_label(trace.unit)}"
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
    else:  # an axis whose run reads no limit switches (it does not move)
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
