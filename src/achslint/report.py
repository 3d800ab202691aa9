"""`achslint report MACHINE`: everything a commissioning review goes through, gathered in one object.

The report decides nothing of its own: it runs the commands a reviewer would otherwise run one by one and
keeps what each returns, for `output/report.py` to render as one HTML page or a Markdown summary:

- `explain` of the machine (`machine.explain.explain_machine`: the axes, their drives and strategies, the
  program's homing order) and of each axis list (`explanation.explain_list`: the effective homing parameters,
  where each value comes from, the CNC's corrections, the parameters without effect and why);
- `lint` of the machine, and of the homing program against it (`linting.run.run_lint`);
- the dry-run: with a program, the program over the whole machine (`machine.run`, the timeline); without
  one, the configured homing of each axis on its own (`dryrun.dry_run`), each in the scenario given for it
  or in the assumed default geometry;
- with `--against`, `diff` of the machine (or the list) and its backup (`machinediff`, `listdiff`).

MACHINE is a start-up list, a folder holding one (as `diff` finds it), or a single axis list.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .core.decode import UnreadableInput
from .core.files import Refused, reason, shown_path
from .dryrun import DryRun, DryRunRefused
from .explanation import ListReport, default_underneath, explain_list
from .homing.scenario import ScenarioError
from .linting.config import ConfigError
from .linting.linter import read_axis_list
from .linting.run import LintOutcome, LintRequest, run_lint
from .machine.resolved import MachineError
from .machinediff import MachineDiffError, MachineDiffReport, startup_in

if TYPE_CHECKING:
    from .listdiff import DiffReport
    from .machine.model import MachineAxis
    from .machine.run import AxisRun, MachineRun
    from .machine.scenario import MachineScenario


class ReportFailed(Exception):
    """The report cannot be made as asked: one line naming the file (exit code 2)."""


@dataclass(frozen=True)
class ReportRequest:
    """What `achslint report` was asked for (paths as the user gave them)."""

    target: Path
    program: Path | None = None
    scenario: Path | None = None
    against: Path | None = None
    config: Path | None = None
    channel: int = 1
    gear: int = 0


@dataclass(frozen=True)
class ListFile:
    """One list of the machine: its kind in words, the start-up entry that names it, and its file."""

    kind: str
    entry: str | None
    path: str


@dataclass
class AxisSection:
    """One axis: its explanation, and its dry-run (on its own, or its part of the program's run)."""

    name: str
    logical_number: int | None
    explained: ListReport
    dry_run: DryRun | None = None  # without a program: the axis's configured homing on its own
    program_run: AxisRun | None = None  # with a program: what the program did with the axis
    refused: str | None = None  # why there is no dry-run of the axis
    dry_run_refused: bool = False  # `dry-run` refuses it (the CNC does not run this homing), exit 2


@dataclass
class CommissioningReport:
    target: str  # the start-up list (or the axis list) as named
    machine: dict[str, Any] | None  # `explain_machine` of the machine; None for a single axis list
    lists: list[ListFile]
    axes: list[AxisSection]
    lint: LintOutcome
    run: MachineRun | None = None  # the homing program over the machine
    against: str | None = None
    machine_diff: MachineDiffReport | None = None
    list_diff: DiffReport | None = None
    notes: list[str] = field(default_factory=list)

    @property
    def findings(self) -> int:
        return sum(len(result.diagnostics) for result in self.lint.results)


def build_report(request: ReportRequest) -> CommissioningReport:
    """The report of a machine (or of one axis list). Raises `ReportFailed` with a one-line message for what
    cannot be read or run (the machine, the program, the scenario, the backup)."""
    try:
        startup = startup_in(request.target)
        report = _axis_report(request) if startup is None else _machine_report(request, startup)
        _compare(report, request, startup)
    except (MachineError, MachineDiffError, ScenarioError, ConfigError, Refused, UnreadableInput) as exc:
        raise ReportFailed(str(exc)) from None
    except DryRunRefused as exc:  # the program itself (a single axis's refusal is shown in its section)
        raise ReportFailed(str(exc)) from None
    except OSError as exc:
        raise ReportFailed(f"cannot read {exc.filename or request.target}: {reason(exc)}") from None
    return report


def report_inputs(request: ReportRequest) -> list[Path]:
    """Every file the report reads (the machine's lists, the program, the scenario, the backup, the
    configuration), for the check that the report file is none of them."""
    from .linting.discovery import machine_files

    named = [request.target, request.program, request.scenario, request.against, request.config]
    found = [path for path in named if path is not None]
    config = str(request.config) if request.config else None
    for machine in (request.target, request.against):
        startup = _startup_or_none(machine)
        if startup is not None:
            found += machine_files(startup, config_file=config)
    return found


def _startup_or_none(path: Path | None) -> Path | None:
    if path is None:
        return None
    try:
        return startup_in(path)
    except MachineDiffError:
        return None


# --- a machine ------------------------------------------------------------------------------------


def _machine_report(request: ReportRequest, startup: Path) -> CommissioningReport:
    from .machine.build import build_machine, rename
    from .machine.explain import explain_machine
    from .machine.run import machine_dry_run
    from .machine.scenario import machine_scenario_input

    given, cycle_time_us, cnc_root = machine_scenario_input(startup, request.scenario, request.config)
    run: MachineRun | None = None
    if request.program is not None:
        run, _ = machine_dry_run(
            startup, request.program, request.scenario, channel=request.channel, config=request.config
        )
        view = run.machine
    else:
        view = build_machine(startup, cnc_root=cnc_root, channel=request.channel)
        try:
            rename(view, given.names, given.where)
        except ValueError as exc:
            raise ScenarioError(str(exc)) from None
        # as `dry-run --program` does: an [axes.NAME] table must name an axis of the machine
        given.check_names([*view.axes, *(axis.name for axis in view.other_axes)])
    explained = explain_machine(view, run.program if run is not None else None, request.gear)
    axes = [*view.axes.values(), *view.other_axes]
    sections = [_section(axis, request.gear, startup) for axis in axes]
    for section, axis in zip(sections, axes, strict=True):
        if run is not None:
            section.program_run = run.axes.get(axis.name)
            if section.program_run is None:
                section.refused = "not part of the program's run (no axis of this channel)"
        else:
            _axis_dry_run(section, axis, given, cycle_time_us, request.gear)
    lint = run_lint(_lint_request(request, startup))
    return CommissioningReport(
        target=str(startup),
        machine=explained,
        lists=_lists(startup, cnc_root),
        axes=sections,
        lint=lint,
        run=run,
        notes=list(view.notes),
    )


def _lint_request(request: ReportRequest, startup: Path | None) -> LintRequest:
    """`achslint lint MACHINE [rfp.nc --machine MACHINE]`, keeping the lines of the lists for the excerpts."""
    paths = [str(startup or request.target), *([str(request.program)] if request.program else [])]
    return LintRequest(
        paths=paths,
        config_file=str(request.config) if request.config else None,
        machine=str(startup) if startup is not None and request.program else None,
        channel=request.channel,
        keep_source=True,
    )


def _section(axis: MachineAxis, gear: int, startup: Path) -> AxisSection:
    """An axis of the machine explained as `explain` explains its list, with the default list underneath."""
    name = str(axis.list_path) if axis.list_path else axis.name
    under = f"the machine's default axis list underneath, as {startup} loads it" if axis.defaults else None
    explained = explain_list(axis.data, name, gear, axis.defaults, under)
    return AxisSection(axis.name, axis.logical_number, explained)


def _axis_dry_run(
    section: AxisSection, axis: MachineAxis, given: MachineScenario, cycle_time_us: int, gear: int
) -> None:
    """The axis's configured homing on its own, in its machine scenario table (or the assumed geometry)."""
    from .dryrun import dry_run

    try:
        section.dry_run = dry_run(
            axis.data,
            section.explained["file"],
            given.given(axis.name),
            gear=gear,
            cycle_time_us=round(given.cycle_time_ms * 1000) if given.cycle_time_ms else cycle_time_us,
            defaults=axis.defaults,
        )
    except DryRunRefused as exc:
        section.refused = str(exc)
        section.dry_run_refused = True


def _lists(startup: Path, cnc_root: Path | None) -> list[ListFile]:
    """The start-up list and every list it names, with their kinds, in the order of the start-up list."""
    from .catalogue.kinds import entry_kind
    from .machine.startup import read_startup

    read = read_startup(startup, cnc_root=cnc_root)
    found = [ListFile("start-up list", None, str(startup))]
    entries = [read.default, read.default_channel, *read.axes, *read.channels, *read.compensations]
    entries += read.others
    for entry in sorted((e for e in entries if e is not None), key=lambda e: e.line):
        kind = entry_kind(entry.key)
        shown = shown_path(entry.path) if entry.path is not None else f"{entry.raw} (not found)"
        found.append(ListFile(kind.name if kind is not None else "list", entry.key, shown))
    return found


# --- one axis list --------------------------------------------------------------------------------


def _axis_report(request: ReportRequest) -> CommissioningReport:
    from .dryrun import dry_run, scenario_input

    path = request.target
    if request.program is not None:
        raise ReportFailed(
            f"--program goes with a start-up list (hochlauf.lis), not with the axis list {path}"
        )
    data = read_axis_list(path, str(path))
    defaults, under = default_underneath(path)
    explained = explain_list(data, str(path), request.gear, defaults, under)
    axis = explained["axis"]
    name = str(axis["name"]) if axis["name"] is not None else path.name
    number = axis["number"]
    section = AxisSection(name, number if isinstance(number, int) else None, explained)
    given, cycle_time_us = scenario_input(path, request.scenario, {}, request.config)
    try:
        section.dry_run = dry_run(
            data, str(path), given, gear=request.gear, cycle_time_us=cycle_time_us, defaults=defaults
        )
    except DryRunRefused as exc:
        section.refused = str(exc)
        section.dry_run_refused = True
    return CommissioningReport(
        target=str(path),
        machine=None,
        lists=[ListFile("axis list", None, str(path))],
        axes=[section],
        lint=run_lint(_lint_request(request, None)),
    )


# --- against a backup -----------------------------------------------------------------------------


def _compare(report: CommissioningReport, request: ReportRequest, startup: Path | None) -> None:
    """`diff MACHINE BACKUP` (two machines, or two axis lists) into the report."""
    if request.against is None:
        return
    from .listdiff import diff_lists
    from .machinediff import diff_machines, machines_to_compare

    report.against = str(request.against)
    machines = machines_to_compare(request.against, startup or request.target)  # A: the backup, B: now
    if machines is not None:
        report.machine_diff = diff_machines(*machines)
        return

    # Each list with the default list the CNC loads under it, as the report explains it: the current one's
    # machine's, and the backup's own machine's when it has one, else (a list copied on its own) the
    # current one's, the machine it would be loaded into.
    ours = read_axis_list(request.target, str(request.target))
    theirs = read_axis_list(request.against, str(request.against))
    our_defaults, _ = default_underneath(request.target)
    their_defaults, _ = default_underneath(request.against)
    report.list_diff = diff_lists(
        theirs,
        str(request.against),
        ours,
        str(request.target),
        b_defaults=our_defaults,
        a_defaults=their_defaults if their_defaults is not None else our_defaults,
    )
