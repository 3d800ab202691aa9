"""A robustness review of `achslint server`: hostile or unusual input from the client never makes the server
read files it was not pointed at, never floods the editor or the log, and never changes a setting the user
did not give."""

from __future__ import annotations

import logging
import os
from collections.abc import Iterator
from pathlib import Path

import pytest

pytest.importorskip("pygls.lsp.server", reason="the lsp extra is not installed")

from achslint.lsp.server import _path
from achslint.lsp.session import ClientSettings

from .test_lsp_protocol import INITIALIZE, InProcess, hover, notification, opened, request


@pytest.fixture
def wire() -> Iterator[InProcess]:
    server = InProcess()
    server.send(INITIALIZE, notification("initialized", {}))
    server.answer(1)
    yield server
    server.close()
    assert server.code == 0


def shown(wire: InProcess) -> list[str]:
    return [m["params"]["message"] for m in wire.received if m.get("method") == "window/showMessage"]


# -- URIs that name no file of this system ----------------------------------------------------------------


@pytest.mark.parametrize(
    "uri",
    [
        "file:///C:/x/achsmds1.lis",  # a Windows drive: on POSIX a relative path "c:/x/..."
        "file:achsmds1.lis",  # no authority, no leading slash: relative as well
        "file://fileserver/share/achsmds1.lis",  # a remote host (UNC)
    ],
)
def test_a_uri_that_names_no_local_absolute_path_is_a_buffer(uri: str) -> None:
    """Such a URI became a path relative to the server's working folder (or `//host/...`, which POSIX reads as
    `/host/...`): the server then read a file of that folder, outside the workspace, as the document's own
    (a binary one there made the buffer "a binary file")."""
    if os.name == "nt":
        pytest.skip("POSIX reading of the URIs")
    assert _path(uri) is None


def test_a_localhost_file_uri_names_the_local_path(tmp_path: Path) -> None:
    """`file://localhost/p` is `file:///p` (RFC 8089); it was read as `//localhost/p`, another file."""
    if os.name == "nt":
        pytest.skip("POSIX paths")
    assert _path("file://localhost" + (tmp_path / "a.lis").as_posix()) == tmp_path / "a.lis"
    assert _path((tmp_path / "a b.lis").as_uri()) == tmp_path / "a b.lis"  # the usual form is unchanged


def test_a_windows_drive_uri_reads_nothing_of_the_working_folder(
    wire: InProcess, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """End to end: a binary file at the relative path the drive URI became, in the server's working folder,
    decided what the editor showed for a clean buffer."""
    elsewhere = tmp_path / "elsewhere"
    (elsewhere / "c:" / "x").mkdir(parents=True)
    (elsewhere / "c:" / "x" / "achsmds1.lis").write_bytes(b"\0\1\2 not a list")
    monkeypatch.chdir(elsewhere)
    uri = "file:///C:/x/achsmds1.lis"
    wire.send(opened(uri, "kopf.achs_nr  1\nEnde\n"))
    found = wire.diagnostics(uri, 1)["params"]["diagnostics"]
    assert not [d for d in found if "binary" in d["message"]], found


# -- settings ----------------------------------------------------------------------------------------------


def test_many_bad_codes_in_the_settings_are_one_message(wire: InProcess) -> None:
    """Each code that picks no rule was a window/showMessage of its own: 3,000 pop-ups for one setting."""
    codes = [f"XX{number}" for number in range(3000)]
    wire.send(notification("workspace/didChangeConfiguration", {"settings": {"achslint": {"select": codes}}}))
    wire.send(
        request(
            2,
            "textDocument/hover",
            {"textDocument": {"uri": "file:///a.lis"}, "position": {"line": 0, "character": 0}},
        )
    )
    wire.answer(2)  # the notification before it was handled
    messages = shown(wire)
    assert len(messages) == 1, len(messages)
    assert "XX0" in messages[0] and "XX4" in messages[0] and "and 2995 more" in messages[0]


@pytest.mark.parametrize("given", ["false", "no", "0", {"on": True}, [True]])
def test_a_switch_of_the_wrong_type_does_not_turn_inlay_hints_on(given: object) -> None:
    """`bool(value)`: the string "false" switched inlay hints on."""
    settings = ClientSettings.from_dict({"achslint": {"inlayHints": given}})
    assert settings.inlay_hints is False
    if given not in ("false", "0"):  # a word that says off is read as off; anything else is told
        assert any("inlayHints" in problem for problem in settings.problems)


def test_a_switch_given_as_a_word_or_a_number_is_read() -> None:
    assert ClientSettings.from_dict({"inlayHints": "true"}).inlay_hints is True
    assert ClientSettings.from_dict({"inlayHints": True}).inlay_hints is True
    assert ClientSettings.from_dict({"inlay_hints": 1}).inlay_hints is True


def test_a_boolean_is_no_debounce_delay() -> None:
    """`isinstance(True, int)`: `debounceMs: true` became a delay of 1 ms."""
    assert ClientSettings.from_dict({"debounceMs": True}).debounce_ms == 0


# -- the log -----------------------------------------------------------------------------------------------


def test_cancelling_a_request_already_answered_is_not_logged(
    wire: InProcess, caplog: pytest.LogCaptureFixture
) -> None:
    """The client may cancel a request whose answer is on its way (the protocol allows it, editors do it while
    typing): each was a warning line in the log."""
    wire.send(
        request(
            2,
            "textDocument/hover",
            {"textDocument": {"uri": "file:///a.lis"}, "position": {"line": 0, "character": 0}},
        )
    )
    wire.answer(2)
    with caplog.at_level(logging.WARNING):
        for _ in range(20):
            wire.send(notification("$/cancelRequest", {"id": 2}))
        wire.send(hover(3, "file:///a.lis", 0, 0))
        wire.answer(3)
    assert not [r for r in caplog.records if "Cancel" in r.getMessage()], caplog.records
