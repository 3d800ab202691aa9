"""`dry-run --plot`: position and velocity over time (matplotlib: the `plot` extra, `pip install '.[plot]'`
in the achslint checkout).

What the figure shows: each phase in its own shade with its number and name in a legend beside the plot
(labels never overlap the curves); the cam zone (every revolution of it on a modulo axis); zero-pulse marks;
limit switches and software limits as lines; the reference point with "actual value -> new value"; the
final position; a failure marker with the reason and, for a search a bound ended, what it searched for
(within the view); and an inset zooming on the phase where the reference is
found. `build_figure` returns the figure (tests read its data series); `plot_trace` writes PNG or SVG.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, Literal

from ..homing.motion import Event, Trace

if TYPE_CHECKING:
    from matplotlib.artist import Artist
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

_LineStyle = Literal["-", "--"]

if TYPE_CHECKING:
    from ..machine.run import AxisPhase, AxisRun, MachineRun

# One colour per phase (colour-blind friendly qualitative palette), repeated for long sequences.
PHASE_COLOURS = ("#4477aa", "#ee6677", "#228833", "#ccbb44", "#66ccee", "#aa3377", "#bbbbbb")
MAX_PULSE_MARKS = 80


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


def _use_matplotlib() -> None:
    """Load matplotlib with its file-only backend (Agg); PlotUnavailable when it is not installed."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot  # imported here so that a broken installation is reported
    except ImportError:
        raise PlotUnavailable(
            "--plot needs matplotlib, the plot extra: in the achslint checkout, pip install '.[plot]'"
        ) from None


def _legend(panel: Axes, handles: list[Artist], fontsize: int) -> None:
    """The legend to the right of a panel, without a frame."""
    panel.legend(
        handles=handles,
        loc="upper left",
        bbox_to_anchor=(1.01, 1.0),
        fontsize=fontsize,
        frameon=False,
        borderaxespad=0.0,
    )


def _fmt(value: float) -> str:
    text = f"{value:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text.replace("-", "\u2212")


def _soft_limits_in_trace_frame(trace: Trace) -> tuple[float, float] | None:
    """The software limits (homed frame) drawn where they lie in the trace's frame, once the reference is known."""
    setup = trace.strategy.setup
    if trace.reference is None or setup.spindle or setup.modulo:
        return None
    offset = trace.reference["value"] - trace.reference["position"]
    low, high = setup.soft_limits
    return low - offset, high - offset


