"""The typed axis model: pydantic v2 classes generated from the catalogue.

`AxisParameters` mirrors the list structure: `kopf`, `kenngr` (with
`kenngr.homing`), `getriebe[0..5]`, `lr_hw[0..1]`, `antr` (with `simu`,
`sercos`, `fixed_stop`, `reference_check`, ...) and every other group the
catalogue knows. Every field has the parameter's type, its range where the
catalogue gives literal bounds, its default and its description, so the JSON
Schema documents the whole list format.

Values come from the resolved axis (`resolved.py`): the built-in default, the
default axis list (if given), the axis list, references resolved and the CNC's
load-time corrections applied. `source_of(path)` tells where a value came from,
`corrections` what the CNC replaced, `findings` what the rules found.

The cross-parameter rules are part of the model: validating data with
`AxisParameters.model_validate(...)` runs the same rule code as `achslint lint`
on the axis the data describes and raises one `ValidationError` with an entry
per error-level finding (its code, parameter and message). `achslint.load()`
is lenient and keeps the findings on the model; `load(..., strict=True)` raises.
"""

from __future__ import annotations

import keyword
import re
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, Literal, Optional

from pydantic import BaseModel, ConfigDict, Field, PrivateAttr, ValidationError, ValidationInfo, create_model, model_validator
from pydantic_core import InitErrorDetails, PydanticCustomError

from .catalogue import BOOL, INTEGER, REAL, SYMBOL, Parameter, catalogue


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


class _Node:
    def __init__(self) -> None:
        self.children: dict[str, _Node] = {}
        self.bounds: tuple[int, int] | None = None  # this member is an array
        self.parameter: Parameter | None = None


# Catalogue paths whose group is itself a parameter (`kenngr.swe_pos.zero_limit`, P-AXIS-00560, next to
# `kenngr.swe_pos`): the model keeps them as one field of the parent group, named by joining the rest with "_".
_JOINED: dict[str, tuple[str, str]] = {}  # catalogue path -> (written rest, field name)


def _tree() -> _Node:
    root = _Node()
    for parameter in catalogue().parameters:
        node = root
        segments = parameter.path.split(".")
        bounds = iter(parameter.index_bounds)
        for position, segment in enumerate(segments):
            name, is_array = segment.replace("[i]", ""), "[i]" in segment
            last = position == len(segments) - 1
            child = node.children.get(name)
            if not last and child is not None and child.parameter is not None and "[i]" not in parameter.path:
                rest = ".".join(segments[position:])
                _JOINED[parameter.path] = (rest, rest.replace(".", "_"))
                child = node.children[rest] = _Node()
                child.parameter = parameter
                break
            if child is None:
                child = node.children[name] = _Node()
            if is_array:
                child.bounds = next(bounds)
            node = child
            if last:
                node.parameter = parameter
    return root


def _field_name(name: str) -> str:
    if "." in name:
        return name.replace(".", "_")
    return name + "_" if keyword.iskeyword(name) or name in ("model_config",) or name.startswith("model_") else name


def _class_name(path: list[str]) -> str:
    return "".join(part.capitalize() for part in re.split(r"[_\W]+", "_".join(path)) if part) or "AxisParameters"


def _leaf_type(parameter: Parameter) -> tuple[Any, dict]:
    kind = parameter.kind
    constraints: dict = {}
    if kind == BOOL:
        return bool, constraints
    if kind == SYMBOL:
        return Literal[tuple(parameter.symbols)], constraints
    if kind in (INTEGER, REAL):
        low, high = parameter.limits
        if low is not None:
            constraints["ge"] = low
        if high is not None:
            constraints["le"] = high
        if kind == REAL:
            return float, constraints
        return (int | str if parameter.symbols else int), constraints
    if parameter.max_length:
        constraints["max_length"] = max(parameter.max_length, len(str(parameter.default or "")))
    return str, constraints


def _description(parameter: Parameter) -> str:
    text = f"{parameter.id}: {parameter.summary}".rstrip(": ")
    unit = parameter.unit("T")
    if unit:
        text += f" [{unit}]"
    return text


