"""What the language server knows about the open documents, computed by achslint's own API.

Nothing here decides what a finding is or which files form a machine: the file-level findings
come from the linter (`linter.lint_parsed` / `lint_file`, the same path as `achslint lint`), the
settings from the nearest configuration (`config.discover`, `linter.file_settings`), the machines
a document belongs to from `discovery.Finder` (the one discovery of `achslint lint`), and their
findings from the machine step (`machines.machine_findings`), fed with the members' texts as the
editor has them: open buffers, else the files.

This module does not import pygls: the benchmarks time it directly.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..catalogue.kinds import STARTUP
from ..core.decode import UnreadableInput, decode, text_bytes
from ..core.diagnostics import Diagnostic, Severity
from ..core.files import is_xml, read_list, starts_with_bom
from ..core.pause import pause
from ..linting.config import (
    ConfigError,
    Overrides,
    ResolvedConfig,
    Settings,
    discover,
    parse_codes,
)
from ..linting.discovery import (
    Discovery,
    Finder,
    Target,
    is_list_update,
    is_startup,
    loaded_under,
    updated_list,
)
from ..linting.linter import FileResult, FileSettings, file_settings, lint_file, lint_parsed
from ..linting.machines import machine_findings
from ..machine.resolved import Machine
from ..machine.startup import StartupEntry
from ..syntax.parser import ListFile, parse_bytes
from ..syntax.xmlinput import single_list
from .documents import Document

if TYPE_CHECKING:
    from ..rules.context import Context


@dataclass
class ClientSettings:
    """Settings the editor sends (initializationOptions / workspace/didChangeConfiguration, section `achslint`).

    They act like the command-line flags: on top of the nearest configuration file."""

    select: list[str] | None = None
    extend_select: list[str] = field(default_factory=list)
    ignore: list[str] = field(default_factory=list)
    inlay_hints: bool = False
    debounce_ms: int = 0  # 0: each edit is linted as soon as the lint before it is done
    problems: list[str] = field(default_factory=list)  # codes that pick no rule (shown to the user, not used)

    @classmethod
    def from_dict(cls, given: object) -> ClientSettings:
        if not isinstance(given, dict):
            return cls()
        raw: dict[str, Any] = given["achslint"] if isinstance(given.get("achslint"), dict) else given
        problems: list[str] = []

        def codes(key: str) -> list[str] | None:
            value = raw.get(key)
            if isinstance(value, str):
                value = value.split(",")
            if not isinstance(value, list):
                return None
            chosen = []
            for code in value:  # the same check as --select and the configuration file
                try:
                    chosen.extend(parse_codes([str(code)]))
                except ValueError as exc:
                    problems.append(f"achslint.{key}: {exc}")
            return chosen

        def switch(key: str, value: object) -> bool:
            """A yes/no setting: a boolean, a number, or the words true/false; anything else is off (and told:
            `bool("false")` would be on)."""
            if isinstance(value, (bool, int)):
                return bool(value)
            word = value.strip().lower() if isinstance(value, str) else None
            if word in ("true", "1", "on", "yes"):
                return True
            if word not in ("false", "0", "off", ""):
                problems.append(f"achslint.{key}: true or false, not {_shown(value)}; left off")
            return False

        debounce = raw.get("debounceMs", raw.get("debounce_ms", 0))
        hints_key = "inlayHints" if "inlayHints" in raw else "inlay_hints"
        return cls(
            select=codes("select") or None,
            extend_select=codes("extendSelect") or codes("extend_select") or [],
            ignore=codes("ignore") or [],
            inlay_hints=switch(hints_key, raw.get(hints_key, False)),
            debounce_ms=(
                debounce
                if isinstance(debounce, int) and not isinstance(debounce, bool) and 0 <= debounce <= 5000
                else 0
            ),
            problems=problems,
        )

    @property
    def overrides(self) -> Overrides:
        return Overrides(select=self.select, extend_select=list(self.extend_select), ignore=list(self.ignore))


def _shown(value: object) -> str:
    """A setting's value as the user wrote it, shortened for a message."""
    text = repr(value)
    return text if len(text) <= 40 else text[:40] + "..."


