"""`achslint server`: the language server (stdio), on pygls 2.

The handlers only translate between the protocol and `session` / `features`; no finding,
card or fix is computed here. Every handler is guarded: whatever a document contains, the
server answers (at worst with nothing) and keeps running.
"""

from __future__ import annotations

import asyncio
import functools
import logging
import traceback
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, TypeVar

from lsprotocol import types as lsp
from pygls.lsp.server import LanguageServer
from pygls.uris import to_fs_path

from .. import __version__
from ..files import is_xml
from . import features
from .documents import Document
from .session import ClientSettings, Session, Snapshot

if TYPE_CHECKING:
    from ..config import FmtOptions
    from ..context import Context
    from ..machine import StartupEntry
    from ..syntax import ListFile

log = logging.getLogger("achslint.lsp")
_Params = TypeVar("_Params")  # the parameters of a request or notification


class AchslintServer(LanguageServer):
    def __init__(self) -> None:
        super().__init__(
            "achslint", __version__, text_document_sync_kind=lsp.TextDocumentSyncKind.Incremental
        )
        self.session = Session()
        self._timers: dict[str, asyncio.TimerHandle] = {}

    # -- client capabilities -------------------------------------------------------------------
    def _text_capabilities(self) -> lsp.TextDocumentClientCapabilities | None:
        try:
            return self.client_capabilities.text_document
        except AttributeError:  # no client capabilities yet (before initialize)
            return None

    def _completion_capabilities(self) -> lsp.CompletionClientCapabilities | None:
        text = self._text_capabilities()
        return text.completion if text is not None else None

    @property
    def markdown(self) -> bool:
        text = self._text_capabilities()
        hover = text.hover if text is not None else None
        formats = hover.content_format if hover is not None else None
        return not formats or lsp.MarkupKind.Markdown in formats

    @property
    def markdown_in_completion(self) -> bool:
        """Whether completion documentation may be Markdown (completionItem.documentationFormat)."""
        completion = self._completion_capabilities()
        item = completion.completion_item if completion is not None else None
        formats = item.documentation_format if item is not None else None
        return not formats or lsp.MarkupKind.Markdown in formats

    @property
    def snippets(self) -> bool:
        completion = self._completion_capabilities()
        item = completion.completion_item if completion is not None else None
        return item is not None and bool(item.snippet_support)

    @property
    def edit_range_default(self) -> bool:
        completion = self._completion_capabilities()
        completion_list = completion.completion_list if completion is not None else None
        defaults = completion_list.item_defaults if completion_list is not None else None
        return defaults is not None and "editRange" in defaults

    @property
    def encoding(self) -> str:
        encoding = self.workspace.position_encoding if self.workspace is not None else None
        names: dict[str, str] = {
            lsp.PositionEncodingKind.Utf8: "utf-8",
            lsp.PositionEncodingKind.Utf32: "utf-32",
        }
        return names.get(encoding or "", "utf-16")

    # -- diagnostics -----------------------------------------------------------------------------
    def publish(self, uri: str) -> None:
        self._timers.pop(uri, None)
        document = self.session.documents.get(uri)
        if document is None:
            return
        peers: list[str] = []
        try:
            snapshot, found, peers = self.session.diagnostics(uri)
            diagnostics = features.publishable(document, snapshot, found)
        except Exception as exc:
            log.error("achslint: cannot lint %s: %s\n%s", uri, exc, traceback.format_exc())
            diagnostics = [
                lsp.Diagnostic(
                    lsp.Range(lsp.Position(0, 0), lsp.Position(0, 1)),
                    f"achslint could not check this document: internal error {type(exc).__name__}: {exc}",
                    lsp.DiagnosticSeverity.Error,
                    source="achslint",
                )
            ]
        self.text_document_publish_diagnostics(
            lsp.PublishDiagnosticsParams(uri=uri, diagnostics=diagnostics, version=document.version)
        )
        for peer in peers:  # other open lists of the machine whose machine findings changed with this one
            self.publish(peer)

    def schedule(self, uri: str, delay_ms: int | None = None) -> None:
        delay = self.session.settings.debounce_ms if delay_ms is None else delay_ms
        timer = self._timers.pop(uri, None)
        if timer is not None:
            timer.cancel()
        if delay <= 0:
            self.publish(uri)
            return
        loop = asyncio.get_running_loop()
        self._timers[uri] = loop.call_later(delay / 1000, self.publish, uri)

    def publish_all(self) -> None:
        for uri in list(self.session.documents):
            self.publish(uri)


