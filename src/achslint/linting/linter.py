"""Lint of one list, or of the lists of one XML file: bytes -> parsed list -> the lint engine.

parse -> kind (`list_kind`) -> `lintengine.run` with that kind's catalogue and rules (enabled rules ->
      `noqa` suppressions -> LIS009 -> severity overrides -> sort)
      -> a `FileResult` with what the machine step needs (`machine.summary`, axis lists only)

A list of a kind with a catalogue (channel, tool data, start-up ... `catalogue.kinds`) is checked by the
rules that apply to its kind (`Rule.kinds`: the LIS0/1/2 families); a kind without one is skipped with
a note.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING

from ..axis.source import NOT_A_LIST, looks_like_a_list, read_one_list
from ..catalogue.kinds import AXIS, AXIS_PREFIX, BY_ID, DEFAULT_AXIS, Kind, content_kind, kind_of
from ..core.decode import UnreadableInput
from ..core.diagnostics import Diagnostic, Severity
from ..core.files import is_xml
from ..machine import startup as machine
from ..machine.resolved import Machine
from ..rules import Scope
from ..rules.context import Context
from ..syntax.parser import ListFile, parse_bytes
from .config import PROGRAM_SUFFIXES, Overrides, ResolvedConfig, Settings
from .engine import Policy, run
from .suppression import Suppressions

if TYPE_CHECKING:
    from ..machine.startup import Member, Summary
    from ..syntax.xmlinput import EmbeddedList


@dataclass
class FileSettings:
    """Everything that decides what is reported for one file: its settings (configuration nearest the file
    with the command line applied), the codes `per-file-ignores` ignores for it, and what to keep."""

    settings: Settings = field(default_factory=Settings)
    ignored_here: list[str] = field(default_factory=list)  # per-file-ignores matching this file
    keep_source: bool = True  # keep the line texts for code frames (the full and gitlab formats)
    keep_context: bool = False  # keep the rules' Context on the result (the language server reuses it)
    machine_in_file: bool = (
        True  # check the lists of one XML file as a machine (off: the caller groups files)
    )
    # The list's kind when a start-up list's entry says it (`default_achs_mds` -> "default_axis"); None: told
    # from the name (`default*mds*.lis`) or the content (`catalogue.kinds.kind_of`).
    kind: str | None = None

    @classmethod
    def of(
        cls, select: list[str] | None = None, ignore: list[str] | None = None, *, keep_source: bool = True
    ) -> FileSettings:
        """Settings that run the rules `select` (default: all) minus `ignore`."""
        return cls(Settings(select=select, ignore=list(ignore or [])), keep_source=keep_source)

    @property
    def policy(self) -> Policy:
        """Which rules run for this file, and the severities its configuration sets."""
        s = self.settings
        return Policy.of(
            s.select, s.extend_select, [*s.ignore, *self.ignored_here], s.severity, s.fixable, s.unfixable
        )

    @property
    def fail_on(self) -> str:
        return self.settings.fail_on


def file_settings(
    config: ResolvedConfig, overrides: Overrides, target: Path, keep_source: bool = True
) -> FileSettings:
    """The settings of one file: its configuration with the command line's (or the editor's) overrides."""
    return FileSettings(
        overrides.apply(config.settings),
        config.ignored_for(target),
        keep_source=keep_source,
        machine_in_file=False,
    )


@dataclass
class FileResult:
    name: str
    diagnostics: list[Diagnostic]
    error: str | None = None  # the file could not be read or decoded at all
    source_lines: list[str] = field(default_factory=list)  # kept for code frames when there are findings
    fixed: int = 0  # diagnostics fixed by --fix
    noqa_added: int = 0  # lines --add-noqa gave a new or longer `noqa`
    diff: str = ""  # what --fix --diff would change
    fixed_data: bytes | None = None  # the fixed content (standard input only)
    summary: Summary | None = None  # what the machine-level rules need (machine.summary)
    context: Context | None = None  # with FileSettings.keep_context: the parsed, resolved list
    summaries: list[Summary] = field(default_factory=list)  # the same, one per list, for an XML file
    note: str | None = None  # skipped on purpose (XML without an axis list): said once, not an error
    fail_on: str = "error"  # lowest severity that fails the run for this file (its configuration's fail-on)

    @property
    def failing(self) -> bool:
        """Whether a finding reaches this file's fail-on severity."""
        threshold = Severity(self.fail_on).rank
        return any(d.severity.rank >= threshold for d in self.diagnostics)


