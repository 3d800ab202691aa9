"""`achslint server` with a plain client: plain-text hovers, no snippets, UTF-8 positions, no inlay hints;
requests for documents it does not know or cannot offer anything for; saves, watched files and settings
that change what is published. One server for the module (pytest-lsp over stdio)."""

from __future__ import annotations

import asyncio
import sys
from collections.abc import AsyncIterator, Callable
from pathlib import Path

import pytest

pytest.importorskip("pygls.lsp.server", reason="the lsp extra is not installed")
pytest_lsp = pytest.importorskip("pytest_lsp")

from lsprotocol import types as lsp  # noqa: E402
from pytest_lsp import ClientServerConfig, LanguageClient  # noqa: E402

pytestmark = pytest.mark.asyncio(loop_scope="module")

PLAIN_CLIENT = lsp.ClientCapabilities(
    general=lsp.GeneralClientCapabilities(position_encodings=[lsp.PositionEncodingKind.Utf8]),
    text_document=lsp.TextDocumentClientCapabilities(
        hover=lsp.HoverClientCapabilities(content_format=[lsp.MarkupKind.PlainText]),
        completion=lsp.CompletionClientCapabilities(
            completion_list=lsp.CompletionListCapabilities(item_defaults=["editRange"])
        ),
    ),
)
XML = (
    '<?xml version="1.0" encoding="utf-8"?>\n'
    "<TcSmItem>\n"
    "  <AchsMds><![CDATA[kopf.achs_nr  1\n"
    "kenngr.ref_richt  1\n"
    "Ende\n"
    "]]></AchsMds>\n"
    "</TcSmItem>\n"
)