server = AchslintServer()


def guarded(
    default: Callable[[], object] | None = None,
) -> Callable[[Callable[[AchslintServer, _Params], object]], Callable[[AchslintServer, _Params], object]]:
    """Answer `default()` (or None) instead of failing when a handler meets something unexpected (logged on
    stderr)."""

    def wrap(
        handler: Callable[[AchslintServer, _Params], object],
    ) -> Callable[[AchslintServer, _Params], object]:
        @functools.wraps(handler)
        def run(ls: AchslintServer, params: _Params) -> object:
            try:
                return handler(ls, params)
            except Exception as exc:
                log.error("achslint: %s failed: %s\n%s", handler.__name__, exc, traceback.format_exc())
                return default() if default is not None else None

        return run

    return wrap


def _take_settings(ls: AchslintServer, raw: object) -> None:
    """Use the editor's settings; codes that pick no rule are told to the user (and not used)."""
    ls.session.settings = ClientSettings.from_dict(raw)
    for problem in ls.session.settings.problems:
        ls.window_show_message(lsp.ShowMessageParams(lsp.MessageType.Warning, problem))


def _path(uri: str) -> Path | None:
    try:
        path = to_fs_path(uri)
    except Exception:
        return None
    # A NUL (file:///a%00b) names no file: the document is checked as an unsaved buffer.
    return Path(path) if path and uri.startswith("file:") and "\0" not in path else None


@server.feature(lsp.INITIALIZE)
@guarded()
def initialize(ls: AchslintServer, params: lsp.InitializeParams) -> None:
    _take_settings(ls, params.initialization_options or {})
    folders = params.workspace_folders or []
    root = _path(folders[0].uri) if folders else (_path(params.root_uri) if params.root_uri else None)
    ls.session.root = root


@server.feature(lsp.TEXT_DOCUMENT_DID_OPEN)
@guarded()
def did_open(ls: AchslintServer, params: lsp.DidOpenTextDocumentParams) -> None:
    item = params.text_document
    ls.session.open(Document(item.uri, _path(item.uri), item.text, item.version, ls.encoding))
    ls.publish(item.uri)


@server.feature(lsp.TEXT_DOCUMENT_DID_CHANGE)
@guarded()
def did_change(ls: AchslintServer, params: lsp.DidChangeTextDocumentParams) -> None:
    document = ls.session.documents.get(params.text_document.uri)
    if document is None:
        return
    for change in params.content_changes:
        if isinstance(change, lsp.TextDocumentContentChangePartial):
            start, end = change.range.start, change.range.end
            document.apply((start.line, start.character), (end.line, end.character), change.text)
        else:
            document.apply(None, None, change.text)
    document.version = params.text_document.version
    ls.schedule(document.uri)


@server.feature(lsp.TEXT_DOCUMENT_DID_SAVE)
@guarded()
def did_save(ls: AchslintServer, params: lsp.DidSaveTextDocumentParams) -> None:
    uri = params.text_document.uri
    if uri.endswith(".toml"):
        ls.session.forget_disk()
        ls.publish_all()
    elif uri in ls.session.documents:
        ls.session.forget_disk()  # the saved list is now what its neighbours see on disk
        ls.schedule(uri, 0)


@server.feature(lsp.TEXT_DOCUMENT_DID_CLOSE)
@guarded()
def did_close(ls: AchslintServer, params: lsp.DidCloseTextDocumentParams) -> None:
    uri = params.text_document.uri
    timer = ls._timers.pop(uri, None)
    if timer is not None:
        timer.cancel()
    document = ls.session.documents.get(uri)
    ls.session.close(uri)
    ls.text_document_publish_diagnostics(lsp.PublishDiagnosticsParams(uri=uri, diagnostics=[]))
    if document is not None and document.path is not None:
        # Its neighbours now see the file on disk instead of the buffer.
        near = {document.path.parent, document.path.parent.parent}
        ls.session.forget_disk()
        for other in list(ls.session.documents.values()):
            if other.path is not None and other.path.parent in near:
                ls.publish(other.uri)


