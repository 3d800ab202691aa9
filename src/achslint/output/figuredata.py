"""What the dry-run figures show, worked out once for both of their renderers.

`figures` draws them with matplotlib (`--plot FILE.png`); `svgplot` writes SVG itself (`--plot FILE.svg` and
every figure of `achslint report`). Both take what they draw from here, so the two can differ in pixels but
never in content: the samples of the curves, the phase colours, the view of the position panel, the cam
zone, zero pulses, limit lines, markers, legend entries with their words, titles and the assumed-geometry
note of a single-axis trace (`trace_figure`), and the lanes, bars, labels and position curves of a machine
dry-run's timeline (`machine_figure`). Nothing here imports matplotlib.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from ..catalogue.units import unit_label
from ..homing.motion import Event, PhaseRecord, Trace

if TYPE_CHECKING:
    from ..machine.run import AxisPhase, AxisRun, MachineRun

# One colour per phase (colour-blind friendly qualitative palette), repeated for long sequences.
PHASE_COLOURS = ("#4477aa", "#ee6677", "#228833", "#ccbb44", "#66ccee", "#aa3377", "#bbbbbb")
MAX_PULSE_MARKS = 80
CAM_COLOUR = "#117733"
PULSE_COLOUR = "#882255"
REFERENCE_COLOUR = "#ddaa33"
EVENT_COLOUR = "#555555"
FAILURE_COLOUR = "#cc3311"
ASSUMED_COLOUR = "#aa3377"
MOVE_COLOUR = "#999999"
STILL_COLOUR = "#ee7733"
# The assumed values the machine figure names per axis: where the axis starts and what it searches for.
ASSUMED_GEOMETRY = ("start_position", "cam", "zero_pulse_period", "zero_pulse_phase", "limit_switches")
# Labels at the top of the timeline closer than this share of the time axis would overlap (`N1015` at
# fontsize 7 takes about 4 %): the later one is left out, its line is still drawn.
LABEL_GAP = 0.05
LEGEND_WIDTH = 48  # characters of a legend entry per line (a trace's figure; the timeline's takes 40)


class PlotUnavailable(Exception):
    pass


def samples(trace: Trace, per_segment: int = 40) -> tuple[list[float], list[float], list[float]]:
    times: list[float] = []
    positions: list[float] = []
    velocities: list[float] = []
    for phase in trace.phases:
        for segment in phase.segments:
            steps = per_segment if segment.t1 > segment.t0 else 1
            for k in range(steps + 1):
                t = segment.t0 + (segment.t1 - segment.t0) * k / steps
                times.append(t)
                positions.append(segment.position(t))
                velocities.append(segment.velocity(t))
    return times, positions, velocities


def fmt(value: float) -> str:
    text = f"{value:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text.replace("-", "\u2212")


def wrap(text: str, width: int) -> str:
    words, lines, line = text.split(), [], ""
    for word in words:
        if line and len(line) + 1 + len(word) > width:
            lines.append(line)
            line = word
        else:
            line = f"{line} {word}".strip()
    lines.append(line)
    return "\n".join(lines)


def assumed_note(assumed: str) -> str:
    """The line under a figure naming the geometry the run assumed ("" when it assumed none): what the plot
    shows there is the default scenario's, not the machine's."""
    return wrap(f"ASSUMED, not given: {assumed}", 150) if assumed else ""


def soft_limits_in_trace_frame(trace: Trace) -> tuple[float, float] | None:
    """The software limits (homed frame) drawn where they lie in the trace's frame, once the reference is known."""
    setup = trace.strategy.setup
    if trace.reference is None or setup.spindle or setup.modulo:
        return None
    offset = trace.reference["value"] - trace.reference["position"]
    low, high = setup.soft_limits
    return low - offset, high - offset


