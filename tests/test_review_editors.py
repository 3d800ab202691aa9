"""A review of the editor integration as the README documents it: the VS Code extension's settings are the
server's and the README names each of them, a TwinCAT file opened on its own starts the extension, and
turning inlay hints on in the editor shows them without an edit."""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from typing import Any

import pytest

from achslint.core.files import XML_SUFFIXES
from achslint.lsp.session import ClientSettings

from .conftest import ROOT

VSCODE = ROOT / "editors" / "vscode"
README = ROOT / "README.md"

# The settings only the extension reads (how to start the server, which files it hands over).
CLIENT_ONLY = {"interpreter", "path", "filePatterns", "xml"}


def package() -> dict[str, Any]:
    loaded: dict[str, Any] = json.loads((VSCODE / "package.json").read_text(encoding="utf-8"))
    return loaded


def properties() -> dict[str, dict[str, Any]]:
    found: dict[str, dict[str, Any]] = package()["contributes"]["configuration"]["properties"]
    return found


def editor_section() -> str:
    text = README.read_text(encoding="utf-8")
    start = text.index("### In the editor")
    return text[start : text.index("\n## ", start)]


def vscode_paragraph() -> str:
    section = editor_section()
    start = section.index("**Visual Studio Code**")
    return section[start : section.index("\n\n", start)]


# -- settings ------------------------------------------------------------------------------------------------


def test_every_server_setting_the_extension_contributes_is_read_with_its_type() -> None:
    """Each setting the server acts on: a value of the contributed type, not the default, reaches the
    server's settings under the same name."""
    given = {
        "select": ["LIS2"],
        "extendSelect": ["LIS5"],
        "ignore": ["LIS401"],
        "inlayHints": True,
        "debounceMs": 150,
    }
    contributed = {key.removeprefix("achslint.") for key in properties()}
    assert contributed - CLIENT_ONLY == set(given)
    kinds = {"array": list, "boolean": bool, "integer": int}
    for key, value in given.items():
        assert isinstance(value, kinds[properties()[f"achslint.{key}"]["type"]]), key
    read = ClientSettings.from_dict({"achslint": {**given, "path": "achslint", "xml": True}})
    assert read.select == ["LIS2"] and read.extend_select == ["LIS5"] and read.ignore == ["LIS401"]
    assert read.inlay_hints is True and read.debounce_ms == 150 and read.problems == []
    # the defaults the extension sends are the server's own defaults
    defaults = {key: properties()[f"achslint.{key}"]["default"] for key in given}
    assert ClientSettings.from_dict({"achslint": defaults}) == ClientSettings()


def test_the_readme_names_every_setting_of_the_extension() -> None:
    paragraph = vscode_paragraph()
    missing = [key for key in properties() if f"`{key}`" not in paragraph]
    assert missing == []


def test_the_readme_tells_how_inlay_hints_show_in_vs_code() -> None:
    paragraph = vscode_paragraph()
    assert "`achslint.inlayHints`" in paragraph and "`editor.inlayHints.enabled`" in paragraph


def test_the_readme_names_every_xml_list_name_the_extension_starts_on() -> None:
    events = package()["activationEvents"]
    names = [e.removeprefix("workspaceContains:**/") for e in events if e.startswith("workspaceContains:")]
    xml = [n for n in names if n.lower().endswith(".xml")]
    assert xml and [n for n in xml if f"`{n}`" not in vscode_paragraph()] == []


# -- activation ----------------------------------------------------------------------------------------------


def test_a_twincat_file_opened_on_its_own_starts_the_extension() -> None:
    """`workspaceContains` needs a folder: `code Axis_X.xti` (no folder) never started the server, although
    `achslint.xml` is on. TwinCAT files are XML (as the Neovim and Emacs snippets take them); VS Code knows
    `.xml` as XML but not `.xti` or `.tsproj`."""
    manifest = package()
    assert "onLanguage:xml" in manifest["activationEvents"]
    xml = [lang for lang in manifest["contributes"]["languages"] if lang["id"] == "xml"]
    assert len(xml) == 1
    assert set(xml[0].get("extensions", [])) == set(XML_SUFFIXES) - {".xml"}


# -- inlay hints switched on while a list is open ------------------------------------------------------------


@pytest.fixture
def wire() -> Iterator[Any]:
    pytest.importorskip("pygls.lsp.server", reason="the lsp extra is not installed")
    from .test_lsp_protocol import InProcess, notification, request

    server = InProcess()
    capabilities = {"workspace": {"inlayHint": {"refreshSupport": True}}}
    server.send(
        request(1, "initialize", {"capabilities": capabilities, "initializationOptions": {}}),
        notification("initialized", {}),
    )
    server.answer(1)
    yield server
    server.close()


def test_turning_inlay_hints_on_asks_the_editor_to_show_them(wire: Any) -> None:
    """The server linted again but never sent workspace/inlayHint/refresh: VS Code kept the (empty) hints it
    had until the list was edited."""
    from .test_lsp_protocol import notification

    settings = {"achslint": {"inlayHints": True}}
    wire.send(notification("workspace/didChangeConfiguration", {"settings": settings}))
    found = wire.wait(lambda m: m.get("method") == "workspace/inlayHint/refresh", timeout=5)
    assert found["method"] == "workspace/inlayHint/refresh"


def test_the_inlay_hint_setting_is_documented_as_off_by_default() -> None:
    hints = properties()["achslint.inlayHints"]
    assert hints["default"] is False and ClientSettings().inlay_hints is False
    assert re.search(r"`inlayHints` \(default off\)", editor_section())
