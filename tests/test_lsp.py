"""`achslint server` end to end: a real LSP client (pytest-lsp) talks to the server over stdio; a second
server answers a plain client (plain text, no snippets, UTF-8 positions)."""

from __future__ import annotations

import asyncio
import os
import random
import shutil
import sys
from collections.abc import AsyncIterator
from pathlib import Path

import pytest

pytest.importorskip("pygls.lsp.server", reason="the lsp extra is not installed")
pytest_lsp = pytest.importorskip("pytest_lsp")

from lsprotocol import types as lsp
from pytest_lsp import ClientServerConfig, LanguageClient, client_capabilities

from achslint.api import lint
from achslint.fmt import LiveFormat, format_bytes
from achslint.lsp.server import LOOP_FORMAT_LINES

from .conftest import FIXTURES

# every test here talks to a real server process: the slow tier (.ci/run, `pytest -m slow`)
pytestmark = [pytest.mark.asyncio(loop_scope="module"), pytest.mark.slow]
WORK = Path(os.environ.get("ACHSLINT_LSP_TEST_DIR", "")) if os.environ.get("ACHSLINT_LSP_TEST_DIR") else None


# The server of `client` is `achslint server` with two limits a tenth of their size, so that the paths of a
# long list are reached by a list of 1,400 lines rather than 14,000 (test_formatting_of_a_long_list_...): it
# formats on the loop lists up to LOOP_FORMAT_LINES // 10 lines, and brings a formatting up to date on the
# loop for edits up to LiveFormat.LOCAL_LINES // 10 lines. Every other test's lists are far shorter; the
# server of `plain_client` (and test_lsp_protocol's) is the plain `python -m achslint server`.
SCALE = 10
SCALED_SERVER = (
    "import sys\n"
    "import achslint.cli\n"
    "from achslint.fmt import LiveFormat\n"
    "from achslint.lsp import server\n"
    f"server.LOOP_FORMAT_LINES //= {SCALE}\n"
    f"LiveFormat.LOCAL_LINES //= {SCALE}\n"
    "sys.exit(achslint.cli.main(['server']))\n"
)


@pytest_lsp.fixture(
    scope="module", config=ClientServerConfig(server_command=[sys.executable, "-c", SCALED_SERVER])
)
async def client(lsp_client: LanguageClient):
    await lsp_client.initialize_session(
        lsp.InitializeParams(
            capabilities=client_capabilities("visual-studio-code"),
            initialization_options={"debounceMs": 20, "inlayHints": True},
        )
    )
    yield
    await lsp_client.shutdown_session()


