"""The behaviour of the typed axis model; its fields are generated into `model/generated.py`.

`AxisBase` is the base class of the generated root class `AxisParameters`: it holds where each value came
from, the CNC's corrections and the rules' findings, and runs the cross-parameter rules when data is validated.
What that needs sits here too, below the generated classes: how a canonical path names the model's fields
(`field_name`, `model_parts`), the model written back as a list (`dumps`), and rule findings as one
`ValidationError` (`rule_errors`).
"""

from __future__ import annotations

import keyword
import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from pydantic import (
    BaseModel,
    ConfigDict,
    Field,
    PrivateAttr,
    ValidationError,
    ValidationInfo,
    model_validator,
)
from pydantic_core import InitErrorDetails, PydanticCustomError

from ..catalogue import catalogue
from ..linting.linter import FileSettings, findings

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
        errors = [d for d in _rule_findings(dumps(self)) if d.severity.value == "error"]
        if errors:
            raise rule_errors(errors, type(self))
        return self

    def source_of(self, path: str) -> Source:
        """Where the effective value of a canonical path (`getriebe[0].vb_reflow`) came from."""
        return self._sources.get(path, DEFAULT)

    def get(self, path: str) -> Any:
        """The effective value of a canonical path, e.g. `getriebe[0].vb_reflow`."""
        value: Any = self
        for name, index in model_parts(type(self), path):
            value = getattr(value, field_name(name))
            if index:
                value = value[int(index)]
        return value


def field_name(name: str) -> str:
    """The Python name of a list member: keywords and `model_*` get a trailing "_", dotted rests are joined
    with "_". tools/gen_model.py names the generated fields with this same function."""
    if "." in name:
        return name.replace(".", "_")
    return name + "_" if keyword.iskeyword(name) or name.startswith("model_") else name


_MEMBER = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)(?:\[(\d+)\])?")


def model_parts(model: type[BaseModel], path: str) -> list[tuple[str, str]]:
    """A canonical path as (member, index) pairs of `model`'s fields.

    A parameter below another parameter (`kenngr.swe_pos.zero_limit` beside `kenngr.swe_pos`, P-AXIS-00560)
    is one field of the group, named by joining the rest (`swe_pos_zero_limit`): the walk meets a value
    where the path goes on, and the rest is that field."""
    parts: list[tuple[str, str]] = _MEMBER.findall(path)
    group: type[BaseModel] = model
    for position, (name, _) in enumerate(parts):
        info = group.model_fields.get(field_name(name))
        if info is None:
            break
        inner = inner_model(info.annotation)
        if inner is None:
            if position < len(parts) - 1:
                return [*parts[:position], (field_name(".".join(n for n, _ in parts[position:])), "")]
            break
        group = inner
    return parts


def inner_model(annotation: Any) -> type[BaseModel] | None:
    """The model class of a group field (`kenngr`) or of the elements of a list of groups (`getriebe`)."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    args = getattr(annotation, "__args__", ())
    if args and isinstance(args[0], type) and issubclass(args[0], BaseModel):
        return args[0]
    return None


def rule_errors(diagnostics: Iterable[Diagnostic], model: type[BaseModel]) -> ValidationError:
    """One ValidationError with an entry per finding: its code, the parameter's place in `model` and the
    message."""
    details = [
        InitErrorDetails(
            type=PydanticCustomError(
                "cross_rule", "{code}: {message}", {"code": d.code, "message": d.message}
            ),
            loc=_loc(model, d.parameter) if d.parameter else ("list",),
            input=d.parameter,
        )
        for d in diagnostics
    ]
    return ValidationError.from_exception_data("AxisParameters", details)


def _loc(model: type[BaseModel], path: str) -> tuple[str | int, ...]:
    loc: list[str | int] = []
    for name, index in model_parts(model, path):
        loc.append(name)
        if index:
            loc.append(int(index))
    return tuple(loc)


def _rule_findings(text: str) -> list[Diagnostic]:
    settings = FileSettings.of(["LIS3", "LIS4"], keep_source=False)
    return findings(text.encode("utf-8"), "<model>", settings)


def dumps(axis: BaseModel) -> str:
    """The model as an axis list in canonical layout: every value that differs from the CNC's default, then `Ende`."""
    lines = [f"{path:<48}{_written(value)}".rstrip() for path, value in _changed(axis, "")]
    return "\n".join([*lines, "Ende", ""])


def _changed(node: BaseModel, prefix: str) -> Iterator[tuple[str, Any]]:
    for name, info in type(node).model_fields.items():
        if name == "unknown":
            continue
        member = prefix + (info.alias or name)
        value = getattr(node, name)
        items = list(enumerate(value)) if isinstance(value, list) else [(None, value)]
        for index, item in items:
            path = member if index is None else f"{member}[{index}]"
            if isinstance(item, BaseModel):
                yield from _changed(item, path + ".")
                continue
            resolution = catalogue().resolve(path)
            if resolution is not None and item is not None and item != resolution.parameter.typed_default:
                yield path, item


def _written(value: Any) -> str:
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, str) and (not value or any(c in value for c in ' \t"(')):
        return '"' + value.replace('"', "") + '"' if value else ""
    return str(value)