def build_figure(trace: Trace) -> Figure:
    """The figure for a trace; the caller saves or closes it."""
    _use_matplotlib()
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    times, positions, velocities = samples(trace)
    unit = trace.unit
    figure, (top, bottom) = plt.subplots(
        2, 1, sharex=True, figsize=(12, 7.5), gridspec_kw={"height_ratios": [3, 1.4]}
    )
    figure.subplots_adjust(left=0.08, right=0.66, top=0.9, bottom=0.08, hspace=0.08)
    top.plot(times, positions, color="black", linewidth=1.4, label="position", gid="position")
    bottom.plot(times, velocities, color="black", linewidth=1.2, label="velocity", gid="velocity")
    top.set_ylabel(f"position [{unit}]")
    bottom.set_ylabel(f"velocity [{unit}/s]")
    bottom.set_xlabel("time [s]")
    bottom.axhline(0.0, color="grey", linewidth=0.6)

    handles: list[Artist] = []
    for number, phase in enumerate(trace.phases, 1):
        colour = PHASE_COLOURS[(number - 1) % len(PHASE_COLOURS)]
        for axis in (top, bottom):
            axis.axvspan(phase.start_time, phase.end_time, color=colour, alpha=0.18, zorder=0, linewidth=0)
        top.text(
            (phase.start_time + phase.end_time) / 2,
            1.01,
            str(number),
            transform=top.get_xaxis_transform(),
            ha="center",
            va="bottom",
            fontsize=9,
            fontweight="bold",
            color=colour,
        )
        handles.append(
            Patch(
                color=colour,
                alpha=0.45,
                label=_wrap(
                    f"{number}. {phase.name} ({phase.direction or '-'}, {_fmt(phase.velocity)} {unit}/s)", 48
                ),
            )
        )

    low, high = (min(positions), max(positions)) if positions else (trace.scenario.start_position,) * 2
    if trace.searched is not None:  # a failed search: the view includes what it looked for
        low, high = min(low, trace.searched[1]), max(high, trace.searched[1])
    span = max(high - low, 1e-6)
    y_low, y_high = low - 0.08 * span, high + 0.08 * span
    scenario = trace.scenario
    if scenario.cam:
        lo, hi = scenario.cam
        shown = False
        revolution = (scenario.modulo[1] - scenario.modulo[0]) if scenario.modulo else 0.0
        shifts = [0.0]
        if revolution:
            first = math.floor((y_low - hi) / revolution)
            shifts = [k * revolution for k in range(first, first + int(span / revolution) + 3)]
        for shift in shifts:
            if lo + shift <= y_high and hi + shift >= y_low:
                top.axhspan(
                    lo + shift, hi + shift, color="#117733", alpha=0.14, zorder=0, linewidth=0, gid="cam"
                )
                shown = True
        if shown:
            handles.append(
                Patch(
                    color="#117733",
                    alpha=0.3,
                    label=f"reference cam [{_fmt(lo)}, {_fmt(hi)}]"
                    + (" every revolution" if revolution else ""),
                )
            )
    if trace.strategy.with_zero_pulse and scenario.zero_pulse_period > 0:
        period, phase_at = scenario.zero_pulse_period, scenario.zero_pulse_phase
        first = math.ceil((y_low - phase_at) / period)
        last = math.floor((y_high - phase_at) / period)
        if 0 <= last - first <= MAX_PULSE_MARKS:
            marks = [phase_at + k * period for k in range(first, last + 1)]
            top.hlines(
                marks,
                0,
                0.012,
                transform=top.get_yaxis_transform(),
                color="#882255",
                linewidth=1.5,
                gid="zero_pulses",
            )
            handles.append(
                Line2D(
                    [], [], color="#882255", linewidth=1.5, label=f"zero pulses (every {_fmt(period)} {unit})"
                )
            )
    lines: list[tuple[float, str, str, _LineStyle]] = []
    if scenario.limit_switches:
        lines += [(value, "limit switch", "#cc3311", "-") for value in scenario.limit_switches]
    soft = _soft_limits_in_trace_frame(trace)
    if soft:
        lines += [(value, "software limit (after homing)", "#ee7733", "--") for value in soft]
    labels: dict[str, list[str]] = {}
    styles: dict[str, tuple[str, _LineStyle]] = {}
    for value, name, colour, style in lines:
        top.axhline(value, color=colour, linestyle=style, linewidth=1.0, gid=name)
        labels.setdefault(name, []).append(_fmt(value))
        styles[name] = (colour, style)
        if low - span <= value <= high + span:  # widen the view to lines near the motion, not to far ones
            y_low, y_high = min(y_low, value), max(y_high, value)
    for name, values in labels.items():
        colour, style = styles[name]
        handles.append(
            Line2D([], [], color=colour, linestyle=style, label=f"{name}: {', '.join(values)} {unit}")
        )
    if trace.searched is not None:
        target, searched_at = trace.searched
        top.axhline(searched_at, color="#cc3311", linestyle=":", linewidth=1.2, gid="searched")
        handles.append(
            Line2D(
                [],
                [],
                color="#cc3311",
                linestyle=":",
                label=_wrap(f"searched for: {target} at {_fmt(searched_at)} {unit}", 48),
            )
        )
    top.set_ylim(y_low - 0.02 * span, y_high + 0.02 * span)

    reference = trace.reference
    reference_event = None
    if reference is not None:
        reference_event = next((e for e in reversed(trace.events) if e.kind == reference["kind"]), None)
        t_ref = (
            reference_event.time if reference_event else (trace.phases[-1].end_time if trace.phases else 0.0)
        )
        x_ref = reference_event.position if reference_event else reference["position"]
        top.plot(
            [t_ref],
            [x_ref],
            marker="*",
            markersize=14,
            color="#ddaa33",
            markeredgecolor="black",
            linestyle="none",
            gid="reference",
            zorder=5,
        )
        handles.append(
            Line2D(
                [],
                [],
                marker="*",
                markersize=12,
                color="#ddaa33",
                markeredgecolor="black",
                linestyle="none",
                label=f"reference ({reference['kind']}): "
                f"{_fmt(reference['position'])} {unit} \u2192 {_fmt(reference['value'])} {unit}",
            )
        )
    if trace.final_position is not None and trace.phases:
        last_phase = trace.phases[-1]
        top.plot(
            [last_phase.end_time],
            [last_phase.end_position],
            marker="s",
            markersize=8,
            color="white",
            markeredgecolor="black",
            linestyle="none",
            gid="final",
            zorder=5,
        )
        moving = " (still turning)" if trace.ends_moving else ""
        handles.append(
            Line2D(
                [],
                [],
                marker="s",
                color="white",
                markeredgecolor="black",
                linestyle="none",
                label=f"final position {_fmt(trace.final_position)} {unit} (homed){moving}",
            )
        )
    for event in trace.events:
        if event is reference_event:
            continue
        top.plot(
            [event.time],
            [event.position],
            marker="o",
            markersize=5,
            color="#555555",
            linestyle="none",
            zorder=4,
        )
    if trace.events:
        kinds = list(dict.fromkeys(e.kind for e in trace.events if e is not reference_event))
        if kinds:
            handles.append(
                Line2D(
                    [],
                    [],
                    marker="o",
                    markersize=5,
                    color="#555555",
                    linestyle="none",
                    label=_wrap("events: " + "; ".join(kinds), 48),
                )
            )
    if trace.outcome == "failed":
        where = (trace.phases[-1].end_time, trace.phases[-1].end_position) if trace.phases else (0.0, low)
        top.plot(
            [where[0]],
            [where[1]],
            marker="X",
            markersize=14,
            color="#cc3311",
            linestyle="none",
            gid="failure",
            zorder=6,
        )
        handles.append(
            Line2D(
                [],
                [],
                marker="X",
                markersize=12,
                color="#cc3311",
                linestyle="none",
                label=_wrap(f"FAILED: {trace.failure or 'homing failed'}", 48),
            )
        )

    _legend(top, handles, 8)
    title = f"{trace.strategy.title}: {trace.outcome}"
    if trace.phases:
        title += f" in {_fmt(trace.total_time)} s"
    figure.suptitle(title, fontsize=11, x=0.37)
    _assumed_note(figure, ", ".join(trace.scenario.assumed))
    if reference_event is not None and trace.phases:
        _inset(figure, top, trace, reference_event)
    if not trace.phases:
        top.text(
            0.5,
            0.5,
            "no homing motion" + (f": {trace.failure}" if trace.failure else ""),
            transform=top.transAxes,
            ha="center",
            va="center",
            fontsize=10,
        )
    return figure


