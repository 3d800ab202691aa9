"""Generate src/achslint/model/generated.py: the typed axis model as plain pydantic classes.

Usage:
    python tools/gen_model.py           # rewrite the module from the catalogue
    python tools/gen_model.py --check   # exit 1 when the committed module is stale

`tools/build_catalogue.py` runs this after writing the catalogue. The module mirrors the list's
structure (`kopf`, `kenngr.homing`, `getriebe[0..5]`, `antr.sercos`, ...): one class per group, one
field per parameter with its type, bounds, default and description, so that IDEs and type checkers
see every field. Runtime behaviour (cross-rule validation, sources, corrections) lives in
`achslint.model.base.AxisBase`, the root class's base.
"""

from __future__ import annotations

import argparse
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from achslint.catalogue import BOOL, INTEGER, REAL, SYMBOL, Parameter, catalogue  # noqa: E402
from achslint.model import field_name  # noqa: E402  (the runtime model resolves paths by the same names)

OUTPUT = ROOT / "src" / "achslint" / "model" / "generated.py"


@dataclass
class Node:
    """A member of the list structure: a group (children) or a parameter, possibly an array."""

    children: dict[str, Node] = field(default_factory=dict)
    bounds: tuple[int, int] | None = None
    parameter: Parameter | None = None


def class_name(path: list[str]) -> str:
    return (
        "".join(part.capitalize() for part in re.split(r"[_\W]+", "_".join(path)) if part) or "AxisParameters"
    )


def tree() -> Node:
    """The structure of every catalogue path.

    A path whose group is itself a parameter (`kenngr.swe_pos.zero_limit`, P-AXIS-00560, next to
    `kenngr.swe_pos`) becomes a field of the parent group named by joining the rest with "_"; the model
    finds such a field by the same rule (`achslint.model.base.model_parts`)."""
    root = Node()
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
                node.children[rest] = Node(parameter=parameter)
                break
            if child is None:
                child = node.children[name] = Node()
            if is_array:
                low, high = next(bounds)
                child.bounds = (low, high)
            node = child
            if last:
                node.parameter = parameter
    return root


def leaf_type(parameter: Parameter) -> tuple[str, dict[str, object]]:
    """The annotation (as source text) and the constraints of a parameter's field."""
    kind = parameter.kind
    if kind == BOOL:
        return "bool", {}
    if kind == SYMBOL:
        return f"Literal[{', '.join(repr(s) for s in parameter.symbols)}]", {}
    if kind in (INTEGER, REAL):
        low, high = parameter.limits
        constraints = {key: bound for key, bound in (("ge", low), ("le", high)) if bound is not None}
        if kind == REAL:
            return "float", constraints
        return ("Union[int, str]" if parameter.symbols else "int"), constraints
    if parameter.max_length:
        return "str", {"max_length": max(parameter.max_length, len(str(parameter.default or "")))}
    return "str", {}


def description(parameter: Parameter) -> str:
    text = f"{parameter.id}: {parameter.summary}".rstrip(": ")
    unit = parameter.unit("T")
    if unit:
        text += f" [{unit}]"
    return text


def _arguments(**values: object) -> str:
    return ", ".join(f"{key}={value}" for key, value in values.items())


def classes(node: Node, path: list[str], out: list[str]) -> str:
    """Append the source of the class for `node` (children first) to `out`; return its name."""
    lines = []
    for name, child in node.children.items():
        python_name = field_name(name)
        alias = {"alias": repr(name)} if python_name != name else {}
        if child.parameter is not None:
            parameter = child.parameter
            annotation, constraints = leaf_type(parameter)
            default = parameter.typed_default
            if default is None:
                annotation = f"Optional[{annotation}]"
            text = repr(description(parameter))
            if child.bounds is not None:
                size = child.bounds[1] + 1
                lines.append(
                    f"    {python_name}: List[{annotation}] = Field("
                    + _arguments(
                        default_factory=f"lambda: [{default!r}] * {size}",
                        min_length=size,
                        max_length=size,
                        description=text,
                        **alias,
                    )
                    + ")"
                )
            else:
                lines.append(
                    f"    {python_name}: {annotation} = Field("
                    + _arguments(
                        default=repr(default),
                        description=text,
                        **{k: repr(v) for k, v in constraints.items()},
                        **alias,
                    )
                    + ")"
                )
            continue
        sub = classes(child, [*path, name], out)
        if child.bounds is not None:
            size = child.bounds[1] + 1
            lines.append(
                f"    {python_name}: List[{sub}] = Field("
                + _arguments(
                    default_factory=f"lambda: [{sub}() for _ in range({size})]",
                    min_length=size,
                    max_length=size,
                    **alias,
                )
                + ")"
            )
        else:
            lines.append(
                f"    {python_name}: {sub} = Field(" + _arguments(default_factory=sub, **alias) + ")"
            )
    own = class_name(path) if path else "AxisParameters"
    base = "AxisBase" if not path else "_Group"
    title = ".".join(path) or "the axis list"
    out.append(f'class {own}({base}):\n    """Parameters of {title}."""\n\n' + "\n".join(lines) + "\n")
    return own


def model_source() -> str:
    root = tree()
    out: list[str] = []
    classes(root, [], out)
    header = (
        '"""The typed axis model, one class per group of the list. Generated by tools/gen_model.py from the\n'
        'catalogue: do not edit; run `python tools/build_catalogue.py` after changing the catalogue."""\n\n'
        "# ruff: noqa: E501\n"
        "from typing import List, Literal, Optional, Union\n\n"
        "from pydantic import BaseModel, ConfigDict, Field\n\n"
        "from .base import AxisBase\n\n\n"
        "class _Group(BaseModel):\n"
        '    """A group of parameters below the axis list."""\n\n'
        '    model_config = ConfigDict(populate_by_name=True, extra="forbid", validate_default=False)\n'
    )
    return header + "".join("\n\n" + text for text in out)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="change nothing; exit 1 if the module is stale")
    args = parser.parse_args(argv)
    text = model_source()
    if args.check:
        if not OUTPUT.exists() or OUTPUT.read_text(encoding="utf-8") != text:
            print(f"{OUTPUT} is stale: run python tools/build_catalogue.py", file=sys.stderr)
            return 1
        return 0
    OUTPUT.write_text(text, encoding="utf-8")
    print(f"wrote {OUTPUT}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
