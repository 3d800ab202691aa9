"""Review of `achslint report`: what the page shows must be what `lint`, `explain` and `dry-run` say.

Each case builds the report as `achslint report` does (`build_report`, `as_html`) and compares it with the
documents of the commands it summarises (`trace_json`, the `dry-run --format json` document)."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest

from achslint.output.dryrun import trace_json
from achslint.output.report import as_html, as_markdown
from achslint.report import ReportFailed, ReportRequest, build_report

from .conftest import FIXTURES, ROOT

EXAMPLE = ROOT / "docs" / "dry-run" / "machine"


def _axis_part(page: str, name: str) -> str:
    start = page.index(f'data-axis="{name}"')
    return page[start : page.index("</section>", start)]


def test_a_simulated_drive_s_figure_draws_no_zero_pulses_the_run_does_not_read() -> None:
    """A simulated drive references at rpf_weg_bis_nip, not on an encoder's zero pulse: its dry-run reads no
    zero pulses (JSON `zero_pulse_period` null), yet the figure drew the default scenario's pulses "every
    5 mm" as if they were the machine's."""
    listed = FIXTURES / "machines" / "sdk" / "listen" / "achsmds2.lis"  # antr_typ 4: simulation
    report = build_report(ReportRequest(listed))
    section = report.axes[0]
    assert section.dry_run is not None
    document = trace_json(section.dry_run)
    assert document["scenario"]["zero_pulse_period"] is None and document["phases"]
    page = as_html(report)
    figure = _axis_part(page, section.name)
    assert "<svg" in figure
    assert "-zero_pulses" not in figure
    assert "zero pulses (every" not in figure


def test_an_axis_s_homing_time_is_one_number_on_the_page() -> None:
    """The summary's dry-run column and the axis's outcome line give its homing time from one value: A of the
    example machine homes in 6.3025 s (`dry-run --format json`), which the summary showed as 6.302 s (the
    float below it) and the axis page as 6.303 s."""
    report = build_report(ReportRequest(EXAMPLE / "listen" / "hochlauf.lis"))
    page = as_html(report)
    summary = page[page.index('<section id="summary"') : page.index("</section>")]
    for number, section in enumerate(report.axes, 1):
        if section.dry_run is None or not section.dry_run.trace.phases:
            continue
        total = trace_json(section.dry_run)["total_time"]
        row = re.search(rf'<a href="#axis-{number}">.*?</tr>', summary)
        assert row is not None
        in_summary = re.search(r"homed in ([\d.]+) s", row.group(0))
        in_section = re.search(r"\(homed frame\); ([\d.]+) s</p>", _axis_part(page, section.name))
        assert in_summary is not None and in_section is not None
        assert in_summary.group(1) == in_section.group(1), (section.name, total)
        assert abs(float(in_summary.group(1)) - total) <= 0.0005 + 1e-12, (section.name, total)


def _example(tmp_path: Path) -> Path:
    target = tmp_path / "machine"
    shutil.copytree(EXAMPLE, target)
    return target


def test_an_axis_whose_dry_run_is_refused_is_refused_in_the_summary(tmp_path: Path) -> None:
    """`dry-run` refuses TORQ homing on a conventional drive (LIS306, exit 2: the CNC does not run it); the
    summary called that "not simulated", the words of a mode the simulator does not cover (exit 0)."""
    machine = _example(tmp_path)
    listed = machine / "listen" / "achsmds2.lis"
    listed.write_bytes(
        listed.read_bytes().replace(b"homing_type                 CNC_CONTROLLED", b"homing_type TORQ")
    )
    report = build_report(ReportRequest(machine / "listen" / "hochlauf.lis"))
    y = next(section for section in report.axes if section.name == "Y")
    assert y.dry_run is None and y.refused is not None and "dry-run refused" in y.refused
    page = as_html(report)
    row = re.search(r'<a href="#axis-2">Y</a>.*?</tr>', page)
    assert row is not None
    assert "not simulated" not in row.group(0) and "refused" in row.group(0)
    assert "| Y | 2 | linear | homing to a fixed stop (TORQ) | refused |" in as_markdown(report)


def test_a_scenario_table_of_no_axis_of_the_machine_is_refused_without_a_program_too(tmp_path: Path) -> None:
    """`dry-run --program` refuses `[axes.Q]` on a machine without Q (a misspelt name would leave the axis it
    meant on assumed geometry); the report without a program took the file and ignored the table."""
    machine = _example(tmp_path)
    scenario = machine / "machine.toml"
    scenario.write_text(scenario.read_text() + "\n[axes.Q]\nstart_position = 1.0\n")
    for program in (machine / "rfp.nc", None):
        with pytest.raises(ReportFailed, match=r"\[axes\.Q\]: the machine has no axis Q"):
            build_report(
                ReportRequest(machine / "listen" / "hochlauf.lis", program=program, scenario=scenario)
            )