def lint_file(
    data: bytes, name: str, settings: FileSettings | None = None, defaults: bytes | None = None
) -> FileResult:
    """Lint the bytes of one list (or of an XML file holding lists); unreadable input sets `error`.

    `defaults` is the default axis list the CNC loads underneath (start-up key default_achs_mds).
    """
    settings = settings or FileSettings()
    try:
        default_file = default_list(defaults) if defaults is not None else None
        if is_xml(name) or (name in UNNAMED and _xml_content(data)):
            return _check_xml(data, name, settings, default_file)
        file = parse_bytes(data, name)
    except UnreadableInput as exc:
        return FileResult(name, [], f"{name}: {exc}")
    if not looks_like_a_list(file):
        return FileResult(name, [], f"{name}: {NOT_A_LIST}")
    kind = list_kind(file, name, settings.kind)
    if not kind.has_catalogue:
        return FileResult(name, [], note=_skip_note(kind, name))
    return _check_file(file, name, settings, default_file=default_file, kind=kind)


# The names of bytes that came without a file name (the API's bytes and text, standard input without
# --stdin-filename): their content tells whether they are XML.
UNNAMED = ("<bytes>", "<string>", "<stdin>", "-")


def _xml_content(data: bytes) -> bool:
    """Whether bytes without a file name are XML: `<` first, after a byte-order mark (UTF-8 or UTF-16) and
    white space. No list starts so (a list line starts with a name, `#` or `(`)."""
    for mark, encoding in (
        (b"\xef\xbb\xbf", "utf-8"),
        (b"\xff\xfe", "utf-16-le"),
        (b"\xfe\xff", "utf-16-be"),
    ):
        if data.startswith(mark):
            text = data[len(mark) : len(mark) + 400].decode(encoding, "ignore")
            break
    else:
        text = data[:200].decode("latin-1")
    return text.lstrip().startswith("<")


@lru_cache(maxsize=4)
def default_list(data: bytes) -> ListFile:
    """A default list, parsed once for all the axis lists of a machine that load it (a run lints them one
    after another with the same bytes underneath). Raises `UnreadableInput`."""
    return parse_bytes(data, "default list")


def list_kind(file: ListFile, name: str, given: str | None = None) -> Kind:
    """The kind of a list: as the start-up list's entry says (`given`), a default list by its name, else told
    by its content (`kinds.content_kind`); a list whose content does not clearly show another kind is an axis
    list."""
    if given is not None:
        return BY_ID[given]
    if machine.is_default_list(Path(name)):
        return DEFAULT_AXIS
    return content_kind(file) or AXIS


class NotAnAxisList(UnreadableInput):
    """A list of another kind given to a command that reads one axis list; `kind` is the kind's id (None: an
    NC program, or a text that names no parameter of any kind)."""

    def __init__(self, message: str, kind: str | None = None) -> None:
        super().__init__(message)
        self.kind = kind


def axis_list_only(data: bytes, name: str) -> bytes:
    """`data` when it is an axis list (or a default axis list), for the commands that read one axis list
    (explain, dry-run, diff, report; the API's explain and dry_run). A list of another kind, told as lint
    tells it, raises `NotAnAxisList`: read as an axis list, a channel or tool list would be an invented axis
    of catalogue defaults, explained and homed as if it existed. So does an NC program (by its name, as
    `achslint lint` tells one) and a text none of whose assignments names a parameter of any list kind."""
    if name.lower().endswith(PROGRAM_SUFFIXES):
        raise NotAnAxisList(
            f"{name} is an NC program, not an axis list: a homing program runs on a machine; give its "
            f"start-up list: `achslint dry-run hochlauf.lis --program {Path(name).name}` (or `achslint lint "
            f"{Path(name).name} --machine hochlauf.lis`)"
        )
    file = parse_bytes(data, name)
    kind = list_kind(file, name)
    if kind.id in (AXIS.id, DEFAULT_AXIS.id):
        if _names_nothing_known(file):
            raise NotAnAxisList(
                f"{name}: none of its assignments names a parameter of an axis list (or of any other list "
                "kind), so it is not an axis list; `achslint lint` shows each unknown name"
            )
        return data
    hint = (
        "; a channel's axes are shown by explaining the start-up list that loads it (with --channel)"
        if kind.id in ("channel", "default_channel")
        else ""
    )
    raise NotAnAxisList(
        f"{name} is {kind.a_name}, not an axis list: this command reads one axis list. "
        f"`achslint lint` checks it against the parameters of its kind{hint}",
        kind.id,
    )


