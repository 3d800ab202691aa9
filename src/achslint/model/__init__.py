"""The typed axis model: building it from a list, validating it, and writing it back as a list.

The classes are plain pydantic v2 code generated from the catalogue into `model/generated.py`
(`python tools/build_catalogue.py`); their shared behaviour is `base.AxisBase`.

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

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from pydantic import BaseModel, ValidationError

from ..axis.resolved import resolve_bytes
from . import base
from .base import DEFAULT, AxisBase, Source, dumps, field_name, inner_model, model_parts

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic

__all__ = [
    "DEFAULT",
    "AxisBase",
    "Source",
    "axis_model",
    "build_model",
    "dumps",
    "field_name",
    "json_schema",
    "rule_errors",
]


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


# Values by model path, nested as the model is: member names map to groups or values, and an array's
# indices to its elements (turned into full lists by `_materialise`).
_Nested = dict[str | int, Any]


def _nested_set(target: _Nested, model: type[BaseModel], path: str, value: Any) -> None:
    parts = model_parts(model, path)
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
            inner = inner_model(info.annotation)
            items = []
            for i in range(len(default_list)):
                if i in value:
                    item = value[i]
                    items.append(_materialise(inner, item) if inner and isinstance(item, dict) else item)
                else:
                    items.append(default_list[i])
            result[field_key] = items
        elif isinstance(value, dict):
            group = inner_model(info.annotation)
            if group is None:
                raise TypeError(f"not a group of the model: {info.annotation!r}")
            result[field_key] = _materialise(group, value)
        else:
            result[field_key] = value
    return result


def build_model(data: bytes, name: str, default_list: tuple[bytes, str] | None = None) -> AxisBase:
    """The typed model of an axis list (on top of an optional default list), built from its resolved axis."""
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
    model = axis_model()
    nested: _Nested = {}
    for path, value in values.items():
        _nested_set(nested, model, path, value)
    result = model.model_validate(
        {**_materialise(model, nested), "unknown": unknown}, context={"lenient": True}
    )
    result._sources = sources
    result._corrections = axis.corrections
    return result


def _is_plain(value: Any) -> bool:
    return isinstance(value, (bool, int, float, str))


def rule_errors(diagnostics: Iterable[Diagnostic]) -> ValidationError:
    """One ValidationError with an entry per finding of the rules: its code, the parameter path in
    `AxisParameters` and the message."""
    return base.rule_errors(diagnostics, axis_model())
