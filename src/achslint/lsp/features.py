"""Editor features as Language Server Protocol answers, computed from achslint's own data.

Each function takes the session's document and snapshot and returns lsprotocol types. The
texts come from the catalogue of the document's kind (`explain.parameter_card`; a channel list's
hover and completion read the channel catalogue: `document_kind`), the resolved axis of an axis list
(`explain.parameter_row`: value, source, correction, effect under the homing strategy), the
units module, the rules' documentation and their fixes; formatting is `fmt`'s.
"""

from __future__ import annotations

import bisect
import json
import os
import re
from collections.abc import Callable, Iterable, Iterator, Sequence, Set
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING

from lsprotocol import types as lsp

from ..catalogue import (
    BOOL,
    INTEGER,
    REAL,
    Parameter,
    fill_indices,
)
from ..catalogue.kinds import AXIS, AXIS_PREFIX, BY_ID, STARTUP, Kind, content_kind
from ..catalogue.units import describe, unit_label
from ..core.diagnostics import Diagnostic, Fix, Severity
from ..core.pause import pause
from ..rules import registry
from ..syntax import parser as syntax
from ..syntax.numbers import Reference
from .documents import Document, units
from .textdiff import changed_blocks

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from ..axis.resolved import ResolvedAxis
    from ..fmt import Block, LiveFormat
    from ..linting.config import FmtOptions
    from ..machine.startup import StartupEntry
    from ..rules.context import Context
    from .session import Snapshot

SEVERITY = {
    Severity.ERROR: lsp.DiagnosticSeverity.Error,
    Severity.WARNING: lsp.DiagnosticSeverity.Warning,
    Severity.INFO: lsp.DiagnosticSeverity.Information,
}
FIX_ALL = "source.fixAll.achslint"
_CODE = re.compile(r"LIS[0-9]{3}", re.IGNORECASE)


# -- positions ------------------------------------------------------------------------------------


def lsp_range(document: Document, line: int, column: int, end_line: int, end_column: int) -> lsp.Range:
    start = document.to_lsp(line, column)
    end = document.to_lsp(end_line, end_column)
    end = max(end, start)
    return lsp.Range(lsp.Position(*start), lsp.Position(*end))


def uri_of(path: str | Path) -> str:
    return Path(os.path.abspath(path)).as_uri()


# -- rule documentation ------------------------------------------------------------------------------


@lru_cache(maxsize=1)
def rules_document() -> str | None:
    """A file URI of the rule documentation: docs/rules.md of a source checkout, else a copy generated
    from the rule modules into the user's cache folder (the same text); None when neither works."""
    checkout = Path(__file__).resolve().parents[3] / "docs" / "rules.md"
    if checkout.is_file():
        return checkout.as_uri()
    from .. import __version__
    from ..core.codecache import private_folder
    from ..docs import rules_markdown

    folder = private_folder()  # the user's own cache folder (a relative XDG_CACHE_HOME is ignored), or none
    if folder is None:
        return None
    target = Path(folder) / f"rules-{__version__}.md"
    try:
        text = rules_markdown()
        if target.is_symlink() or (target.exists() and not target.is_file()):
            return None  # a link or a FIFO where the copy belongs: never written through, never read
        if not target.is_file() or target.read_text(encoding="utf-8") != text:
            temporary = target.with_name(f"{target.name}.{os.getpid()}.tmp")
            handle = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)  # never through a link
            with os.fdopen(handle, "w", encoding="utf-8") as stream:
                stream.write(text)
            os.replace(temporary, target)
    except OSError:
        return None
    return target.as_uri()


def rule_href(code: str) -> str | None:
    base = rules_document()
    return f"{base}#{code.lower()}" if base else None


# -- diagnostics -----------------------------------------------------------------------------------


def to_lsp_diagnostic(document: Document, d: Diagnostic) -> lsp.Diagnostic:
    related = []
    for r in d.related:
        where = (
            lsp_range(document, r.line, r.column, r.line, r.column + 1)
            if r.path == d.path
            else lsp.Range(
                lsp.Position(max(r.line - 1, 0), max(r.column - 1, 0)),
                lsp.Position(max(r.line - 1, 0), r.column),
            )
        )
        target = document.uri if r.path == d.path else uri_of(r.path)
        text = r.message or (f"`{r.parameter}`" if r.parameter else "related")
        if r.parameter and r.message:
            text = f"`{r.parameter}`: {r.message}"
        related.append(lsp.DiagnosticRelatedInformation(lsp.Location(target, where), text))
    href = rule_href(d.code)
    return lsp.Diagnostic(
        range=lsp_range(document, d.line, d.column, d.end_line, d.end_column),
        message=d.message,
        severity=SEVERITY[d.severity],
        code=d.code,
        code_description=lsp.CodeDescription(href) if href else None,
        source="achslint",
        related_information=related or None,
        data={"fix": d.fix.applicability} if d.fix else None,
    )


MAX_DIAGNOSTICS = 1000  # findings sent for one document; a summary tells how many more there are
_SEVERITY_ORDER = {Severity.ERROR: 0, Severity.WARNING: 1, Severity.INFO: 2}


def capped(found: list[Diagnostic], limit: int | None = None) -> tuple[list[Diagnostic], int]:
    """At most `limit` findings, the most severe first chosen, in their order; and how many were left out.

    A list with 50,000 unknown names would otherwise send megabytes to the editor on every edit; the
    first thousand say what is wrong, and errors are never hidden behind warnings."""
    limit = MAX_DIAGNOSTICS if limit is None else limit
    if len(found) <= limit:
        return found, 0
    ranked = sorted(
        range(len(found)), key=lambda index: (_SEVERITY_ORDER.get(found[index].severity, 3), index)
    )
    kept = sorted(ranked[:limit])
    return [found[index] for index in kept], len(found) - limit


