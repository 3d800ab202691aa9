"""What a rule sees: the parsed file, the typed settings and helpers to report."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from functools import cached_property

from . import syntax
from .analysis import Analysis, Setting, analyse
from .catalogue import Catalogue, catalogue
from .diagnostics import Diagnostic, Fix, Related, Severity


@dataclass
class Options:
    """Settings that change what rules report (not which rules run)."""

    unknown_parameters: str = "warn"  # warn | error | ignore
    cycle_time_us: int = 1000
    repeatability_tolerance_um: float = 20.0


@dataclass
class Context:
    name: str
    file: syntax.ListFile
    options: Options = field(default_factory=Options)
    catalogue: Catalogue = field(default_factory=catalogue)
    embedded: object = None  # xmlinput.EmbeddedList when the list came from an XML file
    default_file: syntax.ListFile | None = None  # the default axis list loaded underneath (start-up list)

    @cached_property
    def analysis(self) -> Analysis:
        return analyse(self.file, self.catalogue)

    @cached_property
    def values(self):
        """Effective values of the axis (defaults filled in, references resolved)."""
        from .effective import AxisValues

        defaults = analyse(self.default_file, self.catalogue) if self.default_file is not None else None
        return AxisValues(self.analysis, defaults, cat=self.catalogue)

    @cached_property
    def strategy(self):
        """The homing strategy the axis is configured for (gear stage 0)."""
        from .strategy import classify

        return classify(self.values)

    @property
    def settings(self) -> list[Setting]:
        return self.analysis.settings

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
        from .rules import registry

        parameter = setting.canonical if setting else None
        p_axis = setting.parameter.id if setting and setting.parameter else None
        return Diagnostic(
            path=self.name,
            line=line.number,
            column=column if column is not None else line.path_column,
            end_line=end_line if end_line is not None else line.number,
            end_column=end_column if end_column is not None else line.end_column,
            code=code,
            severity=severity or registry()[code].severity,
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
        """`path = value unit (human)` for messages, marked "(default)" when the list does not set it."""
        from .units import describe

        values = self.values
        value = values.get(path)
        unit = values.parameter(path).unit(values.axis_type)
        shown = describe(value, unit) if isinstance(value, (int, float)) and not isinstance(value, bool) else (
            str(int(value)) if isinstance(value, bool) else str(value))
        origin = "" if values.is_set(path) else " (default)"
        return f"`{path}` = {shown}{origin}"

    def cross(self, code: str, message: str, paths: list[str], *, severity: Severity | None = None) -> Diagnostic:
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
        return self.report(code, line, message, column=column, end_column=max(end, column + 1),
                           severity=severity, setting=main, related=related)

    def problem_span(self, line: syntax.Line, span) -> tuple[int, int]:
        if isinstance(span, tuple):
            return span
        if span == "rest" and line.rest is not None:
            return line.rest_column, line.end_column
        return self.value_span(line)

    def path_span(self, line: syntax.Line) -> tuple[int, int]:
        start = line.path_column
        return start, start + len(line.path or "")
