"""The dry-run figures written as SVG by hand: `dry-run --plot FILE.svg` and every figure of `achslint report`.

matplotlib lays out ticks and text for each of its figures (about half a second each), which a report of a
32-axis machine cannot afford; this module writes the same figures directly. What each shows comes from
`figuredata` (`trace_figure`, `machine_figure`), as for the PNG that `figures` draws with matplotlib:

- a trace: position over time above velocity over time, each phase shaded in its colour and numbered above
  the plot, the cam zone, zero-pulse ticks, limit and software-limit lines, the position searched for, the
  reference star, the final square, events, the failure cross, a legend beside, a zoom on the reference
  event, the title and the assumed-geometry note;
- a machine run: one lane per axis (phase bars by name, moves grey, following and standing still hatched,
  stars where a reference is taken, crosses where an axis failed or was aborted), blocks shaded in turn and
  labelled, group lines, the failure time in red, then each moving axis's position over the program's time.

The SVG is self-contained (no script, style sheet, font or image), text stays text, every string from the
user's files is escaped, and the same run gives the same bytes. Every id starts with the figure's prefix,
so that several figures share an HTML page; the element of a series or marker carries the id matplotlib's
gid would (`{prefix}-position`, `{prefix}-reference`, ...). Long curves are thinned for drawing to the
first, lowest, highest and last point of each pixel column, so that peaks survive.
"""

from __future__ import annotations

import html
import math
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING

from ..core.display import printable
from .figuredata import (
    ASSUMED_COLOUR,
    FAILURE_COLOUR,
    PULSE_COLOUR,
    REFERENCE_COLOUR,
    BarStyle,
    Key,
    Label,
    MachineFigure,
    Mark,
    Panel,
    TraceFigure,
    machine_figure,
    trace_figure,
)

if TYPE_CHECKING:
    from ..homing.motion import Trace
    from ..machine.run import MachineRun

WIDTH = 1000
FONT = "DejaVu Sans, Helvetica, Arial, sans-serif"
LINE = 15  # px between the lines of a legend entry
DASHES = {"-": None, "--": "6 3", ":": "1.5 2.5"}
POINT = 100 / 72  # px per point: matplotlib's marker sizes at its 100 dpi


def _n(value: float) -> str:
    """A pixel coordinate with one decimal, as short as it gets."""
    text = f"{value:.1f}"
    if text.endswith(".0"):
        text = text[:-2]
    return "0" if text == "-0" else text


def _esc(text: str) -> str:
    return html.escape(printable(text), quote=True)


def _data(value: float) -> str:
    """A data value in an attribute (what tests and readers of the SVG compare)."""
    return format(value, ".9g")


class _Scale:
    """Data values onto pixels, linearly; a range of no width is widened so that it can be drawn."""

    def __init__(self, low: float, high: float, start: float, end: float) -> None:
        if not (math.isfinite(low) and math.isfinite(high)) or high - low <= 1e-9 * max(1.0, abs(low)):
            middle = low if math.isfinite(low) else 0.0
            low, high = middle - 1.0, middle + 1.0
        self.low, self.high = low, high
        self.start, self.end = start, end
        self.factor = (end - start) / (high - low)

    def __call__(self, value: float) -> float:
        return self.start + (value - self.low) * self.factor

    def ticks(self, count: int) -> list[tuple[float, str]]:
        """About `count` round values within the range, with their labels."""
        span = self.high - self.low
        magnitude = 10 ** math.floor(math.log10(span / count))
        step = magnitude
        for multiple in (1.0, 2.0, 2.5, 5.0, 10.0):
            step = multiple * magnitude
            if span / step <= count:
                break
        decimals = max(0, -math.floor(math.log10(step) + 1e-9))
        if round(step, decimals) != step:  # 0.25, 2.5e-05
            decimals += 1
        first, last = math.ceil(self.low / step - 1e-9), math.floor(self.high / step + 1e-9)
        ticks = []
        for k in range(first, last + 1):
            text = f"{k * step:.{decimals}f}"
            if text.lstrip("-").strip("0.") == "":
                text = "0"
            ticks.append((k * step, text.replace("-", "\u2212")))
        return ticks