def publishable(
    document: Document, snapshot: Snapshot | None, found: list[Diagnostic]
) -> list[lsp.Diagnostic]:
    shown, left_out = capped(found)
    out = []
    for number, d in enumerate(shown):
        if not number % 64:
            pause()  # the language server's worker gives way to the editor's requests
        out.append(to_lsp_diagnostic(document, d))
    start = lsp.Range(lsp.Position(0, 0), lsp.Position(0, 1))
    if left_out:
        out.insert(
            0,
            lsp.Diagnostic(
                start,
                f"{left_out:,} more findings are not shown here (the editor gets the first {len(shown):,}); "
                f"`achslint lint {document.name}` lists them all",
                lsp.DiagnosticSeverity.Information,
                source="achslint",
            ),
        )
    if snapshot is not None and snapshot.result.error:
        out.insert(
            0, lsp.Diagnostic(start, snapshot.result.error, lsp.DiagnosticSeverity.Error, source="achslint")
        )
    if snapshot is not None and snapshot.config_error:
        out.insert(
            0,
            lsp.Diagnostic(
                start,
                f"{snapshot.config_error} (the built-in defaults are used)",
                lsp.DiagnosticSeverity.Error,
                source="achslint",
            ),
        )
    return out


# -- where the cursor is -------------------------------------------------------------------------------


def part_at(line: syntax.Line, column: int) -> str | None:
    """ "path", "value", "rest", "end" or "comment": the part of a parsed line at a 1-based column."""
    if line.kind == syntax.END:
        return "end" if column <= line.path_column + len(line.path or "") else "rest"
    if line.kind == syntax.COMMENT:
        return "comment"
    if line.kind != syntax.ASSIGNMENT:
        return None
    if column < line.path_column:
        return None
    if column <= line.path_column + len(line.path or ""):
        return "path"
    if line.value is not None and line.value_column <= column <= line.value_column + len(line.value):
        return "value"
    if line.rest is not None and column >= line.rest_column:
        return "rest"
    return None


def code_at(text: str, index: int) -> str | None:
    """A rule code (LIS202) around a 0-based index of `text`."""
    for match in _CODE.finditer(text):
        if match.start() <= index <= match.end():
            return match.group(0).upper()
    return None


def setting_of(context: Context | None, line: syntax.Line) -> Setting | None:
    if context is None:
        return None
    for setting in context.analysis.settings:
        if setting.line is line:
            return setting
    return None


# -- hover --------------------------------------------------------------------------------------------


def document_kind(snapshot: Snapshot | None) -> Kind | None:
    """The kind of list a document is, as its lint decided it (the start-up entry that names it, or its
    content: `linter.list_kind`): a start-up list, the kind of its rules' Context, the axis kind before the
    first lint. None for a kind achslint has no catalogue of (HMI objects, cam tables): nothing to offer."""
    if snapshot is None:
        return AXIS
    if snapshot.startup:
        return STARTUP
    if snapshot.context is not None:
        return snapshot.context.kind
    return None if snapshot.result.note else AXIS


def card_text(parameter: Parameter, markdown: bool = True, kind: Kind = AXIS) -> list[str]:
    from ..explanation import parameter_card, range_words

    card = parameter_card(parameter, kind)
    b = (lambda s: f"**{s}**") if markdown else (lambda s: s)
    c = (lambda s: f"`{s}`") if markdown else (lambda s: s)
    out = [f"{b(card['p_axis'])} {c(card['path'])}", "", card["description"], ""]
    rows = [
        ("list", card["list"] if kind.prefix != AXIS_PREFIX else None),
        ("type", card["type"]),
        ("unit", card["units"] and ", ".join(f"{v} ({k})" for k, v in card["units"].items())),
        ("range", card["range"]),
        (
            "checked range",
            card["checked_range"] and range_words(card["checked_range"]),
        ),
        ("symbols", card["symbols"] and ", ".join(card["symbols"])),
        ("accepted values", card["accepted_values"] and ", ".join(map(str, card["accepted_values"]))),
        ("max length", card["max_length"]),
        ("default", card["default"] if card["default"] not in (None, "") else None),
        ("indices", card["index_bounds"] and ", ".join(f"{a}..{b_}" for a, b_ in card["index_bounds"])),
        ("axis types", card["axis_types"] and ", ".join(card["axis_types"])),
        ("drive types", card["drive_types"] and ", ".join(card["drive_types"])),
        (
            "old names",
            ", ".join(f"{a['path']} ({a['kind']})" for a in card["aliases"] if a["kind"] != "misspelling"),
        ),
        ("restart", "a change needs a CNC restart" if card["restart_required"] else None),
    ]
    for key, value in rows:
        if value not in (None, "", [], {}):
            out.append(f"- {key}: {value}")
    return out


def value_words(values: ResolvedAxis, path: str) -> str:
    parameter = values.parameter(path)
    unit = parameter.unit(values.axis_type)
    value = values.get(path)
    if isinstance(value, bool):
        return str(int(value))
    if isinstance(value, (int, float)):
        return describe(value, unit)
    return "(empty)" if value in ("", None) else str(value)


def axis_lines(context: Context, path: str, markdown: bool = True) -> list[str]:
    """This list's value of a parameter: human units, where it comes from, correction, effect."""
    from ..explanation import parameter_row
    from ..homing.registry import is_homing_parameter

    values = context.values
    strategy = context.strategy
    row = parameter_row(values, strategy, path)
    c = (lambda s: f"`{s}`") if markdown else (lambda s: s)
    out = [("**In this list**" if markdown else "In this list") + f" ({c(path)}):"]
    out.append(f"- value: {value_words(values, path)}")
    out.append(f"- from: {values.origin(path)}" if values.is_set(path) else "- from: the built-in default")
    correction = values.correction(path)
    if correction is not None:
        out.append(
            f"- CNC correction {correction.error}: written {correction.written}, the CNC uses "
            f"{correction.used} — {correction.reason}"
        )
    found_effect = row["effective"]
    if is_homing_parameter(path) or not found_effect:
        verdict = "takes effect" if found_effect else "has no effect"
        out.append(f"- {verdict} under {strategy.title}: {row['reason']}")
    return out