@server.feature(lsp.WORKSPACE_DID_CHANGE_CONFIGURATION)
@guarded()
def did_change_configuration(ls: AchslintServer, params: lsp.DidChangeConfigurationParams) -> None:
    if isinstance(params.settings, dict) and params.settings:
        _take_settings(ls, params.settings)
    ls.session.forget_disk()
    ls.publish_all()


@server.feature(lsp.WORKSPACE_DID_CHANGE_WATCHED_FILES)
@guarded()
def did_change_watched_files(ls: AchslintServer, params: lsp.DidChangeWatchedFilesParams) -> None:
    ls.session.forget_disk()
    ls.publish_all()


# -- requests ---------------------------------------------------------------------------------------


def _where(
    ls: AchslintServer, uri: str, position: lsp.Position
) -> tuple[Document | None, Snapshot | None, int, int]:
    document = ls.session.documents.get(uri)
    if document is None:
        return None, None, 0, 0
    line, column = document.from_lsp(position.line, position.character)
    return document, ls.session.snapshot(uri), line, column


def _xml_target(
    ls: AchslintServer, document: Document, line: int, column: int
) -> tuple[Context | None, ListFile, int, int] | None:
    """The embedded list, its context and the list position under an XML position (TwinCAT CDATA, ISG XML)."""
    from ..decode import UnreadableInput
    from ..linter import lint_parsed
    from ..syntax import parse_text
    from ..xmlinput import extract
    from .session import xml_bytes

    try:
        lists = extract(xml_bytes(document.text), document.name)
    except UnreadableInput:
        return None
    for embedded in lists:
        count = len(embedded.text.splitlines()) + 1
        for number in range(1, count + 1):
            xml_line, xml_column = embedded.position(number, 1)
            if xml_line != line:
                continue
            file = parse_text(embedded.text, document.name)
            config, _ = ls.session.config_for(document)
            result = lint_parsed(
                file, document.name, ls.session.file_settings(config, document.path, document.name)
            )
            list_column = 1 if embedded.line_map is not None else column - xml_column + 1
            return result.context, file, number, max(list_column, 1)
    return None


@server.feature(lsp.TEXT_DOCUMENT_HOVER)
@guarded()
def hover(ls: AchslintServer, params: lsp.HoverParams) -> lsp.Hover | None:
    document, snapshot, line, column = _where(ls, params.text_document.uri, params.position)
    if document is None or snapshot is None:
        return None
    context: Context | None
    file: ListFile | None
    if is_xml(document.name):
        found = _xml_target(ls, document, line, column)
        if found is None:
            return None
        context, file, line, column = found
    else:
        context, file = snapshot.context, snapshot.file
    text = features.hover_text(context, file, line, column, ls.markdown)
    if not text:
        return None
    kind = lsp.MarkupKind.Markdown if ls.markdown else lsp.MarkupKind.PlainText
    return lsp.Hover(lsp.MarkupContent(kind, text))


@server.feature(
    lsp.TEXT_DOCUMENT_COMPLETION,
    lsp.CompletionOptions(trigger_characters=[".", "[", " ", ":", ","], resolve_provider=True),
)
@guarded()
def completion(ls: AchslintServer, params: lsp.CompletionParams) -> lsp.CompletionList | None:
    document, snapshot, line, column = _where(ls, params.text_document.uri, params.position)
    if document is None or is_xml(document.name):
        return None
    return features.complete(document, snapshot, line, column, ls.snippets, ls.edit_range_default)


@server.feature(lsp.COMPLETION_ITEM_RESOLVE)
@guarded(default=None)
def completion_resolve(ls: AchslintServer, item: lsp.CompletionItem) -> lsp.CompletionItem:
    return features.resolve_item(item, ls.markdown_in_completion)


