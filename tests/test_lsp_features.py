"""The language server's answers, computed in this process without a client: what the session makes of a
document (its findings, its configuration, its machine: start-up lists, default lists, neighbours on disk
or in open buffers) and what the features answer for it (hover, rule documentation links, code actions,
completion, formatting, definitions, inlay hints). test_lsp.py runs the server end to end."""

from __future__ import annotations

import os
import shutil
from collections.abc import Iterator
from pathlib import Path

import pytest

pytest.importorskip("lsprotocol", reason="the lsp extra is not installed")

from lsprotocol import types as lsp

from achslint.api import lint
from achslint.core.decode import UnreadableInput
from achslint.core.diagnostics import Diagnostic, Severity
from achslint.docs import rules_markdown
from achslint.fmt import LiveFormat, format_text
from achslint.lsp import features
from achslint.lsp.documents import Document
from achslint.lsp.session import ClientSettings, Session, Snapshot, xml_bytes
from achslint.machine.startup import StartupEntry

from .conftest import FIXTURES, one_machine

EVERYWHERE = lsp.Range(lsp.Position(0, 0), lsp.Position(99, 0))


def opened(session: Session, path: Path, text: str | None = None) -> Document:
    """Open `path` in the session with `text` (else the file's content), as the editor would."""
    path.parent.mkdir(parents=True, exist_ok=True)
    if text is None:
        text = path.read_bytes().decode("latin-1")
    document = Document(path.as_uri(), path, text, 1)
    session.open(document)
    return document


def codes(found: list[Diagnostic]) -> list[str]:
    return sorted(d.code for d in found)


def snapshot_of(session: Session, document: Document) -> Snapshot:
    snapshot = session.snapshot(document.uri)
    assert snapshot is not None
    return snapshot


def apply(text: str, edits: list[lsp.TextEdit]) -> str:
    """The text after the edits (positions in code points: the tests use ASCII lines)."""
    lines = text.splitlines(keepends=True)

    def offset(position: lsp.Position) -> int:
        return sum(len(line) for line in lines[: position.line]) + position.character

    for edit in sorted(edits, key=lambda e: (e.range.start.line, e.range.start.character), reverse=True):
        text = text[: offset(edit.range.start)] + edit.new_text + text[offset(edit.range.end) :]
    return text


@pytest.fixture
def session(tmp_path: Path) -> Session:
    return Session(tmp_path)


# -- hover ----------------------------------------------------------------------------------------------

HOVER_LIST = (
    "kenngr.antr_typ 1\n"
    "  kenngr.ref_richt 1  # noqa: LIS202\n"
    "kopf.log_achs_name  X  ( the axis name\n"
    "kenngr.homing.homing_type  CNC_CONTROLLED\n"
    "# noqa: LIS202, LIS999 LIS201\n"
    "getriebe[0].vb_refmax  P-AXIS-00218.0\n"
    "Ende\n"
    "kenngr.ref_richt 1\n"
)


def test_hover_on_values_comments_and_codes_in_plain_text(session: Session, tmp_path: Path) -> None:
    document = opened(session, tmp_path / "achsmds1.lis", HOVER_LIST)
    snapshot = snapshot_of(session, document)

    def hover(line: int, column: int) -> str | None:
        return features.hover_text(snapshot.context, snapshot.file, line, column, markdown=False)

    assert hover(2, 20) == "1 (on)"  # a boolean value
    assert hover(4, 30) == (
        "CNC_CONTROLLED (one of DRIVE_DEFAULT, NONE, TORQ, CNC_CONTROLLED, DRIVE_CONTROLLED, DISABLED, "
        "IGNORE_ABS_POS)"
    )
    reference = hover(6, 30)
    assert reference is not None
    assert reference.startswith("P-AXIS-00218.0 → getriebe[0].vb_reflow (")
    assert "from: the built-in default" in reference
    rule = hover(5, 25)  # on LIS201 of a comment line
    assert rule is not None and rule.startswith("LIS201 wrong-type (error; fix: ")
    assert "**" not in rule and "[Documentation]" not in rule  # plain text: no markdown, no link
    assert hover(5, 10).startswith("LIS202 out-of-range")
    # nothing to say: indentation, a text value, an unknown code, a word of a comment, a line after `Ende`
    # (not read by the CNC), a column past the value, a line that does not exist
    assert hover(2, 1) is None
    assert hover(3, 22) is None
    assert hover(5, 17) is None
    assert hover(5, 3) is None
    assert hover(8, 18) is None
    assert hover(1, 30) is None
    assert hover(20, 1) is None


def test_hover_on_a_parameter_shows_the_value_the_cnc_corrects(session: Session, tmp_path: Path) -> None:
    text = "kenngr.antr_typ 1\nkenngr.homing_type  DRIVE_CONTROLLED\nkenngr.ref_richt 1\nEnde\n"
    document = opened(session, tmp_path / "achsmds1.lis", text)
    snapshot = snapshot_of(session, document)
    card = features.hover_text(snapshot.context, snapshot.file, 2, 3, markdown=True)
    assert card is not None
    assert card.startswith("**P-AXIS-00299** `kenngr.homing.homing_type`\n\n(written with the old name")
    assert "**In this list** (`kenngr.homing.homing_type`):" in card
    assert "- CNC correction P-ERR-110384: written DRIVE_CONTROLLED, the CNC uses CNC_CONTROLLED" in card
    value = features.hover_text(snapshot.context, snapshot.file, 2, 22, markdown=True)
    assert value is not None and value.startswith("DRIVE_CONTROLLED (one of ")
    assert value.endswith(")") and "\n\nthe CNC uses CNC_CONTROLLED instead (P-ERR-110384: " in value
    boolean = features.hover_text(snapshot.context, snapshot.file, 3, 3, markdown=True)
    assert boolean is not None and "- value: 1\n" in boolean


