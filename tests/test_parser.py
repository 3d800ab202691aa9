"""The grammar and the lossless syntax tree."""

from __future__ import annotations

import pytest

from achslint.core.decode import UnreadableInput, decode
from achslint.syntax import parser as syntax
from achslint.syntax.parser import parse_bytes, parse_text

from .conftest import FIXTURES

SAMPLE = (
    "# Achsmaschinendaten\r\n"
    "kopf.achs_nr                  1     ( P-AXIS-00016 : logical axis number\r\n"
    "\t\r\n"
    "   #TC_AXIS_DESC: indented marker\r\n"
    "kenngr.achs_mode       0x400001\r\n"
    "getriebe[0].vb_refmax    100000  [µm/s] bare text comment\r\n"
    "kenngr.faktor          -1.92901234E-10 /* c style\r\n"
    "handbetrieb.hb.vb_max  P-AXIS-00212.0\r\n"
    'kopf.log_achs_name     "X (1)"   ( quoted because of the paren\r\n'
    "antr.fixed_stop.drive_ident[0].rd_ident\r\n"
    "Ende\r\n"
)


def test_kinds_values_and_columns():
    file = parse_text(SAMPLE)
    kinds = [line.kind for line in file.lines]
    assert kinds == [
        "comment",
        "assignment",
        "blank",
        "comment",
        "assignment",
        "assignment",
        "assignment",
        "assignment",
        "assignment",
        "assignment",
        "end",
        "blank",
    ]
    achs_nr = file.lines[1]
    assert (achs_nr.path, achs_nr.value, achs_nr.value_kind) == ("kopf.achs_nr", "1", syntax.INT)
    assert achs_nr.value_column == 31
    assert achs_nr.rest == "( P-AXIS-00016 : logical axis number"
    assert achs_nr.rest_column == 37
    assert file.lines[3].indent == "   " and file.lines[3].comment.startswith("#TC_AXIS_DESC:")
    assert file.lines[4].value_kind == syntax.HEX
    assert file.lines[5].rest == "[µm/s] bare text comment"
    assert (file.lines[6].value, file.lines[6].value_kind) == ("-1.92901234E-10", syntax.REAL)
    assert file.lines[7].value_kind == syntax.REFERENCE
    assert (file.lines[8].value, file.lines[8].value_kind) == ('"X (1)"', syntax.STRING)
    assert file.lines[9].value is None
    assert file.end_index == 10
    assert all(line.newline == "\r\n" for line in file.lines[:-1])


def test_round_trip_is_byte_identical_for_fixtures():
    for path in sorted(FIXTURES.rglob("*.lis")):
        data = path.read_bytes()
        file = parse_bytes(data, str(path))
        assert decode(data).encode(file.unparse()) == data, path


@pytest.mark.parametrize("newline", ["\n", "\r\n", "\r"])
def test_line_numbers_for_every_line_break_style(newline):
    text = newline.join(["a 1", "", "bad[x] 2", "c 3"]) + newline
    file = parse_text(text)
    assert [line.number for line in file.lines if line.path] == [1, 3, 4]
    assert file.lines[2].path_ok is False
    assert file.unparse() == text


def test_a_bad_line_does_not_stop_the_rest():
    file = parse_text('x[ 1\n"open 2\nkenngr.ref_richt 1\n')
    assert [line.path_ok for line in file.lines[:3]] == [False, False, True]
    assert file.lines[2].value == "1"


def test_value_lookalikes_are_words():
    file = parse_text("a 12abc\nb 0x1G\nc 1e\nd P-AXIS-12x\n")
    assert all(line.value_kind == syntax.SYMBOL for line in file.lines[:4])


def test_encodings_and_bom():
    latin = "kopf.log_achs_name X ( µm\n".encode("latin-1")
    assert decode(latin).encoding == "cp1252"
    assert decode("a 1 ( µm\n".encode()).encoding == "utf-8"
    with_bom = b"\xef\xbb\xbfa 1\n"
    source = decode(with_bom)
    assert source.bom and source.text == "a 1\n" and source.encode() == with_bom
    with pytest.raises(UnreadableInput):
        decode("a 1\n".encode("utf-16"))