@server.feature(
    lsp.TEXT_DOCUMENT_CODE_ACTION,
    lsp.CodeActionOptions(
        code_action_kinds=[lsp.CodeActionKind.QuickFix, features.FIX_ALL, lsp.CodeActionKind.SourceFixAll]
    ),
)
@guarded(default=list)
def code_action(ls: AchslintServer, params: lsp.CodeActionParams) -> list[lsp.CodeAction]:
    uri = params.text_document.uri
    document = ls.session.documents.get(uri)
    if document is None:
        return []
    snapshot, found, _ = ls.session.diagnostics(uri)

    def fix_all() -> list[lsp.TextEdit]:
        from ..fixer import fix_bytes

        config, _ = ls.session.config_for(document)
        settings = ls.session.file_settings(config, document.path, document.name)
        settings.keep_context = False
        outcome = fix_bytes(document.body.encode("utf-8"), document.name, settings)
        if not outcome.fixed:
            return []
        text = outcome.data.decode("utf-8")
        return features.diff_edits(document, ("\ufeff" if document.bom else "") + text)

    return features.code_actions(document, snapshot, found, params.range, params.context.only, fix_all)


def _list_file(ls: AchslintServer, uri: str) -> tuple[Document, ListFile] | None:
    """An open axis list (not XML) and its parse."""
    document = ls.session.documents.get(uri)
    if document is None or is_xml(document.name):
        return None
    snapshot = ls.session.snapshot(uri)
    return (document, snapshot.file) if snapshot is not None and snapshot.file is not None else None


@server.feature(lsp.TEXT_DOCUMENT_FORMATTING)
@guarded(default=list)
def formatting(ls: AchslintServer, params: lsp.DocumentFormattingParams) -> list[lsp.TextEdit]:
    found = _list_file(ls, params.text_document.uri)
    return features.format_document(*found, _fmt_options(ls, found[0])) if found is not None else []


@server.feature(lsp.TEXT_DOCUMENT_RANGE_FORMATTING)
@guarded(default=list)
def range_formatting(ls: AchslintServer, params: lsp.DocumentRangeFormattingParams) -> list[lsp.TextEdit]:
    found = _list_file(ls, params.text_document.uri)
    return (
        features.format_range(*found, params.range, _fmt_options(ls, found[0])) if found is not None else []
    )


def _fmt_options(ls: AchslintServer, document: Document) -> FmtOptions:
    """The `[fmt]` settings of the document's configuration: the editor formats as `achslint fmt` does."""
    return ls.session.config_for(document)[0].settings.fmt


@server.feature(lsp.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
@guarded(default=list)
def document_symbol(ls: AchslintServer, params: lsp.DocumentSymbolParams) -> list[lsp.DocumentSymbol]:
    found = _list_file(ls, params.text_document.uri)
    return features.document_symbols(*found) if found is not None else []


@server.feature(lsp.TEXT_DOCUMENT_DEFINITION)
@guarded(default=list)
def definition(ls: AchslintServer, params: lsp.DefinitionParams) -> list[lsp.Location]:
    document, snapshot, line, column = _where(ls, params.text_document.uri, params.position)
    if document is None or is_xml(document.name):
        return []
    if snapshot is not None and snapshot.startup and snapshot.file is None:
        snapshot.file = document.parse()

    def entries() -> list[StartupEntry]:
        from ..machine import read_startup

        if document.path is None:  # not a file: no start-up list
            return []
        startup = read_startup(document.path)
        return ([startup.default] if startup.default else []) + startup.axes

    return features.definition(document, snapshot, line, column, entries)


@server.feature(lsp.TEXT_DOCUMENT_INLAY_HINT)
@guarded(default=list)
def inlay_hint(ls: AchslintServer, params: lsp.InlayHintParams) -> list[lsp.InlayHint]:
    if not ls.session.settings.inlay_hints:
        return []
    document = ls.session.documents.get(params.text_document.uri)
    if document is None or is_xml(document.name):
        return []
    return features.inlay_hints(document, ls.session.snapshot(document.uri), params.range)


def run() -> None:
    """Serve on standard input and output until the client says exit."""
    logging.basicConfig(level=logging.WARNING, format="%(message)s")
    server.start_io()