def hover_text(
    context: Context | None,
    file: syntax.ListFile | None,
    line_number: int,
    column: int,
    markdown: bool = True,
    kind: Kind | None = AXIS,
) -> str | None:
    """The hover text at a 1-based (line, column) of a parsed list with its context: a parameter's card from
    the catalogue of the list's kind (the context's, else `kind`; None: no catalogue, no card)."""
    if file is None or not 1 <= line_number <= len(file.lines):
        return None
    line = file.lines[line_number - 1]
    part = part_at(line, column)
    if part is None:
        return None
    if part == "end":
        return "\n".join(
            [
                "**Ende** — the end marker" if markdown else "Ende — the end marker",
                "",
                (
                    "The CNC stops reading the list here: lines after it are ignored (LIS003). Without it the "
                    "CNC reports the list as incomplete (LIS002); `End` or `ENDE` are not the marker (LIS004)."
                ),
            ]
        )
    if part in ("rest", "comment"):
        text = line.rest if part == "rest" else (line.indent + (line.comment or ""))
        start = line.rest_column if part == "rest" else 1
        code = code_at(text or "", column - start)
        return rule_text(code, markdown) if code else None
    if context is not None:
        kind = context.kind
    cat = kind.catalogue() if kind is not None else None
    setting = setting_of(context, line)
    resolution = cat.resolve(line.path or "") if cat is not None and line.path_ok else None
    if kind is not None and resolution is None and part == "path" and line.path_ok:
        return _other_kind_card(file, line.path or "", kind, markdown)
    if kind is None or resolution is None:
        return None
    parameter = resolution.parameter
    canonical = setting.canonical if setting is not None else None
    axis = context is not None and context.axis_list
    if part == "path":
        out = card_text(parameter, markdown, kind)
        if resolution.alias is not None and resolution.alias.kind != "alternative":
            out.insert(2, f"(written with the {resolution.alias.kind} name {line.path})")
        if context is not None and axis and canonical is not None:
            out += ["", *axis_lines(context, canonical, markdown)]
        return "\n".join(out)
    # the value
    if context is None or canonical is None:
        return None
    written = setting.value if setting is not None else None
    if not axis:  # no resolved axis: the value as written, in the unit the parameter has whatever the axis
        units = set(parameter.units.values()) - {None, ""}
        return _value_text(parameter, written, units.pop() if len(units) == 1 else None)
    values = context.values
    unit = parameter.unit(values.axis_type)
    if isinstance(written, Reference):
        target = values.referenced(canonical, written)
        referenced = values.parameter(target)
        origin = f"from: {values.origin(target)}" if values.is_set(target) else "from: the built-in default"
        out = [
            f"{written} → {target} ({referenced.summary})",
            "",
            f"resolved value: {value_words(values, target)}",
            origin,
        ]
        return "\n".join(out)
    words = _value_text(parameter, written, unit)
    if words is None:
        return None
    out = [words]
    correction = values.correction(canonical)
    if correction is not None:
        out.append(
            f"the CNC uses {value_words(values, canonical)} instead ({correction.error}: {correction.reason})"
        )
    return "\n\n".join(out)


def _other_kind_card(file: syntax.ListFile, path: str, read_as: Kind, markdown: bool) -> str | None:
    """The card of a name the list's kind does not know, from the kind its content clearly shows (a channel
    list a start-up entry names as an axis list: LIS523, LIS101), said to be read as the other; else None."""
    shown = content_kind(file)
    if shown is None or shown.prefix == read_as.prefix:
        return None
    catalogue = shown.catalogue()
    resolution = catalogue.resolve(path) if catalogue is not None else None
    if resolution is None:
        return None
    note = (
        f"This list is read as {read_as.a_name} (LIS523: the start-up entry that names it), but its content "
        f"is {shown.a_name}: the parameter below is not one of {read_as.a_name}."
    )
    return "\n".join([*card_text(resolution.parameter, markdown, shown), "", note])


def _value_text(parameter: Parameter, written: object, unit: str | None) -> str | None:
    """A written value in words: a number in human units, a switch as on or off, symbols with their choice."""
    if isinstance(written, bool):
        return f"{int(written)} ({'on' if written else 'off'})"
    if isinstance(written, (int, float)):
        return describe(written, unit)
    if written is not None and parameter.symbols:
        return f"{written} (one of {', '.join(parameter.symbols)})"
    return None


def rule_text(code: str, markdown: bool = True) -> str | None:
    rule = registry().get(code)
    if rule is None:
        return None
    head = f"{rule.code} {rule.name} ({rule.severity.value}; fix: {rule.fix})"
    out = [f"**{head}**" if markdown else head, "", rule.summary]
    for title in ("What", "Why"):
        body = rule.section(title)
        if body:
            out += ["", f"{title}: {body}"]
    href = rule_href(code)
    if href and markdown:
        out += ["", f"[Documentation]({href})"]
    return "\n".join(out)


# -- completion ------------------------------------------------------------------------------------

_PATH_PREFIX = re.compile(r"^[ \t]*([A-Za-z_][A-Za-z0-9_\-.\[\]]*)?$")
_VALUE_PREFIX = re.compile(r"^[ \t]*([A-Za-z_][A-Za-z0-9_\-.\[\]]*)[ \t]+(\S*)$")
# A flag after `|` in an OR-combined value (`error_protocol_mode  REPORT | REP`), before any `(` comment.
_FLAG_PREFIX = re.compile(r"^[ \t]*([A-Za-z_][A-Za-z0-9_\-.\[\]]*)[ \t]+[^(]*\|[ \t]*([^ \t|(]*)$")
_NOQA_PREFIX = re.compile(r"noqa:[ \t]*(?:[A-Za-z0-9]+[ \t]*,[ \t]*)*([A-Za-z0-9]*)$", re.IGNORECASE)