def _reads_zero_pulses(trace: Trace) -> bool:
    """Whether the run looked for encoder zero pulses: a simulated drive's "pulse" is a distance
    (rpf_weg_bis_nip), so its scenario's pulses are not the machine's and the JSON leaves them out."""
    return trace.strategy.with_zero_pulse and "zero_pulse" in trace.scenario.uses


def pulse_marks(period: float, phase_at: float, low: float, high: float) -> list[float]:
    """The zero pulses between low and high; none when there would be more than MAX_PULSE_MARKS."""
    first, last = math.ceil((low - phase_at) / period), math.floor((high - phase_at) / period)
    if 0 <= last - first <= MAX_PULSE_MARKS:
        return [phase_at + k * period for k in range(first, last + 1)]
    return []


@dataclass(frozen=True)
class Key:
    """One legend entry: a shaded patch, a line or a lone marker, and its label (line breaks included)."""

    label: str
    colour: str
    kind: str  # "patch", "line" or "marker"
    alpha: float = 1.0
    style: str = "-"  # a line's style: "-", "--" or ":"
    marker: str = ""  # "*", "s", "o" or "X"
    size: float = 0.0  # a marker's size in points
    edge: str | None = None  # a marker's or patch's outline
    hatch: str | None = None  # a patch's hatching: "//" or "xx"
    width: float = 1.5  # a line's width in points


@dataclass(frozen=True)
class Mark:
    """A marker on the position panel: the reference, the final position, an event, the failure."""

    time: float
    position: float
    marker: str  # "*", "s", "o" or "X"
    size: float  # points
    colour: str
    edge: str | None
    gid: str | None
    layer: int  # drawn above the lower layers


@dataclass(frozen=True)
class Level:
    """A horizontal line over the position panel: a limit switch, a software limit, the position searched."""

    value: float
    name: str
    colour: str
    style: str  # "-", "--" or ":"
    width: float


@dataclass(frozen=True)
class Zoom:
    """The zoom on the moments around the reference event (the phase where it is found is often a sliver)."""

    event: Event
    times: list[float]
    positions: list[float]
    pulses: list[float]  # the zero pulses within the zoomed positions
    title: str


@dataclass
class TraceFigure:
    """A single-axis trace's figure: position over time above velocity over time, and the legend beside."""

    unit: str  # as shown on the figure (`°`, `mm`)
    times: list[float]
    positions: list[float]
    velocities: list[float]
    phases: list[tuple[int, PhaseRecord, str]]  # number (from 1), phase, colour
    view: tuple[float, float]  # the position panel's range
    cam: list[tuple[float, float]] = field(default_factory=list)  # every revolution of it within the view
    pulses: list[float] = field(default_factory=list)
    levels: list[Level] = field(default_factory=list)
    marks: list[Mark] = field(default_factory=list)
    keys: list[Key] = field(default_factory=list)
    title: str = ""
    assumed: str = ""  # the note naming the assumed geometry, "" when none was assumed
    empty: str | None = None  # what the position panel says when there is no motion
    zoom: Zoom | None = None


