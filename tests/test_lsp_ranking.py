"""Completion ranks paths from what the list sets, worked out once per parse (`features._Written`): the
ranks are those of walking the list afresh for the cursor's line, on every line of a list that sets paths
once, twice and by index."""

from __future__ import annotations

from pathlib import Path

import pytest

pytest.importorskip("lsprotocol", reason="the lsp extra is not installed")

from achslint.catalogue.kinds import AXIS
from achslint.lsp import features
from achslint.lsp.documents import Document
from achslint.lsp.session import Session
from achslint.syntax import parser as syntax

LIST = (
    "kopf.achs_nr 1\n"
    "getriebe[0].vb_reflow 100\n"
    "# a comment between\n"
    "getriebe[1].vb_reflow 200\n"
    "kenngr.homing.homing_type CNC_CONTROLLED\n"
    "getriebe[0].vb_reflow 300\n"
    "lr_hw[0].nummer 1\n"
    "kopf.log_achs_name X\n"
    "Ende\n"
)


def afresh(file: syntax.ListFile, line_number: int) -> tuple[set[str], set[str], str | None]:
    """What the list sets apart from the cursor's line (paths, patterns) and the path nearest the line."""
    paths = [
        (line.number, line.path.lower())
        for line in file.lines
        if line.kind == syntax.ASSIGNMENT and line.path_ok and line.path and line.number != line_number
    ]
    written = {path for _, path in paths}
    above = [path for number, path in paths if number < line_number]
    below = [path for number, path in paths if number > line_number]
    near = above[-1] if above else (below[0] if below else None)
    return written, {syntax.path_pattern(path)[0] for path in written}, near


def test_ranks_are_those_of_the_list_walked_for_each_line(tmp_path: Path):
    path = tmp_path / "achsmds1.lis"
    path.write_text(LIST, encoding="utf-8")
    session = Session(tmp_path)
    document = Document(path.as_uri(), path, LIST, 1)
    session.open(document)
    snapshot = session.snapshot(document.uri)
    assert snapshot is not None and snapshot.file is not None
    catalogue = AXIS.catalogue()
    assert catalogue is not None
    wanted = [
        "kopf.achs_nr",
        "kopf.log_achs_name",
        "getriebe[i].vb_reflow",
        "lr_hw[i].nummer",
        "kopf.clone_of",
    ]
    parameters = [p for p in catalogue.parameters if p.path in wanted]
    assert len(parameters) >= 4
    seen = set()
    for number in range(1, len(snapshot.file.lines) + 1):
        around = features._Around.of(snapshot, AXIS, number)
        written, patterns, near = afresh(snapshot.file, number)
        near_group = syntax.path_pattern(near.rsplit(".", 1)[0])[0] if near and "." in near else None
        assert around.group == near_group
        for parameter in parameters:
            labels = [parameter.path]
            if "[i]" in parameter.path:
                labels += [parameter.path.replace("[i]", f"[{index}]") for index in (0, 1, 2)]
            for label in labels:
                lowered = label.lower()
                expected = lowered in written if "[i]" not in lowered else parameter.path in patterns
                assert around.rank(parameter, label)[0] == str(int(expected)), (number, label)
                seen.add((label, expected))
    # the cases that matter were met: set elsewhere, set only on the cursor's line, never set
    assert ("getriebe[0].vb_reflow", True) in seen and ("kopf.achs_nr", False) in seen
    assert ("getriebe[2].vb_reflow", False) in seen and ("getriebe[i].vb_reflow", True) in seen