def _applies(parameter: Parameter, context: Context | None) -> bool:
    """Whether a parameter takes effect for the list's drive and axis type (as LIS105 judges it; lists of
    other kinds describe no axis)."""
    if context is None or not context.axis_list:
        return True
    analysis = context.analysis
    if (
        analysis.drive_type is not None
        and parameter.drive_group
        and analysis.drive_type not in parameter.drive_group
    ):
        return False
    return not (
        analysis.axis_type_known and parameter.axis_types and analysis.axis_type not in parameter.axis_types
    )


def _snippet_path(
    pattern: str, typed: tuple[int, ...], bounds: tuple[tuple[int, int], ...], snippets: bool
) -> str:
    """A catalogue pattern with the typed indices filled in and the others as snippet placeholders."""
    text = fill_indices(pattern, typed)
    number = 0
    out = []
    parts = text.split("[i]")
    for index, part in enumerate(parts):
        out.append(part.replace("$", "\\$") if snippets else part)
        if index < len(parts) - 1:
            low = bounds[len(typed) + index][0] if len(typed) + index < len(bounds) else 0
            number += 1
            out.append(f"[${{{number}:{low}}}]" if snippets else f"[{low}]")
    return "".join(out)


def complete(
    document: Document,
    snapshot: Snapshot | None,
    line_number: int,
    column: int,
    snippets: bool = True,
    edit_range_default: bool = False,
) -> lsp.CompletionList:
    """Completion at a 1-based position: rule codes after `noqa:`, parameter paths at the start of a
    line, symbols and references in the value (and a flag after `|`), all from the catalogue of the
    document's kind.

    Every client can use the answer as it is: the items are those the typed prefix leads to (matched
    here, case aside: a client that takes the list as filtered, as Neovim does, offers nothing else),
    each carries the text a client filters by (`filterText`: the prefix as typed, then the rest) and
    replaces the typed prefix (its `textEdit`; with `edit_range_default`, when the client supports
    `itemDefaults.editRange`, the range is sent once for the list), and `sortText` ranks them by relevance
    (`_path_rank`). The list is marked incomplete: a client asks again as the user types on."""
    text = document.line(line_number)
    before = text[: column - 1]
    context = snapshot.context if snapshot is not None else None
    kind = document_kind(snapshot)
    noqa = _NOQA_PREFIX.search(before)
    if noqa and "noqa" in before.lower():
        typed = noqa.group(1)
        start = column - len(typed)
        return lsp.CompletionList(True, _code_items(document, snapshot, line_number, start, column, typed))
    if kind is None:
        return lsp.CompletionList(False, [])
    match = _PATH_PREFIX.match(before)
    if match:
        typed = match.group(1) or ""
        start = column - len(typed)
        where = lsp_range(document, line_number, start, line_number, column)
        around = _Around.of(snapshot, kind, line_number)
        items = _path_items(context, kind, typed, snippets, None if edit_range_default else where, around)
        defaults = lsp.CompletionItemDefaults(edit_range=where) if edit_range_default else None
        return lsp.CompletionList(True, items, item_defaults=defaults)
    match = _VALUE_PREFIX.match(before) or (
        _FLAG_PREFIX.match(before) if kind.prefix != AXIS_PREFIX else None
    )
    if match:
        start = column - len(match.group(2))
        return lsp.CompletionList(
            True,
            _value_items(document, context, kind, line_number, start, column, match.group(1), match.group(2)),
        )
    return lsp.CompletionList(False, [])


def _edit(document: Document, line: int, start: int, end: int, text: str) -> lsp.TextEdit:
    return lsp.TextEdit(lsp_range(document, line, start, line, end), text)


def _filter_text(typed: str, label: str) -> str | None:
    """What a client compares with the typed text: the label with its first characters as they were typed
    (matched case aside); None when the label does not begin with the typed text."""
    if not label.lower().startswith(typed.lower()):
        return None
    return typed + label[len(typed) :]


_OPEN_INDEX = re.compile(r"\[([0-9]*)$")  # an index being typed: `getriebe[`, `getriebe[1`


@dataclass(frozen=True)
class _Written:
    """The paths a parsed list sets, for ranking completions: worked out once per parse (the loop keeps the
    last one), as a 50,000-line list takes tens of milliseconds to walk."""

    numbers: list[int]  # the lines that set a path, in order
    paths: list[str]  # the path each of them sets (lowercase)
    counts: dict[str, int]  # how many lines set each path
    patterns: dict[str, int]  # how many of the paths set have each pattern (`getriebe[i].vb_reflow`)

    @classmethod
    def of(cls, file: syntax.ListFile) -> _Written:
        kept = _WRITTEN[0] if _WRITTEN else None  # (the server's worker may replace it meanwhile: read once)
        if kept is not None and kept[0] is file:
            return kept[1]
        numbers: list[int] = []
        paths: list[str] = []
        counts: dict[str, int] = {}
        for line in file.lines:
            if line.kind == syntax.ASSIGNMENT and line.path_ok and line.path:
                path = line.path.lower()
                numbers.append(line.number)
                paths.append(path)
                counts[path] = counts.get(path, 0) + 1
        patterns: dict[str, int] = {}
        for path in counts:
            pattern = syntax.path_pattern(path)[0]
            patterns[pattern] = patterns.get(pattern, 0) + 1
        written = cls(numbers, paths, counts, patterns)
        _WRITTEN[:] = [(file, written)]
        return written


# The last parse asked about, and its paths (the language server's worker works them out with each analysis,
# before the loop has it).
_WRITTEN: list[tuple[syntax.ListFile, _Written]] = []