def trace_figure(trace: Trace) -> TraceFigure:
    """What the figure of a single-axis trace shows (`dry-run --plot`, the report's per-axis figures)."""
    times, positions, velocities = samples(trace)
    unit = unit_label(trace.unit)
    keys: list[Key] = []
    phases = []
    for number, phase in enumerate(trace.phases, 1):
        colour = PHASE_COLOURS[(number - 1) % len(PHASE_COLOURS)]
        phases.append((number, phase, colour))
        label = f"{number}. {phase.name} ({phase.direction or '-'}, {fmt(phase.velocity)} {unit}/s)"
        keys.append(Key(wrap(label, LEGEND_WIDTH), colour, "patch", alpha=0.45))

    low, high = (min(positions), max(positions)) if positions else (trace.scenario.start_position,) * 2
    if trace.searched is not None:  # a failed search: the view includes what it looked for
        low, high = min(low, trace.searched[1]), max(high, trace.searched[1])
    span = max(high - low, 1e-6)
    y_low, y_high = low - 0.08 * span, high + 0.08 * span
    scenario = trace.scenario
    cam: list[tuple[float, float]] = []
    if scenario.cam:
        lo, hi = scenario.cam
        revolution = (scenario.modulo[1] - scenario.modulo[0]) if scenario.modulo else 0.0
        shifts = [0.0]
        if revolution:
            first = math.floor((y_low - hi) / revolution)
            shifts = [k * revolution for k in range(first, first + int(span / revolution) + 3)]
        cam = [(lo + s, hi + s) for s in shifts if lo + s <= y_high and hi + s >= y_low]
        if cam:
            every = " every revolution" if revolution else ""
            keys.append(Key(f"reference cam [{fmt(lo)}, {fmt(hi)}]{every}", CAM_COLOUR, "patch", alpha=0.3))
    pulses: list[float] = []
    if _reads_zero_pulses(trace) and scenario.zero_pulse_period > 0:
        period = scenario.zero_pulse_period
        pulses = pulse_marks(period, scenario.zero_pulse_phase, y_low, y_high)
        if pulses:
            keys.append(Key(f"zero pulses (every {fmt(period)} {unit})", PULSE_COLOUR, "line"))
    levels: list[Level] = []
    if scenario.limit_switches:
        levels += [Level(value, "limit switch", "#cc3311", "-", 1.0) for value in scenario.limit_switches]
    soft = soft_limits_in_trace_frame(trace)
    if soft:
        levels += [Level(value, "software limit (after homing)", "#ee7733", "--", 1.0) for value in soft]
    values: dict[str, list[str]] = {}
    for level in levels:
        values.setdefault(level.name, []).append(fmt(level.value))
        if low - span <= level.value <= high + span:  # widen the view to lines near the motion, not far ones
            y_low, y_high = min(y_low, level.value), max(y_high, level.value)
    for name, shown in values.items():
        first_level = next(level for level in levels if level.name == name)
        keys.append(
            Key(f"{name}: {', '.join(shown)} {unit}", first_level.colour, "line", style=first_level.style)
        )
    if trace.searched is not None:
        target, searched_at = trace.searched
        levels.append(Level(searched_at, "searched", "#cc3311", ":", 1.2))
        label = wrap(f"searched for: {target} at {fmt(searched_at)} {unit}", LEGEND_WIDTH)
        keys.append(Key(label, "#cc3311", "line", style=":"))
    view = (y_low - 0.02 * span, y_high + 0.02 * span)

    marks: list[Mark] = []
    reference = trace.reference
    reference_event = None
    if reference is not None:
        reference_event = next((e for e in reversed(trace.events) if e.kind == reference["kind"]), None)
        t_ref = (
            reference_event.time if reference_event else (trace.phases[-1].end_time if trace.phases else 0.0)
        )
        x_ref = reference_event.position if reference_event else reference["position"]
        marks.append(Mark(t_ref, x_ref, "*", 14, REFERENCE_COLOUR, "black", "reference", 5))
        label = (
            f"reference ({reference['kind']}): "
            f"{fmt(reference['position'])} {unit} \u2192 {fmt(reference['value'])} {unit}"
        )
        keys.append(Key(label, REFERENCE_COLOUR, "marker", marker="*", size=12, edge="black"))
    if trace.final_position is not None and trace.phases:
        last_phase = trace.phases[-1]
        marks.append(Mark(last_phase.end_time, last_phase.end_position, "s", 8, "white", "black", "final", 5))
        moving = " (still turning)" if trace.ends_moving else ""
        label = f"final position {fmt(trace.final_position)} {unit} (homed){moving}"
        keys.append(Key(label, "white", "marker", marker="s", size=6, edge="black"))
    others = [e for e in trace.events if e is not reference_event]
    marks += [Mark(e.time, e.position, "o", 5, EVENT_COLOUR, None, None, 4) for e in others]
    if others:
        kinds = list(dict.fromkeys(e.kind for e in others))
        keys.append(
            Key(wrap("events: " + "; ".join(kinds), LEGEND_WIDTH), EVENT_COLOUR, "marker", marker="o", size=5)
        )
    if trace.outcome == "failed":
        where = (trace.phases[-1].end_time, trace.phases[-1].end_position) if trace.phases else (0.0, low)
        marks.append(Mark(where[0], where[1], "X", 14, FAILURE_COLOUR, None, "failure", 6))
        label = wrap(f"FAILED: {trace.failure or 'homing failed'}", LEGEND_WIDTH)
        keys.append(Key(label, FAILURE_COLOUR, "marker", marker="X", size=12))

    title = f"{trace.strategy.title}: {trace.outcome}"
    if trace.phases:
        title += f" in {fmt(trace.total_time)} s"
    empty = None
    if not trace.phases:
        empty = "no homing motion" + (f": {trace.failure}" if trace.failure else "")
    zoom = _zoom(trace, reference_event) if reference_event is not None and trace.phases else None
    return TraceFigure(
        unit,
        times,
        positions,
        velocities,
        phases,
        view,
        cam,
        pulses,
        levels,
        marks,
        keys,
        title,
        assumed_note(", ".join(trace.scenario.assumed)),
        empty,
        zoom,
    )


