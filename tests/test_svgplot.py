"""The dry-run figures written as SVG without matplotlib (`output/svgplot.py`, issue 29's budget): what
`--plot FILE.svg` writes and what `achslint report` embeds.

A hand-made trace (the arithmetic in the comments) gives known panels, series, phase spans and markers; the
SVG parses as XML, its ids carry the figure's prefix, the same trace gives the same bytes, text from the
lists is escaped, a long curve is thinned without losing its peaks, and the machine timeline has its lanes,
labels, position curves and failure. Writing an SVG never loads matplotlib.
"""

from __future__ import annotations

import math
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

import pytest

from achslint.homing.motion import Event, PhaseRecord, Segment, Trace
from achslint.homing.scenario import Scenario
from achslint.machine.run import machine_dry_run
from achslint.output.svgplot import machine_svg, trace_svg

from .conftest import FIXTURES, ROOT

NS = "{http://www.w3.org/2000/svg}"
EXAMPLE = ROOT / "docs" / "dry-run" / "machine"


@dataclass(frozen=True)
class _Setup:
    spindle: bool = False
    modulo: tuple[float, float] | None = None
    soft_limits: tuple[float, float] = (-1000.0, 1000.0)


@dataclass(frozen=True)
class _Strategy:
    """What a figure reads of a homing strategy."""

    title: str = "hand-made <homing> & 'test'"
    setup: _Setup = field(default_factory=_Setup)
    with_zero_pulse: bool = True


def hand_made() -> Trace:
    """Two phases, then the reference on a zero pulse.

    1. to the cam, negative at 25 mm/s, 100 mm/s²: accelerating 0..0.25 s to -3.125 mm, constant to 1.95 s
       (-3.125 - 25 x 1.7 = -45.625), braking to 2.2 s (-45.625 - 6.25 + 3.125 = -48.75);
    2. off the cam, positive at 5 mm/s: accelerating 2.2..2.25 s to -48.625, constant to 4.25 s (+10 =
       -38.625), braking to 4.3 s (-38.5). The zero pulse at -45 (every 10 mm from -55) comes at
       2.25 + 3.625 / 5 = 2.975 s; it becomes 0, so the axis ends at -38.5 + 45 = 6.5 mm homed.
    """
    scenario = Scenario(
        start_position=0.0,
        cam=(-60.0, -40.0),
        zero_pulse_period=10.0,
        zero_pulse_phase=-55.0,
        hardware_latch=False,
        cycle_time=0.001,
        limit_switches=(-70.0, 10.0),
        fixed_stop=None,
        assumed=["limit_switches"],
    )
    first = PhaseRecord(
        "to the reference cam",
        "negative",
        25.0,
        0.0,
        -48.75,
        0.0,
        2.2,
        "cam reached",
        [
            Segment(0.0, 0.25, 0.0, 0.0, -100.0),
            Segment(0.25, 1.95, -3.125, -25.0, 0.0),
            Segment(1.95, 2.2, -45.625, -25.0, 100.0),
        ],
    )
    second = PhaseRecord(
        "off the cam <&>",
        "positive",
        5.0,
        -48.75,
        -38.5,
        2.2,
        4.3,
        "cam left",
        [
            Segment(2.2, 2.25, -48.75, 0.0, 100.0),
            Segment(2.25, 4.25, -48.625, 5.0, 0.0),
            Segment(4.25, 4.3, -38.625, 5.0, -100.0),
        ],
    )
    return Trace(
        strategy=_Strategy(),  # type: ignore[arg-type]  # a stand-in with what the figure reads
        scenario=scenario,
        unit="mm",
        acceleration=100.0,
        phases=[first, second],
        events=[Event(1.85, -43.125, "cam reached"), Event(2.975, -45.0, "zero pulse")],
        reference={"kind": "zero pulse", "position": -45.0, "value": 0.0, "speed": 5.0, "time": 2.975},
        final_position=6.5,
    )


def parse(text: str) -> ET.Element:
    return ET.fromstring(text)


def by_id(root: ET.Element) -> dict[str, ET.Element]:
    found = {}
    for element in root.iter():
        if "id" in element.attrib:
            assert element.attrib["id"] not in found, element.attrib["id"]  # no id twice
            found[element.attrib["id"]] = element
    return found


def texts(element: ET.Element) -> list[str]:
    return ["".join(e.itertext()) for e in element.iter(f"{NS}text")]