# -- rule documentation links ------------------------------------------------------------------------------


@pytest.fixture
def outside_a_checkout(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> Iterator[Path]:
    """The server runs from an installed package: no docs/rules.md three folders above the module."""
    monkeypatch.setattr(features, "__file__", str(tmp_path / "site" / "achslint" / "lsp" / "features.py"))
    features.rules_document.cache_clear()
    yield tmp_path
    features.rules_document.cache_clear()


def test_rule_links_point_to_a_generated_copy_outside_a_checkout(
    outside_a_checkout: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    cache = outside_a_checkout / "cache"
    monkeypatch.setenv("XDG_CACHE_HOME", str(cache))
    uri = features.rules_document()
    assert uri is not None and uri.startswith(cache.as_uri() + "/achslint/rules-")
    written = next((cache / "achslint").iterdir())
    assert written.read_text(encoding="utf-8") == rules_markdown()
    # a stale copy (another version's text) is written again
    written.write_text("old text", encoding="utf-8")
    features.rules_document.cache_clear()
    assert features.rules_document() == uri
    assert written.read_text(encoding="utf-8") == rules_markdown()
    stamp = written.stat().st_mtime_ns
    os.utime(written, ns=(stamp - 10**9, stamp - 10**9))
    features.rules_document.cache_clear()
    assert features.rules_document() == uri
    assert written.stat().st_mtime_ns == stamp - 10**9  # the same text is not written again
    assert features.rule_href("LIS202") == f"{uri}#lis202"


def test_without_a_writable_cache_diagnostics_carry_no_link(
    outside_a_checkout: Path, monkeypatch: pytest.MonkeyPatch, session: Session
) -> None:
    blocked = outside_a_checkout / "not-a-folder"
    blocked.write_text("", encoding="utf-8")
    monkeypatch.setenv("XDG_CACHE_HOME", str(blocked))
    assert features.rules_document() is None
    document = opened(session, outside_a_checkout / "achsmds1.lis", "kopf.achs_nr  1\nEnd\n")
    snapshot, found, _ = session.diagnostics(document.uri)
    shown = features.publishable(document, snapshot, found)
    assert [d.code for d in shown] == ["LIS004"] and shown[0].code_description is None
    text = features.rule_text("LIS004", markdown=True)
    assert text is not None and text.startswith("**LIS004") and "[Documentation]" not in text


# -- diagnostics of documents achslint cannot read ---------------------------------------------------------


def test_broken_xml_is_one_error_at_the_start(session: Session, tmp_path: Path) -> None:
    document = opened(
        session, tmp_path / "Axis.xti", "<?xml version='1.0'?><TcSmItem><AchsMds><![CDATA[kopf.achs_nr 1\n"
    )
    snapshot, found, peers = session.diagnostics(document.uri)
    shown = features.publishable(document, snapshot, found)
    assert len(shown) == 1 and peers == []
    assert shown[0].severity == lsp.DiagnosticSeverity.Error
    assert (shown[0].range.start.line, shown[0].range.start.character) == (0, 0)
    assert "is not well-formed XML: unclosed CDATA section" in shown[0].message
    # nothing of a list to offer in XML: no quick fixes, outline or hints
    assert features.code_actions(document, snapshot, found, EVERYWHERE, None, list) == []
    assert features.inlay_hints(document, snapshot, EVERYWHERE) == []


def test_a_broken_configuration_is_shown_and_the_defaults_are_used(session: Session, tmp_path: Path) -> None:
    (tmp_path / ".achslint.toml").write_text("select = [\n", encoding="utf-8")
    document = opened(session, tmp_path / "achsmds1.lis", "kopf.achs_nr  1\nEnd\n")
    snapshot, found, _ = session.diagnostics(document.uri)
    shown = features.publishable(document, snapshot, found)
    assert shown[0].message.endswith("(the built-in defaults are used)")
    assert ".achslint.toml" in shown[0].message
    assert [d.code for d in shown[1:]] == ["LIS004"]  # still checked, with the defaults


def test_unknown_documents_have_no_snapshot_or_machine(session: Session, tmp_path: Path) -> None:
    untitled = Document("untitled:Untitled-1", None, "kopf.achs_nr  1\nkopf.achs_nr  2\nEnde\n", 1)
    session.open(untitled)
    snapshot, found, peers = session.diagnostics(untitled.uri)
    assert snapshot is not None and codes(found) == ["LIS005"] and peers == []
    assert session.machines(untitled) == []
    assert session.diagnostics("file:///nowhere/achsmds1.lis") == (None, [], [])
    session.close(untitled.uri)
    session.close(untitled.uri)  # closing twice is harmless
    assert session.snapshot(untitled.uri) is None


# -- what lint refuses to read ----------------------------------------------------------------------------


@pytest.mark.parametrize("codec", ["utf-16", "utf-32"])
def test_a_wide_file_the_editor_decoded_is_refused_as_lint_refuses_it(
    session: Session, tmp_path: Path, codec: str
) -> None:
    """Issue 28 item 4: the editor shows the decoded text, the CNC gets the wide bytes it saves."""
    text = "kopf.achs_nr  1\nEnde\n"
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(text.encode(codec))  # with its byte-order mark
    with pytest.raises(UnreadableInput) as refused:
        lint(path)
    document = opened(session, path, text)
    snapshot = snapshot_of(session, document)
    assert snapshot.result.error is not None and codec.upper() in snapshot.result.error
    assert snapshot.result.error in str(refused.value)  # the command line's words
    shown = features.publishable(document, snapshot, [])
    assert shown[0].severity == lsp.DiagnosticSeverity.Error and codec.upper() in shown[0].message
    path.write_bytes(text.encode("latin-1"))  # saved as the CNC reads it: checked again
    session.forget_disk()
    assert snapshot_of(session, document).result.error is None


def test_nul_characters_in_the_buffer_are_refused_as_a_binary_file(session: Session, tmp_path: Path) -> None:
    document = opened(session, tmp_path / "achsmds1.lis", "kopf.achs_nr  1\0\0\nEnde\n")
    error = snapshot_of(session, document).result.error
    assert error is not None and "binary" in error
    buffer = Document("untitled:1", None, "\0Ende\n", 1)  # not a file: the buffer alone decides
    session.open(buffer)
    assert "binary" in (snapshot_of(session, buffer).result.error or "")


# -- editor settings ---------------------------------------------------------------------------------------


def test_editor_settings_are_read_leniently() -> None:
    assert ClientSettings.from_dict(["LIS202"]) == ClientSettings()
    nested = ClientSettings.from_dict(
        {"achslint": {"select": "LIS202,LIS203", "extend_select": ["LIS301"], "debounceMs": 99999}}
    )
    assert nested.select == ["LIS202", "LIS203"] and nested.extend_select == ["LIS301"]
    assert nested.debounce_ms == 0  # out of range: the default (no delay: lint as soon as the last lint ends)
    assert ClientSettings.from_dict({"debounce_ms": "fast", "inlay_hints": 1}).debounce_ms == 0
    assert ClientSettings.from_dict({"debounceMs": 150}).debounce_ms == 150
    assert ClientSettings.from_dict({"inlay_hints": 1}).inlay_hints is True
    assert ClientSettings.from_dict({"select": 5}).select is None


def test_xml_text_is_encoded_as_it_declares() -> None:
    latin = "<?xml version='1.0' encoding='ISO-8859-1'?><a>µ</a>"
    assert xml_bytes(latin) == latin.encode("latin-1")
    for declared in ("no-such-codec", "ascii"):  # unknown, or cannot hold µ: UTF-8
        text = f'<?xml version="1.0" encoding="{declared}"?><a>µ</a>'
        assert xml_bytes(text) == text.encode("utf-8")


# -- code actions ------------------------------------------------------------------------------------------

ACTIONS_LIST = (
    "kenngr.antr_typ 1\n"
    "kenngr.homing.homing_type  DRIVE_CONROLLED  ( noqa: LIS202\n"
    "kenngr.achs_typ  1  ( linear\n"
    'kenngr.swe_pos  "abc"\n'
    "End\n"
)


def test_noqa_actions_extend_a_directive_or_add_a_comment_in_the_right_style(
    session: Session, tmp_path: Path
) -> None:
    document = opened(session, tmp_path / "achsmds1.lis", ACTIONS_LIST)
    snapshot, found, _ = session.diagnostics(document.uri)
    actions = features.code_actions(document, snapshot, found, EVERYWHERE, None, list)
    noqa = {
        (a.title, e.range.start.line, e.range.start.character, e.new_text)
        for a in actions
        for e in a.edit.changes[document.uri]
        if "noqa" in a.title
    }
    # the directive on line 2 gets the code added; text values get `(`, numbers `#`; LIS004 (no value to
    # put a comment after) is suppressed for the whole file
    assert ("Suppress LIS203 on this line (noqa)", 1, 58, ", LIS203") in noqa
    assert ("Suppress LIS201 on this line (noqa)", 3, 21, "  ( noqa: LIS201") in noqa
    assert ("Suppress LIS004 in this file (noqa)", 0, 0, "# achslint: noqa: LIS004\n") in noqa
    suppressed = apply(
        ACTIONS_LIST, [a.edit.changes[document.uri][0] for a in actions if "LIS201" in a.title]
    )
    document.apply(None, None, suppressed)
    assert "LIS201" not in codes(session.diagnostics(document.uri)[1])


def test_noqa_edit_after_a_comment_and_never_into_a_bare_noqa(session: Session, tmp_path: Path) -> None:
    text = "kenngr.achs_typ  1  ( linear\nkenngr.ref_richt 1  # noqa\n"
    document = opened(session, tmp_path / "achsmds1.lis", text)
    file = document.parse()

    def finding(line: int) -> Diagnostic:
        return Diagnostic(document.name, line, 1, line, 2, "LIS202", Severity.ERROR, "out of range")

    after_comment = features.noqa_edit(document, file, finding(1))
    assert after_comment is not None and after_comment.new_text == "  noqa: LIS202"
    assert (after_comment.range.start.line, after_comment.range.start.character) == (
        0,
        len("kenngr.achs_typ  1  ( linear"),
    )
    assert features.noqa_edit(document, file, finding(2)) is None  # a bare noqa already silences it
    assert features.noqa_edit(document, file, finding(9)) is None  # no such line


def test_a_byte_order_mark_is_lis006_in_the_editor_as_on_the_command_line(
    session: Session, tmp_path: Path
) -> None:
    # The CLI reports LIS006 for a list saved "UTF-8 with BOM"; so must the editor, whether it keeps the
    # mark as a character of the text or (like VS Code) hides it and writes it back on save. Only a mark in
    # the text can be removed by a quick fix.
    body = "kopf.achs_nr  1\nkopf.log_achs_name  X\nEnde\n"
    path = tmp_path / "achsmds1.lis"

    def lis006(text: str) -> tuple[bool, list[str]]:
        document = opened(session, path, text)
        snapshot, found, _ = session.diagnostics(document.uri)
        actions = features.code_actions(document, snapshot, found, EVERYWHERE, None, list)
        return "LIS006" in codes(found), [a.title for a in actions if a.title.startswith("LIS006")]

    path.write_bytes(body.encode())
    assert lis006(body) == (False, [])
    assert lis006("\ufeff" + body) == (True, ["LIS006: remove the byte-order mark"])
    path.write_bytes(b"\xef\xbb\xbf" + body.encode())
    assert lis006(body) == (True, [])  # hidden by the editor: reported, no edit that could remove it


def test_a_bare_noqa_that_suppresses_nothing_gets_no_noqa_action(session: Session, tmp_path: Path) -> None:
    document = opened(session, tmp_path / "achsmds1.lis", "kopf.achs_nr  1  # noqa\nEnde\n")
    snapshot, found, _ = session.diagnostics(document.uri)
    assert codes(found) == ["LIS009"]
    assert features.code_actions(document, snapshot, found, EVERYWHERE, None, list) == []


def test_fix_all_is_offered_only_for_the_kinds_asked_for(session: Session, tmp_path: Path) -> None:
    document = opened(session, tmp_path / "achsmds1.lis", ACTIONS_LIST)
    snapshot, found, _ = session.diagnostics(document.uri)
    edit = lsp.TextEdit(lsp.Range(lsp.Position(4, 0), lsp.Position(4, 3)), "Ende")

    def kinds(only: list[str] | None, edits: list[lsp.TextEdit]) -> list[tuple[str, str]]:
        actions = features.code_actions(document, snapshot, found, EVERYWHERE, only, lambda: edits)
        return [(a.kind, a.title) for a in actions if "fix all" in a.title]

    fix_all = "achslint: fix all safe findings"
    assert kinds(None, [edit]) == [(lsp.CodeActionKind.QuickFix, fix_all)]
    assert kinds([lsp.CodeActionKind.SourceFixAll], [edit]) == [(features.FIX_ALL, fix_all)]
    assert kinds([lsp.CodeActionKind.SourceFixAll], []) == []  # nothing a fix would change
    assert kinds([lsp.CodeActionKind.Refactor], [edit]) == []
    assert kinds(None, []) == []


def test_findings_of_another_file_get_no_noqa_action(session: Session, tmp_path: Path) -> None:
    document = opened(session, tmp_path / "achsmds1.lis", "kopf.achs_nr  1\nEnde\n")
    snapshot = snapshot_of(session, document)
    other = Diagnostic(
        str(tmp_path / "achsmds2.lis"), 1, 1, 1, 5, "LIS501", Severity.ERROR, "the same axis number"
    )
    assert features.code_actions(document, snapshot, [other], EVERYWHERE, None, list) == []


def test_machine_findings_get_no_noqa_action(session: Session, tmp_path: Path) -> None:
    # A `noqa` cannot suppress what the machine step finds (LIS501 here): the action would only add LIS009.
    one_machine(tmp_path)
    text = "kopf.achs_nr 1\nkenngr.ref_richt 7\nEnde\n"
    for name in ("achsmds1.lis", "achsmds2.lis"):
        (tmp_path / name).write_text(text, encoding="latin-1")
    document = opened(session, tmp_path / "achsmds2.lis")
    snapshot, found, _ = session.diagnostics(document.uri)
    assert {"LIS501", "LIS201"} <= set(codes(found))
    titles = [a.title for a in features.code_actions(document, snapshot, found, EVERYWHERE, None, list)]
    assert "Suppress LIS201 on this line (noqa)" in titles  # the list's own finding: suppressed by a noqa
    assert not [title for title in titles if "LIS501" in title]
    suppressed = text.replace("kopf.achs_nr 1", "kopf.achs_nr 1  # noqa: LIS501")
    again = opened(session, tmp_path / "achsmds2.lis", suppressed)
    assert {"LIS501", "LIS009"} <= set(codes(session.diagnostics(again.uri)[1]))  # why none is offered


# -- completion --------------------------------------------------------------------------------------------


def test_completion_of_boolean_values_unknown_paths_and_codes(session: Session, tmp_path: Path) -> None:
    text = "kenngr.ref_richt  \nkenngr.nothing  \nkenngr.achs_typ  1  ( noqa: LIS2\nEnde\n"
    document = opened(session, tmp_path / "achsmds1.lis", text)
    snapshot = snapshot_of(session, document)
    boolean = features.complete(document, snapshot, 1, 19)
    assert [(i.label, i.detail) for i in boolean.items] == [("0", "off"), ("1", "on")]
    assert features.complete(document, snapshot, 2, 17).items == []
    after_comment = len("kenngr.achs_typ  1  ( ") + 1  # in a comment without noqa: nothing to offer
    assert features.complete(document, snapshot, 3, after_comment).items == []
    codes_here = features.complete(document, None, 3, len("kenngr.achs_typ  1  ( noqa: LIS2") + 1)
    first = codes_here.items[0]
    assert first.label == "LIS201" and first.sort_text == "1LIS201" and first.filter_text == "LIS201"
    assert all(i.label.startswith("LIS2") for i in codes_here.items)  # filtered by the typed prefix
    assert first.text_edit.range.start.character == len("kenngr.achs_typ  1  ( noqa: ")


def test_path_completion_with_an_edit_range_default_and_without_snippets(
    session: Session, tmp_path: Path
) -> None:
    document = opened(session, tmp_path / "achsmds1.lis", "getriebe[1].vb_re\nEnde\n")
    snapshot = snapshot_of(session, document)
    found = features.complete(document, snapshot, 1, 18, snippets=False, edit_range_default=True)
    assert found.item_defaults is not None
    assert found.item_defaults.edit_range == lsp.Range(lsp.Position(0, 0), lsp.Position(0, 17))
    reflow = next(i for i in found.items if i.label == "getriebe[1].vb_reflow")
    assert reflow.text_edit is None and reflow.insert_text_format == lsp.InsertTextFormat.PlainText
    assert reflow.text_edit_text is None  # the label is what is inserted
    assert reflow.filter_text == "getriebe[1].vb_reflow"


def test_path_completion_is_filtered_by_the_typed_prefix_for_every_client(
    session: Session, tmp_path: Path
) -> None:
    """Issue 28 item 2: Neovim takes the list as filtered when the items have a textEdit; an item the typed
    prefix does not lead to would replace the line with an unrelated path."""
    document = opened(session, tmp_path / "achsmds1.lis", "getriebe[0].vb_re\nEnde\n")
    snapshot = snapshot_of(session, document)
    found = features.complete(document, snapshot, 1, 18)
    labels = [i.label for i in found.items]
    assert found.is_incomplete and labels
    assert {"getriebe[0].vb_reflow", "getriebe[0].vb_refmax"} <= set(labels)
    assert all(label.startswith("getriebe[0].vb_re") for label in labels)
    for item in found.items:  # the edit replaces exactly the typed prefix; the client filters by filterText
        assert item.text_edit.range == lsp.Range(lsp.Position(0, 0), lsp.Position(0, 17))
        assert item.filter_text is not None and item.filter_text.startswith("getriebe[0].vb_re")
    # typed otherwise: case aside, and inside an index
    upper = opened(session, tmp_path / "achsmds2.lis", "Getriebe[\nEnde\n")
    found = features.complete(upper, snapshot_of(session, upper), 1, 10)
    assert found.items and all(i.filter_text.startswith("Getriebe[") for i in found.items)
    assert "getriebe[i].vb_reflow" in {i.label for i in found.items}
    index = opened(session, tmp_path / "achsmds3.lis", "getriebe[3\nEnde\n")
    found = features.complete(index, snapshot_of(session, index), 1, 11)
    assert "getriebe[3].vb_reflow" in {i.label for i in found.items}
    assert all(i.label.startswith("getriebe[3]") for i in found.items)


def test_path_completion_ranks_unset_paths_of_the_group_and_unit_near_the_cursor_first(
    session: Session, tmp_path: Path
) -> None:
    text = "kenngr.achs_typ  1\ngetriebe[0].vb_refmax  100000\ngetriebe[0].\nEnde\n"
    document = opened(session, tmp_path / "achsmds1.lis", text)
    snapshot = snapshot_of(session, document)
    items = features.complete(document, snapshot, 3, len("getriebe[0].") + 1).items
    ranked = [i.label for i in sorted(items, key=lambda i: i.sort_text or i.label)]
    # vb_reflow: not set yet, same group, same unit as vb_refmax on the line above
    assert ranked.index("getriebe[0].vb_reflow") < ranked.index("getriebe[0].a_ref")  # unit
    assert ranked.index("getriebe[0].a_ref") < ranked.index("getriebe[0].vb_refmax")  # set already
    top = features.complete(document, snapshot, 3, 1).items
    first = min(top, key=lambda i: i.sort_text or i.label)
    assert first.label.startswith("getriebe[")  # the group of the line above comes first


def test_resolve_keeps_given_documentation_and_ignores_other_items() -> None:
    given = lsp.CompletionItem("kenngr.ref_richt", kind=lsp.CompletionItemKind.Field, documentation="mine")
    assert features.resolve_item(given).documentation == "mine"
    code = lsp.CompletionItem("LIS202", kind=lsp.CompletionItemKind.Constant)
    assert features.resolve_item(code).documentation is None
    card = features.resolve_item(
        lsp.CompletionItem("kenngr.ref_richt", kind=lsp.CompletionItemKind.Field), False
    )
    assert card.documentation.kind == lsp.MarkupKind.PlainText
    assert card.documentation.value.startswith("P-AXIS-00158 kenngr.ref_richt\n")


# -- formatting, edits -------------------------------------------------------------------------------------


def test_range_formatting_leaves_formatted_lines_alone(session: Session, tmp_path: Path) -> None:
    text = "kenngr.antr_typ 1\nkenngr.achs_typ  1\nEnde\n"
    document = opened(session, tmp_path / "achsmds1.lis", text)
    live = LiveFormat()
    live.update(document.body_lines)
    assert features.format_range(document, live, lsp.Range(lsp.Position(1, 0), lsp.Position(2, 4))) == []
    whole = features.format_range(document, live, EVERYWHERE)
    assert [(e.range.start.line, e.new_text) for e in whole] == [(0, "kenngr.antr_typ  1")]


def test_formatting_edits_give_fmt_text_with_a_byte_order_mark(tmp_path: Path) -> None:
    text = "\ufeffkopf.achs_nr 1\r\nkenngr.antr_typ   1\r\nEnde\r\n\r\n  "
    document = Document("untitled:bom", None, text, 1)
    edits = features.format_document(document)
    # the two values, and the lines after the end marker up to the last one's blanks
    assert [(e.range.start.line, e.range.end.line) for e in edits] == [(0, 2), (3, 4)]
    for edit in reversed(edits):  # as the editor applies them
        start, end = edit.range.start, edit.range.end
        document.apply((start.line, start.character), (end.line, end.character), edit.new_text)
    assert document.text == "\ufeff" + format_text(text[1:])


def test_edits_from_an_empty_document(tmp_path: Path) -> None:
    empty = Document("untitled:new", None, "", 1)
    edits = features.diff_edits(empty, "kopf.achs_nr  1\nEnde\n")
    assert [(e.range.start.line, e.range.end.line, e.new_text) for e in edits] == [
        (0, 0, "kopf.achs_nr  1\nEnde\n")
    ]


# -- definitions and inlay hints ----------------------------------------------------------------------------


def test_definition_only_from_a_reference_to_a_written_parameter(session: Session, tmp_path: Path) -> None:
    text = (
        "getriebe[0].dynamik.vb_max  500000\n"
        "getriebe[0].vb_refmax  P-AXIS-00212.0\n"
        "getriebe[0].vb_reflow  P-AXIS-00219.1\n"
        "kenngr.ref_richt  1\n"
        "Ende\n"
    )
    document = opened(session, tmp_path / "achsmds1.lis", text)
    snapshot = snapshot_of(session, document)

    def where(line: int, column: int) -> list[tuple[int, int]]:
        found = features.definition(document, snapshot, line, column, list)
        return [(f.range.start.line, f.range.start.character) for f in found]

    assert where(2, 26) == [(0, 0)]
    assert where(3, 26) == []  # getriebe[1].vb_refmax is not written: the built-in default has no place
    assert where(4, 20) == []  # not a reference
    assert where(2, 3) == []  # on the path, not the value
    assert where(9, 1) == []
    assert features.definition(document, None, 2, 26, list) == []
    assert features.inlay_hints(document, None, EVERYWHERE) == []
    # hints only for numbers with a unit: not for references, booleans or zero
    hints = features.inlay_hints(document, snapshot, EVERYWHERE)
    assert [(h.position.line, h.label) for h in hints] == [(0, " = 500 mm/s = 30 m/min")]
    document.apply(None, None, text.replace("500000", "0"))
    assert features.inlay_hints(document, session.snapshot(document.uri), EVERYWHERE) == []


# -- machines: start-up lists, default lists, neighbours -----------------------------------------------------


def sdk_machine(root: Path) -> Path:
    """A start-up list above `listen/` naming two axis lists and a default list (the SDK layout)."""
    (root / "listen").mkdir(parents=True)
    (root / "hochlauf.lis").write_text(
        "zahl_mds  2\n"
        "default_achs_mds  ./listen/default_mds.lis\n"
        "achs_mds[0]  ./listen/achsmds1.lis\n"
        "achs_mds[1]  ./listen/achsmds2.lis\n"
        "Ende\n",
        encoding="latin-1",
    )
    (root / "listen" / "default_mds.lis").write_text("getriebe[0].dynamik.vb_max  300000\nEnde\n")
    (root / "listen" / "achsmds1.lis").write_text("kopf.achs_nr  1\nkopf.log_achs_name  X\nEnde\n")
    (root / "listen" / "achsmds2.lis").write_text("kopf.achs_nr  2\nkopf.log_achs_name  Y\nEnde\n")
    return root / "listen"


def test_the_open_default_list_is_loaded_under_the_axis_list(session: Session, tmp_path: Path) -> None:
    listen = sdk_machine(tmp_path)
    opened(session, listen / "default_mds.lis", "getriebe[0].dynamik.vb_max  400000\nEnde\n")  # not saved
    text = "kopf.achs_nr  1\nhandbetrieb.hb.vb_max  P-AXIS-00212.0\nEnde\n"
    document = opened(session, listen / "achsmds1.lis", text)
    snapshot = snapshot_of(session, document)
    card = features.hover_text(snapshot.context, snapshot.file, 2, 26)
    assert card is not None and "resolved value: 400000 µm/s (= 400 mm/s = 24 m/min)" in card
    assert f"from: {listen / 'default_mds.lis'} line 1 (default list)" in card
    target = features.definition(document, snapshot, 2, 26, list)
    assert [(t.uri, t.range.start.line, t.range.end.character) for t in target] == [
        ((listen / "default_mds.lis").as_uri(), 0, len("getriebe[0].dynamik.vb_max"))
    ]


def test_machine_findings_follow_the_buffers_and_the_files_on_disk(session: Session, tmp_path: Path) -> None:
    listen = sdk_machine(tmp_path)
    second = opened(session, listen / "achsmds2.lis", "kopf.achs_nr  1\nkopf.log_achs_name  Y\nEnde\n")
    _, found, _ = session.diagnostics(second.uri)
    duplicate = [d for d in found if d.code == "LIS501"]
    assert len(duplicate) == 1 and str(listen / "achsmds1.lis") in duplicate[0].message
    # the first list vanishes from disk (the editor has not told yet): the finding goes with it
    (listen / "achsmds1.lis").unlink()
    assert "LIS501" not in codes(session.diagnostics(second.uri)[1])
    # in its place something that is not a file to read
    os.mkfifo(listen / "achsmds1.lis")
    assert "LIS501" not in codes(session.diagnostics(second.uri)[1])


def test_a_start_up_list_shows_its_entries_and_its_own_lines(session: Session, tmp_path: Path) -> None:
    sdk_machine(tmp_path)
    (tmp_path / "listen" / "achsmds2.lis").unlink()
    startup = opened(session, tmp_path / "hochlauf.lis")
    snapshot, found, _ = session.diagnostics(startup.uri)
    # its lines are clean start-up parameters; the missing axis list is its entry's finding
    assert snapshot is not None and snapshot.startup and snapshot.file is not None
    assert [(d.code, d.line) for d in found] == [("LIS504", 4)]
    entries = [StartupEntry("achs_mds[0]", "./gone.lis", 3, 20, None)]  # an entry whose file was not found
    assert features.definition(startup, snapshot, 3, 20, lambda: entries) == []
    assert features.definition(startup, snapshot, 4, 20, lambda: entries) == []


def test_an_unreadable_default_list_leaves_the_axis_list_checked(session: Session, tmp_path: Path) -> None:
    listen = sdk_machine(tmp_path)
    (listen / "default_mds.lis").write_bytes(b"getriebe[0].a_ref\x00 1\n")
    document = opened(session, listen / "achsmds1.lis", "kopf.achs_nr  1\nkenngr.ref_richt  5\nEnde\n")
    assert "LIS201" in codes(session.diagnostics(document.uri)[1])


def test_start_up_lists_that_do_not_name_the_list_leave_its_declared_machine(
    session: Session, tmp_path: Path
) -> None:
    (tmp_path / "hochlauf.lis").write_text("achs_mds[0]  ./other.lis\nEnde\n", encoding="latin-1")
    (tmp_path / "hochlauf_binary.lis").write_bytes(b"\x00\x01\x02")
    (tmp_path / "hochlauf_folder.lis").mkdir()
    (tmp_path / "achsmds2.lis").write_text("kopf.achs_nr  1\nEnde\n", encoding="latin-1")
    (tmp_path / "achsmds3.lis").mkdir()  # matches the pattern, but a folder
    os.mkfifo(tmp_path / "achsmds4.lis")
    (tmp_path / ".achslint.toml").write_text(
        'exclude = ["achsmds5.lis"]\n\n[[machine]]\nlists = ["*.lis"]\n', encoding="utf-8"
    )
    (tmp_path / "achsmds5.lis").write_text("kopf.achs_nr  1\nEnde\n", encoding="latin-1")
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr  1\nEnde\n", encoding="latin-1")
    document = opened(session, tmp_path / "achsmds1.lis")
    [machine] = session.machines(document)
    assert machine.startup is None
    assert [f.name for f in machine.files] == ["achsmds1.lis", "achsmds2.lis"]
    assert session.diagnostics(document.uri)[1] == []  # the finding goes to the second list
    second = opened(session, tmp_path / "achsmds2.lis")
    _, found, peers = session.diagnostics(second.uri)
    assert "LIS501" in codes(found) and peers == []  # nothing changed for the first list


def test_a_list_in_a_folder_that_is_gone_has_no_machine(session: Session, tmp_path: Path) -> None:
    gone = tmp_path / "gone" / "achsmds1.lis"
    document = Document(gone.as_uri(), gone, "kopf.achs_nr  1\nkopf.achs_nr  2\nEnde\n", 1)
    session.open(document)
    assert session.machines(document) == []
    assert codes(session.diagnostics(document.uri)[1]) == ["LIS005"]


def test_a_broken_configuration_of_a_neighbour_does_not_stop_the_machine_rules(
    session: Session, tmp_path: Path
) -> None:
    (tmp_path / ".achslint.toml").write_text("select = [\n", encoding="utf-8")
    (tmp_path / "hochlauf.lis").write_text("achs_mds[0]  ./achsmds1.lis\nachs_mds[1]  ./achsmds2.lis\nEnde\n")
    (tmp_path / "achsmds2.lis").write_text("kopf.achs_nr  1\nEnde\n", encoding="latin-1")
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr  1\nEnde\n", encoding="latin-1")
    second = opened(session, tmp_path / "achsmds2.lis")
    assert "LIS501" in codes(session.diagnostics(second.uri)[1])


def test_the_text_of_a_list_is_the_buffer_else_the_file(session: Session, tmp_path: Path) -> None:
    path = tmp_path / "achsmds1.lis"
    path.write_text("kopf.achs_nr  1\nEnde\n", encoding="latin-1")
    assert session.text_of(path) == b"kopf.achs_nr  1\nEnde\n"
    opened(session, path, "kopf.achs_nr  µ\nEnde\n")
    assert session.text_of(path) == "kopf.achs_nr  µ\nEnde\n".encode()


def test_closed_lists_of_the_machine_are_read_once_while_unchanged(
    session: Session, tmp_path: Path, monkeypatch
):
    # The neighbour achsmds1.lis is not open: its summary comes from disk and is kept until the file changes.
    one_machine(tmp_path)
    for name in ("achsmds1.lis", "achsmds2.lis"):
        (tmp_path / name).write_text("kopf.achs_nr 1\nEnde\n", encoding="latin-1")
    document = opened(session, tmp_path / "achsmds2.lis")  # repeats the number of achsmds1.lis: LIS501
    import achslint.lsp.session as module

    reads: list[str] = []
    real = module.lint_file

    def counting(data, name, *args, **kwargs):
        reads.append(Path(name).name)
        return real(data, name, *args, **kwargs)

    monkeypatch.setattr(module, "lint_file", counting)
    for _ in range(3):
        _, found, _ = session.diagnostics(document.uri)
        assert "LIS501" in codes(found)
    assert reads.count("achsmds1.lis") == 1


def test_a_document_whose_uri_holds_a_nul_is_checked_as_a_buffer():
    from achslint.lsp.server import _path

    assert _path("file:///a%00b/achsmds1.lis") is None
    assert _path("file:///tmp/achsmds1.lis") == Path("/tmp/achsmds1.lis")


def test_an_open_start_up_list_gets_its_own_lines_checked_as_lint_checks_them(
    session: Session, tmp_path: Path
) -> None:
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr  1\nEnde\n")
    startup = tmp_path / "basis.lis"  # a start-up list by its content
    startup.write_text("zahl_mds  1\nachs_mds[0]  ./achsmds1.lis\nachs_mds[1]  ./missing.lis\nEnde\n")
    # in the buffer: a line after `Ende` (LIS003), and the missing entry beyond zahl_mds (LIS516)
    document = opened(session, startup, startup.read_text() + "zahl_mdz  2\n")
    _, found, _ = session.diagnostics(document.uri)
    assert [(d.line, d.code) for d in found] == [(3, "LIS516"), (5, "LIS003")]


# -- outline -------------------------------------------------------------------------------------------------


def test_outline_positions_are_the_clients_units_in_ascii_and_wide_texts(
    session: Session, tmp_path: Path
) -> None:
    """An ASCII text's outline is built without measuring lines; a text with a character outside the BMP
    (two UTF-16 units) is measured: both give the positions `lsp_range` gives."""
    for name, comment in (("achsmds1.lis", "plain"), ("achsmds2.lis", "\U0001d707 wide")):
        text = f"kopf.achs_nr  1  # {comment}\ngetriebe[0].vb_reflow  100\nEnde\n"
        document = opened(session, tmp_path / name, text)
        file = snapshot_of(session, document).file
        assert file is not None
        symbols = features.document_symbols(document, file)
        kopf = next(s for s in symbols if s.name == "kopf")
        line = file.lines[0]
        assert kopf.children[0].range == features.lsp_range(document, 1, 1, 1, line.end_column)
        assert kopf.children[0].range.end.character == len(text.splitlines()[0].encode("utf-16-le")) // 2
        assert [s.name for s in symbols] == ["kopf", "getriebe[0]", "Ende"]


def test_hover_on_a_list_named_as_another_kind_shows_the_kind_its_content_is(
    session: Session, tmp_path: Path
) -> None:
    # sda_mds[0] names an axis list (LIS523): read as a channel list, `kopf.achs_nr` is none of its names, so
    # the card comes from the axis catalogue the content shows, and says how the list is read.
    machine = tmp_path / "machine"
    shutil.copytree(FIXTURES / "rules" / "LIS523" / "bad", machine)
    document = opened(session, machine / "achsmds2.lis")
    snapshot = snapshot_of(session, document)
    assert features.document_kind(snapshot) is not None and features.document_kind(snapshot).id == "channel"
    line = next(n for n, text in enumerate(document.text.splitlines(), 1) if text.startswith("kopf.achs_nr"))
    card = features.hover_text(snapshot.context, snapshot.file, line, 2, markdown=False)
    assert card is not None and card.startswith("P-AXIS-00016 kopf.achs_nr")
    assert "read as a channel list (LIS523" in card and "its content is an axis list" in card
    # the list read as its own kind: the card has no such note
    right = opened(session, machine / "achsmds1.lis")
    mine = snapshot_of(session, right)
    own = features.hover_text(mine.context, mine.file, 1, 2, markdown=False)
    assert own is not None and "LIS523" not in own


def test_a_quick_fix_that_lint_fix_refuses_is_offered_as_unsafe(session: Session, tmp_path: Path) -> None:
    """Both fixes of this list are safe by their rule but change what the CNC does (on the simulated drive of
    antr_typ 4, `DRIVE_CONTROLLED` is LIS305): `achslint lint` calls them unsafe and `--fix` refuses them, so
    the editor must not offer them as safe, preferred quick fixes. A fix that passes stays safe."""
    text = (
        "kopf.achs_nr 1\nkopf.log_achs_name X\nkenngr.achs_typ 1\nkenngr.antr_typ 4\n"
        "kenngr.ref_ricth 1\nkenngr.homing.homing_type DRIVE_CONROLLED\nEnde\n"
    )
    document = opened(session, tmp_path / "achsmds1.lis", text)
    snapshot = snapshot_of(session, document)
    found = snapshot.result.diagnostics
    refused = session.unsafe_fixes(document)
    assert {code for code, _, _ in refused} == {"LIS101", "LIS203"}
    for action in features.code_actions(document, snapshot, found, EVERYWHERE, None, list, refused):
        if action.title.startswith(("LIS101", "LIS203")):
            assert action.title.endswith("(unsafe fix: check the result)") and not action.is_preferred
    assert session.fixed_text(document) is None  # what fix-all applies: nothing, as `--fix`
    # a misspelt end marker's fix changes nothing the CNC does: safe and preferred
    plain = opened(session, tmp_path / "achsmds2.lis", "kopf.achs_nr 2\nkenngr.antr_typ 1\nENDE\n")
    assert session.unsafe_fixes(plain) == set()
    found = snapshot_of(session, plain).result.diagnostics
    actions = features.code_actions(plain, snapshot_of(session, plain), found, EVERYWHERE, None, list)
    assert [a.title for a in actions if a.is_preferred and a.title.startswith("LIS004")], [
        a.title for a in actions
    ]