def paths_for_completion(file: syntax.ListFile) -> None:
    """Work out what completion ranks by for `file` now (a 50,000-line list takes 15 ms)."""
    _Written.of(file)


@dataclass(frozen=True)
class _Around:
    """What ranks a path at the cursor: the paths the list sets already (as written and as patterns; those
    of the cursor's line only when another line sets them too), the group and the unit of the nearest
    assignment above the line (below it when none is above)."""

    written: _Written | None = None
    alone: str | None = None  # the path set on the cursor's line and nowhere else: not counted as set
    group: str | None = None
    unit: str | None = None
    axis_type: str = "T"

    @classmethod
    def of(cls, snapshot: Snapshot | None, kind: Kind, line_number: int) -> _Around:
        file = snapshot.file if snapshot is not None else None
        if file is None:
            return cls()
        context = snapshot.context if snapshot is not None else None
        axis_type = context.values.axis_type if context is not None and context.axis_list else "T"
        written = _Written.of(file)
        numbers, paths = written.numbers, written.paths
        at = bisect.bisect_left(numbers, line_number)  # the first assignment on the line or below it
        here = at < len(numbers) and numbers[at] == line_number
        alone = paths[at] if here and written.counts[paths[at]] == 1 else None
        if at > 0:
            near: str | None = paths[at - 1]
        else:
            below = at + 1 if here else at
            near = paths[below] if below < len(paths) else None
        group = unit = None
        if near is not None:
            group = syntax.path_pattern(near.rsplit(".", 1)[0])[0] if "." in near else None
            cat = kind.catalogue()
            resolution = cat.resolve(near) if cat is not None else None
            unit = resolution.parameter.unit(axis_type) if resolution is not None else None
        return cls(written, alone, group, unit, axis_type)

    def _set(self, parameter: Parameter, lowered: str) -> bool:
        written = self.written
        if written is None:
            return False
        if "[i]" not in lowered:
            return lowered != self.alone and lowered in written.counts
        count = written.patterns.get(parameter.path, 0)
        if self.alone is not None and syntax.path_pattern(self.alone)[0] == parameter.path:
            count -= 1
        return count > 0

    def rank(self, parameter: Parameter, label: str) -> str:
        """`sortText` of a path: not yet set in this list first, then the group of the line near the cursor,
        then its unit; alphabetical within each."""
        lowered = label.lower()
        set_here = self._set(parameter, lowered)
        group = parameter.path.rsplit(".", 1)[0] if "." in parameter.path else None
        same_group = group is not None and group == self.group
        unit = parameter.unit(self.axis_type)
        same_unit = unit is not None and unit == self.unit
        return f"{int(set_here)}{int(not same_group)}{int(not same_unit)} {label}"


def _path_items(
    context: Context | None,
    kind: Kind,
    typed: str,
    snippets: bool,
    where: lsp.Range | None,
    around: _Around | None = None,
) -> list[lsp.CompletionItem]:
    """The paths of the kind's catalogue the typed prefix leads to (of an axis list: those that take effect
    for its drive and axis type); old names marked deprecated, ranked last. Items carry no documentation:
    `completionItem/resolve` adds the card of the one the user looks at (an item of another kind than axis
    lists names its kind in `data`)."""
    cat = kind.catalogue()
    if cat is None:
        return []
    around = around or _Around()
    data = {"kind": kind.id} if kind.prefix != AXIS_PREFIX else None
    pattern, indices = syntax.path_pattern(typed)
    opened = _OPEN_INDEX.search(pattern)
    if opened is not None:  # `getriebe[1`: matches `getriebe[i]`, and the index typed so far fills it
        pattern = pattern[: opened.start()] + "["
        if opened.group(1):
            indices = (*indices, int(opened.group(1)))
    key = pattern.lower()
    items = []
    plain, snippet = lsp.InsertTextFormat.PlainText, lsp.InsertTextFormat.Snippet
    for parameter in cat.parameters:
        if not parameter.path.startswith(key) or not _applies(parameter, context):
            continue
        label = fill_indices(parameter.path, indices)
        filter_text = _filter_text(typed, label)
        if filter_text is None:  # an index typed that is no index (`[01`)
            continue
        insert = _snippet_path(parameter.path, indices, parameter.index_bounds, snippets)
        is_snippet = snippets and "$" in insert
        items.append(
            lsp.CompletionItem(
                label=label,
                kind=lsp.CompletionItemKind.Field,
                detail=f"{parameter.id} {parameter.type}",
                sort_text=around.rank(parameter, label),
                filter_text=filter_text,
                text_edit=lsp.TextEdit(where, insert) if where is not None else None,
                text_edit_text=insert if where is None and insert != label else None,
                insert_text_format=snippet if is_snippet else plain,
                data=data,
            )
        )
        for alias in parameter.aliases:
            if alias.kind != "old" or not alias.path.lower().startswith(key):
                continue
            old = fill_indices(alias.path, indices)
            old_filter = _filter_text(typed, old)
            if old_filter is None:
                continue
            items.append(
                lsp.CompletionItem(
                    label=old,
                    kind=lsp.CompletionItemKind.Field,
                    detail=f"old name of {parameter.path}",
                    tags=[lsp.CompletionItemTag.Deprecated],
                    sort_text="~" + old,
                    filter_text=old_filter,
                    text_edit=lsp.TextEdit(where, old) if where is not None else None,
                )
            )
    return items