def test_split_path_and_pattern():
    assert syntax.split_path("antr.function[2].wr_ident[1]") == [
        ("antr", ()),
        ("function", (2,)),
        ("wr_ident", (1,)),
    ]
    assert syntax.path_pattern("getriebe[3].achs_position[2]") == ("getriebe[i].achs_position[i]", (3, 2))


GRAMMAR_PROBE = (
    "from achslint.syntax.parser import parse_text\n"
    "print([line.kind for line in parse_text('kopf.achs_nr 1\\nEnde\\n').lines])\n"
)


def _probe(cache_home):
    import os
    import subprocess
    import sys

    env = {**os.environ, "XDG_CACHE_HOME": str(cache_home)}
    return subprocess.run(
        [sys.executable, "-c", GRAMMAR_PROBE], capture_output=True, text=True, env=env, timeout=60
    )


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_grammar_cache_is_private_and_a_damaged_cache_is_harmless(tmp_path):
    first = _probe(tmp_path)
    assert first.returncode == 0, first.stderr
    folder = tmp_path / "achslint"
    caches = list(folder.glob("grammar-*.lark-cache"))
    assert len(caches) == 1
    assert folder.stat().st_mode & 0o777 == 0o700
    caches[0].write_bytes(b"not a pickle at all")
    second = _probe(tmp_path)
    assert second.returncode == 0, second.stderr
    assert second.stdout == first.stdout
    assert "Traceback" not in second.stderr


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_grammar_cache_is_not_used_in_a_folder_others_can_write(tmp_path):
    folder = tmp_path / "achslint"
    folder.mkdir()
    folder.chmod(0o777)
    result = _probe(tmp_path)
    assert result.returncode == 0, result.stderr
    assert list(folder.iterdir()) == []


def test_the_grammar_without_possessive_repeats_reads_every_line_alike():
    """Python 3.10 reads the PATH terminal with plain repeats (`_without_possessive`): the same tokens for
    every fixture line and for paths made to tempt backtracking (indices, members, hyphens, a trailing dot)."""
    from lark import Lark

    possessive = syntax._grammar_text()
    plain = syntax._without_possessive(possessive)
    path = [line for line in possessive.splitlines() if line.startswith("PATH.")]
    plain_path = [line for line in plain.splitlines() if line.startswith("PATH.")]
    assert "*+" in path[0] and "*+" not in plain_path[0] and "++" not in plain_path[0]
    lexers = [
        Lark(text, parser="lalr", lexer="contextual", maybe_placeholders=False)
        for text in (possessive, plain)
    ]
    lines = {
        line
        for path in FIXTURES.glob("**/*.lis")
        for line in path.read_bytes().decode("latin-1").splitlines()
    }
    lines |= {
        "getriebe" + "[0]" * 50 + ".vb_reflow 1",
        "a[0]x 1",
        "a[0]. 1",
        "a.b-c[12][3].d 1",
        "a..b 1",
        "a[ 1",
        "a[0]] 1",
        "_x[9].y[0] 2",
        "x.[0] 1",
    }
    for line in sorted(lines):
        tokens = [[(t.type, str(t)) for t in lexer.lex(line + "\n")] for lexer in lexers]
        assert tokens[0] == tokens[1], line


def test_split_lines_breaks_only_where_the_parser_does():
    # Every text of up to four characters over line breaks, the characters only str.splitlines breaks at, and
    # ordinary ones: the quick way (str.splitlines on a text without the latter) and the pattern agree.
    import itertools

    alphabet = ["a", "\r", "\n", "\x0b", "\x0c", "\x1c", "\x1e", "\x85", "\u2028", "\u2029", "é"]
    for length in range(5):
        for letters in itertools.product(alphabet, repeat=length):
            text = "".join(letters)
            kept = syntax._LINE.findall(text)
            assert syntax.split_lines(text, keepends=True) == kept, repr(text)
            assert syntax.split_lines(text) == [line.rstrip("\r\n") for line in kept], repr(text)
    assert syntax.split_lines("a\x0bb\r\nc\u2028d") == ["a\x0bb", "c\u2028d"]