class _Svg:
    """The elements of one figure, written in order."""

    def __init__(self, prefix: str) -> None:
        self.prefix = prefix
        self.out: list[str] = []
        self.defs: list[str] = []
        self.hatches: dict[tuple[str, str], str] = {}

    def id(self, name: str) -> str:
        return _esc(f"{self.prefix}-{name}".replace(" ", "_"))

    def add(self, element: str) -> None:
        self.out.append(element)

    def text(
        self,
        x: float,
        y: float,
        text: str,
        *,
        size: float = 11,
        anchor: str = "start",
        colour: str | None = None,
        bold: bool = False,
        rotate: bool = False,
        extra: str = "",
    ) -> None:
        """One line of text, or several (`\\n`) going down from `y`."""
        attributes = f' font-size="{_n(size)}"'
        if anchor != "start":
            attributes += f' text-anchor="{anchor}"'
        if colour:
            attributes += f' fill="{colour}"'
        if bold:
            attributes += ' font-weight="bold"'
        if rotate:
            attributes += f' transform="rotate(-90 {_n(x)} {_n(y)})"'
        lines = text.split("\n")
        if len(lines) == 1:
            self.add(f'<text x="{_n(x)}" y="{_n(y)}"{attributes}{extra}>{_esc(text)}</text>')
            return
        spans = "".join(
            f'<tspan x="{_n(x)}" dy="{0 if index == 0 else _n(size * 1.25)}">{_esc(line)}</tspan>'
            for index, line in enumerate(lines)
        )
        self.add(f'<text x="{_n(x)}" y="{_n(y)}"{attributes}{extra}>{spans}</text>')

    def hatch(self, kind: str, colour: str) -> str:
        """The id of a hatching pattern ("//" or "xx") in `colour`, defined once per figure."""
        if (kind, colour) not in self.hatches:
            name = self.id(f"hatch{len(self.hatches) + 1}")
            lines = "M0 8L8 0M-2 2L2 -2M6 10L10 6" if kind == "//" else "M0 8L8 0M0 0L8 8"
            self.defs.append(
                f'<pattern id="{name}" width="8" height="8" patternUnits="userSpaceOnUse">'
                f'<path d="{lines}" stroke="{colour}" stroke-width="0.8"/></pattern>'
            )
            self.hatches[(kind, colour)] = name
        return self.hatches[(kind, colour)]

    def render(self, width: float, height: float, title: str, standalone: bool) -> str:
        size = f'width="{_n(width)}" height="{_n(height)}" ' if standalone else ""
        namespace = 'xmlns="http://www.w3.org/2000/svg" ' if standalone else ""
        head = (
            f'<svg {namespace}{size}class="figure" role="img" viewBox="0 0 {_n(width)} {_n(height)}" '
            f'font-family="{FONT}" font-size="11">'
        )
        defs = f"<defs>{''.join(self.defs)}</defs>" if self.defs else ""
        body = f'{head}<title>{_esc(title)}</title><rect width="100%" height="100%" fill="white"/>{defs}'
        text = body + "".join(self.out) + "</svg>"
        return f'<?xml version="1.0" encoding="UTF-8"?>\n{text}\n' if standalone else text


def _path(xs: Sequence[float], ys: Sequence[float], sx: _Scale, sy: _Scale, columns: float) -> str:
    """The `d` of a polyline through (x, y) in data units, broken where a value is NaN (or infinite). More points than two per
    pixel column are thinned to the first, lowest, highest and last of each column (in their order);
    runs of points on one pixel row or column keep only their ends."""
    parts: list[str] = []
    run: list[tuple[float, float]] = []

    def flush() -> None:
        if run:
            points = _thin(run) if len(run) > 2 * columns else run
            parts.append(_straight([(_n(x), _n(y)) for x, y in points]))
            run.clear()

    # `sx(x)` and `sy(y)` written out (the same arithmetic): a figure has hundreds of thousands of points
    x_low, x_start, x_factor = sx.low, sx.start, sx.factor
    y_low, y_start, y_factor = sy.low, sy.start, sy.factor
    finite, add = math.isfinite, run.append
    for x, y in zip(xs, ys, strict=True):
        if finite(x) and finite(y):
            add((x_start + (x - x_low) * x_factor, y_start + (y - y_low) * y_factor))
        else:
            flush()
    flush()
    return "".join(parts)