def _value_items(
    document: Document,
    context: Context | None,
    kind: Kind,
    line: int,
    start: int,
    end: int,
    path: str,
    typed: str,
) -> list[lsp.CompletionItem]:
    """The symbols of the parameter on the line (in the catalogue's order), 0 and 1 for a switch, and (in
    axis lists) references to parameters of the same unit, ranked after them; those the typed prefix leads
    to."""
    cat = kind.catalogue()
    resolution = cat.resolve(path) if cat is not None else None
    if cat is None or resolution is None:
        return []
    parameter = resolution.parameter
    items = []

    def item(
        label: str, sort: str, what: lsp.CompletionItemKind, detail: str, documentation: str | None = None
    ) -> None:
        filter_text = _filter_text(typed, label)
        if filter_text is not None:
            items.append(
                lsp.CompletionItem(
                    label=label,
                    kind=what,
                    detail=detail,
                    documentation=documentation,
                    sort_text=sort,
                    filter_text=filter_text,
                    text_edit=_edit(document, line, start, end, label),
                )
            )

    for number, symbol in enumerate(parameter.symbols):
        item(
            symbol,
            f"0{number:04}",
            lsp.CompletionItemKind.EnumMember,
            f"{parameter.path} ({parameter.id})",
            f"a value of {parameter.path}: {parameter.summary}",
        )
    if parameter.kind == BOOL and not parameter.symbols:
        for value, words in (("0", "off"), ("1", "on")):
            item(value, f"0{value}", lsp.CompletionItemKind.Value, words)
    if kind.prefix != AXIS_PREFIX:  # a reference names an axis parameter: none of this kind's
        return items
    if parameter.kind in (INTEGER, REAL) and (typed.upper().startswith("P") or not typed):
        axis_type = context.values.axis_type if context is not None and context.axis_list else "T"
        unit = parameter.unit(axis_type)
        for other in cat.parameters:
            if other is parameter or other.kind not in (INTEGER, REAL) or other.unit(axis_type) != unit:
                continue
            label = other.id + (".0" if "[i]" in other.path else "")
            item(
                label,
                "~" + label,
                lsp.CompletionItemKind.Reference,
                other.path,
                f"take the value of {other.path} ({unit_label(unit) or 'no unit'}): {other.summary}",
            )
    return items


def _code_items(
    document: Document, snapshot: Snapshot | None, line: int, start: int, end: int, typed: str = ""
) -> list[lsp.CompletionItem]:
    """The rule codes the typed prefix leads to; those found on this line first."""
    here = set()
    if snapshot is not None:
        here = {d.code for d in snapshot.result.diagnostics if d.line == line}
    items = []
    for code, rule in registry().items():
        filter_text = _filter_text(typed, code)
        if filter_text is None:
            continue
        items.append(
            lsp.CompletionItem(
                label=code,
                kind=lsp.CompletionItemKind.Constant,
                detail=rule.summary,
                documentation=f"{rule.name} ({rule.severity.value})",
                sort_text=("0" if code in here else "1") + code,
                filter_text=filter_text,
                text_edit=_edit(document, line, start, end, code),
            )
        )
    return items


def resolve_item(item: lsp.CompletionItem, markdown: bool = True) -> lsp.CompletionItem:
    """Add the parameter card to a path item (computed only for the item the user looks at), from the
    catalogue of the kind its `data` names (axis lists when it names none)."""
    named = item.data.get("kind") if isinstance(item.data, dict) else None
    kind = BY_ID.get(named, AXIS) if isinstance(named, str) else AXIS
    cat = kind.catalogue() if item.kind == lsp.CompletionItemKind.Field else None
    resolution = cat.resolve(item.label) if cat is not None else None
    if resolution is not None and item.documentation is None:
        text = "\n".join(card_text(resolution.parameter, markdown, kind))
        item.documentation = lsp.MarkupContent(
            lsp.MarkupKind.Markdown if markdown else lsp.MarkupKind.PlainText, text
        )
    return item


# -- code actions ----------------------------------------------------------------------------------


def text_edits(document: Document, fix: Fix) -> list[lsp.TextEdit]:
    edits = [
        lsp.TextEdit(lsp_range(document, e.line, e.column, e.end_line, e.end_column), e.content)
        for e in fix.edits
    ]
    if fix.remove_bom and document.bom:
        edits.append(lsp.TextEdit(lsp.Range(lsp.Position(0, 0), lsp.Position(0, 1)), ""))
    return edits


def diff_edits(document: Document, new_text: str) -> list[lsp.TextEdit]:
    """The line edits that turn the document's text into `new_text` (linear in its length: textdiff)."""
    old = document.raw_lines
    new = syntax.split_lines(new_text, keepends=True)
    return [
        _line_edit(document, old, i1, i2, "".join(new[j1:j2])) for i1, i2, j1, j2 in changed_blocks(old, new)
    ]


def format_edits(document: Document, blocks: Iterable[Block]) -> list[lsp.TextEdit]:
    """The edits of `fmt.LiveFormat.changes` (lines of the text as achslint reads it) in the document."""
    return [
        lsp.TextEdit(lsp.Range(lsp.Position(*start), lsp.Position(*end)), text)
        for start, end, text in _block_spans(document, blocks)
    ]


_EDIT_JSON = (
    '{"range": {"start": {"line": %d, "character": %d}, "end": {"line": %d, "character": %d}}, "newText": %s}'
)


def format_edits_json(document: Document, blocks: Iterable[Block]) -> str:
    """`format_edits` written as JSON at once: a long list's formatting is thousands of edits, and made into
    objects and serialised by the protocol's converter they take the loop three times as long."""
    spans = _block_spans(document, blocks)
    return "[" + ", ".join(_EDIT_JSON % (*start, *end, json.dumps(text)) for start, end, text in spans) + "]"


def _block_spans(
    document: Document, blocks: Iterable[Block]
) -> Iterator[tuple[tuple[int, int], tuple[int, int], str]]:
    old = document.raw_lines
    mark = "\ufeff" if document.bom else ""  # (read without it, the first line is written back with it)
    for first, stop, text in blocks:
        start, end = _line_start(document, old, first), _line_start(document, old, stop)
        yield start, end, mark + text if first == 0 else text


