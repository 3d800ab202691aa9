"""The behaviour of the typed list models; their fields are generated into `model/generated*.py`.

`ListBase` is the base class of every generated root class: it holds the names the catalogue does not know
and where each value came from. `AxisBase`, the base of `AxisParameters`, adds the CNC's corrections and the
rules' findings, and runs the cross-parameter rules when data is validated; the channel and start-up models
(`ChannelParameters`, `StartupParameters`) sit on `ListBase` itself.
What that needs sits here too, below the generated classes: how a canonical path names the model's fields
(`field_name`, `model_parts`), the model written back as a list (`dumps`), and rule findings as one
`ValidationError` (`rule_errors`).
"""

from __future__ import annotations

import keyword
import math
import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

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

from ..catalogue import Catalogue
from ..catalogue.kinds import BY_ID
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


class ListBase(BaseModel):
    """Shared behaviour of the generated root models: names the catalogue does not know, where each value
    came from, and a value by its canonical path."""

    model_config = ConfigDict(populate_by_name=True, extra="forbid")
    KIND: ClassVar[str] = "axis"  # the kind of list (`catalogue.kinds` id) whose catalogue the model mirrors
    unknown: dict[str, str] = Field(
        default_factory=dict, description="Parameters the catalogue does not know, as written."
    )
    _sources: dict[str, Source] = PrivateAttr(default_factory=dict)

    @classmethod
    def catalogue(cls) -> Catalogue:
        """The catalogue of the model's kind of list."""
        cat = BY_ID[cls.KIND].catalogue()
        if cat is None:
            raise TypeError(f"{cls.__name__}: no catalogue of {cls.KIND} lists")
        return cat

    def __eq__(self, other: object) -> bool:
        """Models are equal when they hold the same values (`loads(dumps(m)) == m`): where the values came
        from (`source_of`), the corrections and the findings describe the file read, not the list."""
        if not isinstance(other, BaseModel):
            return NotImplemented
        return (
            type(self) is type(other)
            and self.__dict__ == other.__dict__
            and self.__pydantic_extra__ == other.__pydantic_extra__
        )

    def source_of(self, path: str) -> Source:
        """Where the value of a canonical path (`getriebe[0].vb_reflow`, `gruppe[0].achs_anzahl`) came from."""
        return self._sources.get(path, DEFAULT)

    def get(self, path: str) -> Any:
        """The value of a canonical path, e.g. `getriebe[0].vb_reflow`."""
        value: Any = self
        for name, indices in model_parts(type(self), path):
            value = getattr(value, field_name(name))
            for index in indices:
                value = value[index]
        return value


class AxisBase(ListBase):
    """Shared behaviour of the generated axis model: the CNC's corrections, the rules' findings, and the
    cross-parameter rules run when data is validated."""

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


def field_name(name: str) -> str:
    """The Python name of a list member: keywords and `model_*` get a trailing "_", dotted rests are joined
    with "_", a name that starts with a digit (`2nd_path_on_actual_1st_path`, P-CHAN-00396) gets "p_" in
    front. tools/gen_model.py names the generated fields with this same function."""
    if "." in name:
        name = name.replace(".", "_")
    elif keyword.iskeyword(name) or name.startswith("model_"):
        name += "_"
    return "p_" + name if name[:1].isdigit() else name


# A member (it may start with a digit: P-CHAN-00396) and its indices (two for `trafo[i].linkage[i][i]`).
_MEMBER = re.compile(r"([A-Za-z0-9_]+)((?:\[\d+\])*)")
_INDEX = re.compile(r"\d+")


