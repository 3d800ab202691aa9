"""Generate the typed list models as plain pydantic classes: src/achslint/model/generated.py (axis lists),
generated_channel.py (channel lists) and generated_startup.py (start-up lists).

Usage:
    python tools/gen_model.py           # rewrite the modules from the catalogues
    python tools/gen_model.py --check   # exit 1 when a committed module is stale

`tools/build_catalogue.py` runs this after writing the axis catalogue, `tools/build_kinds.py` after writing
the kind catalogues. Each module mirrors its list's structure (`kopf`, `kenngr.homing`, `getriebe[0..5]`,
`antr.sercos`, ...; `gruppe[i].achse[i]` of a channel list): one class per group, one field per parameter
with its type, bounds, default and description, so that IDEs and type checkers see every field. Runtime
behaviour lives in `achslint.model.base`: `AxisBase` (cross-rule validation, sources, corrections) under the
axis model, `ListBase` (sources, unknown names) under the others.

The kind catalogues give no array sizes (the reference tables have none), so their arrays are open lists
(an element the list does not write is None, or a group of defaults); a symbol parameter of those lists
takes one symbol or several joined by `|`, as the linter reads them (`axis.analysis.combined_flags`).
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
from achslint.catalogue.kinds import CHANNEL, STARTUP, Kind  # noqa: E402
from achslint.model import field_name  # noqa: E402  (the runtime model resolves paths by the same names)

MODELS = ROOT / "src" / "achslint" / "model"
OUTPUT = MODELS / "generated.py"


@dataclass(frozen=True)
class Target:
    """One generated module: the kind of list, its root class and the base class of that root."""

    kind: Kind | None  # None: the axis catalogue
    output: Path
    root: str
    base: str
    title: str  # the list, for the docstrings


AXIS_MODEL = Target(None, OUTPUT, "AxisParameters", "AxisBase", "the axis list")
TARGETS = (
    AXIS_MODEL,
    Target(CHANNEL, MODELS / "generated_channel.py", "ChannelParameters", "ListBase", "the channel list"),
    Target(STARTUP, MODELS / "generated_startup.py", "StartupParameters", "ListBase", "the start-up list"),
)


@dataclass
class Node:
    """A member of the list structure: a group (children) or a parameter, possibly an array."""

    children: dict[str, Node] = field(default_factory=dict)
    bounds: tuple[int, int] | None = None
    parameter: Parameter | None = None
    array: bool = False  # an array; of unknown size when it has no bounds (the kind catalogues give none)
    depth: int = 1  # indices per element: 2 for an array of arrays (`trafo[i].linkage[i][i]`, P-CHAN-00295)


def class_name(path: list[str]) -> str:
    return (
        "".join(part.capitalize() for part in re.split(r"[_\W]+", "_".join(path)) if part) or "AxisParameters"
    )


def tree(parameters: list[Parameter]) -> Node:
    """The structure of every catalogue path.

    A path whose group is itself a parameter (`kenngr.swe_pos.zero_limit`, P-AXIS-00560, next to
    `kenngr.swe_pos`) becomes a field of the parent group named by joining the rest with "_"; the model
    finds such a field by the same rule (`achslint.model.base.model_parts`)."""
    root = Node()
    for parameter in parameters:
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
                child.array = True
                child.depth = segment.count("[i]")
                child.bounds = next(bounds, None)
                for _ in range(child.depth - 1):
                    next(bounds, None)
            node = child
            if last:
                node.parameter = parameter
    return root


def leaf_type(parameter: Parameter, flags: bool = False) -> tuple[str, dict[str, object]]:
    """The annotation (as source text) and the constraints of a parameter's field; with `flags` a symbol
    parameter takes several symbols joined by `|` too."""
    kind = parameter.kind
    if kind == BOOL:
        return "bool", {}
    if kind == SYMBOL and flags:
        one = "(?:" + "|".join(re.escape(s) for s in parameter.symbols) + ")"
        return "str", {"pattern": rf"^{one}(?:\s*\|\s*{one})*$"}
    if kind == SYMBOL:
        return f"Literal[{', '.join(repr(s) for s in parameter.symbols)}]", {}
    if kind in (INTEGER, REAL):
        low, high = parameter.limits
        default = parameter.outside_default  # a model holds it too (the list leaves the parameter unset)
        if default is not None:
            low, high = (
                min(low, default) if low is not None else low,
                max(high, default) if high is not None else high,
            )
        constraints = {key: bound for key, bound in (("ge", low), ("le", high)) if bound is not None}
        if kind == REAL:
            return "float", constraints
        if parameter.symbols:  # a number or one of its symbols: pydantic cannot bound a symbol (LIS202 does)
            return "Union[int, str]", {}
        return "int", constraints
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


def classes(node: Node, path: list[str], out: list[str], target: Target = AXIS_MODEL) -> str:
    """Append the source of the class for `node` (children first) to `out`; return its name."""
    lines = []
    for name, child in node.children.items():
        python_name = field_name(name)
        alias = {"alias": repr(name)} if python_name != name else {}
        if child.parameter is not None:
            parameter = child.parameter
            annotation, constraints = leaf_type(parameter, flags=target.kind is not None)
            default = parameter.typed_default
            if default is None or (child.array and child.bounds is None):
                annotation = f"Optional[{annotation}]"
            text = repr(description(parameter))
            if child.array and child.bounds is None:  # an element the list does not write is None
                lines.append(
                    f"    {python_name}: {'List[' * child.depth}{annotation}{']' * child.depth} = Field("
                    + _arguments(default_factory="list", description=text, **alias)
                    + ")"
                )
            elif child.bounds is not None:
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
        sub = classes(child, [*path, name], out, target)
        if child.depth > 1:
            raise SystemExit(f"{'.'.join([*path, name])}: an array of arrays of groups has no model yet")
        if child.array and child.bounds is None:
            lines.append(
                f"    {python_name}: List[{sub}] = Field(" + _arguments(default_factory="list", **alias) + ")"
            )
        elif child.bounds is not None:
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
    own = class_name(path) if path else target.root
    base = target.base if not path else "_Group"
    title = ".".join(path) or target.title
    if not path and target.kind is not None:  # the kind whose catalogue the model mirrors (`ListBase.KIND`)
        lines.insert(0, f"    KIND: ClassVar[str] = {target.kind.id!r}\n")
    out.append(f'class {own}({base}):\n    """Parameters of {title}."""\n\n' + "\n".join(lines) + "\n")
    return own


def model_source(target: Target = AXIS_MODEL) -> str:
    """The source of one generated module."""
    cat = target.kind.catalogue() if target.kind is not None else catalogue()
    assert cat is not None, target  # a kind with a catalogue
    root = tree(cat.parameters)
    out: list[str] = []
    classes(root, [], out, target)
    if target.kind is None:
        header = (
            '"""The typed axis model, one class per group of the list. Generated by tools/gen_model.py from the\n'
            'catalogue: do not edit; run `python tools/build_catalogue.py` after changing the catalogue."""\n\n'
        )
        imports = "from typing import List, Literal, Optional, Union\n\n"
    else:
        header = (
            f'"""The typed model of {target.title}, one class per group of the list. Generated by\n'
            f"tools/gen_model.py from the {target.kind.table} catalogue: do not edit; run "
            '`python tools/build_kinds.py`\nafter changing the catalogue."""\n\n'
        )
        source = "".join(out)
        used = [name for name in ("ClassVar", "List", "Literal", "Optional", "Union") if f"{name}[" in source]
        imports = f"from typing import {', '.join(used)}\n\n"
    header += (
        "# ruff: noqa: E501\n" + imports + "from pydantic import BaseModel, ConfigDict, Field\n\n"
        f"from .base import {target.base}\n\n\n"
        "class _Group(BaseModel):\n"
        f'    """A group of parameters below {target.title}."""\n\n'
        '    model_config = ConfigDict(populate_by_name=True, extra="forbid", validate_default=False)\n'
    )
    return header + "".join("\n\n" + text for text in out)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="change nothing; exit 1 if a module is stale")
    args = parser.parse_args(argv)
    stale = 0
    for target in TARGETS:
        text = model_source(target)
        if args.check:
            if not target.output.exists() or target.output.read_text(encoding="utf-8") != text:
                tool = "build_catalogue.py" if target.kind is None else "build_kinds.py"
                print(f"{target.output} is stale: run python tools/{tool}", file=sys.stderr)
                stale = 1
            continue
        target.output.write_text(text, encoding="utf-8")
        print(f"wrote {target.output}", file=sys.stderr)
    return stale


if __name__ == "__main__":
    sys.exit(main())