def read_axis_list(path: Path, name: str) -> bytes:
    """The one axis list of a file named on the command line (`axis.source.read_one_list`), refused as
    `axis_list_only` refuses a list of another kind. Raises `OSError`, `UnreadableInput` or `NotAnAxisList`."""
    return axis_list_only(read_one_list(path, name), name)


def _names_nothing_known(file: ListFile) -> bool:
    """Whether the list assigns something but no name of it is in any catalogue (an NC program, a note): read
    as an axis list it would be every catalogue default under a file name."""
    guess = kind_of(file)
    return guess.unknown > 0 and not guess.paths and not guess.ids


def not_checked(file: ListFile, name: str, given: str | None = None) -> str | None:
    """The note for a list of a kind achslint has no catalogue of (HMI objects, cam tables), said once
    instead of a finding for every parameter; None for a list achslint checks."""
    kind = list_kind(file, name, given)
    return None if kind.has_catalogue else _skip_note(kind, name)


def _skip_note(kind: Kind, name: str) -> str:
    return f"{name}: skipped, it is a {kind.name}; achslint has no catalogue of its parameters yet"


def lint_parsed(
    file: ListFile, name: str, settings: FileSettings | None = None, default_file: ListFile | None = None
) -> FileResult:
    """`lint_file` for a list that is already parsed (the language server parses edited lines only)."""
    settings = settings or FileSettings()
    if not looks_like_a_list(file):
        return FileResult(name, [], f"{name}: {NOT_A_LIST}")
    kind = list_kind(file, name, settings.kind)
    if not kind.has_catalogue:
        return FileResult(name, [], note=_skip_note(kind, name))
    return _check_file(file, name, settings, default_file=default_file, kind=kind)


def _check_file(
    file: ListFile,
    name: str,
    settings: FileSettings,
    embedded: EmbeddedList | None = None,
    default_file: ListFile | None = None,
    kind: Kind = AXIS,
) -> FileResult:
    if kind.prefix != AXIS_PREFIX:
        return _check_other_kind(file, name, settings, kind, default_file)
    # A default list (default_mds.lis) only supplies values underneath every axis: alone it is no axis,
    # so the rules that judge a whole axis do not run on it (they run on the axis lists that load it).
    partial = embedded is None and kind.id == DEFAULT_AXIS.id
    ctx = Context(
        name,
        file,
        settings.settings,
        embedded=embedded,
        default_file=default_file,
        default_list=partial,
        kind=kind,
    )
    diagnostics = run(
        Scope.LIST,
        (ctx,),
        settings.policy,
        suppressions=Suppressions.of_list(file, name),
        whole_axis=not partial,
        kind=kind.id,
    )
    lines = [line.body for line in file.lines] if diagnostics and settings.keep_source else []
    return FileResult(
        name,
        diagnostics,
        None,
        lines,
        summary=machine.summary(ctx.values),
        context=ctx if settings.keep_context else None,
    )