def _line_edit(document: Document, old: list[str], first: int, stop: int, text: str) -> lsp.TextEdit:
    """Lines [first, stop) of the document replaced by `text`."""
    start, end = _line_start(document, old, first), _line_start(document, old, stop)
    return lsp.TextEdit(lsp.Range(lsp.Position(*start), lsp.Position(*end)), text)


def _line_start(document: Document, old: list[str], index: int) -> tuple[int, int]:
    """The LSP position where line `index` starts (the end of the text after its last line)."""
    if index < len(old) or (old and old[-1].endswith(("\n", "\r"))):
        return index, 0
    if not old:
        return 0, 0
    return len(old) - 1, units(old[-1], document.encoding)


def noqa_edit(document: Document, file: syntax.ListFile | None, d: Diagnostic) -> lsp.TextEdit | None:
    """Where `noqa: CODE` goes: into the line's trailing comment, else a new comment after the value
    (`#` after a number or reference, `(` after text, where only `(` starts a comment)."""
    from ..linting.suppression import LINE_NOQA

    if file is None or not 1 <= d.line <= len(file.lines):
        return None
    line = file.lines[d.line - 1]
    end = document.to_lsp(d.line, line.end_column)
    at_end = lsp.Range(lsp.Position(*end), lsp.Position(*end))
    if line.kind != syntax.ASSIGNMENT or not line.path_ok or line.value is None:
        top = lsp.Range(lsp.Position(0, 0), lsp.Position(0, 0))
        return lsp.TextEdit(top, f"# achslint: noqa: {d.code}{line.newline or chr(10)}")
    trailing = line.rest or ""
    existing = LINE_NOQA.search(trailing)
    if existing and existing.group("codes"):
        column = line.rest_column + existing.end()
        where = document.to_lsp(d.line, column)
        return lsp.TextEdit(lsp.Range(lsp.Position(*where), lsp.Position(*where)), f", {d.code}")
    if existing:
        return None  # a bare noqa already suppresses everything
    after_number = line.value_kind in (syntax.INT, syntax.HEX, syntax.REAL, syntax.REFERENCE)
    if line.rest is not None and (after_number or line.rest.startswith("(")):
        return lsp.TextEdit(at_end, f"  noqa: {d.code}")  # into the comment there
    # after a symbol or string only `(` starts a comment: other text there is read with the value
    marker = "#" if after_number else "("
    return lsp.TextEdit(at_end, f"  {marker} noqa: {d.code}")


def code_actions(
    document: Document,
    snapshot: Snapshot | None,
    found: list[Diagnostic],
    request: lsp.Range,
    only: Sequence[str] | None,
    fix_all_edits: Callable[[], list[lsp.TextEdit]],
    refused: Set[tuple[str, int, int]] = frozenset(),
) -> list[lsp.CodeAction]:
    """The quick fixes, noqa actions and fix-all for the findings in `request`. `refused`: (code, line,
    column) of the findings whose fix the lint calls safe and `--fix` refuses (`Session.fix_all`):
    offered as unsafe, as `achslint lint` shows them."""
    start_line, end_line = request.start.line + 1, request.end.line + 1

    def wanted(kind: str) -> bool:
        return not only or any(kind == k or kind.startswith(k + ".") for k in only)

    actions = []
    file = snapshot.file if snapshot is not None else None
    xml = file is None
    # A `noqa` in a list suppresses only the list's own findings: the machine step's (LIS5xx) are not
    # suppressed (`engine.run`), and a `noqa` for one would only add LIS009.
    own = {id(d) for d in snapshot.result.diagnostics} if snapshot is not None else set()
    if wanted(lsp.CodeActionKind.QuickFix):
        for d in found:
            if not (d.line <= end_line and d.end_line >= start_line):
                continue
            diagnostic = to_lsp_diagnostic(document, d)
            if d.fix is not None and (d.fix.edits or (d.fix.remove_bom and document.bom)):
                unsafe = d.fix.applicability != "safe" or (d.code, d.line, d.column) in refused
                actions.append(
                    lsp.CodeAction(
                        title=f"{d.code}: {d.fix.description}"
                        + (" (unsafe fix: check the result)" if unsafe else ""),
                        kind=lsp.CodeActionKind.QuickFix,
                        diagnostics=[diagnostic],
                        is_preferred=not unsafe,
                        edit=lsp.WorkspaceEdit(changes={document.uri: text_edits(document, d.fix)}),
                    )
                )
            if not xml and d.path == document.name and id(d) in own:
                edit = noqa_edit(document, file, d)
                if edit is not None:
                    whole_file = edit.new_text.startswith("# achslint: noqa")
                    actions.append(
                        lsp.CodeAction(
                            title=f"Suppress {d.code} in this file (noqa)"
                            if whole_file
                            else f"Suppress {d.code} on this line (noqa)",
                            kind=lsp.CodeActionKind.QuickFix,
                            diagnostics=[diagnostic],
                            edit=lsp.WorkspaceEdit(changes={document.uri: [edit]}),
                        )
                    )
    if not xml and any(d.fix is not None and d.fix.applicability == "safe" for d in found):
        for kind in (FIX_ALL, lsp.CodeActionKind.SourceFixAll):
            if only and wanted(kind):
                edits = fix_all_edits()
                if edits:
                    actions.append(
                        lsp.CodeAction(
                            "achslint: fix all safe findings",
                            kind=FIX_ALL,
                            edit=lsp.WorkspaceEdit(changes={document.uri: edits}),
                        )
                    )
                break
        else:
            if not only or wanted(lsp.CodeActionKind.QuickFix):
                edits = fix_all_edits()
                if edits:
                    actions.append(
                        lsp.CodeAction(
                            "achslint: fix all safe findings",
                            kind=lsp.CodeActionKind.QuickFix,
                            edit=lsp.WorkspaceEdit(changes={document.uri: edits}),
                        )
                    )
    return actions


