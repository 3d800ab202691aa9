"""The behaviour of the typed axis model; its fields are generated into `model/generated.py`.

`AxisBase` is the base class of the generated root class `AxisParameters`: it holds where each value came
from, the CNC's corrections and the rules' findings, and runs the cross-parameter rules when data is validated.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from pydantic import BaseModel, ConfigDict, Field, PrivateAttr, ValidationInfo, model_validator

if TYPE_CHECKING:
    from ..axis.resolved import Correction
    from ..core.diagnostics import Diagnostic


@dataclass(frozen=True, slots=True)
class Source:
    """Where an effective value came from."""

    kind: str  # "list", "default list" or "default"
    file: str | None = None
    line: int | None = None
    column: int | None = None

    def __str__(self) -> str:
        if self.kind == "default":
            return "default"
        return f"{self.file}:{self.line}:{self.column}"


DEFAULT = Source("default")


class AxisBase(BaseModel):
    """Shared behaviour of the generated root model."""

    model_config = ConfigDict(populate_by_name=True, extra="forbid")
    unknown: dict[str, str] = Field(
        default_factory=dict, description="Parameters the catalogue does not know, as written."
    )
    _sources: dict[str, Source] = PrivateAttr(default_factory=dict)
    _corrections: list[Correction] = PrivateAttr(default_factory=list)
    _findings: list[Diagnostic] = PrivateAttr(default_factory=list)

    @property
    def corrections(self) -> list[Correction]:
        """The CNC's load-time corrections (`resolved.Correction`) behind the values of this model."""
        return list(self._corrections)

    @property
    def findings(self) -> list[Diagnostic]:
        """The diagnostics `achslint lint` reports for the list this model was loaded from."""
        return list(self._findings)

    @model_validator(mode="after")
    def _cross_rules(self, info: ValidationInfo) -> AxisBase:
        """The cross-parameter rules, run by the same rule code as `achslint lint` on the axis the data describes."""
        if info.context and info.context.get("lenient"):
            return self
        from . import _rule_findings, dumps, rule_errors

        errors = [d for d in _rule_findings(dumps(self)) if d.severity.value == "error"]
        if errors:
            raise rule_errors(errors)
        return self

    def source_of(self, path: str) -> Source:
        """Where the effective value of a canonical path (`getriebe[0].vb_reflow`) came from."""
        return self._sources.get(path, DEFAULT)

    def get(self, path: str) -> Any:
        """The effective value of a canonical path, e.g. `getriebe[0].vb_reflow`."""
        from . import _parts, field_name

        value: Any = self
        for name, index in _parts(path):
            value = getattr(value, field_name(name))
            if index:
                value = value[int(index)]
        return value