def _check_other_kind(
    file: ListFile, name: str, settings: FileSettings, kind: Kind, default_file: ListFile | None = None
) -> FileResult:
    """A list of another kind (channel, tool data ...) against its kind's catalogue, by the rules that apply
    to it. It is no axis: no resolved axis and no machine summary (the machine step reads channel and start-up
    lists itself); the editor keeps its Context for the kind and its catalogue (hover, completion)."""
    cat = kind.catalogue()
    assert cat is not None  # has_catalogue
    # default_file: the default channel list under a channel list (what LIS703 counts), as the CNC loads it
    ctx = Context(name, file, settings.settings, catalogue=cat, kind=kind, default_file=default_file)
    diagnostics = run(
        Scope.LIST,
        (ctx,),
        settings.policy,
        suppressions=Suppressions.of_list(file, name),
        whole_axis=False,
        kind=kind.id,
    )
    lines = [line.body for line in file.lines] if diagnostics and settings.keep_source else []
    return FileResult(name, diagnostics, None, lines, context=ctx if settings.keep_context else None)


def _mapped_summary(summary: Summary, embedded: EmbeddedList) -> Summary:
    """A list's machine summary with its positions moved into the XML file, and its TwinCAT tree item."""
    mapped = dict(summary)
    for key, value in summary.items():
        if key.endswith("_at") and value is not None:
            mapped[key] = embedded.position(*value)
    if embedded.tree_item is not None:
        mapped["identity"] = embedded.tree_item.identity()
    return mapped


def _check_xml(
    data: bytes, name: str, settings: FileSettings, default_file: ListFile | None = None
) -> FileResult:
    """Lint every list in an XML file — its axis lists, and the lists of a TwinCAT channel item against their
    own kinds —; positions are moved to the XML file's lines and columns."""
    from ..syntax.parser import parse_text, split_lines
    from ..syntax.xmlinput import NoAxisList, extract_lists, root_element, source_text

    try:
        lists = extract_lists(data, name)
    except NoAxisList:
        return FileResult(
            name,
            [],
            note=f"{name}: skipped, an XML file without a list "
            f"(<{root_element(data)}>: no <AchsMds>, <AX_MDS> or <IsgChannelDef> in it)",
        )
    except UnreadableInput as exc:
        return FileResult(name, [], str(exc))
    diagnostics: list[Diagnostic] = []
    members: list[Member] = []
    for embedded in lists:
        file = parse_text(embedded.text, name)
        kind = BY_ID.get(embedded.kind, AXIS)
        if kind.id == AXIS.id:
            result = _check_file(file, name, settings, embedded, default_file)
            members.append((name, _mapped_summary(result.summary or {}, embedded)))
        elif kind.has_catalogue:
            result = _check_other_kind(file, name, settings, kind)
        else:  # pragma: no cover - every list a channel item holds has a catalogue
            continue
        diagnostics.extend(_moved(d, embedded) for d in result.diagnostics)
    if len(members) > 1 and settings.machine_in_file:  # a TwinCAT project: its axes form one machine
        diagnostics.extend(run(Scope.MACHINE, (Machine(name, members=members),), settings.policy))
    diagnostics.sort(key=Diagnostic.sort_key)
    lines = split_lines(source_text(data)) if diagnostics and settings.keep_source else []
    return FileResult(name, diagnostics, None, lines, summaries=[summary for _, summary in members])


def _moved(d: Diagnostic, embedded: EmbeddedList) -> Diagnostic:
    """A finding on an embedded list, moved to the XML file's line and column (no fix: XML is not rewritten)."""
    d.line, d.column = embedded.position(d.line, d.column)
    d.end_line, d.end_column = embedded.position(d.end_line, d.end_column)
    if d.end_line < d.line or (d.end_line == d.line and d.end_column <= d.column):
        d.end_line, d.end_column = d.line, d.column + 1
    d.related = tuple(
        replace(r, line=embedded.position(r.line, r.column)[0], column=embedded.position(r.line, r.column)[1])
        for r in d.related
    )
    d.fix = None  # edits refer to the embedded text; XML files are not rewritten
    return d


def findings(data: bytes, name: str, settings: FileSettings | None = None) -> list[Diagnostic]:
    """Diagnostics for the bytes of one list. Raises `UnreadableInput` for UTF-16/32 input."""
    result = lint_file(data, name, settings)
    if result.error or result.note:
        raise UnreadableInput(result.error or result.note)
    return result.diagnostics
