"""Review of XML input: byte-order marks and columns, messages for XML that cannot be read, and the library
functions that read one axis list of an XML export."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from achslint import api
from achslint.core.decode import UnreadableInput
from achslint.linting.linter import lint_file
from achslint.syntax.xmlinput import extract

LIST = "<AchsMds>kenngr.ref_richt 2\nEnde\n</AchsMds>"
# `2` sits in column 27 of line 1 of LIST: 9 characters of `<AchsMds>`, then `kenngr.ref_richt `.
COLUMN = 27


def lis201(data: bytes, name: str = "axis.xml") -> list[tuple[int, int]]:
    result = lint_file(data, name)
    assert result.error is None, result.error
    return [(d.line, d.column) for d in result.diagnostics if d.code == "LIS201"]


@pytest.mark.parametrize(
    "data",
    [
        b"\xef\xbb\xbf" + LIST.encode(),
        LIST.encode("utf-16"),
        b"\xfe\xff" + LIST.encode("utf-16-be"),
    ],
    ids=["utf-8 bom", "utf-16-le bom", "utf-16-be bom"],
)
def test_a_byte_order_mark_takes_no_column_of_the_first_line(data):
    # expat counts the byte-order mark as a character of line 1; no editor shows it, and the code frame
    # (`source_text`) drops it.
    assert lis201(data) == [(1, COLUMN)]
    [embedded] = extract(data, "axis.xml")
    assert (embedded.first_line, embedded.first_column) == (1, 1)


def test_a_byte_order_mark_leaves_the_columns_of_later_lines_alone():
    data = ("<?xml version='1.0' encoding='utf-16'?>\n" + LIST).encode("utf-16")
    assert lis201(data) == [(2, COLUMN)]


def test_broken_xml_says_where_and_what_to_do():
    result = lint_file(b"<TreeItem>\n<AchsMds>kopf.achs_nr 1\n</TreeItm>\n", "axis.xml")
    assert result.error is not None and "\n" not in result.error
    assert result.error.startswith("axis.xml is not well-formed XML: mismatched tag")
    assert "column 3" in result.error  # `</TreeItm>`: expat stops at the tag's name
    assert "correct" in result.error and result.error.endswith("(line 3)")


def test_latin1_without_a_declaration_names_the_encoding_to_declare():
    # An XML file without a declaration is UTF-8; a Latin-1 `Ä` is no UTF-8 byte sequence.
    result = lint_file('<AchsMds>kopf.log_achs_name "Ä"\nEnde\n</AchsMds>'.encode("latin-1"), "axis.xml")
    assert result.error is not None and "not UTF-8" in result.error
    assert 'encoding="ISO-8859-1"' in result.error and "\n" not in result.error


def test_utf32_is_refused_with_what_to_do():
    text = '<?xml version="1.0" encoding="UTF-32"?>' + LIST
    result = lint_file(text.encode("utf-32"), "axis.xml")
    assert result.error is not None and "UTF-32" in result.error and "save it as UTF-8" in result.error


def test_cli_broken_xml_is_one_line_exit_2(cli, tmp_path):
    path = tmp_path / "axis.xml"
    path.write_bytes(b"<TreeItem>\n<AchsMds>kopf.achs_nr 1\n</TreeItm>\n")
    result = cli("lint", str(path))
    assert result.returncode == 2 and b"Traceback" not in result.stderr
    assert len(result.stderr.decode().strip().splitlines()) == 1


# -- outside the files this review may change: kept as strict xfail with the fix described ----------------

ONE_LINE = (
    b"<TreeItem><IsgAxisDef><DriveType>1</DriveType><AchsMds>kopf.achs_nr 1&#10;kenngr.antr_typ 1&#10;"
    b"kenngr.ref_richt 1&#10;Ende&#10;</AchsMds></IsgAxisDef></TreeItem>"
)


def test_api_explain_reads_the_list_inside_xml(tmp_path):
    path = tmp_path / "axis.xml"
    path.write_bytes(ONE_LINE)
    assert api.explain(Path(path))["axis"]["drive_type"] == 1


def test_api_and_cli_explain_agree_on_an_xml_export(cli):
    path = Path(__file__).parent.parent / "fixtures" / "machines" / "twincat_export" / "Axis_X.xti"
    shown = json.loads(cli("explain", str(path), "--format", "json").stdout)
    assert api.explain(path)["parameters"] == shown["parameters"]


def test_api_explain_refuses_two_axes_in_one_xml(tmp_path):
    axis = "<IsgAxisDef><AchsMds><![CDATA[kopf.achs_nr {0}\nkopf.log_achs_name A{0}\nEnde\n]]></AchsMds></IsgAxisDef>\n"
    path = tmp_path / "p.tsproj"
    path.write_text("<P>\n" + axis.format(1) + axis.format(2) + "</P>\n")
    with pytest.raises(UnreadableInput, match="holds 2 axis lists"):
        api.explain(Path(path))


def test_xml_bytes_without_a_name_are_read_as_xml():
    """XML given without a file name (the API's bytes, standard input without --stdin-filename) was read as
    list text: one LIS001 per XML line. Its content tells it: `<` first."""
    data = (
        Path(__file__).parent.parent / "fixtures" / "machines" / "twincat_export" / "Axis_X.xti"
    ).read_bytes()
    assert [d.code for d in api.lint(data)] == [d.code for d in api.lint(data, name="Axis_X.xti")]


def test_api_load_of_an_xml_export_keeps_the_findings_of_the_file(tmp_path):
    """`achslint.load` of an XML export builds the model from its one list and keeps the findings
    `achslint lint` gives the file (at its XML lines); read as list text under the XML name, the lint failed
    and the model came with no findings at all."""
    path = tmp_path / "axis.xml"
    path.write_bytes(ONE_LINE.replace(b"kenngr.ref_richt 1", b"kenngr.ref_richt 7"))
    model = api.load(Path(path))
    assert model.kenngr.antr_typ == 1
    found = [(d.code, d.line) for d in model.findings]
    assert found == [(d.code, d.line) for d in api.lint(Path(path))] and ("LIS201", 1) in found
