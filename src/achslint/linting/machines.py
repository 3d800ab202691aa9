"""The machine-level rules (LIS5xx) over the machines of a run: the same step for `achslint lint` and the
language server.

Each linted list's result carries its machine summary; the lists that share a machine key (see
`discovery`) are handed to the rules together with the machine's start-up list. Findings on files the run
only read for context (neighbours of a named list, a start-up list found beside it) are not reported.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable, Sequence
from pathlib import Path

from ..core.decode import UnreadableInput, decode
from ..core.diagnostics import Diagnostic
from ..core.files import read_list
from ..machine.resolved import Machine
from ..machine.startup import Member, Startup, is_default_list
from ..rules import Scope as RuleScope
from ..syntax.parser import split_lines
from .config import ResolvedConfig
from .discovery import Target
from .engine import Policy, run
from .linter import FileResult, FileSettings


def machine_findings(
    pairs: Sequence[tuple[Target, FileResult]],
    startups: Sequence[Startup],
    settings_of: Callable[[Target], FileSettings],
    config_for: Callable[[Path], ResolvedConfig],
    *,
    hidden: set[str] = frozenset(),  # type: ignore[assignment]
    keep_source: bool = True,
) -> list[FileResult]:
    """Run the machine-level rules per machine, adding their findings to the results of `pairs`; returns
    the results of files with findings that have none in `pairs` (a start-up list).

    `pairs` are (list, its result); results named in `hidden` take part but get no findings, and go first
    in each machine, so a repeated axis number is reported on the reported list that repeats it.
    """
    by_name = {result.name: result for _, result in pairs if result.name not in hidden}
    groups: dict[str, list[Member]] = {}
    settings: dict[str, FileSettings] = {}
    # Members in the order of their start-up list's entries (the CNC's order), read-only context first.
    position = {
        (str(startup.path), os.path.realpath(entry.path)): index
        for startup in startups
        for index, entry in enumerate(startup.axes)
        if entry.path is not None
    }

    def place(pair: tuple[Target, FileResult], key: str) -> tuple[bool, int]:
        target, result = pair
        real = os.path.realpath(target.path) if target.path is not None else ""
        return (result.name not in hidden, position.get((key, real), len(position)))

    by_machine: dict[str, list[tuple[Target, FileResult]]] = {}
    for pair in pairs:
        for key in pair[0].machines:
            by_machine.setdefault(key, []).append(pair)
    for key, members in by_machine.items():
        for target, result in sorted(members, key=lambda pair: place(pair, key)):
            if target.kind == "default_axis" or (target.path is not None and is_default_list(target.path)):
                continue  # loaded underneath the axes, not an axis of its own
            if result.error or (result.summary is None and not result.summaries):
                continue
            for summary in [result.summary] if result.summary is not None else result.summaries:
                groups.setdefault(key, []).append((result.name, summary))
            settings[result.name] = settings_of(target)

    def file_settings(path: str) -> FileSettings:  # a start-up list's own configuration too
        if path not in settings:
            settings[path] = settings_of(Target(path, Path(path), config_for(Path(path))))
        return settings[path]

    policies: dict[str, Policy] = {}

    def policy_of(path: str) -> Policy:
        if path not in policies:
            policies[path] = file_settings(path).policy
        return policies[path]

    extra: dict[str, FileResult] = {}
    seen: set[tuple[object, ...]] = set()
    for machine in _machines(groups, startups):
        for d in run(RuleScope.MACHINE, (machine,), policy_of):
            said = (d.path, d.line, d.column, d.code, d.message)
            if d.path in hidden or said in seen:  # a list in two machines: one finding, said once
                continue
            seen.add(said)
            owner = by_name.get(d.path) or extra.setdefault(
                d.path, FileResult(d.path, [], fail_on=file_settings(d.path).fail_on)
            )
            owner.diagnostics.append(d)
    for result in [*by_name.values(), *extra.values()]:
        result.diagnostics.sort(key=Diagnostic.sort_key)
        if keep_source and result.diagnostics and not result.source_lines and result.name != "<stdin>":
            with contextlib.suppress(OSError, UnreadableInput):
                result.source_lines = split_lines(decode(read_list(Path(result.name))).text)
    return list(extra.values())


def _machines(groups: dict[str, list[Member]], startups: Sequence[Startup]) -> list[Machine]:
    """Every machine to check: the members of each machine key (the path of the start-up list that names
    them, a `[[machine]]` table's name, or a folder of XML exports) with its start-up list, and every
    start-up list none of whose axis lists was read (its entries may all be missing) as a machine of its own.
    Each is read once for every rule (its channel lists, ...)."""
    by_key = {str(startup.path): startup for startup in startups}
    found = [Machine(key, by_key.get(key), members=members) for key, members in groups.items()]
    found.extend(Machine(str(s.path), s) for s in startups if str(s.path) not in groups)
    return found
