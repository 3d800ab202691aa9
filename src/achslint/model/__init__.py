"""The typed list models: building one from a list, validating it, and writing it back as a list.

Three kinds of list have a model (`MODELS`): axis lists (`AxisParameters`, below), channel lists
(`ChannelParameters`, `model/generated_channel.py`) and start-up lists (`StartupParameters`,
`model/generated_startup.py`). `achslint schema --kind channel` prints a model's JSON Schema. The channel and
start-up models are built from what the linter reads of the list (`build_list_model`): each value the
kind's catalogue knows and the linter accepts, typed; names the catalogue does not know in `unknown`.

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

import copy
import functools
import importlib
from collections.abc import Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from pydantic import BaseModel, ValidationError

from ..axis.analysis import analyse
from ..axis.resolved import resolve_bytes
from ..catalogue.kinds import BY_ID
from ..syntax.parser import parse_bytes
from . import base
from .base import DEFAULT, AxisBase, ListBase, Source, dumps, field_name, inner_model, model_parts

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .generated import AxisParameters

__all__ = [
    "DEFAULT",
    "MODELS",
    "AxisBase",
    "ListBase",
    "Source",
    "axis_model",
    "build_list_model",
    "build_model",
    "dumps",
    "field_name",
    "json_schema",
    "list_model",
    "rule_errors",
]


@dataclass(frozen=True)
class ModelInfo:
    """A generated model: its module below `achslint.model`, its root class and what its schema says."""

    module: str
    root: str
    description: str


# Kind of list (`catalogue.kinds` id) -> its model. A default list has the model of the list it lies under.
MODELS: dict[str, ModelInfo] = {
    "axis": ModelInfo(
        "generated",
        "AxisParameters",
        "Axis parameter list (achsmds*.lis) of a TwinCAT 3 CNC / ISG CNC axis, as typed by achslint.",
    ),
    "channel": ModelInfo(
        "generated_channel",
        "ChannelParameters",
        "Channel parameter list (sda_mds[i] of the start-up list) of a TwinCAT 3 CNC / ISG CNC channel, as "
        "typed by achslint from its channel catalogue (P-CHAN; arrays open, their sizes are not in it).",
    ),
    "startup": ModelInfo(
        "generated_startup",
        "StartupParameters",
        "Start-up list (hochlauf.lis) of a TwinCAT 3 CNC / ISG CNC, as typed by achslint from its start-up "
        "catalogue (P-STUP; arrays open, their sizes are not in it).",
    ),
}
ALIASES = {"default_axis": "axis", "default_channel": "channel"}


def list_model(kind: str = "axis") -> type[ListBase]:
    """The root class of a kind's model (its module imported on first use: building it takes a while).
    Raises KeyError for a kind without a model."""
    info = MODELS[ALIASES.get(kind, kind)]
    model: type[ListBase] = getattr(importlib.import_module(f"{__name__}.{info.module}"), info.root)
    return model


def axis_model() -> type[AxisParameters]:
    """The `AxisParameters` class of `model/generated.py` (imported on first use: building it takes a while)."""
    from .generated import AxisParameters

    return AxisParameters


def json_schema(kind: str = "axis") -> dict[str, Any]:
    """The JSON Schema of a kind's model (`axis`, `channel`, `startup`): a copy of its own for each call."""
    return copy.deepcopy(_json_schema(ALIASES.get(kind, kind)))


@functools.cache
def _json_schema(kind: str) -> dict[str, Any]:
    """Made once per process: pydantic takes 0.03-0.3 s to make a kind's schema, copying it 1-13 ms."""
    info = MODELS[kind]
    schema = list_model(kind).model_json_schema(by_alias=True)
    schema["title"] = info.root
    schema["description"] = info.description
    return schema


# Values by model path, nested as the model is: member names map to groups or values, and an array's
# indices to its elements (turned into full lists by `_materialise`).
_Nested = dict[str | int, Any]


