"""`dry-run --plot FILE`: the figure of a run written as PNG or SVG (figures drawn by `achslint.output.figures`).

Both dry-runs come through `write_plot`: a name that is neither .png nor .svg, a missing matplotlib or a
file that cannot be written become one `OutputFailed` line for the user.
"""

from __future__ import annotations

from collections.abc import Callable

from . import OutputFailed


def write_plot(draw: Callable[[str], None], target: str) -> None:
    """`draw(target)` (`plot.plot_trace` or `plot.plot_machine` with their run), refusals as `OutputFailed`."""
    from ..core.files import reason
    from .figures import PlotUnavailable

    try:
        draw(target)
    except PlotUnavailable as exc:
        raise OutputFailed(str(exc)) from None
    except OSError as exc:
        raise OutputFailed(f"cannot write the plot to {target}: {reason(exc)}") from None