# -- formatting ------------------------------------------------------------------------------------


def format_document(document: Document, options: FmtOptions | None = None) -> list[lsp.TextEdit]:
    """The edits that format the document (the server keeps its `LiveFormat` to format again after edits)."""
    from ..fmt import LiveFormat

    live = LiveFormat(options, document.cache.line)
    live.update(document.body_lines)
    return format_edits(document, live.changes())


def format_range(document: Document, live: LiveFormat, request: lsp.Range) -> list[lsp.TextEdit]:
    """Edits of the text of the lines in `request` that formatting rewrites (`live`: the formatting of the
    document's text; line breaks and the lines after the end marker are the whole document's business)."""
    first = max(request.start.line + 1, 1)
    stop = min(max(request.end.line + (1 if request.end.character else 0), first), document.line_count)
    edits = []
    for number, formatted in enumerate(live.formatted(first - 1, stop), first):
        body, text = formatted.rstrip("\r\n"), document.line(number)
        if body != text:
            edits.append(lsp.TextEdit(lsp_range(document, number, 1, number, len(text) + 1), body))
    return edits


# -- outline and definitions ---------------------------------------------------------------------------


def document_symbols(document: Document, file: syntax.ListFile) -> list[lsp.DocumentSymbol]:
    """The outline: `Ende`, and each parameter under its group (`kopf`, `getriebe[0]` ...)."""
    plain = document.encoding == "utf-32" or (not document.bom and document.text.isascii())

    def span(number: int, start: int, end: int) -> lsp.Range:
        if plain:  # code points are the client's units: no line needs to be measured
            return lsp.Range(
                lsp.Position(number - 1, start - 1), lsp.Position(number - 1, max(end, start) - 1)
            )
        return lsp_range(document, number, start, number, end)

    groups: dict[str, list[lsp.DocumentSymbol]] = {}
    out: list[lsp.DocumentSymbol] = []
    field, event = lsp.SymbolKind.Field, lsp.SymbolKind.Event
    for line in file.lines:
        if line.kind == syntax.END:
            where = span(line.number, line.path_column, line.end_column)
            out.append(lsp.DocumentSymbol("Ende", event, where, where, detail="end marker"))
            continue
        path = line.path
        if line.kind != syntax.ASSIGNMENT or not line.path_ok or not path:
            continue
        head, _, tail = path.partition(".")
        where = span(line.number, 1, line.end_column)
        name_range = span(line.number, line.path_column, line.path_column + len(path))
        symbol = lsp.DocumentSymbol(tail or head, field, where, name_range, detail=line.value or "")
        if not tail:
            out.append(symbol)
            continue
        if head not in groups:
            groups[head] = []
            out.append(
                lsp.DocumentSymbol(
                    head,
                    lsp.SymbolKind.Array if "[" in head else lsp.SymbolKind.Namespace,
                    where,
                    name_range,
                    children=groups[head],
                )
            )
        groups[head].append(symbol)
    for group in out:
        if group.children:
            group.range = lsp.Range(group.children[0].range.start, group.children[-1].range.end)
    return out


def definition(
    document: Document,
    snapshot: Snapshot | None,
    line_number: int,
    column: int,
    startup_entries: Callable[[], list[StartupEntry]],
) -> list[lsp.Location]:
    file = snapshot.file if snapshot is not None else None
    if snapshot is None or file is None or not 1 <= line_number <= len(file.lines):
        return []
    line = file.lines[line_number - 1]
    if part_at(line, column) != "value":
        return []
    if snapshot.startup:  # the entries as on disk: the one of this key and value (the buffer may differ)
        for entry in startup_entries():
            if entry.key == line.path and entry.raw == line.value and entry.path is not None:
                zero = lsp.Range(lsp.Position(0, 0), lsp.Position(0, 0))
                return [lsp.Location(uri_of(entry.path), zero)]
        return []
    context = snapshot.context
    setting = setting_of(context, line)
    if (
        context is None
        or not context.axis_list  # a reference resolves in a resolved axis only
        or setting is None
        or not isinstance(setting.value, Reference)
        or setting.canonical is None
    ):
        return []
    values = context.values
    target = values.referenced(setting.canonical, setting.value)
    origin = values.origin(target)
    if origin.setting is None or origin.file is None:  # set together for a value from a list
        return []
    found = origin.setting.line
    if origin.kind == "list":
        return [
            lsp.Location(
                document.uri,
                lsp_range(
                    document,
                    found.number,
                    found.path_column,
                    found.number,
                    found.path_column + len(found.path or ""),
                ),
            )
        ]
    start = lsp.Position(found.number - 1, found.path_column - 1)
    return [
        lsp.Location(
            uri_of(origin.file),
            lsp.Range(start, lsp.Position(found.number - 1, found.path_column - 1 + len(found.path or ""))),
        )
    ]


def inlay_hints(document: Document, snapshot: Snapshot | None, request: lsp.Range) -> list[lsp.InlayHint]:
    """Human units after raw numeric values (`20000` → `= 20 mm/s = 1.2 m/min`)."""
    from ..catalogue.units import to_human

    context = snapshot.context if snapshot is not None else None
    if context is None or not context.axis_list:  # human units need the axis type: axis lists only
        return []
    hints = []
    first, last = request.start.line + 1, request.end.line + 1
    axis_type = context.values.axis_type
    for setting in context.analysis.settings:
        line = setting.line
        if not first <= line.number <= last or setting.parameter is None or setting.problems:
            continue
        value = setting.value
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not value:
            continue
        human = to_human(value, setting.parameter.unit(axis_type))
        if human:
            where = document.to_lsp(line.number, line.value_column + len(line.value or ""))
            hints.append(lsp.InlayHint(lsp.Position(*where), f" = {human}", padding_left=True))
    return hints
