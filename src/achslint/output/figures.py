"""`dry-run --plot FILE.png`: the figures drawn with matplotlib (`pip install 'achslint[plot]'`).

Only PNG comes from here: `--plot FILE.svg` and the figures of `achslint report` are written by `svgplot`,
which needs no matplotlib and is fast enough for a report of many axes. Both draw what `figuredata` works out
(`trace_figure`, `machine_figure`), so a PNG and an SVG of the same run show the same things.

What the figure of a trace shows: each phase in its own shade with its number and name in a legend beside
the plot (labels never overlap the curves); the cam zone (every revolution of it on a modulo axis);
zero-pulse marks; limit switches and software limits as lines; the reference point with "actual value ->
new value"; the final position; a failure marker with the reason and, for a search a bound ended, what it
searched for (within the view); and an inset zooming on the phase where the reference is found.
`build_figure` returns the figure (tests read its data series); `save_png` writes it.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any, BinaryIO

from .figuredata import (
    PULSE_COLOUR,
    REFERENCE_COLOUR,
    BarStyle,
    Key,
    Label,
    PlotUnavailable,
    TraceFigure,
    machine_figure,
    trace_figure,
)

if TYPE_CHECKING:
    from matplotlib.artist import Artist
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..homing.motion import Trace
    from ..machine.run import MachineRun


def _use_matplotlib() -> None:
    """Load matplotlib with its file-only backend (Agg); PlotUnavailable when it is not installed."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot  # imported here so that a broken installation is reported
    except ImportError:
        raise PlotUnavailable("--plot FILE.png needs matplotlib: pip install 'achslint[plot]'") from None