def _inset(figure: Figure, top: Axes, trace: Trace, event: Event) -> None:
    """A zoom on the moments around the reference event (the phase where it is found is often a sliver)."""
    phase = next((p for p in trace.phases if p.start_time <= event.time <= p.end_time), trace.phases[-1])
    window = max(min(phase.end_time - phase.start_time, 0.5), 1e-3)
    t0, t1 = max(phase.start_time, event.time - window / 2), min(phase.end_time, event.time + window / 2)
    if t1 - t0 < 1e-9:
        t0, t1 = event.time - window / 2, event.time + window / 2
    inset = figure.add_axes((0.74, 0.1, 0.22, 0.26))
    times, positions, _ = samples(trace, per_segment=400)
    pairs = [(t, x) for t, x in zip(times, positions, strict=False) if t0 <= t <= t1]
    if pairs:
        inset.plot([t for t, _ in pairs], [x for _, x in pairs], color="black", linewidth=1.2, gid="zoom")
    inset.plot(
        [event.time],
        [event.position],
        marker="*",
        markersize=12,
        color="#ddaa33",
        markeredgecolor="black",
        linestyle="none",
    )
    inset.axhline(event.position, color="#ddaa33", linewidth=0.8, linestyle=":")
    scenario = trace.scenario
    if trace.strategy.with_zero_pulse and scenario.zero_pulse_period > 0 and pairs:
        y0, y1 = min(x for _, x in pairs), max(x for _, x in pairs)
        period, phase_at = scenario.zero_pulse_period, scenario.zero_pulse_phase
        first, last = math.ceil((y0 - phase_at) / period), math.floor((y1 - phase_at) / period)
        if 0 <= last - first <= MAX_PULSE_MARKS:
            inset.hlines(
                [phase_at + k * period for k in range(first, last + 1)],
                0,
                0.05,
                transform=inset.get_yaxis_transform(),
                color="#882255",
                linewidth=2.0,
                gid="zoom_pulses",
            )
    inset.set_title(f"zoom: {event.kind} at t = {_fmt(event.time)} s", fontsize=8)
    inset.tick_params(labelsize=7)


