"""The typed axis model: pydantic v2 classes generated from the catalogue.

`AxisParameters` mirrors the list structure: `kopf`, `kenngr` (with
`kenngr.homing`), `getriebe[0..5]`, `lr_hw[0..1]`, `antr` (with `simu`,
`sercos`, `fixed_stop`, `reference_check`, ...) and every other group the
catalogue knows. Every field has the parameter's type, its range where the
catalogue gives literal bounds, its default and its description, so the JSON
Schema documents the whole list format.

Values are filled the way the CNC loads an axis: the built-in default, then the
default axis list (if given), then the axis list. `source_of(path)` tells where
the effective value came from.
"""

from __future__ import annotations

import keyword
import re
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, Literal, Optional

from pydantic import BaseModel, ConfigDict, Field, PrivateAttr, create_model

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


def _tree() -> _Node:
    root = _Node()
    for parameter in catalogue().parameters:
        node = root
        segments = parameter.path.split(".")
        bounds = iter(parameter.index_bounds)
        placed = True
        for position, segment in enumerate(segments):
            name, is_array = segment.replace("[i]", ""), "[i]" in segment
            child = node.children.get(name)
            last = position == len(segments) - 1
            if child is None:
                child = node.children[name] = _Node()
            if (last and child.children) or (not last and child.parameter is not None):
                placed = False  # a path that clashes with another (a documented misprint)
                break
            if is_array:
                child.bounds = next(bounds)
            node = child
        if placed:
            node.parameter = parameter
    return root


def _field_name(name: str) -> str:
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

    def source_of(self, path: str) -> Source:
        """Where the effective value of a canonical path (`getriebe[0].vb_reflow`) came from."""
        return self._sources.get(path, DEFAULT)

    def get(self, path: str) -> Any:
        """The effective value of a canonical path, e.g. `getriebe[0].vb_reflow`."""
        value: Any = self
        for name, index in re.findall(r"([A-Za-z_][A-Za-z0-9_]*)(?:\[(\d+)\])?", path):
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


def _nested_set(target: dict, path: str, value: Any) -> None:
    parts = re.findall(r"([A-Za-z_][A-Za-z0-9_]*)(?:\[(\d+)\])?", path)
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
    """Parse an axis list (optionally on top of a default list) into `AxisParameters`."""
    from .analysis import analyse
    from .syntax import parse_bytes

    values: dict[str, Any] = {}
    sources: dict[str, Source] = {}
    unknown: dict[str, str] = {}
    layers = []
    if default_list is not None:
        layers.append((default_list[0], default_list[1], "default list"))
    layers.append((data, name, "list"))
    for layer_data, layer_name, kind in layers:
        analysis = analyse(parse_bytes(layer_data, layer_name))
        for setting in analysis.settings:
            line = setting.line
            if not setting.known:
                unknown[line.path] = line.value or ""
                continue
            if setting.problems or setting.value is None or not _is_plain(setting.value):
                continue
            values[setting.canonical] = setting.value
            sources[setting.canonical] = Source(kind, layer_name, line.number, line.path_column)
    nested: dict = {}
    for path, value in values.items():
        _nested_set(nested, path, value)
    model = axis_model()
    axis = model.model_validate({**_materialise(model, nested), "unknown": unknown})
    axis._sources = sources
    return axis


def _is_plain(value: Any) -> bool:
    return isinstance(value, (bool, int, float, str))