def _zoom(trace: Trace, event: Event) -> Zoom:
    phase = next((p for p in trace.phases if p.start_time <= event.time <= p.end_time), trace.phases[-1])
    window = max(min(phase.end_time - phase.start_time, 0.5), 1e-3)
    t0, t1 = max(phase.start_time, event.time - window / 2), min(phase.end_time, event.time + window / 2)
    if t1 - t0 < 1e-9:
        t0, t1 = event.time - window / 2, event.time + window / 2
    times: list[float] = []
    positions: list[float] = []
    per_segment = 400
    for record in trace.phases:  # only the segments within the window are sampled, finely
        for segment in record.segments:
            if segment.t1 < t0 or segment.t0 > t1:
                continue
            steps = per_segment if segment.t1 > segment.t0 else 1
            for k in range(steps + 1):
                t = segment.t0 + (segment.t1 - segment.t0) * k / steps
                if t0 <= t <= t1:
                    times.append(t)
                    positions.append(segment.position(t))
    scenario = trace.scenario
    pulses: list[float] = []
    if _reads_zero_pulses(trace) and scenario.zero_pulse_period > 0 and positions:
        pulses = pulse_marks(
            scenario.zero_pulse_period, scenario.zero_pulse_phase, min(positions), max(positions)
        )
    return Zoom(event, times, positions, pulses, f"zoom: {event.kind} at t = {fmt(event.time)} s")


# --- the machine dry-run ------------------------------------------------------------------------

BarStyle = tuple[str, str, str | None, float, float]  # a lane bar's face, edge, hatch, alpha, line width


@dataclass(frozen=True)
class Label:
    """A block's label above the timeline (bold) or a group's just below its upper edge."""

    time: float
    text: str  # may hold a line break
    above: bool


@dataclass(frozen=True)
class Panel:
    """One moving axis's position over the program's time (a modulo axis's broken by NaN where it wraps)."""

    name: str
    unit: str  # as shown on the figure (`°`, `mm`)
    times: list[float]
    positions: list[float]
    reference: tuple[float, float] | None


@dataclass
class MachineFigure:
    """A machine dry-run's figure: the timeline with one lane per axis, then each moving axis's position."""

    lanes: list[str]  # the lanes' labels, top lane first
    span: float  # the program's time (at least 1 ms)
    shaded: list[tuple[float, float]]  # every other block
    block_lines: list[float]
    group_lines: list[float]
    labels: list[Label]
    failure_time: float | None
    bars: dict[BarStyle, list[tuple[float, float, float]]]  # style -> (start, width, lane y; top = lanes - 1)
    stars: list[tuple[float, float]]  # (time, lane y) where an axis took its reference
    crosses: list[tuple[float, float, bool]]  # (time, lane y, failed): a failed or aborted axis
    panels: list[Panel]
    keys: list[Key]
    title: str
    assumed: str


