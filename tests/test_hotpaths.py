"""The shortcuts of the lint path's hot functions give the answers the long way gives.

The resolved axis remembers what it worked out, the conversion stage takes numbers by a shorter road and the
number parser skips its pattern for plain digits: each test here states what the answer must be and checks
the shortcut against it, so a shortcut that drifts from the rule fails here before it shows in a snapshot.
"""

from __future__ import annotations

import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from achslint.axis.analysis import analyse
from achslint.axis.resolved import ResolvedAxis, resolve_bytes
from achslint.catalogue import catalogue
from achslint.syntax.numbers import MAX_DIGITS, NumberProblem, parse_int
from achslint.syntax.parser import parse_bytes

from .conftest import FIXTURES, examples

# -- parse_int -----------------------------------------------------------------------------------------------


def _int_by_the_rule(text: str) -> int | NumberProblem:
    """What a decimal integer is: an optional sign and ASCII digits, at most MAX_DIGITS of them significant."""
    if not re.fullmatch(r"[+-]?[0-9]+", text):
        return NumberProblem("syntax")
    digits = text.lstrip("+-")
    if len(digits.lstrip("0")) > MAX_DIGITS:
        return NumberProblem("digits", len(digits))
    return int(text)


@pytest.mark.parametrize(
    "text",
    [
        "0",
        "007",
        "2025000",
        "9" * MAX_DIGITS,
        "9" * (MAX_DIGITS + 1),
        "0" * 40 + "5",
        "+5",
        "-5",
        "",
        " 5",
        "5 ",
        "٣",  # an Arabic-Indic digit: a digit to Python, not to a list
        "²",
        "1_000",
        "12a",
    ],
)
def test_parse_int_follows_the_rule_for_edge_cases(text):
    assert parse_int(text) == _int_by_the_rule(text)


@settings(max_examples=examples(500, 200), deadline=None)
@given(st.text(alphabet="0123456789+-_ ٣²a", max_size=40))
def test_parse_int_follows_the_rule_for_any_text(text):
    assert parse_int(text) == _int_by_the_rule(text)


# -- the resolved axis remembers its answers -------------------------------------------------------------------


def _fixture_lists() -> list:
    return sorted((FIXTURES / "rules").glob("*/*.lis"))


def _answers(axis: ResolvedAxis, paths: list[str], types_first: bool) -> dict:
    answers: dict = {}
    if types_first:
        answers["types"] = (axis.axis_type, axis.drive_type, axis.homing_type)
    for path in paths:
        origin, own = axis.origin(path), axis.in_list(path)
        line = origin.setting.line.number if origin.setting else None
        answers[path] = (axis.get(path), axis.written(path), origin.kind, origin.file, line, own is not None)
    if not types_first:
        answers["types"] = (axis.axis_type, axis.drive_type, axis.homing_type)
    return answers


def test_the_answers_of_a_resolved_axis_do_not_depend_on_the_order_of_the_questions():
    plain = [p.path for p in catalogue().parameters if "[i]" not in p.path]
    lists = _fixture_lists()
    assert len(lists) > 50
    for path in lists:
        data = path.read_bytes()
        first = resolve_bytes(data, path.name)
        second = resolve_bytes(data, path.name)
        paths = list(dict.fromkeys([*first.set_paths(), *plain]))
        forward = _answers(first, paths, types_first=True)
        backward = _answers(second, paths[::-1], types_first=False)
        assert forward == backward, path
        assert _answers(first, paths, types_first=False) == forward, path  # asked again: the same


def test_a_correction_replaces_what_the_axis_answered_before_it():
    axis = ResolvedAxis(analyse(parse_bytes(b"kenngr.antr_typ 1\nkenngr.achs_typ 1\nEnde\n", "t.lis")))
    assert (axis.get("kenngr.antr_typ"), axis.axis_type, axis.drive_type) == (1, "T", 1)
    assert axis.homing_type == "CNC_CONTROLLED"  # the default of drive type 1
    axis.correct("kenngr.achs_typ", 2, "P-ERR-0", "a test")
    axis.correct("kenngr.antr_typ", 2, "P-ERR-0", "a test")
    assert (axis.get("kenngr.antr_typ"), axis.axis_type, axis.drive_type) == (2, "R", 2)
    assert axis.homing_type == "DRIVE_CONTROLLED"  # the default of drive type 2 (SERCOS)
    assert axis.written("kenngr.antr_typ") == 1  # what was written stays what it was
    assert [c.parameter for c in axis.corrections] == ["kenngr.achs_typ", "kenngr.antr_typ"]


def test_origins_name_the_layer_that_won():
    defaults = analyse(parse_bytes(b"kenngr.antr_typ 1\nkenngr.achs_typ 1\nEnde\n", "default.lis"))
    axis = ResolvedAxis(analyse(parse_bytes(b"kenngr.achs_typ 2\nEnde\n", "achsmds1.lis")), defaults)
    assert axis.origin("kenngr.achs_typ").kind == "list"
    assert axis.in_list("kenngr.achs_typ") is axis.setting("kenngr.achs_typ")
    assert axis.origin("kenngr.antr_typ").kind == "default list"
    assert axis.origin("kenngr.antr_typ").file == "default.lis"
    assert axis.in_list("kenngr.antr_typ") is None
    assert axis.setting("kenngr.antr_typ") is not None
    assert axis.origin("kenngr.homing.homing_type").kind == "default"
    assert axis.origin("kenngr.achs_typ") is axis.origin("kenngr.achs_typ")  # made once
    assert axis.set_paths() == ["kenngr.antr_typ", "kenngr.achs_typ"]


# -- the conversion stage takes numbers first --------------------------------------------------------------


@pytest.mark.parametrize(
    "line,value,facts",
    [
        ("kenngr.antr_typ 1", 1, []),  # an integer
        ("kenngr.antr_typ 0x1", 1, []),
        ("kenngr.antr_typ 1.5", None, ["RealForInteger"]),
        ("kenngr.antr_typ 99", None, ["NotAccepted"]),
        ("kenngr.homing_overflow_evaluation 1", True, []),  # a boolean
        ("kenngr.homing_overflow_evaluation 2", None, ["NotBoolean"]),
        ("kenngr.homing_overflow_evaluation 1.0", None, ["NotBoolean"]),
        ("kenngr.swe_pos 1000", 1000.0, []),  # a real written as an integer
        ("kenngr.swe_pos 0x10", 16.0, []),
        ("kenngr.swe_pos 1e999", None, ["UnusableNumber"]),
        ("kenngr.antr_typ 1 trailing words", 1, []),  # words after a number are no value
    ],
)
def test_numbers_are_read_as_their_parameter_wants(line, value, facts):
    analysis = analyse(parse_bytes(f"{line}\nEnde\n".encode(), "t.lis"))
    (setting,) = analysis.settings
    if value is not None:
        assert setting.value == value and type(setting.value) is type(value)
    assert [type(fact).__name__ for fact in setting.problems] == facts
