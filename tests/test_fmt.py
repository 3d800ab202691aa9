"""`achslint fmt`: whitespace-only, lossless, idempotent, atomic."""

from __future__ import annotations

import os
import stat

from hypothesis import given, settings
from hypothesis import strategies as st

from achslint.core.decode import decode
from achslint.fmt import format_bytes

from .conftest import FIXTURES, examples

MESSY = (
    "# header comment   \r\n"
    "   kopf.achs_nr\t1\t( P-AXIS-00016 : axis number   \r\n"
    "kenngr.homing.homing_type        CNC_CONTROLLED      ( old value   \r\n"
    "\t \r\n"
    "getriebe[0].vb_reflow   20000   # µm/s comment\r\n"
    "kopf.log_achs_name  X_Achse   # belongs to the string for the CNC\r\n"
    "antr.fixed_stop.drive_ident[0].rd_ident   \r\n"
    "bad[i].line    5\r\n"
    "Ende\r\n"
    "\r\n"
    "\r\n"
).encode("latin-1")


def tokens(data: bytes) -> list[list[str]]:
    lines = decode(data).text.splitlines()
    while lines and not lines[-1].strip():
        lines.pop()
    return [line.split() for line in lines]


def test_canonical_layout():
    formatted, changed = format_bytes(MESSY)
    assert changed
    text = formatted.decode("latin-1")
    lines = text.split("\r\n")
    column = len("antr.fixed_stop.drive_ident[0].rd_ident") + 2
    assert lines[1] == "kopf.achs_nr".ljust(column) + "1 ( P-AXIS-00016 : axis number"
    assert lines[2] == "kenngr.homing.homing_type".ljust(column) + "CNC_CONTROLLED ( old value"
    assert lines[3] == ""
    assert lines[4] == "getriebe[0].vb_reflow".ljust(column) + "20000 # µm/s comment"
    # After a string value, blanks before non-"(" text may be part of the string: left as they are.
    assert lines[5] == "kopf.log_achs_name".ljust(column) + "X_Achse   # belongs to the string for the CNC"
    assert lines[6] == "antr.fixed_stop.drive_ident[0].rd_ident"
    assert lines[7] == "bad[i].line    5"  # unparsable lines are not touched (besides trailing blanks)
    assert text.endswith("Ende\r\n") and not text.endswith("\r\n\r\n")


def test_bytes_encoding_and_line_endings_are_kept():
    formatted, _ = format_bytes(MESSY)
    assert "µ".encode("latin-1") in formatted and "µ".encode() not in formatted
    assert formatted.count(b"\r\n") == formatted.count(b"\n")
    mixed = b"a 1\r\nbb 2\nEnde\r\n"
    assert format_bytes(mixed)[0] == b"a   1\r\nbb  2\nEnde\r\n"
    bom = b"\xef\xbb\xbfa 1\nEnde\n"
    assert format_bytes(bom)[0].startswith(b"\xef\xbb\xbfa  1")


def test_idempotent_and_token_preserving_on_fixtures():
    for path in sorted(FIXTURES.rglob("*.lis")):
        data = path.read_bytes()
        once, _ = format_bytes(data)
        twice, changed = format_bytes(once)
        assert twice == once and not changed, path
        assert tokens(once) == tokens(data), path


PIECES = st.sampled_from(
    [
        "kopf.achs_nr",
        "getriebe[0].vb_reflow",
        "kenngr.homing.homing_type",
        "kopf.log_achs_name",
        "Ende",
        "#",
        "( comment",
        "# note",
        "/* c",
        "1",
        "0x400001",
        "-1.5E-3",
        "X_Achse",
        '"a (b)"',
        "P-AXIS-00212.0",
        "bad[x]",
        " ",
        "  ",
        "\t",
        "\n",
        "\r\n",
        "µ",
    ]
)


@settings(max_examples=examples(300), deadline=None)
@given(st.lists(PIECES, max_size=40).map("".join))
def test_format_preserves_tokens_and_is_idempotent(text):
    data = text.encode("latin-1")
    once, _ = format_bytes(data)
    assert tokens(once) == tokens(data)
    assert format_bytes(once)[0] == once


def test_cli_check_diff_and_write(cli, tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(MESSY)
    os.chmod(path, 0o640)
    check = cli("fmt", "--check", str(path))
    assert check.returncode == 1 and b"would reformat" in check.stdout
    assert path.read_bytes() == MESSY  # --check touches nothing
    diff = cli("fmt", "--diff", str(path))
    assert diff.returncode == 1 and b"+kopf.achs_nr" in diff.stdout
    assert path.read_bytes() == MESSY
    written = cli("fmt", str(path))
    assert written.returncode == 0
    assert path.read_bytes() == format_bytes(MESSY)[0]
    assert stat.S_IMODE(path.stat().st_mode) == 0o640
    assert [p.name for p in tmp_path.iterdir()] == ["achsmds1.lis"]  # no temporary file left behind
    again = cli("fmt", "--check", str(path))
    assert again.returncode == 0


def test_cli_stdin_and_unreadable(cli, tmp_path):
    result = cli("fmt", "-", stdin=b"a 1\nbb 2\nEnde\n")
    assert result.stdout == b"a   1\nbb  2\nEnde\n"
    wide = tmp_path / "achsmds2.lis"
    wide.write_bytes("a 1\n".encode("utf-16"))
    assert cli("fmt", str(wide)).returncode == 2


def test_pre_commit_hooks_name_real_commands(cli):
    from .conftest import ROOT

    text = (ROOT / ".pre-commit-hooks.yaml").read_text()
    entries = [line.split("entry:", 1)[1].split() for line in text.splitlines() if "entry:" in line]
    assert [entry[:2] for entry in entries] == [["achslint", "lint"], ["achslint", "fmt"]]
    for entry in entries:
        assert cli(*entry[1:], "--help").returncode == 0