@pytest_lsp.fixture(
    scope="module", config=ClientServerConfig(server_command=[sys.executable, "-m", "achslint", "server"])
)
async def client(lsp_client: LanguageClient, tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[None]:
    root = tmp_path_factory.mktemp("plain")
    await lsp_client.initialize_session(
        lsp.InitializeParams(
            capabilities=PLAIN_CLIENT, root_uri=root.as_uri(), initialization_options={"debounceMs": 0}
        )
    )
    yield
    await lsp_client.shutdown_session()


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    return tmp_path


def open_doc(client: LanguageClient, path: Path, text: str, language: str = "achsmds") -> str:
    uri = path.as_uri()
    client.diagnostics.pop(uri, None)
    client.text_document_did_open(lsp.DidOpenTextDocumentParams(lsp.TextDocumentItem(uri, language, 1, text)))
    return uri


def close_doc(client: LanguageClient, uri: str) -> None:
    client.text_document_did_close(lsp.DidCloseTextDocumentParams(lsp.TextDocumentIdentifier(uri)))


def codes(found: list[lsp.Diagnostic]) -> list[str]:
    return sorted(str(d.code) for d in found if d.code)


async def published(
    client: LanguageClient, uri: str, check: Callable[[list[lsp.Diagnostic]], bool] = lambda f: True
) -> list[lsp.Diagnostic]:
    """The diagnostics last published for `uri`, once they satisfy `check` (10 s at most)."""
    for _ in range(500):
        found = client.diagnostics.get(uri)
        if found is not None and check(list(found)):
            return list(found)
        await asyncio.sleep(0.02)
    raise AssertionError(f"no matching diagnostics for {uri}: {client.diagnostics.get(uri)}")


def change(client: LanguageClient, uri: str, version: int, text: str) -> None:
    client.text_document_did_change(
        lsp.DidChangeTextDocumentParams(
            lsp.VersionedTextDocumentIdentifier(version=version, uri=uri),
            [lsp.TextDocumentContentChangeWholeDocument(text)],
        )
    )


def document(uri: str) -> lsp.TextDocumentIdentifier:
    return lsp.TextDocumentIdentifier(uri)


ALL = lsp.Range(lsp.Position(0, 0), lsp.Position(20, 0))
FORMAT = lsp.FormattingOptions(4, True)


async def test_plain_text_hover_utf8_positions_and_an_edit_range_default(
    client: LanguageClient, folder: Path
) -> None:
    uri = open_doc(client, folder / "achsmds1.lis", "kenngr.ref_richt  µ\nkenngr.achs_typ  1\nEnde\n")
    [wrong] = await published(client, uri, lambda f: bool(f))
    assert wrong.code == "LIS201"
    # the value starts at code point 18; `µ` is one code point but two UTF-8 bytes
    assert (wrong.range.start.character, wrong.range.end.character) == (18, 20)
    hover = await client.text_document_hover_async(lsp.HoverParams(document(uri), lsp.Position(1, 3)))
    assert hover.contents.kind == lsp.MarkupKind.PlainText
    assert (
        hover.contents.value.startswith("P-AXIS-00018 kenngr.achs_typ\n") and "**" not in hover.contents.value
    )
    found = await client.text_document_completion_async(
        lsp.CompletionParams(document(uri), lsp.Position(1, len("kenngr.achs")))
    )
    assert found.item_defaults.edit_range == lsp.Range(lsp.Position(1, 0), lsp.Position(1, 11))
    assert all(i.text_edit is None for i in found.items)
    assert all(i.insert_text_format != lsp.InsertTextFormat.Snippet for i in found.items)  # not supported
    hints = await client.text_document_inlay_hint_async(lsp.InlayHintParams(document(uri), ALL))
    assert list(hints) == []  # inlay hints are off unless the editor turns them on
    close_doc(client, uri)


async def test_requests_for_documents_the_server_does_not_know(client: LanguageClient, folder: Path) -> None:
    uri = (folder / "never-opened.lis").as_uri()
    where = lsp.Position(0, 0)
    change(client, uri, 2, "kopf.achs_nr  1\n")  # ignored: not open
    assert await client.text_document_hover_async(lsp.HoverParams(document(uri), where)) is None
    assert await client.text_document_completion_async(lsp.CompletionParams(document(uri), where)) is None
    actions = lsp.CodeActionParams(document(uri), ALL, lsp.CodeActionContext([]))
    assert list(await client.text_document_code_action_async(actions)) == []
    assert (
        list(await client.text_document_formatting_async(lsp.DocumentFormattingParams(document(uri), FORMAT)))
        == []
    )
    assert list(await client.text_document_definition_async(lsp.DefinitionParams(document(uri), where))) == []
    assert list(await client.text_document_inlay_hint_async(lsp.InlayHintParams(document(uri), ALL))) == []
    assert uri not in client.diagnostics


async def test_xml_documents_offer_diagnostics_and_hovers_only(client: LanguageClient, folder: Path) -> None:
    uri = open_doc(client, folder / "Axis_X.xti", XML, language="xml")
    assert await published(client, uri) == []
    hover = await client.text_document_hover_async(lsp.HoverParams(document(uri), lsp.Position(3, 3)))
    assert hover.contents.value.startswith("P-AXIS-00158 kenngr.ref_richt")
    outside = await client.text_document_hover_async(lsp.HoverParams(document(uri), lsp.Position(1, 3)))
    assert outside is None  # <TcSmItem>: not a line of the list
    where = lsp.Position(3, 3)
    assert await client.text_document_completion_async(lsp.CompletionParams(document(uri), where)) is None
    assert (
        list(await client.text_document_formatting_async(lsp.DocumentFormattingParams(document(uri), FORMAT)))
        == []
    )
    assert (
        list(await client.text_document_document_symbol_async(lsp.DocumentSymbolParams(document(uri)))) == []
    )
    assert list(await client.text_document_definition_async(lsp.DefinitionParams(document(uri), where))) == []
    # an edit that breaks the XML: one error, and nothing to hover
    change(client, uri, 2, XML.replace("]]>", ""))
    [broken] = await published(client, uri, lambda f: bool(f))
    assert "not well-formed XML" in broken.message and broken.severity == lsp.DiagnosticSeverity.Error
    assert await client.text_document_hover_async(lsp.HoverParams(document(uri), where)) is None
    close_doc(client, uri)


async def test_saving_a_configuration_or_a_change_on_disk_republishes(
    client: LanguageClient, folder: Path
) -> None:
    path = folder / "achsmds1.lis"
    text = "kopf.achs_nr  1\nkenngr.ref_richt  7\nEnd\n"
    path.write_text(text, encoding="latin-1")
    uri = open_doc(client, path, text)
    assert codes(await published(client, uri)) == ["LIS004", "LIS201"]
    config = folder / ".achslint.toml"
    config.write_text('ignore = ["LIS201"]\n', encoding="utf-8")
    client.diagnostics.pop(uri)
    client.text_document_did_save(lsp.DidSaveTextDocumentParams(document(config.as_uri())))
    assert codes(await published(client, uri)) == ["LIS004"]
    config.write_text('ignore = ["LIS004"]\n', encoding="utf-8")
    client.diagnostics.pop(uri)
    client.workspace_did_change_watched_files(
        lsp.DidChangeWatchedFilesParams([lsp.FileEvent(config.as_uri(), lsp.FileChangeType.Changed)])
    )
    assert codes(await published(client, uri)) == ["LIS201"]
    config.unlink()
    client.diagnostics.pop(uri)
    client.workspace_did_change_configuration(lsp.DidChangeConfigurationParams(settings=None))
    assert codes(await published(client, uri)) == ["LIS004", "LIS201"]
    # saving a list that is not open changes nothing; saving the open list checks it at once
    client.text_document_did_save(lsp.DidSaveTextDocumentParams(document((folder / "other.lis").as_uri())))
    client.diagnostics.pop(uri)
    client.text_document_did_save(lsp.DidSaveTextDocumentParams(document(uri)))
    assert codes(await published(client, uri)) == ["LIS004", "LIS201"]
    close_doc(client, uri)


async def test_after_quick_edits_the_last_text_counts(client: LanguageClient, folder: Path) -> None:
    client.workspace_did_change_configuration(
        lsp.DidChangeConfigurationParams({"debounceMs": 50, "inlayHints": True})
    )
    try:
        uri = open_doc(client, folder / "achsmds1.lis", "kopf.achs_nr  1\nEnde\n")
        assert await published(client, uri) == []
        client.diagnostics.pop(uri)
        change(client, uri, 2, "kopf.achs_nr  1\nEnd\n")
        change(client, uri, 3, "kopf.achs_nr  1\nkopf.achs_nr  2\nEnde\n")
        assert codes(await published(client, uri)) == ["LIS005"]
        # closing a list with a check still pending clears its diagnostics for good
        change(client, uri, 4, "kopf.achs_nr  1\nEnd\n")
        close_doc(client, uri)
        assert await published(client, uri, lambda f: f == []) == []
        untitled = "untitled:Untitled-1"
        client.text_document_did_open(
            lsp.DidOpenTextDocumentParams(
                lsp.TextDocumentItem(untitled, "achsmds", 1, "kopf.achs_nr 1\nEnd\n")
            )
        )
        assert codes(await published(client, untitled)) == ["LIS004"]
        close_doc(client, untitled)
        assert await published(client, untitled, lambda f: f == []) == []
        hints = await client.text_document_inlay_hint_async(lsp.InlayHintParams(document(untitled), ALL))
        assert list(hints) == []  # closed: nothing to show
    finally:
        client.workspace_did_change_configuration(lsp.DidChangeConfigurationParams({"debounceMs": 0}))