def points(d: str) -> list[tuple[float, float]]:
    numbers = [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", d)]
    return list(zip(numbers[::2], numbers[1::2], strict=True))


def test_the_trace_figure_has_its_panels_series_phases_and_markers():
    root = parse(trace_svg(hand_made(), "t", standalone=True))
    assert root.tag == f"{NS}svg" and root.attrib["viewBox"].startswith("0 0 ")
    ids = by_id(root)
    assert all(name.startswith("t-") for name in ids)
    assert {"t-position", "t-velocity", "t-phases", "t-cam", "t-zero_pulses", "t-limit_switch"} <= set(ids)
    assert {"t-reference", "t-final", "t-legend", "t-zoom", "t-assumed"} <= set(ids)
    # both panels shaded per phase, each phase numbered above the plot in its colour
    spans = [r for r in ids["t-phases"].iter(f"{NS}rect")]
    assert [r.attrib["data-phase"] for r in spans] == ["1", "1", "2", "2"]
    numbers = {t.text: t.attrib["fill"] for t in ids["t-phases"].iter(f"{NS}text")}
    assert numbers == {"1": spans[0].attrib["fill"], "2": spans[2].attrib["fill"]}
    assert spans[0].attrib["fill"] != spans[2].attrib["fill"]
    # the reference star on the zero pulse, the final square where the motion ends, the cam as drawn
    assert (ids["t-reference"].attrib["data-t"], ids["t-reference"].attrib["data-x"]) == ("2.975", "-45")
    assert (ids["t-final"].attrib["data-t"], ids["t-final"].attrib["data-x"]) == ("4.3", "-38.5")
    cam = ids["t-cam"].find(f"{NS}rect")
    assert cam is not None and (cam.attrib["data-low"], cam.attrib["data-high"]) == ("-60", "-40")
    # zero pulses in the view: -45, -35, -25, -15, -5 (the view runs from -52.65 to 3.9 before the limit
    # switches widen it); both limit switches lie near the motion and are drawn
    assert ids["t-zero_pulses"].attrib["d"].count("M") == 5
    assert ids["t-limit_switch"].attrib["d"].count("M") == 2
    events = [c for c in root.iter(f"{NS}circle") if c.attrib.get("data-t") == "1.85"]
    assert len(events) == 1  # the cam reached; the zero pulse is the star
    legend = " | ".join(texts(ids["t-legend"]))
    assert "1. to the reference cam (negative, 25 mm/s)" in legend
    assert "2. off the cam <&> (positive, 5 mm/s)" in legend
    assert "reference (zero pulse): \u221245 mm \u2192 0 mm" in legend
    assert "limit switch: \u221270, 10 mm" in legend and "software limit (after homing)" in legend
    assert "final position 6.5 mm (homed)" in legend and "events: cam reached" in legend
    assert texts(ids["t-assumed"]) == ["ASSUMED, not given: limit_switches"]
    assert "zoom: zero pulse at t = 2.975 s" in texts(ids["t-zoom"])
    assert texts(root)[0] == "hand-made <homing> & 'test': homed in 4.3 s"
    everything = texts(root)
    assert "position [mm]" in everything and "velocity [mm/s]" in everything and "time [s]" in everything


def test_the_curves_follow_the_samples():
    root = parse(trace_svg(hand_made(), "t", standalone=True))
    ids = by_id(root)
    position = points(ids["t-position"].attrib["d"])
    velocity = points(ids["t-velocity"].attrib["d"])
    # time runs left to right; the lowest position (-48.75 at 2.2 s) is drawn lowest, the start highest
    assert [x for x, _ in position] == sorted(x for x, _ in position)
    lowest = max(position, key=lambda p: p[1])
    assert position[0][1] == min(y for _, y in position)
    share = (lowest[0] - position[0][0]) / (position[-1][0] - position[0][0])
    assert math.isclose(share, 2.2 / 4.3, abs_tol=0.005)
    # the velocity: -25 between 0.25 and 1.95 s as one straight run of two points, +5 after
    flat = [p for p in velocity if p[1] == max(y for _, y in velocity)]
    assert len(flat) == 2


def test_the_same_trace_gives_the_same_bytes_and_the_prefix_only_renames_ids():
    first, second = trace_svg(hand_made(), "a1"), trace_svg(hand_made(), "a1")
    assert first == second
    other = trace_svg(hand_made(), "b2")
    assert other != first and other.replace('"b2-', '"a1-').replace("#b2-", "#a1-") == first


def test_the_html_element_has_no_namespace_address_and_the_file_does():
    embedded, standalone = trace_svg(hand_made(), "a"), trace_svg(hand_made(), "a", standalone=True)
    assert "http" not in embedded and embedded.startswith('<svg class="figure"')
    assert standalone.startswith(
        '<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg"'
    )
    assert 'width="1000"' in standalone


def test_text_from_the_lists_is_escaped():
    text = trace_svg(hand_made(), "t")
    assert "off the cam &lt;&amp;&gt;" in text and "hand-made &lt;homing&gt; &amp; &#x27;test&#x27;" in text
    assert "<homing>" not in text and "<&>" not in text


def test_a_long_curve_is_thinned_and_keeps_its_peaks():
    """2,000 short moves back and forth of 1 mm, and one 10 mm spike in the middle: about 80,000 samples
    are drawn as a few points per pixel column, and the spike's top is still the highest point."""
    trace = hand_made()
    segments = []
    t = 0.0
    for k in range(2000):
        height = 10.0 if k == 1000 else 1.0
        v = height / 0.01 if k % 2 == 0 else -height / 0.01
        x0 = 0.0 if k % 2 == 0 else height
        segments.append(Segment(t, t + 0.01, x0, v, 0.0))
        t += 0.01
    trace.phases = [PhaseRecord("to and fro", "positive", 100.0, 0.0, 0.0, 0.0, t, "done", segments)]
    trace.events, trace.reference, trace.final_position = [], None, None
    root = parse(trace_svg(trace, "t", standalone=True))
    ids = by_id(root)
    drawn = points(ids["t-position"].attrib["d"])
    frame = next(r for r in root.iter(f"{NS}rect") if r.attrib.get("fill") == "none")
    width, height = float(frame.attrib["width"]), float(frame.attrib["height"])
    assert len(drawn) <= 4 * width + 2
    # the view runs 10 % beyond the motion on each side (8 % plus 2 %): the motion 0..10 takes 1/1.2 of it
    top, bottom = min(y for _, y in drawn), max(y for _, y in drawn)
    assert math.isclose(bottom - top, height / 1.2, abs_tol=0.2)


def test_a_trace_without_motion_says_so():
    trace = hand_made()
    trace.phases, trace.events, trace.reference, trace.final_position = [], [], None, None
    trace.outcome, trace.failure = "failed", "no speed"
    root = parse(trace_svg(trace, "t", standalone=True))
    assert "no homing motion: no speed" in texts(root)
    assert "t-failure" in by_id(root) and "t-position" not in by_id(root)


@pytest.fixture(scope="module")
def failed_run(tmp_path_factory: pytest.TempPathFactory):
    folder = tmp_path_factory.mktemp("timeline")
    program = folder / "rfp.nc"
    program.write_text("N10 G74 Z1\nN20 G74 X1 Y1\n")
    scenario = folder / "machine.toml"
    scenario.write_text(
        (EXAMPLE / "machine.toml").read_text(encoding="utf-8").replace("[-30.0, 610.0]", "[-3.0, 610.0]")
    )
    run, _ = machine_dry_run(EXAMPLE / "listen" / "hochlauf.lis", program, scenario)
    assert run.failure is not None and run.failure.axis == "Y"  # Y's limit switch -3 lies before its pulse
    return run


def test_the_timeline_has_a_lane_per_axis_the_blocks_and_the_failure(failed_run):
    root = parse(machine_svg(failed_run, "m", standalone=True))
    ids = by_id(root)
    assert all(name.startswith("m-") for name in ids)
    words = texts(root)
    lanes = [w for w in words if re.fullmatch(r"[A-Z] \(.*\)", w)]
    assert lanes[0] == "X (aborted)" and lanes[-1].startswith("S") and len(lanes) == len(failed_run.axes)
    assert {"m-position_X", "m-position_Y", "m-position_Z"} <= set(ids)  # the axes that moved
    assert not any(name.startswith("m-position_S") for name in ids)
    assert float(ids["m-failure"].attrib["data-t"]) == pytest.approx(failed_run.failure.time)
    labels = texts(ids["m-labels"])
    assert any(label.startswith("N10") for label in labels) and any(
        label.startswith("N20") for label in labels
    )
    legend = " | ".join(texts(ids["m-legend"]))
    assert "FAILED at" in legend and "reference taken" in legend
    # one bar per phase of every axis
    bars = sum(
        len(group.findall(f"{NS}rect"))
        for group in ids["m-lanes"]
        if not group.get("fill", "").startswith("url(")
    )
    assert bars == sum(len(axis.phases) for axis in failed_run.axes.values())
    assert machine_svg(failed_run, "m") == machine_svg(failed_run, "m")


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_plot_svg_from_the_cli_is_the_same_renderer_and_loads_no_matplotlib(tmp_path):
    target = tmp_path / "homing.svg"
    probe = (
        "import sys\n"
        "from achslint.cli import main\n"
        "code = main(sys.argv[1:])\n"
        "print('matplotlib' in sys.modules, code)\n"
    )
    done = subprocess.run(
        [
            sys.executable,
            "-c",
            probe,
            "dry-run",
            str(FIXTURES / "lists" / "achsmds1.lis"),
            "--plot",
            str(target),
        ],
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert done.stdout.split()[-2:] == ["False", "0"], done.stderr
    root = parse(target.read_text(encoding="utf-8"))
    ids = by_id(root)
    assert {"homing-position", "homing-velocity", "homing-phases", "homing-reference"} <= set(ids)


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_the_report_draws_its_figures_without_matplotlib(tmp_path):
    """Issue 29's budget (2 s for 32 axes) holds because no figure of the report goes through matplotlib."""
    page = tmp_path / "report.html"
    probe = (
        "import sys\n"
        "from achslint.cli import main\n"
        "code = main(sys.argv[1:])\n"
        "print('matplotlib' in sys.modules, code)\n"
    )
    startup, program = EXAMPLE / "listen" / "hochlauf.lis", EXAMPLE / "rfp.nc"
    done = subprocess.run(
        [sys.executable, "-c", probe, "report", str(startup), "--program", str(program), "-o", str(page)],
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert done.stdout.split()[-2] == "False", done.stderr
    text = page.read_text(encoding="utf-8")
    # the timeline, and a position/velocity figure per homing of each of the six axes
    assert 'id="timeline-lanes"' in text and text.count('<svg class="figure"') == 1 + 6
