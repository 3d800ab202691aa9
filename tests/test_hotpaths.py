"""The shortcuts of the lint path's hot functions give the answers the long way gives.

The resolved axis remembers what it worked out, the conversion stage takes numbers by a shorter road and the
number parser skips its pattern for plain digits: each test here states what the answer must be and checks
the shortcut against it, so a shortcut that drifts from the rule fails here before it shows in a snapshot.
"""

from __future__ import annotations

import enum
import json
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from achslint.axis.analysis import analyse
from achslint.axis.resolved import ResolvedAxis, resolve_bytes
from achslint.catalogue import catalogue
from achslint.core.display import indented_json
from achslint.syntax.numbers import MAX_DIGITS, NumberProblem, parse_int
from achslint.syntax.parser import parse_bytes

from .conftest import FIXTURES, examples, run_cli

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


# -- JSON written with an indent ---------------------------------------------------------------------------


def _standard(document: object, allow_nan: bool = True) -> str:
    return json.dumps(document, ensure_ascii=False, indent=2, allow_nan=allow_nan)


def _same_as_standard(document: object, allow_nan: bool = True) -> None:
    """indented_json writes what json.dumps writes, or raises what it raises."""
    try:
        expected = _standard(document, allow_nan)
    except Exception as exc:  # whatever json.dumps raises, indented_json must raise too
        with pytest.raises(type(exc)) as raised:
            indented_json(document, allow_nan=allow_nan)
        assert str(raised.value) == str(exc)
        return
    assert indented_json(document, allow_nan=allow_nan) == expected


class _Code(enum.IntEnum):
    ONE = 1


class _Name(str, enum.Enum):
    AXIS = "axis"


class _Dict(dict):
    pass


class _List(list):
    pass


_scalars = (
    st.none()
    | st.booleans()
    | st.integers(min_value=-(10**30), max_value=10**30)
    | st.floats(allow_nan=True, allow_infinity=True)
    | st.text(max_size=12)
    | st.sampled_from(["", "\x1b[2J", "a\nb", '"', "\\", "\u202e", "\ud800", "ü€😀", "\x00", "\u2028"])
    | st.sampled_from([_Code.ONE, _Name.AXIS, -0.0, 1e300, 2**70])
)
_keys = st.text(max_size=6) | st.integers(-5, 5) | st.floats(allow_nan=True) | st.booleans() | st.none()
_documents = st.recursive(
    _scalars,
    lambda inner: (
        st.lists(inner, max_size=4)
        | st.lists(inner, max_size=3).map(tuple)
        | st.lists(inner, max_size=3).map(_List)
        | st.dictionaries(_keys, inner, max_size=4)
        | st.dictionaries(st.text(max_size=4), inner, max_size=3).map(_Dict)
    ),
    max_leaves=30,
)


@settings(max_examples=examples(2000, 300), deadline=None)
@given(_documents, st.booleans())
def test_indented_json_is_json_dumps_for_any_document(document, allow_nan):
    _same_as_standard(document, allow_nan)


@pytest.mark.parametrize(
    "document",
    [
        {},
        [],
        (),
        "text",
        5,
        None,
        {"a": {}, "b": [], "c": [{}], "d": [[[]]]},
        {"nan": float("nan"), "inf": [float("inf"), -float("inf")]},
        {1.5: "float key", True: "bool key", None: "null key", 7: "int key"},
        {"set": {1, 2}},  # no JSON form: the same TypeError
        {(1, 2): "tuple key"},  # no JSON key: the same TypeError
        [object()],
    ],
)
@pytest.mark.parametrize("allow_nan", [True, False])
def test_indented_json_is_json_dumps_for_the_edge_cases(document, allow_nan):
    _same_as_standard(document, allow_nan)


def test_indented_json_refuses_a_cycle_as_json_dumps_does():
    cycle: list = []
    cycle.append(cycle)
    _same_as_standard(cycle)
    _same_as_standard({"a": cycle})


def test_the_json_documents_of_the_commands_are_written_as_json_dumps_writes_them(monkeypatch, tmp_path):
    """Every document the commands print as JSON, checked against json.dumps as it is written."""
    from achslint.core import display

    written = display.indented_json
    seen: list[object] = []

    def checked(document: object, *, allow_nan: bool = True) -> str:
        seen.append(document)
        text = written(document, allow_nan=allow_nan)
        assert text == _standard(document, allow_nan)
        return text

    monkeypatch.setattr(display, "indented_json", checked)
    rules = FIXTURES / "rules"
    some = [str(path) for path in sorted(rules.glob("LIS2*/bad.lis"))]
    homing = str(FIXTURES / "homing" / "tr_ref_linear.lis")
    commands = [
        *(["lint", "--format", fmt, *some] for fmt in ("json", "sarif", "gitlab", "rdjson")),
        ["lint", "--format", "json", str(FIXTURES / "machines")],
        ["explain", "--format", "json", homing],
        ["explain", "--format", "json", "kenngr.homing.homing_type"],
        ["dry-run", "--format", "json", homing],
        ["diff", "--format", "json", homing, str(FIXTURES / "homing" / "tr_ref_trapezoid.lis")],
        ["rules", "--format", "json"],
        ["schema"],
    ]
    for args in commands:
        result = run_cli(*args)
        assert result.stdout.lstrip().startswith((b"{", b"[")), (args, result.stderr)
    assert len(seen) >= len(commands)
