"""One XML parse (defusedxml's expat parser) for every command that reads XML.

Each test is a case the earlier regular-expression extraction got wrong (issue 14, Why 10 and 11).
"""

from __future__ import annotations

import pytest

from achslint.core.decode import UnreadableInput
from achslint.linting.linter import lint_file
from achslint.syntax.xmlinput import extract, single_list, source_text

AXIS = (
    "<IsgAxisDef><AchsMds><![CDATA[kopf.achs_nr 1\nkopf.log_achs_name X\nEnde\n]]></AchsMds></IsgAxisDef>\n"
)
BILLION_LAUGHS = (
    b'<?xml version="1.0"?><!DOCTYPE x [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;">]>'
    b"<TreeItem><AchsMds>&b;</AchsMds></TreeItem>"
)


def codes(data: bytes, name: str = "axis.xml") -> list[tuple[int, int, str]]:
    result = lint_file(data, name)
    assert result.error is None, result.error
    return [(d.line, d.column, d.code) for d in result.diagnostics]


def test_a_list_inside_a_comment_is_not_linted():
    data = f"<Project>\n<!-- {AXIS} -->\n{AXIS}</Project>\n".encode()
    assert len(extract(data, "p.tsproj")) == 1
    assert not [c for c in codes(data, "p.tsproj") if c[2] in ("LIS501", "LIS502")]


def test_two_cdata_sections_form_one_list_with_exact_positions():
    data = b"<AchsMds><![CDATA[kopf.achs_nr 1\nkenngr.ref_ri]]><![CDATA[chtx 2\nEnde\n]]></AchsMds>"
    [embedded] = extract(data, "a.xml")
    assert embedded.text == "kopf.achs_nr 1\nkenngr.ref_richtx 2\nEnde\n"
    assert "LIS001" not in {c[2] for c in codes(data)}
    # `kenngr.ref_richtx` starts on XML line 2, column 1, and its value `2` in the second section.
    [(line, column, _)] = [c for c in codes(data) if c[2] == "LIS101"]
    assert (line, column) == (2, 1)


def test_an_element_with_attributes_is_found():
    data = b'<AchsMds Version="2" xml:space="preserve">kopf.achs_nr 1\nEnde\n</AchsMds>'
    assert extract(data, "a.xml")[0].text == "kopf.achs_nr 1\nEnde\n"


def test_character_references_are_unescaped():
    data = b"<AchsMds>kopf.log_achs_name &quot;X &amp; Y&quot;\nkenngr.ref_richt &#50;\nEnde\n</AchsMds>"
    [embedded] = extract(data, "a.xml")
    assert embedded.text == 'kopf.log_achs_name "X & Y"\nkenngr.ref_richt 2\nEnde\n'
    # `2` is no value of ref_richt; the finding sits where `&#50;` is written (line 2, column 18).
    assert (2, 18, "LIS201") in codes(data)


@pytest.mark.parametrize("encoding", ["utf-16", "utf-16-le", "utf-8-sig", "latin-1"])
def test_any_encoding_expat_knows_is_read(encoding):
    declared = (
        "utf-16" if encoding.startswith("utf-16") else {"utf-8-sig": "utf-8"}.get(encoding, "iso-8859-1")
    )
    text = f'<?xml version="1.0" encoding="{declared}"?>\n<AchsMds>kopf.log_achs_name "µ"\nkenngr.ref_richt 2\nEnde\n</AchsMds>\n'
    data = text.encode(encoding)
    if encoding == "utf-16-le":
        data = b"\xff\xfe" + data
    assert (3, 18, "LIS201") in codes(data)
    assert "kenngr.ref_richt 2" in source_text(data)


def test_an_unknown_declared_encoding_is_a_clear_refusal():
    result = lint_file(b'<?xml version="1.0" encoding="x-nonsense"?><AchsMds>Ende</AchsMds>', "a.xml")
    assert result.error and "declares the unknown encoding `x-nonsense`" in result.error
    assert result.error.endswith("save it as UTF-8")


def test_crlf_xml_keeps_xml_line_numbers():
    data = b"<TreeItem>\r\n<AchsMds><![CDATA[kopf.achs_nr 1\r\nkenngr.ref_richt 2\r\nEnde\r\n]]></AchsMds>\r\n</TreeItem>"
    assert (3, 18, "LIS201") in codes(data)


def test_isg_element_with_thousands_of_index_digits_is_a_finding():
    data = b"<AX_MDS><P-AXIS-00152." + b"1" * 5000 + b' Value="0"/></AX_MDS>'
    assert {c[2] for c in codes(data)} <= {"LIS101", "LIS104"}


def test_isg_elements_count_only_inside_ax_mds():
    data = b'<Doc><P-AXIS-00016 Value="1"/><AX_MDS><P-AXIS-00016 Value="2"/></AX_MDS></Doc>'
    [embedded] = extract(data, "a.xml")
    assert embedded.text == "kopf.achs_nr 2\nEnde\n"


def test_entity_declarations_are_refused_by_the_one_parse():
    with pytest.raises(UnreadableInput, match="refusing to read"):
        extract(BILLION_LAUGHS, "bomb.xml")


def test_single_list_for_the_one_list_commands():
    assert single_list(AXIS.encode(), "a.xti") == b"kopf.achs_nr 1\nkopf.log_achs_name X\nEnde\n"
    with pytest.raises(UnreadableInput, match="holds 2 axis lists"):
        single_list(f"<P>{AXIS}{AXIS}</P>".encode(), "p.tsproj")