def _handles(keys: Sequence[Key]) -> list[Artist]:
    """The legend entries as matplotlib draws them."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    handles: list[Artist] = []
    for key in keys:
        if key.kind == "patch":
            edge: dict[str, Any] = {"edgecolor": key.edge} if key.edge else {}
            face: dict[str, Any] = (
                {"facecolor": key.colour} if key.edge or key.hatch else {"color": key.colour}
            )
            handles.append(Patch(**face, **edge, alpha=key.alpha, hatch=key.hatch, label=key.label))
        elif key.kind == "line":
            style: Any = key.style
            handles.append(
                Line2D([], [], color=key.colour, linestyle=style, linewidth=key.width, label=key.label)
            )
        else:
            marker_edge: dict[str, Any] = {"markeredgecolor": key.edge} if key.edge else {}
            handles.append(
                Line2D(
                    [],
                    [],
                    marker=key.marker,
                    markersize=key.size,
                    color=key.colour,
                    linestyle="none",
                    label=key.label,
                    **marker_edge,
                )
            )
    return handles


def _legend(panel: Axes, keys: Sequence[Key], fontsize: int) -> None:
    """The legend to the right of a panel, without a frame."""
    panel.legend(
        handles=_handles(keys),
        loc="upper left",
        bbox_to_anchor=(1.01, 1.0),
        fontsize=fontsize,
        frameon=False,
        borderaxespad=0.0,
    )


def build_figure(trace: Trace) -> Figure:
    """The figure for a trace; the caller saves or closes it."""
    _use_matplotlib()
    import matplotlib.pyplot as plt

    shown = trace_figure(trace)
    figure, (top, bottom) = plt.subplots(
        2, 1, sharex=True, figsize=(12, 7.5), gridspec_kw={"height_ratios": [3, 1.4]}
    )
    figure.subplots_adjust(left=0.08, right=0.66, top=0.9, bottom=0.08, hspace=0.08)
    top.plot(shown.times, shown.positions, color="black", linewidth=1.4, label="position", gid="position")
    bottom.plot(shown.times, shown.velocities, color="black", linewidth=1.2, label="velocity", gid="velocity")
    top.set_ylabel(f"position [{shown.unit}]")
    bottom.set_ylabel(f"velocity [{shown.unit}/s]")
    bottom.set_xlabel("time [s]")
    bottom.axhline(0.0, color="grey", linewidth=0.6)
    for number, phase, colour in shown.phases:
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
    for low, high in shown.cam:
        top.axhspan(low, high, color="#117733", alpha=0.14, zorder=0, linewidth=0, gid="cam")
    if shown.pulses:
        top.hlines(
            shown.pulses,
            0,
            0.012,
            transform=top.get_yaxis_transform(),
            color=PULSE_COLOUR,
            linewidth=1.5,
            gid="zero_pulses",
        )
    for level in shown.levels:
        top.axhline(
            level.value, color=level.colour, linestyle=level.style, linewidth=level.width, gid=level.name
        )
    top.set_ylim(*shown.view)
    for mark in shown.marks:
        edge = {"markeredgecolor": mark.edge} if mark.edge else {}
        top.plot(
            [mark.time],
            [mark.position],
            marker=mark.marker,
            markersize=mark.size,
            color=mark.colour,
            linestyle="none",
            gid=mark.gid,
            zorder=mark.layer,
            **edge,
        )
    _legend(top, shown.keys, 8)
    figure.suptitle(shown.title, fontsize=11, x=0.37)
    _assumed_note(figure, shown.assumed)
    if shown.zoom is not None:
        _inset(figure, shown)
    if shown.empty is not None:
        top.text(0.5, 0.5, shown.empty, transform=top.transAxes, ha="center", va="center", fontsize=10)
    return figure


def _inset(figure: Figure, shown: TraceFigure) -> None:
    """A zoom on the moments around the reference event (the phase where it is found is often a sliver)."""
    zoom = shown.zoom
    assert zoom is not None
    inset = figure.add_axes((0.74, 0.1, 0.22, 0.26))
    if zoom.times:
        inset.plot(zoom.times, zoom.positions, color="black", linewidth=1.2, gid="zoom")
    event = zoom.event
    inset.plot(
        [event.time],
        [event.position],
        marker="*",
        markersize=12,
        color=REFERENCE_COLOUR,
        markeredgecolor="black",
        linestyle="none",
    )
    inset.axhline(event.position, color=REFERENCE_COLOUR, linewidth=0.8, linestyle=":")
    if zoom.pulses:
        inset.hlines(
            zoom.pulses,
            0,
            0.05,
            transform=inset.get_yaxis_transform(),
            color=PULSE_COLOUR,
            linewidth=2.0,
            gid="zoom_pulses",
        )
    inset.set_title(zoom.title, fontsize=8)
    inset.tick_params(labelsize=7)


def _assumed_note(figure: Figure, note: str) -> None:
    if note:
        figure.text(0.01, 0.005, note, fontsize=8, color="#aa3377", ha="left", va="bottom", gid="assumed")


def save_png(build: Callable[[], Figure], target: str | BinaryIO) -> None:
    """Build a figure and write it to `target` (a file name or a binary stream) as PNG; the figure is closed
    again whether or not it could be written."""
    _use_matplotlib()
    import matplotlib.pyplot as plt

    figure = build()
    try:
        figure.savefig(target, dpi=100, format="png")
    finally:
        plt.close(figure)


# --- the machine dry-run ------------------------------------------------------------------------


def build_machine_figure(run: MachineRun) -> Any:
    """The figure of a machine dry-run (a MachineRun): a timeline with one lane per axis (what it shows:
    `figuredata.machine_figure`), and below it each moving axis's position over time. The caller saves or
    closes it."""
    _use_matplotlib()
    import matplotlib.pyplot as plt

    shown = machine_figure(run)
    lanes = len(shown.lanes)
    heights = [max(1.2, 0.42 * lanes), *([1.1] * len(shown.panels))]
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

    # Every kind of mark is drawn as one collection: one artist per block or phase would make matplotlib
    # recompute the limits over all artists each time (2,000 blocks took minutes).
    for label in shown.labels:
        _label(timeline, label)
    for panel in rows:
        _spans(panel, shown.shaded, color="#eeeeee", zorder=0, linewidth=0)
        _vertical_lines(panel, shown.block_lines, color="#444444", linewidth=0.8, linestyle="-", zorder=1)
        _vertical_lines(panel, shown.group_lines, color="#444444", linewidth=0.8, linestyle="--", zorder=1)
        if shown.failure_time is not None:
            _vertical_lines(
                panel, [shown.failure_time], color="#cc3311", linewidth=1.0, zorder=3, gid="failure time"
            )
    for when, y, failed in shown.crosses:
        timeline.plot(
            [when],
            [y],
            marker="X",
            markersize=12 if failed else 8,
            color="#cc3311",
            linestyle="none",
            zorder=5,
            gid="failure" if failed else None,
        )
    for style, found in shown.bars.items():
        _bars(timeline, style, found)
    if shown.stars:
        timeline.plot(
            [t for t, _ in shown.stars],
            [y for _, y in shown.stars],
            marker="*",
            markersize=11,
            color=REFERENCE_COLOUR,
            markeredgecolor="black",
            linestyle="none",
            zorder=4,
        )
    timeline.set_yticks(range(lanes))
    timeline.set_yticklabels(list(reversed(shown.lanes)), fontsize=8)
    timeline.set_ylim(-0.7, lanes - 0.05)
    timeline.set_xlim(-0.05 * shown.span, 1.05 * shown.span)  # shared by every panel
    for panel, curve in zip(rows[1:], shown.panels, strict=True):
        panel.plot(curve.times, curve.positions, color="black", linewidth=1.2, gid=f"position {curve.name}")
        if curve.reference is not None:
            panel.plot(
                [curve.reference[0]],
                [curve.reference[1]],
                marker="*",
                markersize=10,
                color=REFERENCE_COLOUR,
                markeredgecolor="black",
                linestyle="none",
            )
        panel.set_ylabel(f"{curve.name} [{curve.unit}]", fontsize=8)
        panel.tick_params(labelsize=7)
    rows[-1].set_xlabel("time [s]")
    _legend(timeline, shown.keys, 7)
    figure.suptitle(shown.title, fontsize=11, x=0.4, y=0.995, va="top")
    _assumed_note(figure, shown.assumed)
    return figure


def _label(timeline: Axes, label: Label) -> None:
    """A block's label just above the timeline, or a group's just below its upper edge."""
    style: dict[str, Any] = {"fontweight": "bold"} if label.above else {"color": "#444444"}
    timeline.text(
        label.time,
        1.01 if label.above else 0.99,
        f" {label.text}",
        transform=timeline.get_xaxis_transform(),
        ha="left",
        va="bottom" if label.above else "top",
        fontsize=7,
        **style,
    )


def _bars(timeline: Axes, style: BarStyle, found: list[tuple[float, float, float]]) -> None:
    """The bars of one style (colour, outline, hatching) over every lane, as one collection."""
    face, edge, hatch, alpha, width = style
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
