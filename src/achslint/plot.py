"""`dry-run --plot`: position and velocity over time, phases shaded, events marked (matplotlib)."""

from __future__ import annotations

from .engine import Trace


class PlotUnavailable(Exception):
    pass


def samples(trace: Trace, per_segment: int = 40) -> tuple[list[float], list[float], list[float]]:
    times, positions, velocities = [], [], []
    for phase in trace.phases:
        for segment in phase.segments:
            steps = per_segment if segment.t1 > segment.t0 else 1
            for k in range(steps + 1):
                t = segment.t0 + (segment.t1 - segment.t0) * k / steps
                times.append(t)
                positions.append(segment.position(t))
                velocities.append(segment.velocity(t))
    return times, positions, velocities


def plot_trace(trace: Trace, target: str) -> None:
    if not target.lower().endswith((".png", ".svg")):
        raise PlotUnavailable(f"--plot needs a .png or .svg file name, not {target!r}")
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise PlotUnavailable("--plot needs matplotlib: pip install 'achslint[plot]'") from None
    times, positions, velocities = samples(trace)
    figure, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(10, 6))
    unit = trace.unit
    top.plot(times, positions, color="tab:blue")
    top.set_ylabel(f"position [{unit}]")
    bottom.plot(times, velocities, color="tab:orange")
    bottom.set_ylabel(f"velocity [{unit}/s]")
    bottom.set_xlabel("time [s]")
    shades = ("#f0f0f0", "#dde8f5")
    for number, phase in enumerate(trace.phases):
        for axis in (top, bottom):
            axis.axvspan(phase.start_time, phase.end_time, color=shades[number % 2], zorder=0)
        top.annotate(f" {number + 1}", (phase.start_time, 0.92), xycoords=("data", "axes fraction"),
                     fontsize=9, fontweight="bold")
    if trace.scenario.cam:
        top.axhspan(*trace.scenario.cam, color="tab:green", alpha=0.15, label="reference cam")
    for event in trace.events:
        top.plot([event.time], [event.position], marker="o", color="tab:red")
        top.annotate(event.kind, (event.time, event.position), textcoords="offset points", xytext=(4, 4), fontsize=7)
    phases = "   ".join(f"{n}. {p.name}" for n, p in enumerate(trace.phases, 1))
    top.set_title(f"{trace.strategy.title}: {trace.outcome}\n{phases}", fontsize=10)
    top.legend(loc="lower right", fontsize=8) if trace.scenario.cam else None
    figure.tight_layout()
    figure.savefig(target)
    plt.close(figure)
