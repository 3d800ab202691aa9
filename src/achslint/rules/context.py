"""What a rule sees: the parsed file, its kind, the typed settings and helpers to report.

A list of another kind than an axis list (a channel list, tool data ...) is analysed against its kind's
catalogue (`catalogue.kinds`); it is no axis, so the resolved axis and its homing strategy (`values`,
`strategy`) are only asked for by the axis-only rules, which do not run on it.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING

from ..axis.analysis import Analysis, Setting, analyse
from ..catalogue import Catalogue, Parameter, catalogue
from ..catalogue.kinds import AXIS, AXIS_PREFIX, Kind
from ..core.diagnostics import Diagnostic, Fix, Related, Severity
from ..syntax import parser as syntax
from .codes import severity as default_severity
from .options import DEFAULT_OPTIONS, RuleOptions

if TYPE_CHECKING:
    from ..axis.facts import Span
    from ..axis.resolved import Correction, ResolvedAxis
    from ..homing import Effect, HomingStrategy
    from ..syntax.xmlinput import EmbeddedList


@dataclass
class Context:
    name: str
    file: syntax.ListFile
    options: RuleOptions = (
        DEFAULT_OPTIONS  # what rules read: unknown-parameters, cycle time … (config.Settings)
    )
    catalogue: Catalogue = field(default_factory=catalogue)
    embedded: EmbeddedList | None = None  # when the list came from an XML file
    # the default list loaded underneath (start-up list): the default axis list under an axis list, the
    # default channel list under a channel list
    default_file: syntax.ListFile | None = None
    default_list: bool = False  # the list is itself a default axis list: no axis of its own
    kind: Kind = AXIS  # the list's kind; `catalogue` is that kind's catalogue

    @property
    def axis_list(self) -> bool:
        """Whether the list describes an axis (an axis list or a default axis list)."""
        return self.kind.prefix == AXIS_PREFIX

    @property
    def kind_name(self) -> str:
        """The list's kind for messages: "channel list", "tool data list" ..."""
        return self.kind.name

    @cached_property
    def analysis(self) -> Analysis:
        return analyse(self.file, self.catalogue)

    @cached_property
    def values(self) -> ResolvedAxis:
        """The resolved axis: defaults, default list, the list, references and the CNC's corrections."""
        from ..axis.resolved import ResolvedAxis

        if not self.axis_list:  # a rule that judges an axis declared a kind that is none
            raise TypeError(f"{self.name} is a {self.kind_name}, not an axis list: it has no resolved axis")

        return ResolvedAxis(self.analysis, self.default_analysis, cat=self.catalogue)

    @cached_property
    def strategy(self) -> HomingStrategy:
        """The homing strategy the CNC runs for the axis (gear stage 0)."""
        from ..homing import classify

        return classify(self.values)

    def effect(self, path: str) -> Effect:
        """Whether a parameter takes effect on this axis under its strategy (and why)."""
        from ..homing import effect

        return effect(self.strategy, self.values, path)

    def effective(self, *paths: str) -> bool:
        """True when every one of the parameters takes effect; a rule about them is silent otherwise."""
        return all(self.effect(path).effective for path in paths)

    @property
    def settings(self) -> list[Setting]:
        return self.analysis.settings

    @cached_property
    def known(self) -> list[tuple[Setting, Parameter, str]]:
        """The assignments of catalogue parameters (not misspelt), each with its parameter and canonical
        path, in list order: walked once for the rules that look at every known setting."""
        return [
            (setting, resolution.parameter, canonical)
            for setting in self.analysis.settings
            if (canonical := setting.canonical) is not None and (resolution := setting.resolution) is not None
        ]

    @cached_property
    def with_facts(self) -> list[tuple[Setting, Parameter]]:
        """The known assignments the conversion stage recorded a fact (a problem) about, each with its
        parameter, in list order: the value rules (`_common.value_facts`) look at these only."""
        return [
            (setting, resolution.parameter)
            for setting in self.analysis.settings
            if setting.problems
            and setting.canonical is not None
            and (resolution := setting.resolution) is not None
        ]

    @cached_property
    def default_analysis(self) -> Analysis | None:
        """The default list underneath analysed against the list's catalogue (None without one): once, for
        the resolved axis and the rules that read its settings alike."""
        return analyse(self.default_file, self.catalogue) if self.default_file is not None else None

    @cached_property
    def default_settings(self) -> list[Setting]:
        """The assignments of the default list underneath (none without one), against the list's catalogue."""
        defaults = self.default_analysis
        return defaults.settings if defaults is not None else []

    @cached_property
    def newline(self) -> str:
        """The file's dominant line break (LF when it has none)."""
        counts = Counter(line.newline for line in self.file.lines if line.newline)
        return counts.most_common(1)[0][0] if counts else "\n"

    def report(
        self,
        code: str,
        line: syntax.Line,
        message: str,
        *,
        column: int | None = None,
        end_column: int | None = None,
        end_line: int | None = None,
        severity: Severity | None = None,
        setting: Setting | None = None,
        related: list[Related] | tuple[Related, ...] = (),
        fix: Fix | None = None,
    ) -> Diagnostic:
        parameter = setting.canonical if setting else None
        p_axis = setting.parameter.id if setting and setting.parameter else None
        return Diagnostic(
            path=self.name,
            line=line.number,
            column=column if column is not None else line.path_column,
            end_line=end_line if end_line is not None else line.number,
            end_column=end_column if end_column is not None else line.end_column,
            code=code,
            severity=severity or default_severity(code),
            message=message,
            parameter=parameter,
            p_axis=p_axis,
            related=tuple(related),
            fix=fix,
        )

    def related(self, setting: Setting, message: str = "") -> Related:
        return Related(self.name, setting.line.number, setting.line.path_column, setting.canonical, message)

    def value_span(self, line: syntax.Line) -> tuple[int, int]:
        start = line.value_column
        return start, start + max(len(line.value or ""), 1)

    def show(self, path: str) -> str:
        """`path = value unit (human)` as written, marked "(default)" when no list sets it and followed by
        the value the CNC uses when it corrects it."""
        values = self.values
        unit = values.parameter(path).unit(values.axis_type)
        origin = "" if values.is_set(path) else " (default)"
        text = f"`{path}` = {_shown(values.written(path), unit)}{origin}"
        correction = values.correction(path)
        if correction is not None:
            text += f" (the CNC uses {_shown(correction.used, unit)})"
        return text

    def correction(self, path: str) -> Correction | None:
        """The CNC's correction of a parameter, when a rule should report it: the parameter takes effect, or
        it is wrong for the axis's drive or axis type (then the correction says more than LIS105)."""
        correction = self.values.correction(path)
        if correction is None:
            return None
        found = self.effect(path)
        return correction if found.effective or found.cause != "strategy" else None

    def report_correction(
        self, code: str, correction: Correction, message: str, paths: list[str]
    ) -> Diagnostic:
        """A finding about a load-time correction: the message, then what the CNC does instead."""
        return self.cross(code, f"{message}: {correction.reason} ({correction.error})", paths)

    def cross(
        self, code: str, message: str, paths: list[str], *, severity: Severity | None = None
    ) -> Diagnostic:
        """A diagnostic about several parameters: at the first one the list sets, the others related."""
        present = [s for s in (self.values.in_list(p) for p in paths) if s is not None]
        main = present[0] if present else None
        line = main.line if main else self.file.lines[0]
        column, end = self.path_span(line) if main else (1, line.end_column)
        seen = {id(main)}
        related = []
        for setting in present[1:]:
            if id(setting) not in seen:
                seen.add(id(setting))
                related.append(self.related(setting))
        return self.report(
            code,
            line,
            message,
            column=column,
            end_column=max(end, column + 1),
            severity=severity,
            setting=main,
            related=related,
        )

    def problem_span(self, line: syntax.Line, span: Span) -> tuple[int, int]:
        if isinstance(span, tuple):
            return span
        if span == "rest" and line.rest is not None:
            return line.rest_column, line.end_column
        return self.value_span(line)

    def path_span(self, line: syntax.Line) -> tuple[int, int]:
        start = line.path_column
        return start, start + len(line.path or "")


def _shown(value: object, unit: str | None) -> str:
    from ..catalogue.units import describe

    if isinstance(value, bool):
        return str(int(value))
    if isinstance(value, (int, float)):
        return describe(value, unit)
    return str(value) if value != "" else "(empty)"