def _build(node: _Node, path: list[str]) -> type[BaseModel]:
    fields: dict[str, Any] = {}
    for name, child in node.children.items():
        field_name = _field_name(name)
        extra = {"alias": name} if field_name != name else {}
        if child.parameter is not None:
            parameter = child.parameter
            annotation, constraints = _leaf_type(parameter)
            default = parameter.typed_default
            if default is None:
                annotation = Optional[annotation]
            description = _description(parameter)
            if child.bounds is not None:
                size = child.bounds[1] + 1
                fields[field_name] = (
                    list[annotation],
                    Field(default_factory=lambda d=default, n=size: [d] * n, min_length=size, max_length=size,
                          description=description, **extra),
                )
            else:
                fields[field_name] = (annotation, Field(default, description=description, **constraints, **extra))
            continue
        sub = _build(child, path + [name])
        if child.bounds is not None:
            size = child.bounds[1] + 1
            fields[field_name] = (
                list[sub],
                Field(default_factory=lambda cls=sub, n=size: [cls() for _ in range(n)], min_length=size,
                      max_length=size, **extra),
            )
        else:
            fields[field_name] = (sub, Field(default_factory=sub, **extra))
    config = ConfigDict(populate_by_name=True, extra="forbid", validate_default=False)
    return create_model(_class_name(path), __config__=config, **fields)


class _AxisBase(BaseModel):
    """Shared behaviour of the generated root model."""

    model_config = ConfigDict(populate_by_name=True, extra="forbid")
    unknown: dict[str, str] = Field(default_factory=dict, description="Parameters the catalogue does not know, as written.")
    _sources: dict[str, Source] = PrivateAttr(default_factory=dict)
    _corrections: list = PrivateAttr(default_factory=list)
    _findings: list = PrivateAttr(default_factory=list)

    @property
    def corrections(self) -> list:
        """The CNC's load-time corrections (`resolved.Correction`) behind the values of this model."""
        return list(self._corrections)

    @property
    def findings(self) -> list:
        """The diagnostics `achslint lint` reports for the list this model was loaded from."""
        return list(self._findings)

    @model_validator(mode="after")
    def _cross_rules(self, info: ValidationInfo):
        """The cross-parameter rules, run by the same rule code as `achslint lint` on the axis the data describes."""
        if info.context and info.context.get("lenient"):
            return self
        errors = [d for d in _rule_findings(dumps(self)) if d.severity.value == "error"]
        if errors:
            raise rule_errors(errors)
        return self

    def source_of(self, path: str) -> Source:
        """Where the effective value of a canonical path (`getriebe[0].vb_reflow`) came from."""
        return self._sources.get(path, DEFAULT)

    def get(self, path: str) -> Any:
        """The effective value of a canonical path, e.g. `getriebe[0].vb_reflow`."""
        value: Any = self
        for name, index in _parts(path):
            value = getattr(value, _field_name(name))
            if index:
                value = value[int(index)]
        return value


@lru_cache(maxsize=1)
def axis_model() -> type[BaseModel]:
    """The generated `AxisParameters` class (built once per process)."""
    root = _tree()
    groups = _build(root, [])
    fields = {name: (info.annotation, info) for name, info in groups.model_fields.items()}
    return create_model("AxisParameters", __base__=_AxisBase, **fields)


def json_schema() -> dict:
    schema = axis_model().model_json_schema(by_alias=True)
    schema["title"] = "AxisParameters"
    schema["description"] = "Axis parameter list (achsmds*.lis) of a TwinCAT 3 CNC / ISG CNC axis, as typed by achslint."
    return schema


def _parts(path: str) -> list[tuple[str, str]]:
    """A canonical path as (member, index) pairs of the model, joined groups as one member."""
    for catalogue_path, (rest, field) in _JOINED.items():
        if path == catalogue_path:
            return _parts(path[: -len(rest) - 1]) + [(field, "")]
    return re.findall(r"([A-Za-z_][A-Za-z0-9_]*)(?:\[(\d+)\])?", path)


