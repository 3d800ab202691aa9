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

    @cached_property
    def analysis(self) -> Analysis:
        return analyse(self.file, self.catalogue)

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
        related: list[Related] | None = None,
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
            related=related or [],
            fix=fix,
        )

    def related(self, setting: Setting, message: str = "") -> Related:
        return Related(self.name, setting.line.number, setting.line.path_column, setting.canonical, message)

    def value_span(self, line: syntax.Line) -> tuple[int, int]:
        start = line.value_column
        return start, start + max(len(line.value or ""), 1)

    def problem_span(self, line: syntax.Line, span: str) -> tuple[int, int]:
        if span == "rest" and line.rest is not None:
            return line.rest_column, line.end_column
        return self.value_span(line)

    def path_span(self, line: syntax.Line) -> tuple[int, int]:
        start = line.path_column
        return start, start + len(line.path or "")
