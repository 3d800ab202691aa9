"""`achslint config --show`: which configuration file applies (or that none does), then its settings as
the file spells them, as JSON."""

from __future__ import annotations

from typing import TYPE_CHECKING

from . import Screen, write_json

if TYPE_CHECKING:
    from ..linting.config import ResolvedConfig


def as_text(resolved: ResolvedConfig, screen: Screen) -> None:
    screen.echo(f"# configuration: {resolved.path or 'built-in defaults'}")
    write_json(resolved.settings.as_file_keys(), screen)