def _nested_set(target: dict, path: str, value: Any) -> None:
    parts = _parts(path)
    node = target
    for position, (name, index) in enumerate(parts):
        last = position == len(parts) - 1
        if index:
            items = node.setdefault(name, {})
            if last:
                items[int(index)] = value
            else:
                node = items.setdefault(int(index), {})
        elif last:
            node[name] = value
        else:
            node = node.setdefault(name, {})


def _materialise(model: type[BaseModel], data: dict) -> dict:
    """Turn {index: ...} maps into full lists, filling untouched elements with defaults."""
    result: dict = {}
    for key, value in data.items():
        info = model.model_fields.get(_field_name(key))
        if info is None:
            continue
        field_key = _field_name(key)
        if isinstance(value, dict) and all(isinstance(k, int) for k in value):
            default_list = info.default_factory()
            inner = _list_item_model(info.annotation)
            items = []
            for i in range(len(default_list)):
                if i in value:
                    item = value[i]
                    items.append(_materialise(inner, item) if inner and isinstance(item, dict) else item)
                else:
                    items.append(default_list[i])
            result[field_key] = items
        elif isinstance(value, dict):
            result[field_key] = _materialise(info.annotation, value)
        else:
            result[field_key] = value
    return result


def _list_item_model(annotation: Any) -> type[BaseModel] | None:
    args = getattr(annotation, "__args__", ())
    if args and isinstance(args[0], type) and issubclass(args[0], BaseModel):
        return args[0]
    return None


def build_model(data: bytes, name: str, default_list: tuple[bytes, str] | None = None):
    """The typed model of an axis list (on top of an optional default list), built from its resolved axis."""
    from .resolved import resolve_bytes

    axis = resolve_bytes(data, name, default_list[0] if default_list else None)
    values: dict[str, Any] = {}
    sources: dict[str, Source] = {}
    for path in axis.set_paths() + [c.parameter for c in axis.corrections]:
        value = axis.get(path)
        if not _is_plain(value):
            continue
        values[path] = value
        origin = axis.origin(path)
        if origin.setting is not None:
            line = origin.setting.line
            sources[path] = Source(origin.kind, origin.file if origin.kind == "default list" else name, line.number,
                                   line.path_column)
    unknown = {s.line.path: s.line.value or "" for s in axis.analysis.settings if not s.known}
    model = axis_model()  # also records the joined groups _nested_set needs
    nested: dict = {}
    for path, value in values.items():
        _nested_set(nested, path, value)
    result = model.model_validate({**_materialise(model, nested), "unknown": unknown}, context={"lenient": True})
    result._sources = sources
    result._corrections = axis.corrections
    return result


def _is_plain(value: Any) -> bool:
    return isinstance(value, (bool, int, float, str))


def rule_errors(diagnostics) -> ValidationError:
    """One ValidationError with an entry per finding: its code, the parameter path and the message."""
    details = [
        InitErrorDetails(
            type=PydanticCustomError("cross_rule", "{code}: {message}", {"code": d.code, "message": d.message}),
            loc=_loc(d.parameter) if d.parameter else ("list",),
            input=d.parameter,
        )
        for d in diagnostics
    ]
    return ValidationError.from_exception_data("AxisParameters", details)


def _loc(path: str) -> tuple:
    loc: list = []
    for name, index in _parts(path):
        loc.append(name)
        if index:
            loc.append(int(index))
    return tuple(loc)


def _rule_findings(text: str) -> list:
    from .linter import FileSettings, Selection, lint_bytes

    settings = FileSettings(Selection(["LIS3", "LIS4"]), keep_source=False)
    return lint_bytes(text.encode("utf-8"), "<model>", settings)


def dumps(axis: BaseModel) -> str:
    """The model as an axis list in canonical layout: every value that differs from the CNC's default, then `Ende`."""
    lines = [f"{path:<48}{_written(value)}".rstrip() for path, value in _changed(axis, "")]
    return "\n".join(lines + ["Ende", ""])


def _changed(node: BaseModel, prefix: str):
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
    if isinstance(value, str) and (not value or any(c in value for c in " \t\"(")):
        return '"' + value.replace('"', "") + '"' if value else ""
    return str(value)