def model_parts(model: type[BaseModel], path: str) -> list[tuple[str, tuple[int, ...]]]:
    """A canonical path as (member, indices) pairs of `model`'s fields.

    A parameter below another parameter (`kenngr.swe_pos.zero_limit` beside `kenngr.swe_pos`, P-AXIS-00560)
    is one field of the group, named by joining the rest (`swe_pos_zero_limit`): the walk meets a value
    where the path goes on, and the rest is that field."""
    parts = [(name, tuple(map(int, _INDEX.findall(written)))) for name, written in _MEMBER.findall(path)]
    group: type[BaseModel] = model
    for position, (name, _) in enumerate(parts):
        info = group.model_fields.get(field_name(name))
        if info is None:
            break
        inner = inner_model(info.annotation)
        if inner is None:
            if position < len(parts) - 1:
                return [*parts[:position], (field_name(".".join(n for n, _ in parts[position:])), ())]
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
    for name, indices in model_parts(model, path):
        loc.append(name)
        loc.extend(indices)
    return tuple(loc)


def _rule_findings(text: str) -> list[Diagnostic]:
    settings = FileSettings.of(["LIS3", "LIS4"], keep_source=False)
    return findings(text.encode("utf-8"), "<model>", settings)


def dumps(model: ListBase) -> str:
    """The model as a list of its kind in canonical layout: every value that differs from the CNC's default,
    then the names the catalogue does not know as the list wrote them (`unknown`: a setting the CNC may know
    all the same), then `Ende`. Raises TypeError for anything but a list model, and ValueError for a value no
    list can hold (a line break, a quote in a value that needs quotes, a number that is not finite): written
    some other way, it would read back as another value, or as other assignments."""
    if not isinstance(model, ListBase):
        raise TypeError(
            f"dumps() takes a list model (from load, loads or build_list_model), not {type(model).__name__}"
        )
    cat = type(model).catalogue()
    lines = [
        f"{path:<47} {_written(value, symbols, path)}".rstrip()
        for path, value, symbols in _changed(model, "", cat)
    ]
    for path, raw in model.unknown.items():
        if "\n" in path or "\r" in path or "\n" in raw or "\r" in raw:
            raise ValueError(f"{path!r}: a name or value with a line break cannot be written to a list")
        lines.append(f"{path:<47} {raw}".rstrip())
    return "\n".join([*lines, "Ende", ""])


def _changed(node: BaseModel, prefix: str, cat: Catalogue) -> Iterator[tuple[str, Any, bool]]:
    """(path, value, whether the parameter takes symbols) of every value that differs from its default."""
    for name, info in type(node).model_fields.items():
        if name == "unknown":
            continue
        for path, item in _elements(prefix + (info.alias or name), getattr(node, name)):
            if isinstance(item, BaseModel):
                yield from _changed(item, path + ".", cat)
                continue
            resolution = cat.resolve(path)
            if resolution is not None and item is not None and item != resolution.parameter.typed_default:
                yield path, item, bool(resolution.parameter.symbols)


def _elements(path: str, value: Any) -> Iterator[tuple[str, Any]]:
    """A field's value with its path, or each element of an array (of arrays) with its indices."""
    if not isinstance(value, list):
        yield path, value
        return
    for index, item in enumerate(value):
        yield from _elements(f"{path}[{index}]", item)


# A bare word the parser reads as a reference to another parameter (grammars/achsmds.lark: REFERENCE).
_REFERENCE = re.compile(r"P-AXIS-[0-9]+(?:\.[0-9]+)?")


def _written(value: Any, symbols: bool = False, path: str = "value") -> str:
    """A value as the list writes it; symbols bare, OR-combined flags (`REPORT | PRINT`) too. A string is
    quoted where it would not read back bare: blanks, `(`, a leading `#`, a reference's spelling."""
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(
                f"{path}: {value!r} cannot be written in a list (the CNC reads finite numbers only)"
            )
        return repr(value)
    text = str(value)
    if "\n" in text or "\r" in text:
        raise ValueError(f"{path}: {text!r} cannot be written in a list (a line break ends the assignment)")
    if not isinstance(value, str) or symbols or not text:
        return text
    if not (any(c in text for c in ' \t"(') or text.startswith("#") or _REFERENCE.fullmatch(text)):
        return text
    if '"' not in text:
        return f'"{text}"'
    if not any(c in text for c in " \t(") and not text.startswith(('"', "#")):
        return text  # a quote inside a word: the word is read as it stands
    raise ValueError(f"{path}: {text!r} cannot be written in a list (a quoted value cannot hold a quote)")
