"""What the configuration commands print: `achslint config --show` (which file applies, then its settings
as the file spells them, as JSON), `lint --show-settings` (the settings a run uses for a file, as TOML or
JSON) and `lint --show-files` (what a run would lint)."""

from __future__ import annotations

import json
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from . import Screen, write_json

if TYPE_CHECKING:
    from ..linting.config import ResolvedConfig, Settings
    from ..linting.run import ListedFile


def as_text(resolved: ResolvedConfig, screen: Screen) -> None:
    screen.echo(f"# configuration: {resolved.path or 'built-in defaults'}")
    write_json(resolved.settings.as_file_keys(), screen)


def settings(resolved: ResolvedConfig, used: Settings, form: str, screen: Screen) -> None:
    """The settings a run uses (`used`: the configuration with the command line applied): where they come
    from as comments, then every key as a configuration file writes it (TOML; `form` "json": JSON)."""
    from dataclasses import replace

    keys = replace(used, extend=resolved.settings.extend).as_file_keys()
    if form == "json":
        write_json(
            {
                "configuration": str(resolved.path) if resolved.path else None,
                "extends": [str(path) for path in resolved.extends],
                "settings": keys,
            },
            screen,
        )
        return
    screen.echo(f"# configuration: {resolved.path or 'built-in defaults'}")
    for path in resolved.extends:
        screen.echo(f"# extends: {path}")
    screen.echo(toml_text(keys))


def toml_text(keys: dict[str, Any]) -> str:
    """Settings as TOML: plain keys first, then each table; a key without a value (None) as a comment."""
    plain = {key: value for key, value in keys.items() if not _is_table(value)}
    lines = [
        f"{key} = {_value(value)}" if value is not None else f"# {key} (not set)"
        for key, value in plain.items()
    ]
    for key, value in keys.items():
        if isinstance(value, dict) and value:
            lines += ["", f"[{key}]"] + [
                f"{_key(name)} = {_value(item)}" for name, item in value.items() if item is not None
            ]
        elif isinstance(value, list) and value and all(isinstance(item, dict) for item in value):
            for item in value:
                lines += ["", f"[[{key}]]"] + [
                    f"{_key(name)} = {_value(field)}" for name, field in item.items() if field is not None
                ]
    return "\n".join(lines)


def _is_table(value: Any) -> bool:
    """Whether a key is written as a table (`[fmt]`, `[[machine]]`); an empty one stays inline (`{}`)."""
    if isinstance(value, dict):
        return bool(value)
    return isinstance(value, list) and bool(value) and all(isinstance(item, dict) for item in value)


def _key(name: str) -> str:
    bare = name.replace("-", "").replace("_", "").isalnum() and name.isascii()
    return name if bare else json.dumps(name)


def _value(value: Any) -> str:
    """A TOML value: strings as JSON writes them (a TOML basic string), numbers, booleans, arrays, inline
    tables (empty tables stay inline: `{}`)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, dict):
        return "{" + ", ".join(f"{_key(k)} = {_value(v)}" for k, v in value.items() if v is not None) + "}"
    return "[" + ", ".join(_value(item) for item in value) + "]"


def files(listed: Sequence[ListedFile], screen: Screen) -> None:
    """`lint --show-files`: one file a line, then its kind and the machines it belongs to (tab-separated)."""
    from ..core.display import printable

    for file in listed:
        machines = ", ".join(file.machines) if file.machines else "-"
        screen.echo(f"{printable(file.name)}\t{file.kind}\t{printable(machines)}")
