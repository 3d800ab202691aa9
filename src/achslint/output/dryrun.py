"""`achslint dry-run LIST` as text or JSON: the simulated homing of one axis, then the sweep when `--sweep`
asked for one; `--plot` draws the same run."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from . import Registry, Screen, write_json
from .plot import write_plot

if TYPE_CHECKING:
    from ..dryrun import DryRun


@dataclass(frozen=True)
class AxisDryRun:
    """What the dry-run of one axis reports: the run, and the summary of `--sweep` when one was asked for."""

    run: DryRun
    sweep: dict[str, Any] | None = None


def as_text(report: AxisDryRun, screen: Screen) -> None:
    """The scenario, the phases and events as tables, the outcome; the sweep in words after them."""
    from ..dryrun import render, sweep_words

    render(report.run, screen.console)
    if report.sweep is not None:
        screen.console.print(sweep_words(report.sweep), markup=False, highlight=False)


def as_json(report: AxisDryRun, screen: Screen) -> None:
    """The trace document (its keys in `dryrun`'s docstring), with the sweep under `sweep`."""
    from ..dryrun import trace_json

    document = trace_json(report.run)
    if report.sweep is not None:
        document["sweep"] = report.sweep
    write_json(document, screen, strict=True)


def plot(report: AxisDryRun, target: str) -> None:
    """The run's position and velocity over time, written to `target` (PNG or SVG)."""
    from ..plot import plot_trace

    write_plot(lambda file: plot_trace(report.run.trace, file), target)


RENDERERS: Registry[AxisDryRun] = {"text": as_text, "json": as_json}