def machine_samples(phases: list[AxisPhase], per_segment: int = 30) -> tuple[list[float], list[float]]:
    times: list[float] = []
    positions: list[float] = []
    for phase in phases:
        for segment in phase.segments:
            steps = per_segment if segment.t1 > segment.t0 else 1
            for k in range(steps + 1):
                t = segment.t0 + (segment.t1 - segment.t0) * k / steps
                times.append(t)
                positions.append(segment.position(t))
    return times, positions


def machine_figure(run: MachineRun) -> MachineFigure:
    """What the figure of a machine dry-run shows: phases coloured by name, moves grey, following hatched,
    standing still outlined, groups separated by lines and blocks shaded in turn, reference events starred,
    the failure crossed in red; below, each moving axis's position over time."""
    axes_runs = list(run.axes.values())
    lanes = len(axes_runs)
    colours: dict[str, str] = {}

    def colour_of(name: str) -> str:
        if name not in colours:
            colours[name] = PHASE_COLOURS[len(colours) % (len(PHASE_COLOURS) - 1)]
        return colours[name]

    span = max(run.total_time, 1e-3)
    shaded: list[tuple[float, float]] = []
    block_lines: list[float] = []
    group_lines: list[float] = []
    labels: list[Label] = []
    last: dict[bool, float] = {}

    def label(time: float, text: str, above: bool) -> None:
        # a label closer to the one before in its row than LABEL_GAP would overlap it: left out
        if time >= last.get(above, -math.inf) + LABEL_GAP * span:
            last[above] = time
            labels.append(Label(time, text, above))

    for block in run.blocks:
        if block.start_time is None or block.end_time is None or block.end_time <= block.start_time:
            continue
        if block.index % 2 == 0:
            shaded.append((block.start_time, block.end_time))
        share = (block.end_time - block.start_time) / span
        words = block.text.split(" ", 1)
        text = (
            block.text
            if share > 0.25 or len(words) == 1
            else f"{words[0]}\n{words[1]}"
            if share > 0.12
            else words[0]
        )
        block_lines.append(block.start_time)
        label(block.start_time, text, True)
        for number, group in enumerate(block.groups if len(block.groups) > 1 else []):
            if group.start_time is not None:  # the first group starts with its block: no second line
                if number:
                    group_lines.append(group.start_time)
                label(group.start_time, f"grp {group.sequence}", False)

    bars: dict[BarStyle, list[tuple[float, float, float]]] = {}
    stars: list[tuple[float, float]] = []
    crosses: list[tuple[float, float, bool]] = []
    for lane, axis in enumerate(axes_runs):
        y = lanes - 1 - lane
        for phase in axis.phases:
            width = max(phase.end_time - phase.start_time, 0.0)
            style: BarStyle
            if phase.kind == "still":
                style = ("white", STILL_COLOUR, "xx", 1.0, 1.0)
            elif phase.kind == "following":
                colour = colour_of(phase.name.split(": ", 1)[1])
                style = (colour, colour, "//", 0.55, 0.5)
            else:
                colour = MOVE_COLOUR if phase.kind == "move" else colour_of(phase.name)
                style = (colour, "black", None, 0.9, 0.5)
            bars.setdefault(style, []).append((phase.start_time, width, y))
        if axis.reference is not None:
            stars.append((axis.reference["time"], y))
        failed = axis.outcome == "failed"
        if failed and run.failure is not None:
            crosses.append((run.failure.time, y, True))
        elif axis.outcome in ("failed", "aborted") and axis.phases:
            crosses.append((axis.phases[-1].end_time, y, failed))

    panels = []
    for axis in axes_runs:
        if not any(p.kind != "still" for p in axis.phases):
            continue
        times, positions = machine_samples([p for p in axis.phases if p.kind != "still"])
        # standing before, between and after its phases
        times = [0.0, *times, max(run.total_time, times[-1])]
        positions = [axis.start_position, *positions, positions[-1]]
        if axis.strategy.setup.modulo:
            times, positions = wrapped(axis, times, positions)
        reference = None
        if axis.reference is not None:
            at = axis.reference["time"]
            shown = (
                axis.reference["position"]
                if not axis.strategy.setup.modulo
                else axis.shown(position_at(axis, at))
            )
            reference = (at, shown)
        panels.append(Panel(axis.name, unit_label(axis.unit), times, positions, reference))

    keys = [Key(wrap(n, 40), c, "patch", edge="black") for n, c in colours.items()]
    keys.append(Key("move block (G00/G01)", MOVE_COLOUR, "patch", edge="black"))
    keys.append(Key("following its gantry partner", "#bbbbbb", "patch", alpha=0.55, hatch="//"))
    keys.append(Key("standing still (group moves)", "white", "patch", edge=STILL_COLOUR, hatch="xx"))
    keys.append(Key("reference taken", REFERENCE_COLOUR, "marker", marker="*", size=10, edge="black"))
    if run.failure is not None:
        label_text = wrap(f"FAILED at {fmt(run.failure.time)} s: {run.failure.reason}", 40)
        keys.append(Key(label_text, FAILURE_COLOUR, "marker", marker="X", size=11))
    title = f"{run.program.name.replace(chr(92), '/').rsplit('/', 1)[-1]}: " + (
        f"done in {fmt(run.total_time)} s" if run.failure is None else f"FAILED at {fmt(run.failure.time)} s"
    )
    assumed = "; ".join(
        f"{axis.name}: {', '.join(names)}"
        for axis in axes_runs
        if any(p.kind == "homing" for p in axis.phases)
        for names in [[n for n in axis.scenario.assumed if n in ASSUMED_GEOMETRY]]
        if names
    )
    return MachineFigure(
        [f"{a.name} ({a.outcome.replace('_', ' ')})" for a in axes_runs],
        span,
        shaded,
        block_lines,
        group_lines,
        labels,
        run.failure.time if run.failure is not None else None,
        bars,
        stars,
        crosses,
        panels,
        keys,
        title,
        assumed_note(assumed),
    )


