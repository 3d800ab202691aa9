"""One number parser: every written number becomes a value or a stated problem, never an exception."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from achslint.catalogue import catalogue
from achslint.catalogue.units import describe, to_human
from achslint.linting.linter import lint_file
from achslint.syntax.numbers import (
    NumberProblem,
    Reference,
    as_float,
    parse_hex,
    parse_int,
    parse_real,
    parse_reference,
)

from .conftest import examples


def test_integers_within_the_digit_limit_are_values():
    assert parse_int("-2025000") == -2025000
    assert parse_int("+" + "0" * 100 + "7") == 7  # leading zeros are not significant


def test_an_integer_with_thousands_of_digits_is_a_problem_with_its_digit_count():
    problem = parse_int("1" * 5000)
    assert problem == NumberProblem("digits", 5000)
    assert "5,000 digits" in str(problem)


def test_hex_is_limited_to_64_bits_of_digits():
    assert parse_hex("0x400001") == 0x400001
    assert parse_hex("-0x10") == -16
    assert parse_hex("0x" + "F" * 16) == 2**64 - 1
    problem = parse_hex("0x" + "F" * 300)
    assert isinstance(problem, NumberProblem) and problem.digits == 300


def test_reals_beyond_the_float_range_are_problems_not_infinity():
    assert parse_real("1.5E-3") == pytest.approx(0.0015)
    assert parse_real("0x10") == 16.0
    assert parse_real("1e400") == NumberProblem("range")
    assert parse_real("9" * 320) == NumberProblem("range")
    assert parse_real("1e-400") == 0.0  # underflow only rounds
    assert parse_real("abc") == NumberProblem("syntax")


def test_references_normalise_the_id_and_limit_the_digits():
    assert parse_reference("P-AXIS-212.0") == Reference("P-AXIS-00212", 0)
    assert parse_reference("P-AXIS-00376") == Reference("P-AXIS-00376", None)
    assert parse_reference("P-AXIS-" + "1" * 5000).digits == 5000
    assert parse_reference("P-AXIS-00212." + "1" * 5000).digits == 5000


@settings(max_examples=examples(100))
@given(st.text(max_size=60))
def test_any_text_is_a_number_or_a_stated_problem(text):
    for parse, kind in (
        (parse_int, int),
        (parse_hex, int),
        (parse_real, float),
        (parse_reference, Reference),
    ):
        value = parse(text)
        if isinstance(value, NumberProblem):
            assert value.reason in ("digits", "range", "syntax") and str(value), (parse.__name__, text)
        else:
            assert isinstance(value, kind), (parse.__name__, text, value)


def test_unit_formatting_takes_any_value():
    assert as_float(10**400) is None
    assert "401 digits" in describe(10**400, "um")
    assert describe(float("inf"), "um/s").startswith("inf")
    assert to_human(10**400, "um") is None
    assert to_human(1e300, "um/s").startswith("1e+297 mm/s")


@pytest.mark.parametrize(
    ("line", "code", "words"),
    [
        # Why 6: each of these ended the run with an internal error.
        (b"kenngr.swe_pos 1e400", "LIS202", "range of a 64-bit real"),
        (b"kenngr.swe_pos " + b"9" * 320, "LIS202", "range of a 64-bit real"),
        (b"kopf.achs_nr 0x" + b"F" * 300, "LIS202", "300 digits"),
        (b"kenngr.swe_pos 0x" + b"F" * 300, "LIS202", "300 digits"),
        (b"kenngr.swe_pos P-AXIS-" + b"1" * 5000, "LIS205", "5,000 digits"),
        (b"kopf.achs_nr " + b"7" * 5000, "LIS202", "5,000 digits"),
    ],
)
def test_huge_numbers_in_a_list_are_findings(line, code, words):
    result = lint_file(line + b"\nEnde\n", "achsmds1.lis")
    assert result.error is None
    [finding] = [d for d in result.diagnostics if d.code == code]
    assert words in finding.message


def test_catalogue_lookup_by_an_overlong_id_finds_nothing():
    assert catalogue().find("P-AXIS-218").id == "P-AXIS-00218"
    assert catalogue().find("P-AXIS-" + "2" * 5000) is None