def _nested_set(target: _Nested, model: type[BaseModel], path: str, value: Any) -> None:
    parts = model_parts(model, path)
    node = target
    for position, (name, indices) in enumerate(parts):
        last = position == len(parts) - 1
        if indices:
            items = node.setdefault(name, {})
            for index in indices[:-1]:  # an array of arrays: maps of maps
                items = items.setdefault(index, {})
            if last:
                items[indices[-1]] = value
            else:
                node = items.setdefault(indices[-1], {})
        elif last:
            node[name] = value
        else:
            node = node.setdefault(name, {})


def _materialise(model: type[BaseModel], data: _Nested) -> dict[str, Any]:
    """Turn {index: ...} maps into full lists, filling untouched elements with defaults (an open array, of a
    size the catalogue does not give, reaches its highest index written; a gap is None or a default group)."""
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
            size = len(default_list) or max(value, default=-1) + 1  # bounded arrays keep their size
            items = []
            for i in range(size):
                if i in value:
                    item = value[i]
                    if isinstance(item, dict):  # a group, or the next index of an array of arrays
                        item = _materialise(inner, item) if inner else _open_list(item)
                    items.append(item)
                elif i < len(default_list):
                    items.append(default_list[i])
                else:  # a default group, an empty inner array of an array of arrays, or None
                    items.append({} if inner else [] if _of_arrays(info.annotation) else None)
            result[field_key] = items
        elif isinstance(value, dict):
            group = inner_model(info.annotation)
            if group is None:
                raise TypeError(f"not a group of the model: {info.annotation!r}")
            result[field_key] = _materialise(group, value)
        else:
            result[field_key] = value
    return result


def _of_arrays(annotation: Any) -> bool:
    """Whether a field's annotation is a list of lists (`List[List[Optional[float]]]`)."""
    args: tuple[Any, ...] = getattr(annotation, "__args__", ())
    return bool(args) and getattr(args[0], "__origin__", None) is list


def _open_list(values: dict[int, Any]) -> list[Any]:
    """An inner array of an array of arrays: up to its highest index written, gaps None."""
    return [
        _open_list(values[i]) if isinstance(values.get(i), dict) else values.get(i)
        for i in range(max(values, default=-1) + 1)
    ]


def build_model(data: bytes, name: str, default_list: tuple[bytes, str] | None = None) -> AxisParameters:
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


MAX_INDEX = 1023  # an open array's highest index the model builds; a name with a higher one stays unknown


def build_list_model(data: bytes, name: str, kind: str) -> ListBase:
    """The typed model of a channel or start-up list (`kind`; KeyError for a kind without a model): every
    value its kind's catalogue knows and the linter reads without a problem (a value with one keeps its
    default: the list's findings say why), where it came from, and the names the catalogue does not know
    (or indices beyond `MAX_INDEX`) as written. Raises UnreadableInput for bytes that are no list and
    TypeError for text (`text_bytes` makes the bytes of a text)."""
    if not isinstance(data, (bytes, bytearray)):
        raise TypeError(
            f"build_list_model() takes the bytes of a list, not {type(data).__name__}: "
            "open(path, 'rb').read(), or text.encode() for a str"
        )
    model = list_model(kind)
    cat = BY_ID[kind].catalogue()
    assert cat is not None  # a kind with a model has a catalogue
    analysis = analyse(parse_bytes(data, name), cat)
    nested: _Nested = {}
    sources: dict[str, Source] = {}
    unknown: dict[str, str] = {}
    for setting in analysis.settings:
        line = setting.line
        path, resolution = setting.canonical, setting.resolution
        if path is None or resolution is None or any(index > MAX_INDEX for index in resolution.indices):
            unknown[line.path or ""] = line.value or ""
            continue
        if setting.problems or not _is_plain(setting.value):
            continue
        _nested_set(nested, model, path, setting.value)
        sources[path] = Source("list", name, line.number, line.path_column)
    result = model.model_validate({**_materialise(model, nested), "unknown": unknown})
    result._sources = sources
    return result


def rule_errors(diagnostics: Iterable[Diagnostic]) -> ValidationError:
    """One ValidationError with an entry per finding of the rules: its code, the parameter path in
    `AxisParameters` and the message."""
    return base.rule_errors(diagnostics, axis_model())
