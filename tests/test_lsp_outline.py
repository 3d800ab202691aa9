"""The outline as the server sends it (`outline.Outline`, JSON kept line by line) is the outline
`features.document_symbols` describes, before and after edits, in every position encoding."""

from __future__ import annotations

import json

import pytest

pytest.importorskip("lsprotocol", reason="the lsp extra is not installed")

from lsprotocol import converters

from achslint.lsp import features, outline
from achslint.lsp.documents import Document

from .conftest import FIXTURES

CONVERTER = converters.get_converter()


def expected(document: Document) -> list[dict]:
    return CONVERTER.unstructure(features.document_symbols(document, document.parse()))


def sent(kept: outline.Outline, document: Document) -> list[dict]:
    return json.loads(kept.json(document, document.parse()))


LISTS = [
    FIXTURES / "lists" / "achsmds1.lis",
    FIXTURES / "lists" / "achsmds2.lis",
    FIXTURES / "rules" / "LIS005" / "bad.lis",
]


@pytest.mark.parametrize("path", LISTS, ids=lambda p: p.parent.name + "/" + p.name)
@pytest.mark.parametrize("encoding", ["utf-16", "utf-8", "utf-32"])
def test_outline_is_document_symbols_while_lines_are_edited(path, encoding):
    text = path.read_bytes().decode("latin-1")
    document = Document("file:///outline/achsmds1.lis", None, text, 1, encoding)
    kept = outline.Outline()
    assert sent(kept, document) == expected(document) != []
    lines = document.lines
    number = next(i for i, line in enumerate(lines) if line.startswith("kopf"))
    # a value typed over, a path renamed into another group, a line joined with the next, a new line
    document.apply((number, len(lines[number])), (number, len(lines[number])), "7")
    assert sent(kept, document) == expected(document)
    document.apply((number, 0), (number, 4), "neu_gruppe")
    assert sent(kept, document) == expected(document)
    document.apply((number, len(document.lines[number])), (number + 1, 0), "  ")
    assert sent(kept, document) == expected(document)
    document.apply((0, 0), (0, 0), "kopf.achs_nr 3\n")
    assert sent(kept, document) == expected(document)


@pytest.mark.parametrize("encoding", ["utf-16", "utf-8"])
def test_outline_measures_wide_characters_and_the_byte_order_mark(encoding):
    text = (
        "\ufeffkopf.achs_nr  1  # \U0001d707 wide\ngetriebe[0].vb_reflow  \u00e4\u00e4  ( \U0001d707\nEnde\n"
    )
    document = Document("file:///outline/achsmds1.lis", None, text, 1, encoding)
    kept = outline.Outline()
    assert sent(kept, document) == expected(document)
    document.apply((1, 0), (1, 0), "x")  # the text stays non-ASCII: lines are measured, kept lines too
    assert sent(kept, document) == expected(document)
    document.apply((0, 0), (0, 1), "")  # no mark any more
    assert sent(kept, document) == expected(document)


def test_a_list_beyond_the_limit_is_outlined_by_its_groups(monkeypatch):
    monkeypatch.setattr(outline, "LIMIT", 3)
    text = (
        "kopf.achs_nr 1\ngetriebe[0].vb_reflow 100\ngetriebe[0].vb_min_null 1\nkopf.log_achs_name X\nEnde\n"
    )
    document = Document("file:///outline/achsmds1.lis", None, text, 1)
    full = expected(document)
    groups = sent(outline.Outline(), document)
    assert [s["name"] for s in groups] == [s["name"] for s in full] == ["kopf", "getriebe[0]", "Ende"]
    assert all("children" not in s for s in groups)
    assert [s.get("detail", "").split(" ")[0] for s in groups[:2]] == ["2", "2"]
    assert [s["range"] for s in groups] == [s["range"] for s in full]  # each group still spans its lines
    monkeypatch.setattr(outline, "LIMIT", 4)
    assert sent(outline.Outline(), document) == full