def wrapped(axis: AxisRun, times: list[float], positions: list[float]) -> tuple[list[float], list[float]]:
    """A modulo axis's position curve within its modulo range: where it passes an end of the range (its
    revolution count changes), the line is broken by a NaN point instead of drawn across the panel."""
    low, high = axis.strategy.setup.modulo or (0.0, 1.0)
    span = high - low
    out_t: list[float] = []
    out_x: list[float] = []
    previous: tuple[float, float, int] | None = None
    for t, x in zip(times, positions, strict=True):
        now = math.floor((x - low) / span)
        if previous is not None and now != previous[2]:
            t0, x0, turn = previous
            step = 1 if now > turn else -1
            for crossed in range(turn + (step > 0), now + (step > 0), step):  # every end passed on the way
                edge = low + crossed * span
                at = t0 + (edge - x0) / (x - x0) * (t - t0)  # the samples are joined by straight lines
                out_t += [at, at, at]
                out_x += [high if step > 0 else low, math.nan, low if step > 0 else high]
        previous = (t, x, now)
        out_t.append(t)
        out_x.append(axis.shown(x))
    return out_t, out_x


def position_at(axis: AxisRun, time: float) -> float:
    for phase in axis.phases:
        for segment in phase.segments:
            if segment.t0 <= time <= segment.t1:
                return segment.position(time)
    return axis.position
