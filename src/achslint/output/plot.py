"""`dry-run --plot FILE`: the figure of a run written as SVG (`svgplot`, no matplotlib needed, the same code
that draws the figures of `achslint report`) or as PNG (`figures`, matplotlib: `pip install 'achslint[plot]'`).

Both dry-runs come through `write_plot`: a name that is neither .png nor .svg, a missing matplotlib or a
file that cannot be written become one `OutputFailed` line for the user.
"""

from __future__ import annotations

import io
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from . import OutputFailed

# The figure modules are imported when a plot is written: a dry-run without --plot does not load them.
if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..homing.motion import Trace
    from ..machine.run import MachineRun


def plot_trace(trace: Trace, target: str) -> None:
    """Write a single-axis dry-run's position and velocity plot to a PNG or SVG file."""
    from .figures import build_figure
    from .svgplot import trace_svg

    _write(target, lambda: trace_svg(trace, "homing", standalone=True), lambda: build_figure(trace))


def plot_machine(run: MachineRun, target: str) -> None:
    """Write a machine dry-run's timeline and position plots to a PNG or SVG file."""
    from .figures import build_machine_figure
    from .svgplot import machine_svg

    _write(target, lambda: machine_svg(run, "machine", standalone=True), lambda: build_machine_figure(run))


def _write(target: str, svg: Callable[[], str], figure: Callable[[], Figure]) -> None:
    from ..core.files import write_output
    from .figuredata import PlotUnavailable
    from .figures import save_png

    suffix = target.lower().rsplit(".", 1)[-1] if "." in target else ""
    if suffix == "svg":
        write_output(Path(target), svg().encode("utf-8"))
    elif suffix == "png":
        png = io.BytesIO()
        save_png(figure, png)
        write_output(Path(target), png.getvalue())
    else:
        raise PlotUnavailable(f"--plot needs a .png or .svg file name, not {target!r}")


def write_plot(draw: Callable[[str], None], target: str) -> None:
    """`draw(target)` (`plot_trace` or `plot_machine` with their run), refusals as `OutputFailed`."""
    from ..core.files import reason
    from .figuredata import PlotUnavailable

    try:
        draw(target)
    except PlotUnavailable as exc:
        raise OutputFailed(str(exc)) from None
    except OSError as exc:
        raise OutputFailed(f"cannot write the plot to {target}: {reason(exc)}") from None
    except ValueError:  # a NUL byte in the name
        raise OutputFailed(
            f"cannot write the plot to {target!r}: a name the file system cannot hold"
        ) from None
