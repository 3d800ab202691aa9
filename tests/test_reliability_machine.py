"""Machines, NC programs and XML never crash and say what they did (issue 22, items 7, 10 and 11).

Each test builds its hostile input in `tmp_path` and runs it the way a user would: through the command line
in this process (`achslint.cli.main`) or through the function the command calls. Every test failed before
the change it guards.
"""

from __future__ import annotations

import io
import sys
from pathlib import Path

import pytest

from achslint.cli import main
from achslint.decode import UnreadableInput
from achslint.xmlinput import extract, source_text


@pytest.fixture
def run(capsys, monkeypatch):
    """The command line in this process: (exit code, stdout, stderr)."""

    def invoke(*args: str | Path):
        monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(b"")))
        code = main([str(a) for a in args])
        out, err = capsys.readouterr()
        return code, out, err

    return invoke


# -- XML in an encoding expat cannot use, or with a lone surrogate (item 10) ---------------------------

# A list with a finding of its own (LIS005): it must still be reported beside a refused XML file.
DUPLICATE = b"kopf.achs_nr 1\nkopf.achs_nr 2\nEnde\n"


def _axis_xml(encoding: str) -> bytes:
    return (
        f'<?xml version="1.0" encoding="{encoding}"?>\n'
        "<TcSmProject><IsgAxisDef><AchsMds><![CDATA[kopf.achs_nr 7\nEnde\n]]></AchsMds></IsgAxisDef>"
        "</TcSmProject>\n"
    ).encode("ascii")


UNUSABLE_ENCODINGS = ["Shift_JIS", "GB2312", "EUC-KR", "Big5", "UTF-7", "IDNA", "punycode", "utf-32"]


@pytest.mark.parametrize("encoding", UNUSABLE_ENCODINGS)
def test_xml_in_an_encoding_expat_cannot_use_is_refused_alone(run, tmp_path, encoding):
    (tmp_path / "achsmds1.lis").write_bytes(DUPLICATE)
    (tmp_path / "axis.xml").write_bytes(_axis_xml(encoding))
    code, out, err = run("lint", tmp_path)
    assert "internal error" not in err and "Traceback" not in err
    [line] = [line for line in err.splitlines() if "axis.xml" in line]
    assert f"declares the encoding `{encoding}`" in line and "save it as UTF-8" in line
    assert code == 2
    assert "achsmds1.lis:2:1: LIS005" in out  # the list beside it is still linted


@pytest.mark.parametrize("encoding", UNUSABLE_ENCODINGS)
def test_the_list_beside_an_unusable_xml_is_linted_with_its_folder(run, tmp_path, encoding):
    # Named alone, the list is checked against its folder, which reads the XML file for LIS501-LIS503.
    (tmp_path / "achsmds1.lis").write_bytes(DUPLICATE)
    (tmp_path / "axis.xml").write_bytes(_axis_xml(encoding))
    code, out, err = run("lint", tmp_path / "achsmds1.lis")
    assert "internal error" not in err and "Traceback" not in err
    assert code == 0 and "achsmds1.lis:2:1: LIS005" in out  # a warning: the run passes


def test_an_own_handler_error_is_not_blamed_on_the_encoding(monkeypatch):
    # The encoding refusal covers what expat raises before the first element, not a fault of ours later.
    from achslint import xmlinput

    def broken(self, *args):
        raise ValueError("a bug")

    monkeypatch.setattr(xmlinput._Collector, "characters", broken)
    with pytest.raises(ValueError, match="a bug"):
        extract(_axis_xml("cp1252"), "axis.xml")


@pytest.mark.parametrize(
    "data",
    [
        # UTF-8 bytes of a high surrogate, in the list text
        b"<AchsMds>kopf.log_achs_name X\xed\xa0\x80\nEnde\n</AchsMds>",
        # a character reference to one
        b"<AchsMds>kopf.log_achs_name X&#xD800;\nEnde\n</AchsMds>",
        # a lone low surrogate in UTF-16, in an ISG attribute
        b"\xff\xfe"
        + '<AX_MDS><P-AXIS-00297 Value="X'.encode("utf-16-le")
        + b"\x00\xdc"
        + '"/></AX_MDS>'.encode("utf-16-le"),
    ],
    ids=["utf-8 bytes", "character reference", "utf-16 attribute"],
)
def test_xml_with_a_lone_surrogate_is_a_refusal_naming_the_file(data):
    with pytest.raises(UnreadableInput, match=r"^axis\.xml is not well-formed XML: .*\(line 1\)$"):
        extract(data, "axis.xml")


@pytest.mark.parametrize(
    ("encoding", "body"),
    [("UTF-7", "+2AA-"), ("unicode_escape", "\\ud800"), ("IDNA", "a.xn--a")],
)
def test_source_text_never_holds_a_lone_surrogate(encoding, body):
    # The code frames of a file come from here: UTF-7 `+2AA-` and the escape `\ud800` decode to a lone
    # U+D800, which no output can show; IDNA fails on `xn--a` with a bare UnicodeError.
    data = f'<?xml version="1.0" encoding="{encoding}"?>\n<a>{body}</a>\n'.encode("ascii")
    text = source_text(data)
    assert not any(0xD800 <= ord(c) <= 0xDFFF for c in text)
    assert text.splitlines()[1] == f"<a>{body}</a>"


def test_a_skipped_xml_in_an_unusable_encoding_gets_its_note(run, tmp_path):
    # An XML file without an axis list is only named in a note; working out its root element must not
    # decode it with a codec that fails.
    (tmp_path / "achsmds1.lis").write_bytes(DUPLICATE)
    (tmp_path / "tools.xml").write_bytes(b'<?xml version="1.0" encoding="IDNA"?>\n<Tools>.xn--a</Tools>\n')
    code, out, err = run("lint", tmp_path)
    assert "internal error" not in err and "Traceback" not in err
    assert "skipped, an XML file without an axis list (<Tools>)" in err
    assert code == 0 and "achsmds1.lis:2:1: LIS005" in out
