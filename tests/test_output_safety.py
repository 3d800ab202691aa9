"""Every output format stays valid, and no text format passes control characters through (issue 14, Why 13)."""

from __future__ import annotations

import io
import json
import re

from hypothesis import given, settings
from hypothesis import strategies as st

from achslint.core.diagnostics import Diagnostic, Fix, Related, Severity
from achslint.core.display import printable
from achslint.linting.linter import FileResult, lint_file
from achslint.reporters import REPORTERS, get

from .conftest import examples, jenkins_junit_errors

TEXT_FORMATS = ("concise", "full", "github")
RAW_CONTROL = re.compile("[\x00-\x09\x0b-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069\ud800-\udfff]")

# Names and messages with escape sequences, line breaks, bidi overrides and the undecodable
# bytes of a non-UTF-8 file name (kept by Python as lone surrogates).
HOSTILE = st.lists(
    st.one_of(
        st.sampled_from(
            [
                "\x1b[31m",
                "\x1b]0;x\x07",
                "\r",
                "\n",
                "\x00",
                "\x85",
                "\u202e",
                "\udcff",
                "\udc80",
                "%",
                ",",
                ":",
                "<",
                "&",
                '"',
                "µ",
            ]
        ),
        st.characters(codec="utf-8"),
    ),
    max_size=12,
).map("".join)


def render(fmt: str, results, sources=None) -> str:
    stream = io.StringIO()
    get(fmt)(results, stream, sources=sources or {})
    return stream.getvalue()


def assert_valid(fmt: str, out: str) -> None:
    out.encode("utf-8")  # a strict UTF-8 stdout can take it
    if fmt in ("json", "sarif", "gitlab", "rdjson"):
        json.loads(out)
    elif fmt == "junit":
        assert jenkins_junit_errors(out) == []
    else:
        assert not RAW_CONTROL.search(out), repr(out)


@settings(max_examples=examples(150), deadline=None)
@given(path=HOSTILE, message=HOSTILE, source=HOSTILE, error=HOSTILE)
def test_every_format_is_valid_for_any_name_and_message(path, message, source, error):
    name = path or "x"
    d = Diagnostic(
        name,
        1,
        2,
        1,
        4,
        "LIS101",
        Severity.WARNING,
        message,
        parameter=message or None,
        related=(Related(name, 1, 1, message, message),),
        fix=Fix("safe", message),
    )
    results = [FileResult(name, [d], source_lines=[source]), FileResult(name + "2", [], error=error or "e")]
    for fmt in REPORTERS:
        assert_valid(fmt, render(fmt, results, {name: [source]}))


def test_escape_sequences_from_a_list_are_shown_escaped():
    data = b"kenngr.homing.homing_type \x1b[2J\x1b]0;owned\x07\nEnde\n"
    result = lint_file(data, "achsmds\x1b[31m1.lis")
    for fmt in TEXT_FORMATS:
        out = render(fmt, [result], {result.name: result.source_lines})
        assert "\x1b" not in out and "\x07" not in out
        assert "\\x1b[2J" in out
    assert_valid("junit", render("junit", [result]))


def test_the_caret_stays_under_an_escaped_value():
    result = lint_file(b"kenngr.homing.homing_type \x1bTORQ\nEnde\n", "a.lis")
    out = render("full", [result], {"a.lis": result.source_lines}).splitlines()
    frame = next(i for i, line in enumerate(out) if line.startswith("1 │ "))
    text, caret = out[frame], out[frame + 1]
    assert caret.index("^") == text.index("\\x1bTORQ")
    assert caret.count("^") == len("\\x1bTORQ")


def test_printable_shows_the_bytes_of_a_non_utf8_name():
    assert printable("achsmds\udcff.lis") == "achsmds\\xff.lis"
    assert printable("a\tb\u202ec") == "a\\x09b\\u202ec"
