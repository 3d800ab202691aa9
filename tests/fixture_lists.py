"""The fixture lists a sweep needs to look at once each: the fixtures hold 427 lists but 319 different ones
(bytes and file name), as machines and rule folders keep copies of one axis list. A check that reads only a
list's bytes and its file name does the very same work again on a copy."""

from __future__ import annotations

from pathlib import Path

from .conftest import FIXTURES


def distinct(paths: list[Path]) -> list[Path]:
    """`paths` without the ones whose bytes and file name an earlier one already has, in their order."""
    first: dict[tuple[bytes, str], Path] = {}
    for path in paths:
        first.setdefault((path.read_bytes(), path.name), path)
    return list(first.values())


def distinct_lists() -> list[Path]:
    """Every fixture list (`**/*.lis`, sorted), one of each distinct list."""
    return distinct(sorted(FIXTURES.rglob("*.lis")))