def _wrap(text: str, width: int) -> str:
    words, lines, line = text.split(), [], ""
    for word in words:
        if line and len(line) + 1 + len(word) > width:
            lines.append(line)
            line = word
        else:
            line = f"{line} {word}".strip()
    lines.append(line)
    return "\n".join(lines)


def _assumed_note(figure: Figure, assumed: str) -> None:
    """A line under the figure naming the geometry the run assumed: what the plot shows there is the default
    scenario's, not the machine's."""
    if assumed:
        figure.text(
            0.01,
            0.005,
            _wrap(f"ASSUMED, not given: {assumed}", 150),
            fontsize=8,
            color="#aa3377",
            ha="left",
            va="bottom",
            gid="assumed",
        )


def plot_trace(trace: Trace, target: str) -> None:
    """Write the dry-run's position and velocity plot to a PNG or SVG file."""
    _save(lambda: build_figure(trace), target)


def _save(build: Callable[[], Figure], target: str) -> None:
    """Build a figure and write it to `target`: only .png and .svg names are taken, and the figure is
    closed again whether or not the file could be written."""
    if not target.lower().endswith((".png", ".svg")):
        raise PlotUnavailable(f"--plot needs a .png or .svg file name, not {target!r}")
    _use_matplotlib()
    import matplotlib.pyplot as plt

    figure = build()
    try:
        figure.savefig(target, dpi=100)
    finally:
        plt.close(figure)


def svg_element(build: Callable[[], Figure], prefix: str) -> str:
    """A figure as an `<svg>` element to put inside an HTML page (`achslint report`), drawn by the same
    `build_figure` / `build_machine_figure` as `--plot`: text kept as text, no XML declaration, DOCTYPE or
    metadata (no date: the same run gives the same bytes), no namespace addresses (an HTML parser knows
    SVG), every id prefixed with `prefix` so that several figures share a page, and a width that follows
    the page."""
    _use_matplotlib()
    import io

    import matplotlib
    import matplotlib.pyplot as plt

    with matplotlib.rc_context({"svg.hashsalt": "achslint", "svg.fonttype": "none"}):
        figure = build()
        try:
            buffer = io.StringIO()
            figure.savefig(buffer, format="svg", metadata={"Date": None})
        finally:
            plt.close(figure)
    text = buffer.getvalue()
    text = text[text.index("<svg") :]
    text = re.sub(r"<metadata>.*?</metadata>\s*", "", text, flags=re.DOTALL)
    root = re.match(r"<svg[^>]*>", text)
    view = re.search(r'viewBox="([^"]*)"', root[0]) if root else None
    if root is None or view is None:
        raise PlotUnavailable("matplotlib wrote an SVG without a viewBox")
    text = f'<svg class="figure" role="img" viewBox="{view[1]}">' + text[root.end() :]
    seen: dict[str, int] = {}

    def unique(match: re.Match[str]) -> str:
        # A gid drawn several times (a limit line per limit) repeats its id; matplotlib's own ids, which the
        # references below point at, are unique already and keep their names.
        name = f"{prefix}-{re.sub(r'[^A-Za-z0-9_-]', '_', match[1])}"
        seen[name] = seen.get(name, 0) + 1
        return f'id="{name}"' if seen[name] == 1 else f'id="{name}-{seen[name]}"'

    text = re.sub(r'\bid="([^"]*)"', unique, text)
    text = re.sub(r'href="#([^"]*)"', rf'href="#{prefix}-\1"', text)
    return re.sub(r"url\(#([^)]*)\)", rf"url(#{prefix}-\1)", text).strip()


