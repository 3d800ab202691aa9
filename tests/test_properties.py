"""Property tests: no input crashes the linter, and the parse is lossless."""

from __future__ import annotations

import io

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from achslint.decode import decode
from achslint.linter import check_bytes
from achslint.reporters import REPORTERS, get
from achslint.syntax import parse_bytes

from .conftest import run_cli

# Pieces real lists are made of, so that generated input reaches deep into the rules.
PIECES = st.sampled_from([
    "kopf.achs_nr", "kenngr.homing.homing_type", "kenngr.homing_type", "getriebe[0].vb_reflow", "getriebe[9].x",
    "getriebe[i].vb_refmax", "kenngr.achs_mode", "antr_simu.rpf_weg_bis_nip", "kenngr.achs_typ", "kenngr.antr_typ",
    "antr.fixed_stop.drive_ident[0].rd_ident", "kopf.log_achs_name", "Ende", "End", "#", "(", "/*", " ", "\t",
    "\n", "\r\n", "\r", "0x400001", "-2025000", "1.5E-3", "P-AXIS-00212.0", "P-AXIS-00218.0", "\"", "\"a (b)\"",
    "DRIVE_CONROLLED", "TORQ", "µm", "\xef\xbb\xbf", "]", "[", ".", "1", "2", "40", "\x00", "é",
])
LISTISH = st.lists(PIECES, max_size=60).map("".join)
RAW = st.one_of(st.binary(max_size=400), LISTISH.map(lambda s: s.encode("latin-1", "replace")),
                LISTISH.map(lambda s: s.encode("utf-8")))


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(RAW)
def test_any_bytes_lint_without_exception_and_report_in_every_format(data):
    result = check_bytes(data, "fuzz.lis")
    for name in REPORTERS:
        get(name)([result], io.StringIO(), sources={result.name: result.source_lines})
    for d in result.diagnostics:
        assert 1 <= d.line <= d.end_line
        assert d.column >= 1 and d.end_column >= 1
        assert d.message


@settings(max_examples=300, deadline=None)
@given(RAW)
def test_parse_unparse_is_byte_identical(data):
    try:
        source = decode(data)
    except Exception:  # UTF-16/32 input is refused before parsing
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
