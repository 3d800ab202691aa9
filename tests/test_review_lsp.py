"""A review of the language server against the command line: for the same file and configuration the editor
does what `achslint lint` does. (A machine finding such as LIS501 shows on the list the whole machine's lint
puts it on, as tests/test_discovery.py holds; `achslint lint ONE-LIST` puts it on the list named.)"""

from __future__ import annotations

from pathlib import Path

import pytest

pytest.importorskip("lsprotocol", reason="the lsp extra is not installed")

from achslint.api import lint_paths
from achslint.lsp.documents import Document
from achslint.lsp.session import Session


def opened(session: Session, path: Path, text: str | None = None) -> Document:
    if text is None:
        text = path.read_bytes().decode("latin-1")
    document = Document(path.as_uri(), path, text, 1)
    session.open(document)
    return document


def test_definition_of_a_start_up_entry_uses_the_configured_cnc_root(tmp_path: Path) -> None:
    """`cnc-root` in the configuration decides which file a start-up entry names (`achslint lint` reads that
    one); go to definition opened the file under the start-up list's own folder instead."""
    from achslint.lsp import features

    (tmp_path / ".git").mkdir()  # the repository the CNC root must lie in
    (tmp_path / "achslint.toml").write_text('cnc-root = "cnc"\n', encoding="utf-8")
    startup = tmp_path / "starts" / "hochlauf.lis"
    configured = tmp_path / "cnc" / "listen" / "achsmds1.lis"
    beside = tmp_path / "starts" / "listen" / "achsmds1.lis"  # where the entry points without the setting
    for path, text in (
        (startup, "achs_mds[0]  ./listen/achsmds1.lis\nEnde\n"),
        (configured, "kopf.achs_nr  1\nkenngr.ref_richt  7\nEnde\n"),
        (beside, "kopf.achs_nr  1\nEnde\n"),
    ):
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="latin-1")
    linted = {Path(d.path).resolve() for d in lint_paths([startup])}
    assert configured.resolve() in linted and beside.resolve() not in linted
    session = Session(tmp_path)
    document = opened(session, startup)
    snapshot = session.snapshot(document.uri)
    assert snapshot is not None and snapshot.startup
    found = features.definition(document, snapshot, 1, 14, lambda: session.startup_entries(document))
    assert [location.uri for location in found] == [configured.as_uri()]
