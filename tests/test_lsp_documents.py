"""The language server's document model: line-by-line parsing and LSP positions (no pygls needed)."""

from __future__ import annotations

import subprocess
import sys

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from achslint.lsp.documents import Document, LineCache
from achslint.syntax.parser import parse_text, split_lines

from .conftest import examples

PIECES = st.sampled_from(
    [
        "kopf.achs_nr",
        " ",
        "\t",
        "1",
        "0x1F",
        '"a b"',
        "( c",
        "# d",
        "Ende",
        "End",
        "getriebe[0].vb_reflow",
        "P-AXIS-00212.0",
        "\n",
        "\r\n",
        "\r",
        "\x0c",
        "\u2028",
        "µ",
        "\U0001f600",
        "[",
        "\ufeff",
        "",
    ]
)
TEXTS = st.lists(PIECES, max_size=40).map("".join)


def fields(file):
    return [
        (
            line.kind,
            line.indent,
            line.path,
            line.path_ok,
            line.sep,
            line.value,
            line.value_kind,
            line.sep2,
            line.rest,
            line.comment,
            line.newline,
            line.number,
        )
        for line in file.lines
    ], file.end_index


@settings(max_examples=examples(150), deadline=None)
@given(TEXTS, TEXTS, st.integers(min_value=0, max_value=400))
def test_line_cache_parse_equals_the_full_parse_after_any_edit(before, inserted, at):
    cache = LineCache()
    assert fields(cache.parse(before, "x")) == fields(parse_text(before))
    at = min(at, len(before))
    after = before[:at] + inserted + before[at:]
    assert fields(cache.parse(after, "x")) == fields(parse_text(after))


POSITION = st.tuples(st.integers(0, 12), st.integers(0, 12))


@settings(max_examples=examples(300, 40), deadline=None)
@given(TEXTS, st.lists(st.tuples(POSITION, POSITION, TEXTS), min_size=1, max_size=6))
def test_edits_keep_the_lines_as_a_fresh_split_has_them(text, edits):
    # apply() re-reads only the lines around an edit; the text and its lines must be those of the whole
    # text read again, wherever the edit falls (CR and LF joined or split, past the end, reversed ranges).
    document = Document("file:///a.lis", None, text)
    for start, end, inserted in edits:
        fresh = Document("file:///a.lis", None, document.text)
        a = fresh.offset(*start)
        expected = fresh.text[:a] + inserted + fresh.text[max(a, fresh.offset(*end)) :]
        document.apply(start, end, inserted)
        assert document.text == expected
        assert document.raw_lines == split_lines(expected, keepends=True)
        assert document.lines == Document("file:///a.lis", None, expected).lines


def test_positions_count_utf16_units_and_only_real_line_breaks():
    document = Document("file:///a.lis", None, "a\x0cb \U0001f600 x\r\nµ 1\rEnde")
    assert document.lines == ["a\x0cb \U0001f600 x", "µ 1", "Ende"]
    assert document.to_lsp(1, 7) == (0, 7)  # the emoji before column 7 is two UTF-16 units
    assert document.from_lsp(0, 7) == (1, 7)
    assert document.to_lsp(2, 3) == (1, 2)
    utf32 = Document("file:///a.lis", None, document.text, encoding="utf-32")
    assert utf32.to_lsp(1, 7) == (0, 6)
    document.apply((1, 0), (1, 1), "m")  # replace µ
    document.apply((0, 7), (0, 8), "y")
    assert document.text == "a\x0cb \U0001f600 y\r\nm 1\rEnde"


def test_byte_order_mark_kept_by_the_editor_shifts_only_the_first_line():
    document = Document("file:///a.lis", None, "\ufeffkopf.achs_nr 1\nEnde\n")
    assert (
        document.body.startswith("kopf")
        and document.to_lsp(1, 1) == (0, 1)
        and document.to_lsp(2, 1) == (1, 0)
    )


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_server_without_the_extra_names_it_and_exits_2():
    blocked = (
        "import sys; sys.modules['pygls'] = None; sys.modules['pygls.lsp.server'] = None; "
        "from achslint.cli import main; raise SystemExit(main(['server']))"
    )
    done = subprocess.run(
        [sys.executable, "-c", blocked], check=False, capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 2
    assert (
        done.stderr.strip()
        == "achslint: the language server needs the `lsp` extra: in the achslint checkout, pip install '.[lsp]'"
    )