# --- the machine dry-run ------------------------------------------------------------------------

MOVE_COLOUR = "#999999"
# The assumed values the machine figure names per axis: where the axis starts and what it searches for.
ASSUMED_GEOMETRY = ("start_position", "cam", "zero_pulse_period", "zero_pulse_phase", "limit_switches")
FAILURE_COLOUR = "#cc3311"
_BarStyle = tuple[str, str, str | None, float, float]  # a lane bar's face, edge, hatch, alpha, line width
# Labels at the top of the timeline closer than this share of the time axis would overlap (`N1015` at
# fontsize 7 takes about 4 %): the later one is left out, its line is still drawn.
LABEL_GAP = 0.05


def _machine_samples(phases: list[AxisPhase], per_segment: int = 30) -> tuple[list[float], list[float]]:
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


def build_machine_figure(run: MachineRun) -> Any:
    """The figure of a machine dry-run (a MachineRun): a timeline with one lane per axis (phases coloured by
    name, moves grey, following hatched, standing still outlined, groups separated by lines and shaded by
    block, reference events starred, the failure crossed in red), and below it each moving axis's position
    over time. The caller saves or closes it."""
    _use_matplotlib()
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    axes_runs = list(run.axes.values())
    moving = [a for a in axes_runs if any(p.kind != "still" for p in a.phases)]
    lanes = len(axes_runs)
    heights = [max(1.2, 0.42 * lanes), *([1.1] * len(moving))]
    figure, panels = plt.subplots(
        len(heights),
        1,
        sharex=True,
        figsize=(12, 1.6 + sum(heights)),
        gridspec_kw={"height_ratios": heights},
        squeeze=False,
    )
    rows: list[Axes] = [p[0] for p in panels]
    timeline = rows[0]
    figure.subplots_adjust(left=0.14, right=0.7, top=1 - 0.9 / (1.6 + sum(heights)), bottom=0.06, hspace=0.12)

    colours: dict[str, str] = {}

    def colour_of(name: str) -> str:
        if name not in colours:
            colours[name] = PHASE_COLOURS[len(colours) % (len(PHASE_COLOURS) - 1)]
        return colours[name]

    # Every kind of mark is gathered first and drawn as one collection: one artist per block or phase would
    # make matplotlib recompute the limits over all artists each time (2,000 blocks took minutes).
    span = max(run.total_time, 1e-3)
    shaded: list[tuple[float, float]] = []
    block_lines: list[float] = []
    group_lines: list[float] = []
    labels = _Labels(timeline, span)
    for block in run.blocks:
        if block.start_time is None or block.end_time is None or block.end_time <= block.start_time:
            continue
        if block.index % 2 == 0:
            shaded.append((block.start_time, block.end_time))
        share = (block.end_time - block.start_time) / span
        words = block.text.split(" ", 1)
        label = (
            block.text
            if share > 0.25 or len(words) == 1
            else f"{words[0]}\n{words[1]}"
            if share > 0.12
            else words[0]
        )
        block_lines.append(block.start_time)
        labels.add(block.start_time, label, above=True, fontweight="bold")
        for number, group in enumerate(block.groups if len(block.groups) > 1 else []):
            if group.start_time is not None:  # the first group starts with its block: no second line
                if number:
                    group_lines.append(group.start_time)
                labels.add(group.start_time, f"grp {group.sequence}", above=False, color="#444444")
    for panel in rows:
        _spans(panel, shaded, color="#eeeeee", zorder=0, linewidth=0)
        _vertical_lines(panel, block_lines, color="#444444", linewidth=0.8, linestyle="-", zorder=1)
        _vertical_lines(panel, group_lines, color="#444444", linewidth=0.8, linestyle="--", zorder=1)
        if run.failure is not None:
            _vertical_lines(
                panel, [run.failure.time], color=FAILURE_COLOUR, linewidth=1.0, zorder=3, gid="failure time"
            )

    # The lanes: each style (colour, outline, hatching) is one collection over every lane.
    bars: dict[_BarStyle, list[tuple[float, float, float]]] = {}
    stars: list[tuple[float, float]] = []
    for lane, axis in enumerate(axes_runs):
        y = lanes - 1 - lane
        for phase in axis.phases:
            width = max(phase.end_time - phase.start_time, 0.0)
            style: _BarStyle
            if phase.kind == "still":
                style = ("white", "#ee7733", "xx", 1.0, 1.0)
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
            when: float | None = run.failure.time
        elif axis.outcome in ("failed", "aborted") and axis.phases:
            when = axis.phases[-1].end_time
        else:
            when = None
        if when is not None:
            timeline.plot(
                [when],
                [y],
                marker="X",
                markersize=12 if failed else 8,
                color=FAILURE_COLOUR,
                linestyle="none",
                zorder=5,
                gid="failure" if failed else None,
            )
    for (face, edge, hatch, alpha, width), found in bars.items():
        _rectangles(
            timeline,
            [(x, y - 0.3, w, 0.6) for x, w, y in found],
            facecolor=face,
            edgecolor=edge,
            hatch=hatch,
            alpha=alpha,
            linewidth=width,
            zorder=2,
        )
    if stars:
        timeline.plot(
            [t for t, _ in stars],
            [y for _, y in stars],
            marker="*",
            markersize=11,
            color="#ddaa33",
            markeredgecolor="black",
            linestyle="none",
            zorder=4,
        )
    names = [a.name for a in axes_runs]
    timeline.set_yticks(range(lanes))
    timeline.set_yticklabels(
        [
            f"{n} ({a.outcome.replace('_', ' ')})"
            for n, a in zip(reversed(names), reversed(axes_runs), strict=True)
        ],
        fontsize=8,
    )
    timeline.set_ylim(-0.7, lanes - 0.05)
    timeline.set_xlim(-0.05 * span, 1.05 * span)  # shared by every panel
    for panel, axis in zip(rows[1:], moving, strict=True):
        times, positions = _machine_samples([p for p in axis.phases if p.kind != "still"])
        # standing before, between and after its phases
        times = [0.0, *times, max(run.total_time, times[-1])]
        positions = [axis.start_position, *positions, positions[-1]]
        if axis.strategy.setup.modulo:
            times, positions = _wrapped(axis, times, positions)
        panel.plot(times, positions, color="black", linewidth=1.2, gid=f"position {axis.name}")
        if axis.reference is not None:
            panel.plot(
                [axis.reference["time"]],
                [
                    axis.reference["position"]
                    if not axis.strategy.setup.modulo
                    else axis.shown(_at(axis, axis.reference["time"]))
                ],
                marker="*",
                markersize=10,
                color="#ddaa33",
                markeredgecolor="black",
                linestyle="none",
            )
        panel.set_ylabel(f"{axis.name} [{axis.unit}]", fontsize=8)
        panel.tick_params(labelsize=7)
    rows[-1].set_xlabel("time [s]")
    handles: list[Artist] = [
        Patch(facecolor=c, edgecolor="black", label=_wrap(n, 40)) for n, c in colours.items()
    ]
    handles.append(Patch(facecolor=MOVE_COLOUR, edgecolor="black", label="move block (G00/G01)"))
    handles.append(Patch(facecolor="#bbbbbb", hatch="//", alpha=0.55, label="following its gantry partner"))
    handles.append(
        Patch(facecolor="white", edgecolor="#ee7733", hatch="xx", label="standing still (group moves)")
    )
    handles.append(
        Line2D(
            [],
            [],
            marker="*",
            markersize=10,
            color="#ddaa33",
            markeredgecolor="black",
            linestyle="none",
            label="reference taken",
        )
    )
    if run.failure is not None:
        handles.append(
            Line2D(
                [],
                [],
                marker="X",
                markersize=11,
                color=FAILURE_COLOUR,
                linestyle="none",
                label=_wrap(f"FAILED at {_fmt(run.failure.time)} s: {run.failure.reason}", 40),
            )
        )
    _legend(timeline, handles, 7)
    title = f"{run.program.name.replace(chr(92), '/').rsplit('/', 1)[-1]}: " + (
        f"done in {_fmt(run.total_time)} s"
        if run.failure is None
        else f"FAILED at {_fmt(run.failure.time)} s"
    )
    figure.suptitle(title, fontsize=11, x=0.4, y=0.995, va="top")
    _assumed_note(
        figure,
        "; ".join(
            f"{axis.name}: {', '.join(names)}"
            for axis in axes_runs
            if any(p.kind == "homing" for p in axis.phases)
            for names in [[n for n in axis.scenario.assumed if n in ASSUMED_GEOMETRY]]
            if names
        ),
    )
    return figure