def _thin(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    kept: list[tuple[float, float]] = []
    column: list[tuple[float, float]] = []
    current = math.floor(points[0][0])
    for point in points:
        here = math.floor(point[0])
        if here != current and column:
            kept += _extremes(column)
            column = []
            current = here
        column.append(point)
    kept += _extremes(column)
    return kept


def _extremes(column: list[tuple[float, float]]) -> list[tuple[float, float]]:
    if len(column) <= 4:
        return column
    low = min(range(len(column)), key=lambda i: column[i][1])
    high = max(range(len(column)), key=lambda i: column[i][1])
    return [column[i] for i in sorted({0, low, high, len(column) - 1})]


def _straight(points: list[tuple[str, str]]) -> str:
    """`M x y L x y x y ...` without the inner points of runs along one row or one column of pixels."""
    kept: list[tuple[str, str]] = []
    for point in points:
        if kept and point == kept[-1]:
            continue
        if len(kept) >= 2 and (
            (kept[-2][1] == kept[-1][1] == point[1]) or (kept[-2][0] == kept[-1][0] == point[0])
        ):
            kept[-1] = point
        else:
            kept.append(point)
    head, *rest = kept
    line = "L" + " ".join(f"{x} {y}" for x, y in rest) if rest else ""
    return f"M{head[0]} {head[1]}{line}"


_STAR = [
    (
        math.sin(math.pi * k / 5) * (1.0 if k % 2 == 0 else 0.382),
        -math.cos(math.pi * k / 5) * (1.0 if k % 2 == 0 else 0.382),
    )
    for k in range(10)
]
_CROSS = [
    (-1, -0.6),
    (-0.6, -1),
    (0, -0.4),
    (0.6, -1),
    (1, -0.6),
    (0.4, 0),
    (1, 0.6),
    (0.6, 1),
    (0, 0.4),
    (-0.6, 1),
    (-1, 0.6),
    (-0.4, 0),
]


def _marker(
    svg: _Svg, x: float, y: float, kind: str, size: float, colour: str, edge: str | None, extra: str = ""
) -> None:
    """A marker like matplotlib's ("*", "s", "o", "X") of `size` points, centred on (x, y) px."""
    radius = size * POINT / 2
    stroke = f' stroke="{edge}" stroke-width="1"' if edge else ""
    if kind == "o":
        svg.add(f'<circle cx="{_n(x)}" cy="{_n(y)}" r="{_n(radius)}" fill="{colour}"{stroke}{extra}/>')
        return
    if kind == "s":
        side = radius * 1.6
        svg.add(
            f'<rect x="{_n(x - side / 2)}" y="{_n(y - side / 2)}" width="{_n(side)}" height="{_n(side)}" '
            f'fill="{colour}"{stroke}{extra}/>'
        )
        return
    shape = _STAR if kind == "*" else _CROSS
    scale = radius * (1.1 if kind == "*" else 0.8)
    points = " ".join(f"{_n(x + dx * scale)} {_n(y + dy * scale)}" for dx, dy in shape)
    svg.add(f'<path d="M{points}Z" fill="{colour}"{stroke}{extra}/>')


def _dash(style: str) -> str:
    dash = DASHES.get(style)
    return f' stroke-dasharray="{dash}"' if dash else ""


def _legend(svg: _Svg, keys: Sequence[Key], x: float, y: float, size: float = 11) -> float:
    """The legend entries from (x, y) down; returns where it ends."""
    svg.add(f'<g id="{svg.id("legend")}">')
    for key in keys:
        middle = y - size * 0.35
        if key.kind == "patch":
            fill = f'fill="{key.colour}"' + (f' fill-opacity="{key.alpha:g}"' if key.alpha < 1 else "")
            edge = f' stroke="{key.edge}" stroke-width="0.8"' if key.edge else ""
            svg.add(f'<rect x="{_n(x)}" y="{_n(middle - 5)}" width="22" height="10" {fill}{edge}/>')
            if key.hatch:
                pattern = svg.hatch(key.hatch, key.edge or "#555555")
                svg.add(
                    f'<rect x="{_n(x)}" y="{_n(middle - 5)}" width="22" height="10" fill="url(#{pattern})"/>'
                )
        elif key.kind == "line":
            svg.add(
                f'<path d="M{_n(x)} {_n(middle)}h22" stroke="{key.colour}" stroke-width="{key.width:g}"'
                f"{_dash(key.style)}/>"
            )
        else:
            _marker(svg, x + 11, middle, key.marker, min(key.size, 10), key.colour, key.edge)
        svg.text(x + 30, y, key.label, size=size)
        y += LINE * (key.label.count("\n") + 1) + 3
    svg.add("</g>")
    return y


def _frame(
    svg: _Svg, sx: _Scale, sy: _Scale, *, x_labels: bool, y_ticks: int, x_ticks: int = 7, size: float = 10.5
) -> None:
    """The panel's box, its ticks, and the tick labels on the left (and below when `x_labels`)."""
    left, right, bottom, top = sx.start, sx.end, sy.start, sy.end
    marks = []
    for value, text in sy.ticks(y_ticks):
        y = sy(value)
        marks.append(f"M{_n(left - 4)} {_n(y)}h4")
        svg.text(left - 7, y + size * 0.35, text, size=size, anchor="end")
    for value, text in sx.ticks(x_ticks):
        x = sx(value)
        marks.append(f"M{_n(x)} {_n(bottom)}v4")
        if x_labels:
            svg.text(x, bottom + 6 + size, text, size=size, anchor="middle")
    svg.add(
        f'<rect x="{_n(left)}" y="{_n(top)}" width="{_n(right - left)}" height="{_n(bottom - top)}" '
        'fill="none" stroke="black" stroke-width="0.8"/>'
    )
    svg.add(f'<path d="{"".join(marks)}" stroke="black" stroke-width="0.8"/>')


def _curve(
    svg: _Svg, name: str, xs: Sequence[float], ys: Sequence[float], sx: _Scale, sy: _Scale, width: float
) -> None:
    if xs:
        d = _path(xs, ys, sx, sy, sx.end - sx.start)
        svg.add(
            f'<path id="{svg.id(name)}" d="{d}" fill="none" stroke="black" stroke-width="{width:g}" stroke-linejoin="round"/>'
        )


def _lines_across(
    svg: _Svg,
    name: str | None,
    values: Iterable[float],
    sx: _Scale,
    sy: _Scale,
    colour: str,
    width: float,
    style: str = "-",
) -> None:
    """Horizontal lines across a panel at data values (those outside its range left out)."""
    d = "".join(f"M{_n(sx.start)} {_n(sy(v))}H{_n(sx.end)}" for v in values if sy.end <= sy(v) <= sy.start)
    if d:
        ident = f' id="{svg.id(name)}"' if name else ""
        svg.add(f'<path{ident} d="{d}" stroke="{colour}" stroke-width="{width:g}"{_dash(style)}/>')


# --- a single-axis trace --------------------------------------------------------------------------


def trace_svg(trace: Trace, prefix: str, *, standalone: bool = False) -> str:
    """The figure of a single-axis dry-run as an `<svg>` element (`standalone`: a whole SVG file)."""
    shown = trace_figure(trace)
    svg = _Svg(prefix)
    left, right = 75.0, 640.0
    top_panel, bottom_panel = (60.0, 380.0), (392.0, 540.0)
    t_high = max(shown.times) if shown.times else 1.0
    pad = 0.05 * t_high
    sx = _Scale(-pad if shown.times else 0.0, t_high + pad, left, right)
    sy = _Scale(shown.view[0], shown.view[1], top_panel[1], top_panel[0])
    v_low, v_high = (min(shown.velocities), max(shown.velocities)) if shown.velocities else (0.0, 0.0)
    v_pad = 0.05 * max(v_high - v_low, 1e-9)
    sv = _Scale(min(v_low, 0.0) - v_pad, max(v_high, 0.0) + v_pad, bottom_panel[1], bottom_panel[0])

    svg.text((left + right) / 2, 28, shown.title, size=15, anchor="middle")
    svg.add(f'<g id="{svg.id("phases")}">')
    for number, phase, colour in shown.phases:
        x0, x1 = sx(phase.start_time), sx(phase.end_time)
        for scale in (sy, sv):
            svg.add(
                f'<rect x="{_n(x0)}" y="{_n(scale.end)}" width="{_n(max(x1 - x0, 0.1))}" '
                f'height="{_n(scale.start - scale.end)}" fill="{colour}" fill-opacity="0.18" '
                f'data-phase="{number}"/>'
            )
        svg.text(
            (x0 + x1) / 2, top_panel[0] - 5, str(number), size=12, anchor="middle", colour=colour, bold=True
        )
    svg.add("</g>")
    if shown.cam:
        svg.add(f'<g id="{svg.id("cam")}" fill="#117733" fill-opacity="0.14">')
        for low, high in shown.cam:
            y0, y1 = max(sy(high), sy.end), min(sy(low), sy.start)
            if y1 > y0:
                svg.add(
                    f'<rect x="{_n(left)}" y="{_n(y0)}" width="{_n(right - left)}" height="{_n(y1 - y0)}" data-low="{_data(low)}" data-high="{_data(high)}"/>'
                )
        svg.add("</g>")
    if shown.pulses:
        d = "".join(f"M{_n(left)} {_n(sy(v))}h7" for v in shown.pulses if sy.end <= sy(v) <= sy.start)
        svg.add(f'<path id="{svg.id("zero_pulses")}" d="{d}" stroke="{PULSE_COLOUR}" stroke-width="2"/>')
    by_name: dict[str, list[float]] = {}
    for level in shown.levels:
        by_name.setdefault(level.name, []).append(level.value)
    for name, values in by_name.items():
        level = next(level for level in shown.levels if level.name == name)
        _lines_across(svg, name, values, sx, sy, level.colour, level.width, level.style)
    _lines_across(svg, None, [0.0], sx, sv, "grey", 0.6)
    _curve(svg, "position", shown.times, shown.positions, sx, sy, 1.4)
    _curve(svg, "velocity", shown.times, shown.velocities, sx, sv, 1.2)
    _marks(svg, shown.marks, sx, sy)
    _frame(svg, sx, sy, x_labels=False, y_ticks=6)
    _frame(svg, sx, sv, x_labels=True, y_ticks=3)
    svg.text(
        18,
        (top_panel[0] + top_panel[1]) / 2,
        f"position [{shown.unit}]",
        size=12,
        anchor="middle",
        rotate=True,
    )
    svg.text(
        18,
        (bottom_panel[0] + bottom_panel[1]) / 2,
        f"velocity [{shown.unit}/s]",
        size=12,
        anchor="middle",
        rotate=True,
    )
    svg.text((left + right) / 2, bottom_panel[1] + 40, "time [s]", size=12, anchor="middle")
    if shown.empty is not None:
        svg.text((left + right) / 2, (top_panel[0] + top_panel[1]) / 2, shown.empty, size=13, anchor="middle")
    end = _legend(svg, shown.keys, right + 18, top_panel[0] + 6)
    height = bottom_panel[1] + 60
    if shown.zoom is not None:
        height = max(height, _zoom(svg, shown, max(bottom_panel[0] + 10, end + 30)) + 40)
    height = _note(svg, shown.assumed, height)
    return svg.render(WIDTH, height, shown.title, standalone)


def _marks(svg: _Svg, marks: Sequence[Mark], sx: _Scale, sy: _Scale) -> None:
    for mark in sorted(marks, key=lambda m: m.layer):  # stable: the order within a layer is kept
        extra = f' data-t="{_data(mark.time)}" data-x="{_data(mark.position)}"'
        if mark.gid:
            extra = f' id="{svg.id(mark.gid)}"' + extra
        _marker(svg, sx(mark.time), sy(mark.position), mark.marker, mark.size, mark.colour, mark.edge, extra)


def _zoom(svg: _Svg, shown: TraceFigure, top: float) -> float:
    """The zoom on the reference event below the legend; returns its lower edge."""
    zoom = shown.zoom
    assert zoom is not None
    left, right, bottom = 745.0, 985.0, top + 140
    times = zoom.times or [zoom.event.time]
    positions = [*zoom.positions, zoom.event.position]
    t_pad = 0.05 * max(max(times) - min(times), 1e-9)
    x_pad = 0.08 * max(max(positions) - min(positions), 1e-9)
    sx = _Scale(min(times) - t_pad, max(times) + t_pad, left, right)
    sy = _Scale(min(positions) - x_pad, max(positions) + x_pad, bottom, top)
    svg.add(f'<g id="{svg.id("zoom")}">')
    svg.text((left + right) / 2, top - 7, zoom.title, size=10.5, anchor="middle")
    if zoom.pulses:
        d = "".join(f"M{_n(left)} {_n(sy(v))}h12" for v in zoom.pulses if top <= sy(v) <= bottom)
        if d:
            svg.add(f'<path d="{d}" stroke="{PULSE_COLOUR}" stroke-width="2.5"/>')
    _lines_across(svg, None, [zoom.event.position], sx, sy, REFERENCE_COLOUR, 0.8, ":")
    if zoom.times:
        d = _path(zoom.times, zoom.positions, sx, sy, right - left)
        svg.add(f'<path d="{d}" fill="none" stroke="black" stroke-width="1.2"/>')
    _marker(svg, sx(zoom.event.time), sy(zoom.event.position), "*", 12, REFERENCE_COLOUR, "black")
    _frame(svg, sx, sy, x_labels=True, y_ticks=4, x_ticks=4, size=9)
    svg.add("</g>")
    return bottom + 14


def _note(svg: _Svg, note: str, height: float) -> float:
    """The assumed-geometry note under the figure; returns the figure's new height."""
    if not note:
        return height
    svg.add(f'<g id="{svg.id("assumed")}">')
    svg.text(10, height, note, size=11, colour=ASSUMED_COLOUR)
    svg.add("</g>")
    return height + 14 * (note.count("\n") + 1) + 6


# --- the machine dry-run ------------------------------------------------------------------------


def machine_svg(run: MachineRun, prefix: str, *, standalone: bool = False) -> str:
    """The figure of a machine dry-run as an `<svg>` element (`standalone`: a whole SVG file)."""
    shown = machine_figure(run)
    svg = _Svg(prefix)
    left, right = 130.0, 690.0
    lanes = len(shown.lanes)
    top = 78.0
    bottom = top + max(110.0, 30.0 * lanes + 12)
    sx = _Scale(-0.05 * shown.span, 1.05 * shown.span, left, right)
    sy = _Scale(-0.7, lanes - 0.05, bottom, top)
    svg.text((left + right) / 2, 22, shown.title, size=15, anchor="middle")
    panels: list[tuple[_Scale, Panel]] = []
    y = bottom
    for curve in shown.panels:
        finite = [p for p in curve.positions if math.isfinite(p)] or [0.0]
        low, high = min(finite), max(finite)
        pad = 0.05 * max(high - low, 1e-9)
        panels.append((_Scale(low - pad, high + pad, y + 102, y + 16), curve))
        y += 102
    for scale in [sy, *(scale for scale, _ in panels)]:
        _background(svg, shown, sx, scale)
    # the lanes
    svg.add(f'<g id="{svg.id("lanes")}">')
    for style, found in shown.bars.items():
        _bars(svg, style, found, sx, sy)
    svg.add("</g>")
    if shown.stars:
        svg.add(f'<g id="{svg.id("references")}">')
        for when, lane in shown.stars:
            _marker(svg, sx(when), sy(lane), "*", 11, REFERENCE_COLOUR, "black")
        svg.add("</g>")
    for when, lane, failed in shown.crosses:
        extra = f' id="{svg.id("failure")}"' if failed else ""
        _marker(
            svg,
            sx(when),
            sy(lane),
            "X",
            12 if failed else 8,
            FAILURE_COLOUR,
            None,
            extra + f' data-t="{_data(when)}"',
        )
    for index, text in enumerate(shown.lanes):
        svg.text(left - 8, sy(lanes - 1 - index) + 4, text, size=11, anchor="end")
    svg.add(
        f'<rect x="{_n(left)}" y="{_n(top)}" width="{_n(right - left)}" height="{_n(bottom - top)}" fill="none" stroke="black" stroke-width="0.8"/>'
    )
    svg.add(f'<g id="{svg.id("labels")}">')
    for label, room in _rooms(shown.labels, sx, right):
        if label.above:
            text = _fit(label.text, room, 9 * 0.62)
            svg.text(sx(label.time) + 3, top - 5 - 11.25 * text.count("\n"), text, size=9, bold=True)
        else:
            svg.text(
                sx(label.time) + 3, top + 12, _fit(label.text, room, 10 * 0.55), size=10, colour="#444444"
            )
    svg.add("</g>")
    for number, (scale, curve) in enumerate(panels, 1):
        _curve(svg, f"position {curve.name}", curve.times, curve.positions, sx, scale, 1.2)
        if curve.reference is not None:
            _marker(
                svg, sx(curve.reference[0]), scale(curve.reference[1]), "*", 10, REFERENCE_COLOUR, "black"
            )
        _frame(svg, sx, scale, x_labels=number == len(panels), y_ticks=4, size=9.5)
        svg.text(
            left - 52,
            (scale.start + scale.end) / 2,
            f"{curve.name} [{curve.unit}]",
            size=10.5,
            anchor="middle",
            rotate=True,
        )
    if not panels:
        marks = "".join(f"M{_n(sx(v))} {_n(bottom)}v4" for v, _ in sx.ticks(7))
        svg.add(f'<path d="{marks}" stroke="black" stroke-width="0.8"/>')
        for value, text in sx.ticks(7):
            svg.text(sx(value), bottom + 16, text, size=10.5, anchor="middle")
    last = panels[-1][0].start if panels else bottom
    svg.text((left + right) / 2, last + 38, "time [s]", size=12, anchor="middle")
    end = _legend(svg, shown.keys, right + 15, top + 6, size=10.5)
    height = _note(svg, shown.assumed, max(last + 62, end + 10))
    return svg.render(WIDTH, height, shown.title, standalone)


def _background(svg: _Svg, shown: MachineFigure, sx: _Scale, sy: _Scale) -> None:
    """Every other block shaded, block lines, group lines (dashed) and the failure time over one panel."""
    y0, y1 = sy.end, sy.start
    shaded = "".join(
        f'<rect x="{_n(sx(t0))}" y="{_n(y0)}" width="{_n(sx(t1) - sx(t0))}" height="{_n(y1 - y0)}"/>'
        for t0, t1 in shown.shaded
    )
    if shaded:
        svg.add(f'<g fill="#eeeeee">{shaded}</g>')
    for times, style in ((shown.block_lines, "-"), (shown.group_lines, "--")):
        d = "".join(f"M{_n(sx(t))} {_n(y0)}V{_n(y1)}" for t in times)
        if d:
            svg.add(f'<path d="{d}" stroke="#444444" stroke-width="0.8"{_dash(style)}/>')
    if shown.failure_time is not None:
        svg.add(
            f'<path d="M{_n(sx(shown.failure_time))} {_n(y0)}V{_n(y1)}" stroke="{FAILURE_COLOUR}" stroke-width="1"/>'
        )


def _bars(
    svg: _Svg, style: BarStyle, found: list[tuple[float, float, float]], sx: _Scale, sy: _Scale
) -> None:
    """The bars of one style (face, edge, hatch, alpha, line width) over every lane, as one group."""
    face, edge, hatch, alpha, width = style
    half = (sy(0) - sy(0.6)) / 2
    rects = "".join(
        f'<rect x="{_n(sx(x))}" y="{_n(sy(y) - half)}" width="{_n(max(sx(x + w) - sx(x), 0.1))}" height="{_n(2 * half)}"/>'
        for x, w, y in found
    )
    opacity = f' fill-opacity="{alpha:g}"' if alpha < 1 else ""
    svg.add(f'<g fill="{face}"{opacity} stroke="{edge}" stroke-width="{width:g}">{rects}</g>')
    if hatch:
        svg.add(f'<g fill="url(#{svg.hatch(hatch, edge)})">{rects}</g>')


def _rooms(labels: Sequence[Label], sx: _Scale, right: float) -> list[tuple[Label, float]]:
    """Each label with the pixels it has before the next label of its row (the last: to the legend)."""
    rooms = []
    for index, label in enumerate(labels):
        following = next((other for other in labels[index + 1 :] if other.above == label.above), None)
        end = sx(following.time) if following is not None else right + (0 if label.above else -4)
        rooms.append((label, end - sx(label.time) - 3))
    return rooms


def _fit(text: str, room: float, char: float) -> str:
    """Each line of `text` cut (with an ellipsis) to about `room` pixels at `char` pixels a character: the
    block's full text is in the report's table and in `dry-run`'s output."""
    most = max(int(room / char), 2)
    return "\n".join(line if len(line) <= most else line[: most - 1] + "\u2026" for line in text.split("\n"))
