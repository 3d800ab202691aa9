"""The typed axis model: building it from a list, validating it, and writing it back as a list.

The classes are plain pydantic v2 code generated from the catalogue into `model/generated.py`
(`python tools/build_catalogue.py`); their shared behaviour is `model_base.AxisBase`.

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
from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING, Any

from pydantic import BaseModel, ValidationError
from pydantic_core import InitErrorDetails, PydanticCustomError

from ..catalogue import catalogue
from .base import DEFAULT, AxisBase, Source

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic

__all__ = [
    "DEFAULT",
    "AxisBase",
    "Source",
    "axis_model",
    "build_model",
    "dumps",
    "json_schema",
    "rule_errors",
]


def field_name(name: str) -> str:
    """The Python name of a list member: keywords and `model_*` get a trailing "_", dotted rests are joined
    with "_". tools/gen_model.py names the generated fields with this same function."""
    if "." in name:
        return name.replace(".", "_")
    return name + "_" if keyword.iskeyword(name) or name.startswith("model_") else name


def axis_model() -> type[AxisBase]:
    """The `AxisParameters` class of `model/generated.py` (imported on first use: building it takes a while)."""
    from .generated import AxisParameters

    return AxisParameters


def json_schema() -> dict[str, Any]:
    schema = axis_model().model_json_schema(by_alias=True)
    schema["title"] = "AxisParameters"
    schema["description"] = (
        "Axis parameter list (achsmds*.lis) of a TwinCAT 3 CNC / ISG CNC axis, as typed by achslint."
    )
    return schema


def _parts(path: str) -> list[tuple[str, str]]:
    """A canonical path as (member, index) pairs of the model, joined groups as one member."""
    from .generated import JOINED

    for catalogue_path, (rest, field) in JOINED.items():
        if path == catalogue_path:
            return [*_parts(path[: -len(rest) - 1]), (field, "")]
    return re.findall(r"([A-Za-z_][A-Za-z0-9_]*)(?:\[(\d+)\])?", path)


# Values by model path, nested as the model is: member names map to groups or values, and an array's
# indices to its elements (turned into full lists by `_materialise`).
_Nested = dict[str | int, Any]


def _nested_set(target: _Nested, path: str, value: Any) -> None:
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


def _materialise(model: type[BaseModel], data: _Nested) -> dict[str, Any]:
    """Turn {index: ...} maps into full lists, filling untouched elements with defaults."""
    result: dict[str, Any] = {}
    for key, value in data.items():
        if not isinstance(key, str):
            continue  # indices are only keys of an array's map, handled below
        info = model.model_fields.get(field_name(key))
        if info is None:
            continue
        field_key = field_name(key)
        if isinstance(value, dict) and all(isinstance(k, int) for k in value):
            default_list = info.get_default(call_default_factory=True)
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
            result[field_key] = _materialise(_group_model(info.annotation), value)
        else:
            result[field_key] = value
    return result


def _group_model(annotation: Any) -> type[BaseModel]:
    """The model class of a group field (`kenngr`, `kenngr.homing`)."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    raise TypeError(f"not a group of the model: {annotation!r}")


def _list_item_model(annotation: Any) -> type[BaseModel] | None:
    args = getattr(annotation, "__args__", ())
    if args and isinstance(args[0], type) and issubclass(args[0], BaseModel):
        return args[0]
    return None


def build_model(data: bytes, name: str, default_list: tuple[bytes, str] | None = None) -> AxisBase:
    """The typed model of an axis list (on top of an optional default list), built from its resolved axis."""
    from ..axis.resolved import resolve_bytes

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
            sources[path] = Source(
                origin.kind,
                origin.file if origin.kind == "default list" else name,
                line.number,
                line.path_column,
            )
    unknown = {s.line.path: s.line.value or "" for s in axis.analysis.settings if not s.known}
    model = axis_model()  # also records the joined groups _nested_set needs
    nested: _Nested = {}
    for path, value in values.items():
        _nested_set(nested, path, value)
    result = model.model_validate(
        {**_materialise(model, nested), "unknown": unknown}, context={"lenient": True}
    )
    result._sources = sources
    result._corrections = axis.corrections
    return result


def _is_plain(value: Any) -> bool:
    return isinstance(value, (bool, int, float, str))


def rule_errors(diagnostics: Iterable[Diagnostic]) -> ValidationError:
    """One ValidationError with an entry per finding: its code, the parameter path and the message."""
    details = [
        InitErrorDetails(
            type=PydanticCustomError(
                "cross_rule", "{code}: {message}", {"code": d.code, "message": d.message}
            ),
            loc=_loc(d.parameter) if d.parameter else ("list",),
            input=d.parameter,
        )
        for d in diagnostics
    ]
    return ValidationError.from_exception_data("AxisParameters", details)


def _loc(path: str) -> tuple[str | int, ...]:
    loc: list[str | int] = []
    for name, index in _parts(path):
        loc.append(name)
        if index:
            loc.append(int(index))
    return tuple(loc)


def _rule_findings(text: str) -> list[Diagnostic]:
    from ..linting.linter import FileSettings, findings

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