class _Labels:
    """Block and group labels at the top of the timeline: just above it (blocks) or just below its upper
    edge (groups), each row leaving out a label that would overlap the one before."""

    def __init__(self, timeline: Axes, span: float) -> None:
        self.timeline = timeline
        self.gap = LABEL_GAP * span
        self.last: dict[bool, float] = {}

    def add(self, time: float, text: str, *, above: bool, **style: Any) -> None:
        if time < self.last.get(above, -math.inf) + self.gap:
            return
        self.last[above] = time
        self.timeline.text(
            time,
            1.01 if above else 0.99,
            f" {text}",
            transform=self.timeline.get_xaxis_transform(),
            ha="left",
            va="bottom" if above else "top",
            fontsize=7,
            **style,
        )


def _spans(panel: Axes, spans: list[tuple[float, float]], **style: Any) -> None:
    """Time spans over the panel's full height, as one collection (the limits stay as they are)."""
    if spans:
        _rectangles(
            panel, [(t0, 0.0, t1 - t0, 1.0) for t0, t1 in spans], panel.get_xaxis_transform(), **style
        )


def _vertical_lines(panel: Axes, times: list[float], **style: Any) -> None:
    """Vertical lines over the panel's full height at `times`, as one collection."""
    from matplotlib.collections import LineCollection

    if times:
        lines = LineCollection(
            [[(t, 0.0), (t, 1.0)] for t in times], transform=panel.get_xaxis_transform(), **style
        )
        panel.add_collection(lines, autolim=False)


def _rectangles(
    panel: Axes, boxes: list[tuple[float, float, float, float]], transform: Any = None, **style: Any
) -> None:
    """Rectangles (x, y, width, height) as one collection, in data coordinates unless `transform` is given."""
    from matplotlib.collections import PolyCollection

    vertices = [[(x, y), (x, y + h), (x + w, y + h), (x + w, y)] for x, y, w, h in boxes]
    collection = PolyCollection(vertices, transform=transform or panel.transData, **style)
    panel.add_collection(collection, autolim=False)


def _wrapped(axis: AxisRun, times: list[float], positions: list[float]) -> tuple[list[float], list[float]]:
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


def _at(axis: AxisRun, time: float) -> float:
    for phase in axis.phases:
        for segment in phase.segments:
            if segment.t0 <= time <= segment.t1:
                return segment.position(time)
    return axis.position


def plot_machine(run: MachineRun, target: str) -> None:
    """Write the machine dry-run's timeline and position plots to a PNG or SVG file."""
    _save(lambda: build_machine_figure(run), target)
