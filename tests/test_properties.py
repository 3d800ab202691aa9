"""Property tests: no input crashes the linter, and the parse is lossless."""

from __future__ import annotations

import io
import json

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import achslint
from achslint.core.decode import UnreadableInput, decode
from achslint.dryrun import dry_run
from achslint.explanation import explain_list
from achslint.homing.scenario import ScenarioError
from achslint.linting.linter import lint_file
from achslint.listdiff import diff_lists
from achslint.output.dryrun import trace_json
from achslint.reporters import REPORTERS, get
from achslint.syntax.parser import parse_bytes

from .conftest import examples, run_cli

# Pieces real lists are made of, so that generated input reaches deep into the rules.
PIECES = st.sampled_from(
    [
        "kopf.achs_nr",
        "kenngr.homing.homing_type",
        "kenngr.homing_type",
        "getriebe[0].vb_reflow",
        "getriebe[9].x",
        "getriebe[i].vb_refmax",
        "kenngr.achs_mode",
        "antr_simu.rpf_weg_bis_nip",
        "kenngr.achs_typ",
        "kenngr.antr_typ",
        "antr.fixed_stop.drive_ident[0].rd_ident",
        "kopf.log_achs_name",
        "Ende",
        "End",
        "#",
        "(",
        "/*",
        " ",
        "\t",
        "\n",
        "\r\n",
        "\r",
        "0x400001",
        "-2025000",
        "1.5E-3",
        "P-AXIS-00212.0",
        "P-AXIS-00218.0",
        '"',
        '"a (b)"',
        "DRIVE_CONROLLED",
        "TORQ",
        "µm",
        "\xef\xbb\xbf",
        "]",
        "[",
        ".",
        "1",
        "2",
        "40",
        "\x00",
        "é",
    ]
)
LISTISH = st.lists(PIECES, max_size=60).map("".join)
RAW = st.one_of(
    st.binary(max_size=400),
    LISTISH.map(lambda s: s.encode("latin-1", "replace")),
    LISTISH.map(lambda s: s.encode("utf-8")),
)


@settings(max_examples=examples(300), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(RAW)
def test_any_bytes_lint_without_exception_and_report_in_every_format(data):
    result = lint_file(data, "fuzz.lis")
    for name in REPORTERS:
        get(name)([result], io.StringIO(), sources={result.name: result.source_lines})
    for d in result.diagnostics:
        assert 1 <= d.line <= d.end_line
        assert d.column >= 1 and d.end_column >= 1
        assert d.message


@settings(max_examples=examples(300), deadline=None)
@given(RAW)
def test_parse_unparse_is_byte_identical(data):
    try:
        source = decode(data)
    except UnreadableInput:  # UTF-16/32 input is refused before parsing
        return
    file = parse_bytes(data, "fuzz.lis")
    assert source.encode(file.unparse()) == data
    assert sum(len(line.body) + len(line.newline) for line in file.lines) == len(source.text)


@settings(max_examples=8, deadline=None)
@given(st.binary(min_size=1, max_size=300))
def test_cli_never_prints_a_traceback(data):
    result = run_cli("lint", "-", "--format", "json", stdin=data)
    assert result.returncode in (0, 1, 2)
    assert b"Traceback" not in result.stderr


def _refusal(error: Exception) -> str:
    """The message of a refusal, checked: what the CLI prints after `achslint: ` is one line with words."""
    message = str(error)
    assert message.strip() and "\n" not in message, repr(message)
    return message


def _readable_or_refused(call):
    """Run `call`; the only acceptable failure is input that is not a list at all (UTF-16/32, binary),
    refused with a one-line message."""
    try:
        return call()
    except UnreadableInput as refusal:
        _refusal(refusal)
        return None


@settings(max_examples=examples(150), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(RAW)
def test_any_bytes_give_a_typed_model_or_a_clear_refusal(data):
    model = _readable_or_refused(lambda: achslint.load(data))
    if model is not None:
        # Whatever the bytes, the model is a whole axis (every group present) that serialises as JSON.
        dumped = model.model_dump(mode="json", by_alias=True)
        assert {"kopf", "kenngr", "getriebe", "antr"} <= set(dumped)
        assert len(dumped["getriebe"]) == 6
        json.dumps(dumped)


@settings(max_examples=examples(100), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(RAW, RAW)
def test_any_bytes_explain_diff_and_dry_run_give_a_report_or_a_refusal(data, other):
    report = _readable_or_refused(lambda: explain_list(data, "fuzz.lis"))
    if report is not None:
        json.dumps(report)  # the JSON output of `explain` must always be serialisable
        assert report["file"] == "fuzz.lis" and report["strategy"]["id"]
        assert isinstance(report["phases"], list)
    diff = _readable_or_refused(lambda: diff_lists(data, "a.lis", other, "b.lis"))
    if diff is not None:
        json.dumps(diff)
        assert (diff["a"], diff["b"]) == ("a.lis", "b.lis")
        assert all(d["parameter"] for d in diff["differences"])
    try:
        run = dry_run(data, "fuzz.lis")
    except (UnreadableInput, ScenarioError) as refusal:  # refused with a message the CLI prints
        _refusal(refusal)
        return
    trace = trace_json(run)
    json.dumps(trace)
    assert trace["strategy"]["id"] and isinstance(trace["phases"], list)
    assert trace["outcome"] != "failed" or trace["failure"]  # a failed run says why


XML_PIECES = st.sampled_from(
    [
        '<?xml version="1.0"?>',
        "<TcSmProject>",
        "</TcSmProject>",
        "<AchsMds>",
        "</AchsMds>",
        "<![CDATA[",
        "]]>",
        "<AX_MDS>",
        "</AX_MDS>",
        '<Axis Name="X">',
        "</Axis>",
        "kopf.achs_nr 1\n",
        "Ende\n",
        '<!DOCTYPE x [<!ENTITY a "b">]>',
        "&a;",
        "&amp;",
        "<",
        ">",
        '"',
        "\n",
        "é",
        "\x00",
    ]
)


@settings(max_examples=examples(200), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    st.one_of(st.binary(max_size=300), st.lists(XML_PIECES, max_size=40).map(lambda p: "".join(p).encode()))
)
def test_any_bytes_named_xml_give_diagnostics_or_an_error(data):
    result = lint_file(data, "fuzz.xml")
    assert result.error is None or "fuzz.xml" in result.error  # the error names the file
    for name in REPORTERS:
        get(name)([result], io.StringIO(), sources={result.name: result.source_lines})
