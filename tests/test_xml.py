"""Lists inside XML: TwinCAT tree items / projects and ISG XML lists; entity protection."""

from __future__ import annotations

import json

from achslint.api import lint
from achslint.model import build_model  # noqa: F401  (the same model is used for XML lists)

TWINCAT = b"""<?xml version="1.0" encoding="utf-8"?>
<TreeItem><ItemName>Axis_X</ItemName>
<IsgAxisDef><DriveType>1</DriveType><Spindle>false</Spindle>
<AchsMds><![CDATA[#TC_AXIS_DESC:    X axis
kopf.achs_nr                     1
kenngr.antr_typ                  1
kenngr.ref_richt                 2
getriebe[0].vb_refmax        20000
getriebe[0].vb_reflow       100000
Ende
]]></AchsMds></IsgAxisDef></TreeItem>
"""

ISG = b"""<?xml version="1.0" encoding="utf-8"?>
<AX_MDS>
    <Version Label="1"><Schema Version="1"/></Version>
    <Head>
        <P-AXIS-00016 Value="1" />
        <P-AXIS-00297 Value="X_Axis" />
    </Head>
    <GeneralSettings>
        <P-AXIS-00355 Value="40" />
        <P-AXIS-00299 Value="DRIVE_CONROLLED" />
        <P-AXIS-00218.0 Value="100000" />
        <P-AXIS-00219.0 Value="20000" />
        <P-AXIS-99999 Value="1" />
        <P-AXIS-00020 Value="1" />
    </GeneralSettings>
</AX_MDS>
"""


def found(data: bytes, name: str):
    return sorted((d.line, d.column, d.code) for d in lint(data, name=name))


def test_twincat_xml_positions_are_xml_lines():
    results = found(TWINCAT, "axis_x.xml")
    assert (7, 34, "LIS201") in results  # kenngr.ref_richt 2 on XML line 7
    assert (9, 1, "LIS302") in results  # vb_reflow > vb_refmax on XML line 9
    assert not [r for r in results if r[2] == "LIS002"]  # the embedded list ends with Ende


def test_first_list_line_columns_are_offset():
    data = b"<TreeItem><IsgAxisDef><AchsMds><![CDATA[kenngr.ref_richt 2\nEnde\n]]></AchsMds></IsgAxisDef></TreeItem>"
    ((line, column, _code),) = [r for r in found(data, "one.xti") if r[2] == "LIS201"]
    assert (line, column) == (1, data.index(b"kenngr") + 1 + len("kenngr.ref_richt "))


def test_isg_xml_list_is_linted_by_the_same_rules():
    results = found(ISG, "ax_mds_1.xml")
    assert (9, 9, "LIS202") in results  # encoder_bit_range 40
    assert (10, 9, "LIS203") in results  # DRIVE_CONROLLED
    assert (11, 9, "LIS302") in results  # vb_reflow above vb_refmax, gear stage 0
    assert (13, 9, "LIS101") in results  # unknown id
    assert not [r for r in results if r[2] in ("LIS001", "LIS002")]


def test_entity_expansion_and_external_entities_are_refused(cli, tmp_path):
    bomb = tmp_path / "bomb.xml"
    bomb.write_bytes(
        b'<?xml version="1.0"?><!DOCTYPE x [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;">]>'
        b"<TreeItem><AchsMds>&b;</AchsMds></TreeItem>"
    )
    result = cli("lint", str(bomb))
    assert result.returncode == 2
    assert b"refusing to read" in result.stderr and b"Traceback" not in result.stderr
    external = tmp_path / "external.xml"
    external.write_bytes(b'<?xml version="1.0"?><!DOCTYPE x SYSTEM "file:///etc/passwd"><AchsMds>x</AchsMds>')
    assert cli("lint", str(external)).returncode == 2


def test_broken_xml_is_exit_2_and_listless_xml_is_skipped(cli, tmp_path):
    broken = tmp_path / "broken.xml"
    broken.write_bytes(b"<TreeItem><AchsMds>")
    result = cli("lint", str(broken))
    assert result.returncode == 2 and b"not well-formed" in result.stderr
    empty = tmp_path / "empty.xml"
    empty.write_bytes(b"<TreeItem/>")
    # XML without any list achslint reads is skipped with a note: pre-commit may pass it alone, and that is no
    # failure.
    skipped = cli("lint", str(empty))
    assert skipped.returncode == 0 and b"skipped, an XML file without a list" in skipped.stderr


def test_cli_json_for_xml(cli, tmp_path):
    path = tmp_path / "axis_x.xti"
    path.write_bytes(TWINCAT)
    document = json.loads(cli("lint", str(path), "--format", "json").stdout)
    assert {d["code"] for d in document["diagnostics"]} >= {"LIS201", "LIS302"}
    assert all(d["path"] == str(path) for d in document["diagnostics"])


def test_fix_and_fmt_never_rewrite_xml(cli, tmp_path):
    path = tmp_path / "axis.xml"
    data = TWINCAT.replace(b"Ende\n", b"End\n")
    path.write_bytes(data)
    cli("lint", "--fix", str(path))
    assert path.read_bytes() == data
    result = cli("fmt", str(path))
    assert result.returncode == 2 and b"not XML" in result.stderr
    assert path.read_bytes() == data


def test_twincat_project_axes_form_one_machine():
    axis = (
        b"<IsgAxisDef><DriveType>1</DriveType><AchsMds><![CDATA[kopf.achs_nr 1\n"
        b"kopf.log_achs_name AXIS_%d\nEnde\n]]></AchsMds></IsgAxisDef>\n"
    )
    project = b"<TcSmProject>\n" + axis % 1 + axis % 2 + b"</TcSmProject>\n"
    results = found(project, "machine.tsproj")
    assert (6, 55, "LIS501") in results  # the second axis (its list starts on XML line 6) repeats number 1
    assert not [r for r in results if r[2] == "LIS502"]