@pytest.fixture(scope="module")
def folder(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("lsp")


# -- helpers ------------------------------------------------------------------------------------------


def open_doc(client: LanguageClient, path: Path, text: str | None = None, language: str = "achsmds") -> str:
    uri = path.resolve().as_uri()
    if text is None:
        text = path.read_bytes().decode("latin-1")
    client.diagnostics.pop(uri, None)
    client.text_document_did_open(lsp.DidOpenTextDocumentParams(lsp.TextDocumentItem(uri, language, 1, text)))
    return uri


def close_doc(client: LanguageClient, uri: str) -> None:
    client.text_document_did_close(lsp.DidCloseTextDocumentParams(lsp.TextDocumentIdentifier(uri)))


async def diagnostics_when(client: LanguageClient, uri: str, check=lambda found: True, timeout: float = 10.0):
    """The diagnostics last published for `uri`, once they satisfy `check`."""
    loop = asyncio.get_running_loop()
    deadline = loop.time() + timeout
    while loop.time() < deadline:
        found = client.diagnostics.get(uri)
        if found is not None and check(found):
            return list(found)
        await asyncio.sleep(0.02)
    raise AssertionError(f"no matching diagnostics for {uri}: {client.diagnostics.get(uri)}")


def codes(found) -> list[str]:
    return sorted(str(d.code) for d in found if d.code)


def change(client: LanguageClient, uri: str, version: int, text: str) -> None:
    client.diagnostics.pop(uri, None)
    client.text_document_did_change(
        lsp.DidChangeTextDocumentParams(
            lsp.VersionedTextDocumentIdentifier(version=version, uri=uri),
            [lsp.TextDocumentContentChangeWholeDocument(text)],
        )
    )


def offset(text: str, position: lsp.Position) -> int:
    lines = text.splitlines(keepends=True)
    return sum(len(line) for line in lines[: position.line]) + position.character


def apply_edits(text: str, edits: list[lsp.TextEdit]) -> str:
    """The text with the edits applied, as an editor applies them (last first; in time linear in the text:
    formatting a long list is thousands of edits)."""
    starts = [0]
    for line in text.splitlines(keepends=True):
        starts.append(starts[-1] + len(line))

    def at(position: lsp.Position) -> int:  # (as `offset`)
        return (starts[position.line] if position.line < len(starts) else len(text)) + position.character

    pieces, end = [], len(text)
    for edit in sorted(edits, key=lambda e: (e.range.start.line, e.range.start.character), reverse=True):
        start = at(edit.range.start)
        pieces += [text[at(edit.range.end) : end], edit.new_text]
        end = start
    return text[:end] + "".join(reversed(pieces))


async def hover_at(client, uri, line, character) -> str:
    found = await client.text_document_hover_async(
        lsp.HoverParams(lsp.TextDocumentIdentifier(uri), lsp.Position(line, character))
    )
    return found.contents.value if found is not None else ""


def position_of(text: str, needle: str, shift: int = 0) -> lsp.Position:
    index = text.index(needle) + shift
    before = text[:index]
    return lsp.Position(before.count("\n"), index - (before.rfind("\n") + 1))


# -- diagnostics ------------------------------------------------------------------------------------------


async def test_diagnostics_are_those_of_lint_with_rule_links(client: LanguageClient, folder: Path):
    path = folder / "lint" / "achsmds1.lis"
    path.parent.mkdir()
    shutil.copy(FIXTURES / "rules" / "LIS005" / "bad.lis", path)
    uri = open_doc(client, path)
    found = await diagnostics_when(client, uri)
    expected = lint(path)
    assert [(d.range.start.line + 1, d.range.start.character + 1, d.code, d.message) for d in found] == [
        (d.line, d.column, d.code, d.message) for d in expected
    ]
    duplicate = next(d for d in found if d.code == "LIS005")
    assert duplicate.severity == lsp.DiagnosticSeverity.Warning and duplicate.source == "achslint"
    assert duplicate.code_description.href.endswith("#lis005")
    assert duplicate.code_description.href.startswith("file://")
    related = duplicate.related_information[0]
    assert related.location.uri == uri and related.location.range.start.line == 4
    assert "first assignment" in related.message
    close_doc(client, uri)


async def test_edit_and_quick_fix_make_the_diagnostic_disappear(client: LanguageClient, folder: Path):
    path = folder / "fix" / "achsmds1.lis"
    path.parent.mkdir()
    text = (FIXTURES / "rules" / "LIS203" / "bad.lis").read_bytes().decode("latin-1")
    path.write_text(text, encoding="latin-1")
    uri = open_doc(client, path, text)
    found = await diagnostics_when(client, uri, lambda f: "LIS203" in codes(f))
    wrong = next(d for d in found if d.code == "LIS203")
    actions = await client.text_document_code_action_async(
        lsp.CodeActionParams(lsp.TextDocumentIdentifier(uri), wrong.range, lsp.CodeActionContext([wrong]))
    )
    fix = next(a for a in actions if a.title.startswith("LIS203"))
    assert "DRIVE_CONTROLLED" in fix.title and fix.kind == lsp.CodeActionKind.QuickFix
    # the fixture's axis is simulated (no antr_typ): the fix brings LIS305, so `achslint lint` calls it unsafe
    # and `--fix` refuses it; the editor offers it as unsafe too, not as the preferred fix
    assert fix.title.endswith("(unsafe fix: check the result)") and not fix.is_preferred
    assert any("noqa" in a.title for a in actions)
    fixed = apply_edits(text, fix.edit.changes[uri])
    assert "DRIVE_CONTROLLED" in fixed and "DRIVE_CONROLLED" not in fixed
    change(client, uri, 2, fixed)
    after = await diagnostics_when(client, uri)
    assert not [d for d in after if d.code == "LIS203" and d.range.start.line == wrong.range.start.line]
    # an edit that breaks the value again brings the finding back (debounced, after the last change)
    change(client, uri, 3, fixed.replace("DRIVE_CONTROLLED", "DRIVE_X"))
    again = await diagnostics_when(client, uri)
    assert [d for d in again if d.code == "LIS203" and d.range.start.line == wrong.range.start.line]
    close_doc(client, uri)


async def test_incremental_edits_are_applied_at_the_right_place(client: LanguageClient, folder: Path):
    path = folder / "incremental" / "achsmds1.lis"
    path.parent.mkdir()
    text = (
        "kopf.achs_nr  1\n\x0ckenngr.achs_typ  1\nkenngr.ref_richt  1\nEnde\n"  # a form feed is no line break
    )
    uri = open_doc(client, path, text)
    await diagnostics_when(client, uri)
    client.diagnostics.pop(uri, None)
    client.text_document_did_change(
        lsp.DidChangeTextDocumentParams(
            lsp.VersionedTextDocumentIdentifier(version=2, uri=uri),
            [lsp.TextDocumentContentChangePartial(lsp.Range(lsp.Position(2, 18), lsp.Position(2, 19)), "7")],
        )
    )
    found = await diagnostics_when(client, uri)
    # ref_richt 7 is not a boolean: the edit landed on line 3, after the line with the form feed
    assert [(d.code, d.range.start.line, d.range.start.character) for d in found] == [
        ("LIS001", 1, 0),
        ("LIS201", 2, 18),
    ]
    close_doc(client, uri)


async def test_noqa_and_fix_all_actions(client: LanguageClient, folder: Path):
    path = folder / "noqa" / "achsmds1.lis"
    path.parent.mkdir()
    text = (FIXTURES / "rules" / "LIS102" / "bad.lis").read_text(encoding="latin-1").replace("Ende", "End")
    uri = open_doc(client, path, text)
    found = await diagnostics_when(client, uri, lambda f: {"LIS004", "LIS102"} <= set(codes(f)))
    old = next(d for d in found if d.code == "LIS102")
    actions = await client.text_document_code_action_async(
        lsp.CodeActionParams(lsp.TextDocumentIdentifier(uri), old.range, lsp.CodeActionContext([old]))
    )
    noqa = next(a for a in actions if "noqa" in a.title)
    suppressed = apply_edits(text, noqa.edit.changes[uri])
    assert "noqa: LIS102" in suppressed
    change(client, uri, 2, suppressed)
    after = await diagnostics_when(client, uri)
    assert "LIS102" not in codes(after) and "LIS004" in codes(after)
    whole = lsp.Range(lsp.Position(0, 0), lsp.Position(0, 0))
    fix_all = await client.text_document_code_action_async(
        lsp.CodeActionParams(
            lsp.TextDocumentIdentifier(uri), whole, lsp.CodeActionContext([], only=["source.fixAll.achslint"])
        )
    )
    assert [a.kind for a in fix_all] == ["source.fixAll.achslint"]
    fixed = apply_edits(suppressed, fix_all[0].edit.changes[uri])
    assert fixed.splitlines()[-1] == "Ende"
    close_doc(client, uri)


async def test_config_of_the_files_folder_is_honoured(client: LanguageClient, folder: Path):
    bad = (FIXTURES / "rules" / "LIS203" / "bad.lis").read_bytes()
    plain, configured = folder / "plain", folder / "configured"
    plain.mkdir(), configured.mkdir()
    (configured / ".achslint.toml").write_text('ignore = ["LIS203"]\n', encoding="utf-8")
    (plain / "achsmds1.lis").write_bytes(bad)
    (configured / "achsmds1.lis").write_bytes(bad)
    first = open_doc(client, plain / "achsmds1.lis")
    second = open_doc(client, configured / "achsmds1.lis")
    assert "LIS203" in codes(await diagnostics_when(client, first))
    assert "LIS203" not in codes(await diagnostics_when(client, second))
    close_doc(client, first), close_doc(client, second)


async def test_editor_settings_with_a_code_that_picks_no_rule_are_told_not_used(client: LanguageClient):
    shown = client.wait_for_notification(lsp.WINDOW_SHOW_MESSAGE)
    client.workspace_did_change_configuration(
        lsp.DidChangeConfigurationParams({"achslint": {"debounceMs": 20, "ignore": ["LIS9999", "LIS203"]}})
    )
    message = await asyncio.wait_for(shown, 10)
    assert message.type == lsp.MessageType.Warning
    assert "achslint.ignore" in message.message and "LIS9999" in message.message
    client.workspace_did_change_configuration(
        lsp.DidChangeConfigurationParams({"achslint": {"debounceMs": 20, "inlayHints": True}})
    )


async def test_machine_rule_uses_open_buffers_and_files(client: LanguageClient, folder: Path):
    machine = folder / "machine"
    machine.mkdir()
    (machine / ".achslint.toml").write_text('[[machine]]\nlists = ["*.lis"]\n', encoding="utf-8")
    one = "kopf.achs_nr  1\nkopf.log_achs_name  X\nEnde\n"
    (machine / "achsmds1.lis").write_text(one, encoding="latin-1")
    (machine / "achsmds2.lis").write_text(
        "kopf.achs_nr  2\nkopf.log_achs_name  Y\nEnde\n", encoding="latin-1"
    )
    uri = open_doc(client, machine / "achsmds2.lis", "kopf.achs_nr  1\nkopf.log_achs_name  Y\nEnde\n")
    found = await diagnostics_when(client, uri, lambda f: "LIS501" in codes(f))
    duplicate = next(d for d in found if d.code == "LIS501")
    assert duplicate.range.start.line == 0
    assert duplicate.related_information[0].location.uri == (machine / "achsmds1.lis").resolve().as_uri()
    change(
        client, uri, 2, "kopf.achs_nr  3\nkopf.log_achs_name  Y\nEnde\n"
    )  # the buffer, not the file, counts
    assert "LIS501" not in codes(await diagnostics_when(client, uri))
    # both open: editing the first list updates the findings shown for the second
    first = open_doc(client, machine / "achsmds1.lis", one.replace("achs_nr  1", "achs_nr  3"))
    assert "LIS501" in codes(await diagnostics_when(client, uri, lambda f: "LIS501" in codes(f)))
    change(client, first, 2, one)
    assert "LIS501" not in codes(await diagnostics_when(client, uri, lambda f: "LIS501" not in codes(f)))
    close_doc(client, first), close_doc(client, uri)


# -- hover, completion ---------------------------------------------------------------------------------------


async def test_hover_parameter_with_effect(client: LanguageClient, folder: Path):
    path = folder / "hover" / "achsmds1.lis"
    path.parent.mkdir()
    shutil.copy(FIXTURES / "lists" / "achsmds1.lis", path)
    text = path.read_bytes().decode("latin-1")
    uri = open_doc(client, path, text)
    where = position_of(text, "getriebe[0].vb_refmax", 3)
    card = await hover_at(client, uri, where.line, where.character)
    assert "P-AXIS-00219" in card and "getriebe[i].vb_refmax" in card
    assert "100000 µm/s (= 100 mm/s = 6 m/min)" in card
    assert f"line {where.line + 1}" in card
    assert "takes effect under" in card
    value = position_of(text, "100000        ( P-AXIS-00219", 2)
    assert "= 100 mm/s" in await hover_at(client, uri, value.line, value.character)
    reference = position_of(text, "P-AXIS-00212.0", 3)
    assert "getriebe[0].dynamik.vb_max" in await hover_at(client, uri, reference.line, reference.character)
    end = position_of(text, "\nEnde", 2)
    assert "end marker" in await hover_at(client, uri, end.line, end.character)
    definition = await client.text_document_definition_async(
        lsp.DefinitionParams(lsp.TextDocumentIdentifier(uri), reference)
    )
    assert (
        definition[0].uri == uri
        and definition[0].range.start.line == position_of(text, "getriebe[0].dynamik.vb_max").line
    )
    close_doc(client, uri)


async def test_hover_parameter_without_effect_and_noqa_code(client: LanguageClient, folder: Path):
    path = folder / "hover2" / "achsmds1.lis"
    path.parent.mkdir()
    text = (FIXTURES / "rules" / "LIS401" / "bad.lis").read_text(encoding="latin-1")
    text = text.replace(
        "kenngr.fast_from_cam                            0",
        "kenngr.fast_from_cam                            0  # noqa: LIS401",
    )
    uri = open_doc(client, path, text)
    where = position_of(text, "getriebe[0].vb_refmax", 2)
    card = await hover_at(client, uri, where.line, where.character)
    assert "has no effect under" in card and "200000 µm/s" in card
    code = position_of(text, "noqa: LIS401", 8)
    assert "LIS401 parameter-without-effect" in await hover_at(client, uri, code.line, code.character)
    close_doc(client, uri)


async def test_completion_paths_symbols_references_and_codes(client: LanguageClient, folder: Path):
    path = folder / "complete" / "achsmds1.lis"
    path.parent.mkdir()
    text = "kenngr.antr_typ  1\nkenngr.achs_typ  1\ngetriebe[2].vb_re\nkenngr.homing.homing_type  C\nEnde\n"
    uri = open_doc(client, path, text)

    async def items(line, character):
        found = await client.text_document_completion_async(
            lsp.CompletionParams(lsp.TextDocumentIdentifier(uri), lsp.Position(line, character))
        )
        return found.items if isinstance(found, lsp.CompletionList) else found

    paths = await items(2, len("getriebe[2].vb_re"))
    labels = {i.label for i in paths}
    assert "getriebe[2].vb_reflow" in labels and "getriebe[2].vb_refmax" in labels
    assert all(label.startswith("getriebe[2].") for label in labels)
    resolved = await client.completion_item_resolve_async(
        next(i for i in paths if i.label == "getriebe[2].vb_reflow")
    )
    assert "P-AXIS-00218" in resolved.documentation.value
    top = {i.label for i in await items(2, 0)}
    assert "kenngr.homing.homing_type" in top
    assert not any(label.startswith("antr.sercos.") for label in top)  # a conventional drive: no SERCOS group
    symbols = {i.label for i in await items(3, len("kenngr.homing.homing_type  "))}
    assert {"CNC_CONTROLLED", "DRIVE_CONTROLLED", "TORQ"} <= symbols
    typed = {i.label for i in await items(3, len("kenngr.homing.homing_type  C"))}
    assert "CNC_CONTROLLED" in typed and "TORQ" not in typed  # what the typed `C` leads to
    change(
        client,
        uri,
        2,
        text.replace("vb_re\n", "vb_reflow  P-AXIS-002\n").replace("  C\n", "  TORQ  ( noqa: LIS3\n"),
    )
    await diagnostics_when(client, uri)
    references = {i.label for i in await items(2, len("getriebe[2].vb_reflow  P-AXIS-002"))}
    assert "P-AXIS-00219.0" in references
    rule_codes = {i.label for i in await items(3, len("kenngr.homing.homing_type  TORQ  ( noqa: LIS3"))}
    assert "LIS301" in rule_codes and all(code.startswith("LIS3") for code in rule_codes)
    close_doc(client, uri)


async def test_hover_and_completion_in_lists_of_other_kinds(client: LanguageClient, folder: Path):
    """A channel list and a start-up list get their own kind's cards and paths (issue 25 item 4)."""
    listen = folder / "kinds" / "listen"
    shutil.copytree(FIXTURES / "kinds", listen)
    channel = (listen / "sda_mds1.lis").read_bytes().decode("latin-1")
    uri = open_doc(client, listen / "sda_mds1.lis", channel)
    await diagnostics_when(client, uri)
    where = position_of(channel, "spindel[0].log_achs_nr", 2)
    assert "P-CHAN-00036" in await hover_at(client, uri, where.line, where.character)
    close_doc(client, uri)
    startup = (listen / "hochlauf.lis").read_bytes().decode("latin-1").replace("\nEnde", "   \nEnde")
    uri = open_doc(client, listen / "hochlauf.lis", startup)
    await diagnostics_when(client, uri)
    where = position_of(startup, "kanal_anzahl", 2)
    assert "P-STUP-" in await hover_at(client, uri, where.line, where.character)
    found = await client.text_document_completion_async(
        lsp.CompletionParams(lsp.TextDocumentIdentifier(uri), lsp.Position(where.line, 0))
    )
    items = found.items if isinstance(found, lsp.CompletionList) else found
    assert "zahl_mds" in {i.label for i in items} and not any(i.label.startswith("kenngr.") for i in items)
    formatted = await client.text_document_formatting_async(
        lsp.DocumentFormattingParams(lsp.TextDocumentIdentifier(uri), lsp.FormattingOptions(4, True))
    )
    # formatted like a list of any kind: the trailing blanks go, nothing else changes
    assert apply_edits(startup, list(formatted)) == startup.replace("   \nEnde", "\nEnde")
    close_doc(client, uri)


# -- formatting, outline, definitions, inlay hints ---------------------------------------------------------


async def test_formatting_gives_fmt_output(client: LanguageClient, folder: Path):
    path = folder / "fmt" / "achsmds1.lis"
    path.parent.mkdir()
    data = (FIXTURES / "lsp" / "unaligned.lis").read_bytes()
    text = data.decode("latin-1")
    uri = open_doc(client, path, text)
    edits = await client.text_document_formatting_async(
        lsp.DocumentFormattingParams(lsp.TextDocumentIdentifier(uri), lsp.FormattingOptions(4, True))
    )
    assert edits
    assert apply_edits(text, edits) == format_bytes(data)[0].decode("latin-1")
    ranged = await client.text_document_range_formatting_async(
        lsp.DocumentRangeFormattingParams(
            lsp.TextDocumentIdentifier(uri),
            lsp.Range(lsp.Position(1, 0), lsp.Position(1, 5)),
            lsp.FormattingOptions(4, True),
        )
    )
    assert [e.range.start.line for e in ranged] == [1]
    close_doc(client, uri)


async def test_formatting_after_each_edit_gives_fmt_output(client: LanguageClient, folder: Path):
    """The server keeps a list's formatting and brings it up to date with the edits since the last request
    (`fmt.LiveFormat`): after every edit, the edits it answers turn the text into fmt's."""
    path = folder / "fmt-edits" / "achsmds1.lis"
    path.parent.mkdir()
    text = (FIXTURES / "lsp" / "unaligned.lis").read_bytes().decode("latin-1")
    uri = open_doc(client, path, text)
    rng = random.Random(28)
    for version in range(2, 14):
        lines = text.splitlines(keepends=True)
        line = rng.randrange(len(lines))
        if version % 3:  # a character typed into a line
            character = rng.randrange(len(lines[line].rstrip("\r\n")) + 1)
            where = lsp.Range(lsp.Position(line, character), lsp.Position(line, character))
            typed = rng.choice([" ", "\t", "7", "  "])
        else:  # a line inserted
            where = lsp.Range(lsp.Position(line, 0), lsp.Position(line, 0))
            typed = rng.choice(["kopf.achs_nr 3\n", "  getriebe[0].vb_reflow\t\t900  ( comment\n", "\n"])
        client.text_document_did_change(
            lsp.DidChangeTextDocumentParams(
                lsp.VersionedTextDocumentIdentifier(version=version, uri=uri),
                [lsp.TextDocumentContentChangePartial(range=where, text=typed)],
            )
        )
        text = apply_edits(text, [lsp.TextEdit(where, typed)])
        edits = await client.text_document_formatting_async(
            lsp.DocumentFormattingParams(lsp.TextDocumentIdentifier(uri), lsp.FormattingOptions(4, True))
        )
        expected = format_bytes(text.encode("latin-1"))[0].decode("latin-1")
        assert apply_edits(text, edits) == expected, version
    close_doc(client, uri)


async def test_formatting_of_a_long_list_is_kept_up_to_date(client: LanguageClient, folder: Path):
    """A list longer than the server formats on the loop from scratch: its formatting is made on the worker
    after its first diagnostics (a request meanwhile waits for it), then brought up to date on the loop; an
    edit of more lines than the loop takes is formatted on the worker. Every answer turns the text into
    fmt's. (The server's limits are a tenth of a real one's, see SCALED_SERVER: the lines below are a
    tenth too.)"""
    assert LOOP_FORMAT_LINES // SCALE == 1000 and LiveFormat.LOCAL_LINES // SCALE == 200
    path = folder / "fmt-long" / "achsmds1.lis"
    path.parent.mkdir()
    body = [
        "kopf.achs_nr 1   ( logical axis number   \n",
        "kenngr.achs_typ        1\n",
        "getriebe[0].vb_reflow 20000   ( reference speed\n",
        "kopf.log_achs_name\tX\n",
    ]
    text = "".join(body * 350) + "Ende\n"  # 1,401 lines
    uri = open_doc(client, path, text)
    await diagnostics_when(client, uri)

    async def formatted() -> str:
        edits = await client.text_document_formatting_async(
            lsp.DocumentFormattingParams(lsp.TextDocumentIdentifier(uri), lsp.FormattingOptions(4, True))
        )
        return apply_edits(text, edits)

    edits = [
        (lsp.Range(lsp.Position(1, 0), lsp.Position(1, 0)), "  "),  # an indent
        (lsp.Range(lsp.Position(500, 0), lsp.Position(500, 0)), "kopf.achs_nr\t\t7\n"),  # a line
        (lsp.Range(lsp.Position(2, 0), lsp.Position(350, 0)), ""),  # a quarter of the lines gone
    ]
    for version, (where, typed) in enumerate(edits, 2):
        client.text_document_did_change(
            lsp.DidChangeTextDocumentParams(
                lsp.VersionedTextDocumentIdentifier(version=version, uri=uri),
                [lsp.TextDocumentContentChangePartial(range=where, text=typed)],
            )
        )
        text = apply_edits(text, [lsp.TextEdit(where, typed)])
        assert await formatted() == format_bytes(text.encode("latin-1"))[0].decode("latin-1"), version
    close_doc(client, uri)


async def test_document_symbols_are_grouped(client: LanguageClient, folder: Path):
    path = folder / "outline" / "achsmds1.lis"
    path.parent.mkdir()
    shutil.copy(FIXTURES / "lists" / "achsmds1.lis", path)
    uri = open_doc(client, path)
    symbols = await client.text_document_document_symbol_async(
        lsp.DocumentSymbolParams(lsp.TextDocumentIdentifier(uri))
    )
    names = [s.name for s in symbols]
    assert names[:3] == ["kopf", "kenngr", "lr_hw[0]"] and "getriebe[0]" in names and names[-1] == "Ende"
    gear = next(s for s in symbols if s.name == "getriebe[0]")
    assert "vb_reflow" in [c.name for c in gear.children]
    hints = await client.text_document_inlay_hint_async(
        lsp.InlayHintParams(
            lsp.TextDocumentIdentifier(uri), lsp.Range(lsp.Position(0, 0), lsp.Position(40, 0))
        )
    )
    assert any(h.label == " = 100 mm/s = 6 m/min" for h in hints)
    close_doc(client, uri)


async def test_the_outline_follows_each_edit(client: LanguageClient, folder: Path):
    """Once asked for, the outline is made with each analysis (on the worker): after an edit it is the
    outline of the new text."""
    path = folder / "outline-edits" / "achsmds1.lis"
    path.parent.mkdir()
    text = "kopf.achs_nr 1\ngetriebe[0].vb_reflow 100\nEnde\n"
    uri = open_doc(client, path, text)
    await diagnostics_when(client, uri)

    async def outline() -> list[str]:
        symbols = await client.text_document_document_symbol_async(
            lsp.DocumentSymbolParams(lsp.TextDocumentIdentifier(uri))
        )
        return [f"{s.name}.{c.name}" for s in symbols for c in s.children or []]

    assert await outline() == ["kopf.achs_nr", "getriebe[0].vb_reflow"]
    for version, edited in enumerate(
        [text.replace("getriebe[0]", "getriebe[1]"), "kopf.achs_nr 1\nkopf.log_achs_name X\nEnde\n"], 2
    ):
        change(client, uri, version, edited)
        await diagnostics_when(client, uri)
        expected = [
            f"{line.split('.', 1)[0]}.{line.split('.', 1)[1].split()[0]}" for line in edited.splitlines()[:2]
        ]
        assert await outline() == expected
    close_doc(client, uri)


async def test_definition_from_a_startup_list_opens_the_named_list(client: LanguageClient, folder: Path):
    machine = folder / "startup"
    machine.mkdir()
    shutil.copy(FIXTURES / "lsp" / "hochlauf.lis", machine / "hochlauf.lis")
    shutil.copy(FIXTURES / "lists" / "achsmds1.lis", machine / "achsmds1.lis")
    text = (machine / "hochlauf.lis").read_text(encoding="latin-1")
    uri = open_doc(client, machine / "hochlauf.lis", text)
    found = await diagnostics_when(client, uri, lambda f: "LIS504" in codes(f))  # achsmds2.lis is missing
    assert [d.range.start.line for d in found if d.code == "LIS504"] == [3]
    where = position_of(text, "./achsmds1.lis", 3)
    target = await client.text_document_definition_async(
        lsp.DefinitionParams(lsp.TextDocumentIdentifier(uri), where)
    )
    assert target[0].uri == (machine / "achsmds1.lis").resolve().as_uri()
    # An entry of any list, in a buffer whose lines are not those on disk: the entry of its key and value.
    (machine / "sda_mds1.lis").write_text("grp_anzahl 1\nEnde\n", encoding="latin-1")
    entry = "sda_mds[0]  ./sda_mds1.lis\nEnde\n"
    (machine / "hochlauf.lis").write_text(text.replace("Ende\n", entry), encoding="latin-1")
    edited = "# a line the file on disk does not have\n" + text.replace("Ende\n", entry)
    change(client, uri, 2, edited)
    for needle, name in (("./achsmds1.lis", "achsmds1.lis"), ("./sda_mds1.lis", "sda_mds1.lis")):
        where = position_of(edited, needle, 3)
        target = await client.text_document_definition_async(
            lsp.DefinitionParams(lsp.TextDocumentIdentifier(uri), where)
        )
        assert [t.uri for t in target] == [(machine / name).resolve().as_uri()]
    close_doc(client, uri)


# -- XML, robustness ------------------------------------------------------------------------------------------


async def test_twincat_xml_diagnostics_and_hover_at_xml_positions(client: LanguageClient, folder: Path):
    path = folder / "xml" / "Axis_X.xti"
    path.parent.mkdir()
    shutil.copy(FIXTURES / "lsp" / "axis.xml", path)
    text = path.read_text(encoding="utf-8")
    uri = open_doc(client, path, text, language="xml")
    found = await diagnostics_when(client, uri, lambda f: "LIS203" in codes(f))
    wrong = next(d for d in found if d.code == "LIS203")
    expected = position_of(text, "DRIVE_CONROLLED")
    assert (wrong.range.start.line, wrong.range.start.character) == (expected.line, expected.character)
    where = position_of(text, "getriebe[0].vb_reflow", 4)
    card = await hover_at(client, uri, where.line, where.character)
    assert "P-AXIS-00218" in card and "20 mm/s" in card
    first = position_of(text, "kopf.achs_nr", 2)  # the first list line shares the XML line of <AchsMds>
    assert "P-AXIS-00016" in await hover_at(client, uri, first.line, first.character)
    close_doc(client, uri)


async def test_random_bytes_give_diagnostics_never_a_crash(client: LanguageClient, folder: Path):
    generator = random.Random(15)
    samples = [bytes(generator.randrange(256) for _ in range(2000)).decode("latin-1") for _ in range(3)]
    samples += [
        "\x00\ufeff" * 50 + "Ende\r\r\n\u2028x",
        "getriebe[" * 500 + "\n" * 3,
        "\ufeffkopf.achs_nr 1\nEnd",
    ]
    (folder / "random").mkdir()
    for number, text in enumerate(samples):
        uri = open_doc(client, folder / "random" / f"achsmds{number}.lis", text)
        found = await diagnostics_when(client, uri)
        assert found, f"sample {number}"
        lines = text.count("\n") + text.count("\r") + 1  # an upper bound of the LSP lines
        for line in (0, 1, 5):
            where = lsp.Position(line, 3)
            hover = await client.text_document_hover_async(
                lsp.HoverParams(lsp.TextDocumentIdentifier(uri), where)
            )
            assert hover is None or hover.contents.value  # a card with words, or nothing
            offered = await client.text_document_completion_async(
                lsp.CompletionParams(lsp.TextDocumentIdentifier(uri), where)
            )
            assert offered is None or all(item.label for item in offered.items)
        edits = await client.text_document_formatting_async(
            lsp.DocumentFormattingParams(lsp.TextDocumentIdentifier(uri), lsp.FormattingOptions(4, True))
        )
        assert all(0 <= e.range.start.line <= e.range.end.line <= lines for e in edits or [])
        symbols = await client.text_document_document_symbol_async(
            lsp.DocumentSymbolParams(lsp.TextDocumentIdentifier(uri))
        )
        assert all(symbol.name for symbol in symbols or [])
        actions = await client.text_document_code_action_async(
            lsp.CodeActionParams(
                lsp.TextDocumentIdentifier(uri),
                lsp.Range(lsp.Position(0, 0), lsp.Position(3, 0)),
                lsp.CodeActionContext([]),
            )
        )
        assert all(action.title for action in actions or [])
        close_doc(client, uri)
    # still alive and still right
    uri = open_doc(client, folder / "random" / "achsmds_ok.lis", "kopf.achs_nr  1\nEnd\n")
    assert "LIS004" in codes(await diagnostics_when(client, uri))
    close_doc(client, uri)


# -- a plain client: plain-text hovers, no snippets, UTF-8 positions, no inlay hints --------------------------
# Its own server: requests for documents it does not know or cannot offer anything for; saves, watched files
# and settings that change what is published.

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
async def plain_client(
    lsp_client: LanguageClient, tmp_path_factory: pytest.TempPathFactory
) -> AsyncIterator[None]:
    root = tmp_path_factory.mktemp("plain")
    await lsp_client.initialize_session(
        lsp.InitializeParams(
            capabilities=PLAIN_CLIENT, root_uri=root.as_uri(), initialization_options={"debounceMs": 0}
        )
    )
    yield
    await lsp_client.shutdown_session()


def document(uri: str) -> lsp.TextDocumentIdentifier:
    return lsp.TextDocumentIdentifier(uri)


ALL = lsp.Range(lsp.Position(0, 0), lsp.Position(20, 0))
FORMAT = lsp.FormattingOptions(4, True)


async def test_plain_text_hover_utf8_positions_and_an_edit_range_default(
    plain_client: LanguageClient, tmp_path: Path
) -> None:
    uri = open_doc(plain_client, tmp_path / "achsmds1.lis", "kenngr.ref_richt  µ\nkenngr.achs_typ  1\nEnde\n")
    [wrong] = await diagnostics_when(plain_client, uri, lambda f: bool(f))
    assert wrong.code == "LIS201"
    # the value starts at code point 18; `µ` is one code point but two UTF-8 bytes
    assert (wrong.range.start.character, wrong.range.end.character) == (18, 20)
    hover = await plain_client.text_document_hover_async(lsp.HoverParams(document(uri), lsp.Position(1, 3)))
    assert hover.contents.kind == lsp.MarkupKind.PlainText
    assert (
        hover.contents.value.startswith("P-AXIS-00018 kenngr.achs_typ\n") and "**" not in hover.contents.value
    )
    found = await plain_client.text_document_completion_async(
        lsp.CompletionParams(document(uri), lsp.Position(1, len("kenngr.achs")))
    )
    assert found.item_defaults.edit_range == lsp.Range(lsp.Position(1, 0), lsp.Position(1, 11))
    assert all(i.text_edit is None for i in found.items)
    assert all(i.insert_text_format != lsp.InsertTextFormat.Snippet for i in found.items)  # not supported
    hints = await plain_client.text_document_inlay_hint_async(lsp.InlayHintParams(document(uri), ALL))
    assert list(hints) == []  # inlay hints are off unless the editor turns them on
    close_doc(plain_client, uri)


async def test_requests_for_documents_the_server_does_not_know(
    plain_client: LanguageClient, tmp_path: Path
) -> None:
    uri = (tmp_path / "never-opened.lis").as_uri()
    where = lsp.Position(0, 0)
    change(plain_client, uri, 2, "kopf.achs_nr  1\n")  # ignored: not open
    assert await plain_client.text_document_hover_async(lsp.HoverParams(document(uri), where)) is None
    assert (
        await plain_client.text_document_completion_async(lsp.CompletionParams(document(uri), where)) is None
    )
    actions = lsp.CodeActionParams(document(uri), ALL, lsp.CodeActionContext([]))
    assert list(await plain_client.text_document_code_action_async(actions)) == []
    assert (
        list(
            await plain_client.text_document_formatting_async(
                lsp.DocumentFormattingParams(document(uri), FORMAT)
            )
        )
        == []
    )
    assert (
        list(await plain_client.text_document_definition_async(lsp.DefinitionParams(document(uri), where)))
        == []
    )
    assert (
        list(await plain_client.text_document_inlay_hint_async(lsp.InlayHintParams(document(uri), ALL))) == []
    )
    assert uri not in plain_client.diagnostics


async def test_xml_documents_offer_diagnostics_and_hovers_only(
    plain_client: LanguageClient, tmp_path: Path
) -> None:
    uri = open_doc(plain_client, tmp_path / "Axis_X.xti", XML, language="xml")
    assert await diagnostics_when(plain_client, uri) == []
    hover = await plain_client.text_document_hover_async(lsp.HoverParams(document(uri), lsp.Position(3, 3)))
    assert hover.contents.value.startswith("P-AXIS-00158 kenngr.ref_richt")
    outside = await plain_client.text_document_hover_async(lsp.HoverParams(document(uri), lsp.Position(1, 3)))
    assert outside is None  # <TcSmItem>: not a line of the list
    where = lsp.Position(3, 3)
    assert (
        await plain_client.text_document_completion_async(lsp.CompletionParams(document(uri), where)) is None
    )
    assert (
        list(
            await plain_client.text_document_formatting_async(
                lsp.DocumentFormattingParams(document(uri), FORMAT)
            )
        )
        == []
    )
    assert (
        list(await plain_client.text_document_document_symbol_async(lsp.DocumentSymbolParams(document(uri))))
        == []
    )
    assert (
        list(await plain_client.text_document_definition_async(lsp.DefinitionParams(document(uri), where)))
        == []
    )
    # an edit that breaks the XML: one error, and nothing to hover
    change(plain_client, uri, 2, XML.replace("]]>", ""))
    [broken] = await diagnostics_when(plain_client, uri, lambda f: bool(f))
    assert "not well-formed XML" in broken.message and broken.severity == lsp.DiagnosticSeverity.Error
    assert await plain_client.text_document_hover_async(lsp.HoverParams(document(uri), where)) is None
    close_doc(plain_client, uri)


async def test_saving_a_configuration_or_a_change_on_disk_republishes(
    plain_client: LanguageClient, tmp_path: Path
) -> None:
    path = tmp_path / "achsmds1.lis"
    text = "kopf.achs_nr  1\nkenngr.ref_richt  7\nEnd\n"
    path.write_text(text, encoding="latin-1")
    uri = open_doc(plain_client, path, text)
    assert codes(await diagnostics_when(plain_client, uri)) == ["LIS004", "LIS201"]
    config = tmp_path / ".achslint.toml"
    config.write_text('ignore = ["LIS201"]\n', encoding="utf-8")
    plain_client.diagnostics.pop(uri)
    plain_client.text_document_did_save(lsp.DidSaveTextDocumentParams(document(config.as_uri())))
    assert codes(await diagnostics_when(plain_client, uri)) == ["LIS004"]
    config.write_text('ignore = ["LIS004"]\n', encoding="utf-8")
    plain_client.diagnostics.pop(uri)
    plain_client.workspace_did_change_watched_files(
        lsp.DidChangeWatchedFilesParams([lsp.FileEvent(config.as_uri(), lsp.FileChangeType.Changed)])
    )
    assert codes(await diagnostics_when(plain_client, uri)) == ["LIS201"]
    config.unlink()
    plain_client.diagnostics.pop(uri)
    plain_client.workspace_did_change_configuration(lsp.DidChangeConfigurationParams(settings=None))
    assert codes(await diagnostics_when(plain_client, uri)) == ["LIS004", "LIS201"]
    # saving a list that is not open changes nothing; saving the open list checks it at once
    plain_client.text_document_did_save(
        lsp.DidSaveTextDocumentParams(document((tmp_path / "other.lis").as_uri()))
    )
    plain_client.diagnostics.pop(uri)
    plain_client.text_document_did_save(lsp.DidSaveTextDocumentParams(document(uri)))
    assert codes(await diagnostics_when(plain_client, uri)) == ["LIS004", "LIS201"]
    close_doc(plain_client, uri)


async def test_after_quick_edits_the_last_text_counts(plain_client: LanguageClient, tmp_path: Path) -> None:
    plain_client.workspace_did_change_configuration(
        lsp.DidChangeConfigurationParams({"debounceMs": 50, "inlayHints": True})
    )
    try:
        uri = open_doc(plain_client, tmp_path / "achsmds1.lis", "kopf.achs_nr  1\nEnde\n")
        assert await diagnostics_when(plain_client, uri) == []
        plain_client.diagnostics.pop(uri)
        change(plain_client, uri, 2, "kopf.achs_nr  1\nEnd\n")
        change(plain_client, uri, 3, "kopf.achs_nr  1\nkopf.achs_nr  2\nEnde\n")
        assert codes(await diagnostics_when(plain_client, uri)) == ["LIS005"]
        # closing a list with a check still pending clears its diagnostics for good
        change(plain_client, uri, 4, "kopf.achs_nr  1\nEnd\n")
        close_doc(plain_client, uri)
        assert await diagnostics_when(plain_client, uri, lambda f: not f) == []
        untitled = "untitled:Untitled-1"
        plain_client.text_document_did_open(
            lsp.DidOpenTextDocumentParams(
                lsp.TextDocumentItem(untitled, "achsmds", 1, "kopf.achs_nr 1\nEnd\n")
            )
        )
        assert codes(await diagnostics_when(plain_client, untitled)) == ["LIS004"]
        close_doc(plain_client, untitled)
        assert await diagnostics_when(plain_client, untitled, lambda f: not f) == []
        hints = await plain_client.text_document_inlay_hint_async(
            lsp.InlayHintParams(document(untitled), ALL)
        )
        assert list(hints) == []  # closed: nothing to show
    finally:
        plain_client.workspace_did_change_configuration(lsp.DidChangeConfigurationParams({"debounceMs": 0}))