@dataclass
class Snapshot:
    """One version of a document, linted: the file-level findings and the rules' context."""

    version: int | None
    text: str
    result: FileResult
    file: ListFile | None = None  # lists only
    context: Context | None = None  # lists only
    config_error: str | None = None
    startup: bool = False  # a start-up list: its lines and, by the machine step, its entries (LIS504 ...)


_ENCODING = re.compile(r'<\?xml[^>]*encoding=["\']([A-Za-z0-9_.-]+)["\']')


def xml_bytes(text: str) -> bytes:
    """An XML document's text as bytes in the encoding it declares (positions stay those the editor shows)."""
    match = _ENCODING.match(text)
    if match:
        try:
            return text.encode(match.group(1))
        except (LookupError, UnicodeEncodeError):
            pass
    return text_bytes(text)


_REAL: dict[str, str] = {}


def _real(path: Path | str) -> str:
    """The real path of a file (cached until the session forgets what it knows about the disk)."""
    key = str(path)
    found = _REAL.get(key)
    if found is None:
        try:
            found = os.path.realpath(key)
        except (OSError, ValueError):
            found = os.path.abspath(key)
        _REAL[key] = found
    return found


class Session:
    def __init__(self, root: Path | None = None) -> None:
        self.root = root
        self.settings = ClientSettings()
        self.documents: dict[str, Document] = {}
        self._snapshots: dict[str, Snapshot | None] = {}  # None: to be linted again
        self._disk: dict[_DiskKey, FileResult] = {}  # (real path, stamp, defaults stamp, settings) -> result
        self._by_real: dict[str, Document] = {}  # open files by real path
        self._machines: dict[
            str, list[Machine]
        ] = {}  # real path of a list -> its machines (until forget_disk)
        self._finder: Finder | None = None  # with the editor's settings (until they or the disk change)
        self._machine_found: dict[str, list[_Found]] = {}  # uri -> the machine findings last reported for it
        self._refused: dict[
            tuple[str, int, int], str | None
        ] = {}  # (real path, stamp) -> why lint refuses it

    # -- documents ---------------------------------------------------------------------------
    def open(self, document: Document) -> None:
        self.documents[document.uri] = document
        if document.path is not None:
            self._by_real[_real(document.path)] = document

    def close(self, uri: str) -> None:
        document = self.documents.pop(uri, None)
        self._snapshots.pop(uri, None)
        self._machine_found.pop(uri, None)
        if document is not None and document.path is not None:
            self._by_real.pop(_real(document.path), None)

    def by_path(self, path: Path | str) -> Document | None:
        return self._by_real.get(_real(path))

    def text_of(self, path: Path) -> bytes:
        """A list as the editor has it: the open buffer, else the file."""
        document = self.by_path(path)
        if document is not None:
            return text_bytes(document.body)
        return read_list(path)

    def forget_disk(self) -> None:
        """Files changed on disk (or a configuration did): read them again next time."""
        from ..linting import config

        self._disk.clear()
        self._machines.clear()
        self._refused.clear()
        self._finder = None
        _REAL.clear()
        self._by_real = {_real(d.path): d for d in self.documents.values() if d.path is not None}
        for uri in list(self._snapshots):
            self._snapshots[uri] = None
        config.forget_cached()

    # -- configuration -------------------------------------------------------------------------
    def config_for(self, document: Document) -> tuple[ResolvedConfig, str | None]:
        start = document.path or self.root or Path.cwd()
        try:
            return discover(start), None
        except ConfigError as exc:
            return ResolvedConfig(Settings()), str(exc)

    def file_settings(self, config: ResolvedConfig, path: Path | None, name: str) -> FileSettings:
        settings = file_settings(config, self.settings.overrides, path or Path(name), keep_source=False)
        settings.keep_context = True
        return settings

    def fix_all(self, document: Document) -> tuple[str | None, frozenset[tuple[str, int, int]]]:
        """What `achslint lint --fix` makes of the document: its text with every safe fix applied (None when
        no fix applies), and (code, line, column) of the findings whose fix the lint calls safe but `--fix`
        refuses because it changes what the list does (`fixer.check_fixes`), so that a quick fix is offered
        as safe exactly when the command line calls it safe. One lint and one behaviour test for both."""
        from ..linting.fixer import fix_bytes

        settings, underneath = self._fix_settings(document)
        outcome = fix_bytes(text_bytes(document.body), document.name, settings, defaults=underneath)
        text = ("\ufeff" if document.bom else "") + outcome.data.decode("utf-8") if outcome.fixed else None
        return text, outcome.refused

    def fixed_text(self, document: Document) -> str | None:
        """The document's text with every safe fix applied, as `achslint lint --fix` would write it; None
        when no fix applies."""
        return self.fix_all(document)[0]

    def unsafe_fixes(self, document: Document) -> frozenset[tuple[str, int, int]]:
        """The findings whose fix the lint calls safe but `--fix` refuses (see `fix_all`)."""
        return self.fix_all(document)[1]

    def _fix_settings(self, document: Document) -> tuple[FileSettings, bytes | None]:
        """The settings and the list underneath for fixing the document, as `achslint lint --fix` has them:
        the kind and the list underneath that `_lint` gives it."""
        config, _ = self.config_for(document)
        settings = self.file_settings(config, document.path, document.name)
        settings.keep_context = False
        underneath = None
        if document.path is not None:
            settings.kind = STARTUP.id if is_startup(document.path) else self.finder.entry_kind(document.path)
            if settings.kind != STARTUP.id:
                underneath = self._underneath(document, settings.kind)[1]
        return settings, underneath

    # -- linting ---------------------------------------------------------------------------------
    def snapshot(self, uri: str) -> Snapshot | None:
        """The linted current version of a document (computed when the text changed)."""
        document = self.documents.get(uri)
        if document is None:
            return None
        found = self._snapshots.get(uri)
        if found is not None and found.text is document.text:
            return found
        found = self._snapshots[uri] = self._lint(document)
        return found

    def _lint(self, document: Document) -> Snapshot:
        config, config_error = self.config_for(document)
        refused = None if is_xml(document.name) else self._refusal(document)
        if refused is not None:  # what `achslint lint` refuses to read: its message, nothing else
            return Snapshot(document.version, document.text, FileResult(document.name, [], refused))
        settings = self.file_settings(config, document.path, document.name)
        if document.path is not None:  # the kind a start-up list names it as, as `achslint lint` reads it
            settings.kind = self.finder.entry_kind(document.path)
        name = document.name
        if document.path is not None and is_startup(document.path):  # by its name or its content
            # its own lines against the start-up catalogue, as `achslint lint` checks them; its entries are
            # the machine step's (LIS504 ...)
            settings.kind = STARTUP.id
            file = document.parse()
            result = lint_parsed(file, name, settings)
            return Snapshot(
                document.version, document.text, result, file, result.context, config_error, startup=True
            )
        below, underneath = self._underneath(document, settings.kind)
        if is_xml(name):
            result = lint_file(xml_bytes(document.text), name, settings, underneath)
            return Snapshot(document.version, document.text, result, config_error=config_error)
        default_file = None
        if underneath is not None:
            try:
                default_file = parse_bytes(underneath, str(below))
            except UnreadableInput:
                default_file = None
        file = document.parse()
        if not file.bom and document.path is not None and starts_with_bom(document.path):
            # The editor keeps the mark out of the text (VS Code: "UTF-8 with BOM") and writes it back on
            # save, so the file the CNC reads has it: LIS006 as on the command line.
            file = replace(file, bom=True)
        pause()  # the language server's worker gives way to the editor's requests here (and between rules)
        result = lint_parsed(file, name, settings, default_file)
        return Snapshot(document.version, document.text, result, file, result.context, config_error)

    def _refusal(self, document: Document) -> str | None:
        """Why `achslint lint` refuses the list as the editor will save it: NUL characters in the buffer, or a
        file that is UTF-16/32 or binary on disk (the editor decoded it; it writes it back so)."""
        if "\0" in document.text:
            try:
                decode(text_bytes(document.body))
            except UnreadableInput as exc:
                return str(exc)
        if document.path is None:
            return None
        try:
            info = os.stat(document.path)
        except (OSError, ValueError):
            return None
        key = (_real(document.path), info.st_mtime_ns, info.st_size)
        if key not in self._refused:
            try:
                decode(read_list(document.path))
                self._refused[key] = None
            except UnreadableInput as exc:
                self._refused[key] = str(exc)
            except (OSError, ValueError):
                self._refused[key] = None
        return self._refused[key]

    def _underneath(self, document: Document, kind: str | None = None) -> tuple[Path | None, bytes | None]:
        """The list the CNC loads under the document, as the editor has it: the default list of its start-up
        list, or for a list update the list it changes (`discovery.updated_list`). None when there is none or
        it cannot be read (the start-up list's LIS504 says why)."""
        path = document.path
        if path is None:
            return None, None
        below = updated_list(path) if is_list_update(path) else loaded_under(kind, self.machines(document))
        if below is None:
            return None, None
        try:
            data = self.text_of(below)
            return below, single_list(data, str(below)) if is_xml(below.name) else data
        except (OSError, UnreadableInput):
            return below, None

    def diagnostics(self, uri: str) -> tuple[Snapshot | None, list[Diagnostic], list[str]]:
        """The document's findings, its own and those of the machine it belongs to, and the other open
        documents whose machine findings changed with it (their editors need them again)."""
        snapshot = self.snapshot(uri)
        if snapshot is None:
            return None, [], []
        own = list(snapshot.result.diagnostics)
        document = self.documents[uri]
        peers: list[str] = []
        if document.path is not None:
            by_member = self.machine_diagnostics(document, snapshot)
            mine = by_member.pop(_real(document.path), [])
            self._machine_found[uri] = [_key(d) for d in mine]
            own.extend(mine)
            own.sort(key=Diagnostic.sort_key)
            for real, found in by_member.items():
                other = self._by_real.get(real)
                if other is None or other.uri not in self.documents:
                    continue
                keys = [_key(d) for d in found]
                if self._machine_found.get(other.uri) != keys:
                    peers.append(other.uri)
        return snapshot, own, peers

    # -- machines --------------------------------------------------------------------------------
    @property
    def finder(self) -> Finder:
        """The one discovery of `achslint lint`, with the editor's settings as the command line's flags."""
        if self._finder is None:
            self._finder = Finder(self.settings.overrides, lenient=True)
        return self._finder

    def settings_changed(self) -> None:
        """The editor's settings changed: machines are found again with them (include/exclude may differ)."""
        self._finder = None
        self._machines.clear()

    def machines(self, document: Document) -> list[Machine]:
        """The machines of a document, found as `achslint lint` finds them (`Finder.machines_of`): the
        start-up lists beside it that name it, else the lists of its folder."""
        path = document.path
        if path is None:
            return []
        real = _real(path)
        if real not in self._machines:
            self._machines[real] = self.finder.machines_of(path)
        return self._machines[real]

    def startup_entries(self, document: Document) -> list[StartupEntry]:
        """The entries of a start-up list as saved, resolved as `achslint lint` resolves them (against the CNC
        root of its configuration's `cnc-root`, else the default): where go to definition leads. A discovery
        of its own: the worker's may be in use meanwhile. Empty when the file cannot be read (not saved yet,
        or unreadable: its lint says why)."""
        if document.path is None:  # not a file: no start-up list
            return []
        try:
            startup = Finder(self.settings.overrides, lenient=True).startup(document.path)
        except (OSError, UnreadableInput):
            return []
        single = [startup.default, startup.default_channel]
        found = [entry for entry in single if entry is not None]
        return found + startup.axes + startup.channels + startup.compensations + startup.others

    def _config(self, path: Path) -> ResolvedConfig:
        try:
            return discover(path)
        except ConfigError:
            return ResolvedConfig(Settings())

    def _summary_result(self, target: Target) -> FileResult:
        """A member's result (its summary is what the machine rules compare): open buffer or file."""
        path = target.path or Path(target.name)  # the lists of a machine are files
        document = self.by_path(path)
        if document is not None and not is_startup(path):
            snapshot = self.snapshot(document.uri)
            if snapshot is not None:  # an open document always has one
                return _for_machine(snapshot.result, target.name)
        try:
            info = os.stat(path)
            stamp = (info.st_mtime_ns, info.st_size)
            defaults_stamp = None
            if target.defaults is not None:
                default_info = os.stat(target.defaults)
                defaults_stamp = (str(target.defaults), default_info.st_mtime_ns, default_info.st_size)
        except OSError as exc:
            return FileResult(target.name, [], f"cannot read {target.name}: {exc}")
        key = (_real(path), stamp, defaults_stamp, self.settings.overrides.key())
        cached = self._disk.get(key)
        if cached is None:
            try:
                data = read_list(path)
                defaults = self.text_of(target.defaults) if target.defaults is not None else None
            except OSError as exc:
                return FileResult(target.name, [], f"cannot read {target.name}: {exc}")
            settings = file_settings(target.config, self.settings.overrides, path, keep_source=False)
            full = lint_file(data, target.name, settings, defaults)
            cached = self._disk[key] = _for_machine(full, target.name)
        return _for_machine(cached, target.name)

    def machine_diagnostics(self, document: Document, snapshot: Snapshot) -> dict[str, list[Diagnostic]]:
        """The machine-level findings of every list of the document's machines, by real path."""
        machines = self.machines(document)
        if not machines or document.path is None:
            return {}
        real = _real(document.path)
        found = Discovery()
        # in the machine's order: a repeated number is reported where it repeats
        found.members(self.finder.member_targets(machines))
        if not snapshot.startup:
            keys = tuple(m.key for m in machines)
            kind = self.finder.entry_kind(document.path)  # a default list named otherwise is no axis
            config = self._config(document.path)
            found.add(Target(str(document.path), document.path, config, keys, kind=kind), context=True)
        pairs: list[tuple[Target, FileResult]] = []
        for target in [*found.targets, *found.context]:
            if _real(target.path or target.name) == real and not snapshot.startup:
                result = _for_machine(snapshot.result, target.name)
            else:
                result = self._summary_result(target)
            pairs.append((target, result))
        startups = [m.startup for m in machines if m.startup is not None]
        for startup in startups:  # the channel lists the machine rules read: as the editor has them
            startup.reader = self.text_of
        extra = machine_findings(
            pairs,
            startups,
            lambda target: file_settings(
                target.config, self.settings.overrides, target.path or Path(target.name)
            ),
            self._config,
            keep_source=False,
        )
        by_member: dict[str, list[Diagnostic]] = {}
        for result in [*(result for _, result in pairs), *extra]:
            by_member.setdefault(_real(result.name), []).extend(result.diagnostics)
        for member, diagnostics in by_member.items():
            owner = self._by_real.get(member)
            for d in diagnostics:
                d.path = owner.name if owner is not None else d.path
        return by_member


_Found = tuple[int, int, str, str, Severity]  # what tells two findings apart (for `peers`)
_DiskKey = tuple[str, tuple[int, int], tuple[str, int, int] | None, tuple[tuple[str, str], ...]]


def _for_machine(result: FileResult, name: str) -> FileResult:
    """What the machine step needs of a list's result (its summaries), under the member's name, no findings."""
    return FileResult(name, [], result.error, summary=result.summary, summaries=list(result.summaries))


def _key(d: Diagnostic) -> _Found:
    return (d.line, d.column, d.code, d.message, d.severity)
