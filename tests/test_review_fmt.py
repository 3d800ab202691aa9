"""Review of `achslint fmt` on nasty lists: what it promises (only blanks and tabs change, each line break, the
encoding and the byte-order mark kept, idempotent, the editor's formatting the same as the command's,
`--diff` showing what is written) checked on variants of every fixture list, and the bugs found."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from achslint.core.decode import decode
from achslint.fmt import FmtOptions, LiveFormat, format_bytes, format_file
from achslint.syntax import parser as syntax

from .conftest import FIXTURES, THOROUGH
from .fixture_lists import distinct

LISTS = sorted(path for path in FIXTURES.rglob("*") if path.suffix.lower() == ".lis")
# Every fixture list in its eleven variants and four settings takes about 9 s: the default run takes every
# tenth list (the same ones each time), `ACHSLINT_THOROUGH=1` all of them, as the property tests do; a copy
# of a list taken already (same bytes and name) is left out.
SWEPT = distinct(LISTS if THOROUGH else LISTS[::10])
OPTIONS = [
    None,
    FmtOptions(align_values="right"),
    FmtOptions(value_column=30, comment_column=50),
    FmtOptions(comment_column=1),
]


def variants(data: bytes) -> dict[str, bytes]:
    """The list with other line breaks, a BOM, tabs, trailing blanks, no end marker, text after it, Latin-1."""
    lf = data.replace(b"\r\n", b"\n")
    lines = lf.split(b"\n")
    breaks = [b"\n", b"\r\n", b"\r"]
    return {
        "crlf": lf.replace(b"\n", b"\r\n"),
        "cr": lf.replace(b"\n", b"\r"),
        "mixed": b"".join(line + breaks[index % 3] for index, line in enumerate(lines)),
        "bom": b"\xef\xbb\xbf" + data,
        "tabs": re.sub(rb"  +", b"\t", data),
        "trailing": b"".join(line + b"  \t\n" for line in lines),
        "no end": re.sub(rb"(?m)^[ \t]*Ende.*$", b"", data),
        "after end": data + b"\n  kopf.achs_nr   3  ( x\n\n   \n",
        "latin-1": data.replace(b"(", "(\xe4\xf6 ".encode("latin-1"), 3),
        "gaps": re.sub(rb"[ \t]+", lambda m: [b" ", b"  ", b"\t", b" \t "][len(m.group()) % 4], data),
    }


BLANKS = str.maketrans("", "", " \t")


def without_blanks(text: str) -> str:
    return text.translate(BLANKS)


def assert_fmt_promises(data: bytes, options: FmtOptions | None) -> None:
    out, _ = format_bytes(data, "achsmds1.lis", options)
    assert format_bytes(out, "achsmds1.lis", options) == (out, False), "formatting twice changes the file"
    source, result = decode(data), decode(out)
    assert (source.encoding, source.bom) == (result.encoding, result.bom)
    before = syntax.split_lines(source.text, keepends=True)
    after = syntax.split_lines(result.text, keepends=True)
    assert len(after) <= len(before)
    for number, (old, new) in enumerate(zip(before, after, strict=False), 1):
        old_body, new_body = old.rstrip("\r\n"), new.rstrip("\r\n")
        assert without_blanks(old_body) == without_blanks(new_body), number
        if number < len(after):  # (the end marker gets a break when it has none)
            assert old[len(old_body) :] == new[len(new_body) :], number
    assert all(not line.strip(" \t\r\n") for line in before[len(after) :]), "a line with content was dropped"
    live = LiveFormat(options)
    live.update(before)
    assert live.text() == result.text == format_file(syntax.parse_text(source.text), options)


@pytest.mark.parametrize("path", SWEPT, ids=lambda path: str(path.relative_to(FIXTURES)))
def test_variants_of_every_fixture_list_keep_fmts_promises(path: Path):
    data = path.read_bytes()
    for name, variant in variants(data).items():
        for options in OPTIONS:
            try:
                assert_fmt_promises(variant, options)
            except AssertionError as exc:
                raise AssertionError(f"{name}, {options}: {exc}") from exc


NASTY = {
    "empty": b"",
    "only a break": b"\n",
    "blank lines": b"\n \n\t\n",
    "end marker alone": b"Ende",
    "indented end marker": b"kopf.achs_nr 1\n   Ende   \n",
    "end marker with a comment": b"kopf.achs_nr 1\nEnde\t\t( r\t\n",
    "content after the end marker": b"kopf.achs_nr 1\nEnde\n\n  kopf.achs_nr    2   ( c  \n\n",
    "string with blanks": b'kopf.achs_nr      1\nkopf.log_achs_name   "a b  c"     ( c\nkenngr.swe_pos    100\n',
    "text after a string": b'kopf.achs_nr      1\nkopf.log_achs_name   "a"    text  here\nkenngr.swe_pos  100\n',
    "tabbed text after a string": b'kopf.achs_nr\t1\nkopf.log_achs_name\t"a"\t\ttext\nkenngr.swe_pos\t100\n',
    "comment lines": b"# top\n   # indented  \n( paren\n\t( tabbed\nkopf.achs_nr   1\n",
    "unreadable lines": b'kopf.achs_nr   1\n  =====  weird    line  \nkopf..x   5\n12 34\n"oops   \nkenngr.swe_pos 1\n',
    "very long name": b"kopf.achs_nr   1\nkenngr.swe_pos  2\n" + b"a" * 300 + b".b[0].c 7   ( c\nEnde\n",
    "blank lines between CR and LF": b"kopf.achs_nr 1\r\n  \n   \r\nkenngr.swe_pos    2\rEnde\r\n",
    "CR then a blank line with LF": b"kopf.achs_nr   1\r \nkenngr.swe_pos 2\n",
    "Latin-1": "kopf.achs_nr   1   ( Größe\nkopf.log_achs_name   Ä  \nEnde\n".encode("latin-1"),
    "BOM only": b"\xef\xbb\xbf",
    "no-break space": "kopf.achs_nr\xa0  1\nEnde\n".encode("latin-1"),
    "tab inside a string": b'kopf.achs_nr  1\nkopf.log_achs_name  "a\tb"  ( c\nkenngr.swe_pos  2\n',
    "no value": b"kopf.achs_nr\nkopf.log_achs_name    \nkenngr.swe_pos  2\n",
    "end marker without a break after CR": b"kopf.achs_nr 1\rEnde",
}


@pytest.mark.parametrize("name", NASTY)
@pytest.mark.parametrize("options", [*OPTIONS, FmtOptions(align_values="right", value_column=3)])
def test_nasty_lists_keep_fmts_promises(name, options):
    assert_fmt_promises(NASTY[name], options)


def test_text_after_a_string_keeps_the_blanks_before_it():
    data = b'kopf.achs_nr          1\nkopf.log_achs_name "a"    text  here\nkenngr.swe_pos        100\n'
    out, changed = format_bytes(data)
    assert changed
    assert b'kopf.log_achs_name    "a"    text  here\n' in out


@pytest.mark.parametrize("name", ["text after a string", "Latin-1", "very long name", "string with blanks"])
def test_check_and_diff_exit_codes_and_the_diff_is_what_is_written(cli, tmp_path, name):
    data = NASTY[name]
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(data)
    written, changed = format_bytes(data, path.name)
    check = cli("fmt", "--check", str(path))
    assert check.returncode == (1 if changed else 0)
    diff = cli("fmt", "--diff", str(path))
    assert diff.returncode == check.returncode and path.read_bytes() == data
    new = [line[1:] for line in diff.stdout.decode().splitlines(keepends=True) if line.startswith("+")]
    expected = decode(written).text.splitlines(keepends=True)
    assert all(line in expected for line in new[1:])  # (the first is the +++ header)
    assert cli("fmt", str(path)).returncode == 0 and path.read_bytes() == written
    assert cli("fmt", "--check", str(path)).returncode == 0


def test_diff_shows_an_escape_sequence_the_list_holds(cli, tmp_path):
    # The diff went through the echo that strips ANSI escape sequences when standard output is no terminal:
    # `fmt --diff > change.patch` lost the `ESC [ 3 1 m` the file holds (and fmt keeps), so the diff no
    # longer showed what fmt writes and did not apply. `lint --fix --diff` writes its diff as it is.
    path = tmp_path / "achsmds1.lis"
    data = b"kopf.achs_nr  1  ( \x1b[31mred\nkenngr.swe_pos 2\nEnde\n"
    path.write_bytes(data)
    written, changed = format_bytes(data, path.name)
    assert changed and b"( \x1b[31mred\n" in written
    diff = cli("fmt", "--diff", str(path))
    assert diff.returncode == 1
    assert b"-kopf.achs_nr  1  ( \x1b[31mred\n" in diff.stdout
    assert b"+kopf.achs_nr    1 ( \x1b[31mred\n" in diff.stdout


@pytest.mark.parametrize("value", ["true", '"30"', "30.0"])
def test_fmt_columns_in_the_configuration_must_be_numbers(cli, tmp_path, value):
    """`value-column = true` was read as column 1 and `"30"` as 30 (pydantic's lax mode)."""
    (tmp_path / ".achslint.toml").write_text(f"[fmt]\nvalue-column = {value}\n", encoding="utf-8")
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(b"kopf.achs_nr 1\nkenngr.swe_pos 2\nEnde\n")
    result = cli("fmt", "--check", str(path))
    assert result.returncode == 2 and b"value-column" in result.stderr
