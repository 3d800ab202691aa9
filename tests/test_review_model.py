"""Review of the typed models and `dumps`: what `dumps` writes must read back as the same values, every
fixture list round-trips, and wrong input ends in one clear exception."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import achslint
from achslint.core.decode import text_bytes
from achslint.core.files import read_list
from achslint.linting.linter import list_kind
from achslint.model import axis_model, build_list_model, dumps
from achslint.syntax.parser import parse_bytes

from .conftest import FIXTURES, THOROUGH

MODEL_KINDS = {"axis": "axis", "default_axis": "axis", "channel": "channel", "default_channel": "channel"}
MODEL_KINDS["startup"] = "startup"


def _fixture_models(step: int = 1):
    """(path, kind, model) of every `step`-th fixture list of a kind with a model, read as the library reads
    it."""
    for path in sorted(FIXTURES.rglob("*.lis"))[::step]:
        data = read_list(path)
        kind = MODEL_KINDS.get(list_kind(parse_bytes(data, str(path)), str(path)).id)
        if kind == "axis":
            try:
                yield path, kind, achslint.load(path)
            except achslint.UnreadableInput:
                continue
        elif kind is not None:
            yield path, kind, build_list_model(data, path.name, kind)


def _again(model, kind: str, text: str):
    if kind == "axis":
        return achslint.loads(text)
    return build_list_model(text_bytes(text), "again.lis", kind)


def test_every_fixture_list_reads_back_as_its_values():
    """What `dumps` writes reads back as the same model, unknown names included, for the fixture lists of
    the three kinds with a model: every fourth by default (the same ones each time, about 2 s for all), every
    one with ACHSLINT_THOROUGH=1, as the property tests do."""
    step = 1 if THOROUGH else 4
    count = 0
    for path, kind, model in _fixture_models(step):
        again = _again(model, kind, achslint.dumps(model))
        assert again == model, path
        count += 1
    assert count > 300 // step


def _with_name(value: str):
    model = achslint.loads("kopf.log_achs_name X\nEnde\n")
    model.kopf.log_achs_name = value
    return model


@pytest.mark.parametrize(
    "value",
    [
        "Müller",
        "a b",
        'a"b',  # a quote without blanks: written bare, as the CNC reads it
        "P-AXIS-00016",  # bare, it would be read as a reference to another parameter
        "#x",  # bare, the model read it as nothing (LIS007 says the CNC reads it as the value)
        "12",
        "0x1F",
        "-3",
        "a(b",
        "(x",
        " a",
        "",
        "Ende",
    ],
)
def test_a_string_reads_back_as_written(value: str):
    text = achslint.dumps(_with_name(value))
    assert achslint.loads(text).kopf.log_achs_name == value, text


@pytest.mark.parametrize("value", ["a\nEnde", "X\r\nkopf.achs_nr 7", 'a "b" c'])
def test_a_string_no_list_can_hold_is_refused(value: str):
    """A line break would end the line (and start another assignment, or `Ende`); a quote inside a value
    with blanks cannot be written at all. Writing something else in their place changed the value."""
    with pytest.raises(ValueError, match=r"kopf\.log_achs_name"):
        achslint.dumps(_with_name(value))


@pytest.mark.parametrize("value", [math.inf, -math.inf, math.nan])
def test_a_number_the_cnc_cannot_read_is_refused(value: float):
    model = achslint.loads("Ende\n")
    model.antr.fixed_stop.drive_ident[0].startup_value = value
    with pytest.raises(ValueError, match=r"antr\.fixed_stop\.drive_ident\[0\]\.startup_value"):
        achslint.dumps(model)


@pytest.mark.parametrize(
    "value", [0.1 + 0.2, 1 / 3, -123456.78901234567, 1e-05, 1.5e20, 5e-324, 1.2345678901234568e17]
)
def test_reals_keep_every_digit(value: float):
    model = achslint.loads("Ende\n")
    model.antr.fixed_stop.drive_ident[0].startup_value = value
    assert achslint.loads(achslint.dumps(model)).antr.fixed_stop.drive_ident[0].startup_value == value


def test_the_values_of_a_written_list_survive():
    text = (
        "kopf.log_achs_name                              Z1\n"
        "kenngr.achs_mode                                0x1\n"
        "kenngr.homing_type                              TORQ\n"  # old name of kenngr.homing.homing_type
        "getriebe[0].vb_refmax                           12000\n"
        "getriebe[0].vb_reflow                           P-AXIS-00219.0\n"  # vb_refmax of gear 0
        "getriebe[3].vb_refmax                           7000\n"  # gears 1, 2, 4, 5: a gap of defaults
        "antr.sercos.ident[1].wert                       -2147483648\n"
        "antr.fixed_stop.drive_ident[2].startup_value    -0.000123456789012345\n"
        "Ende\n"
    )
    model = achslint.loads(text)
    assert model.getriebe[0].vb_reflow == 12000 and model.getriebe[3].vb_refmax == 7000
    assert model.kenngr.homing.homing_type == "TORQ" and model.antr.sercos.ident[1].wert == -2147483648
    again = achslint.loads(achslint.dumps(model))
    assert again == model
    assert again.antr.fixed_stop.drive_ident[2].startup_value == -0.000123456789012345


def test_channel_values_with_blanks_quotes_and_flags_survive():
    text = 'gruppe[0].achse[2].bezeichnung  "A 1"\nh_synch[1]  MOS\nEnde\n'
    model = build_list_model(text.encode(), "sda_mds1.lis", "channel")
    assert model.get("gruppe[0].achse[2].bezeichnung") == "A 1"
    again = build_list_model(text_bytes(dumps(model)), "again.lis", "channel")
    assert again == model


def test_model_dumps_takes_a_model_only():
    """`achslint.model.dumps` (README: `from achslint.model import build_list_model, dumps`) raised
    AttributeError from inside the model code for anything else."""
    with pytest.raises(TypeError, match=r"dumps.*NoneType"):
        dumps(None)  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=r"dumps"):
        dumps(axis_model())  # type: ignore[arg-type]


def test_build_list_model_takes_bytes():
    """Text raised `TypeError: startswith first arg must be str ...` from the decoder."""
    with pytest.raises(TypeError, match=r"build_list_model.*bytes.*str"):
        build_list_model("grp_anzahl 1\nEnde\n", "sda_mds1.lis", "channel")  # type: ignore[arg-type]
    with pytest.raises(KeyError):
        build_list_model(b"Ende\n", "x.lis", "tools")  # no model for tool lists, as documented


def test_unknown_names_survive_dumps():
    """dumps left out the names the catalogue does not know, so `loads(dumps(m)) == m` failed for a lenient
    model that has some, and a setting the CNC knows but the table lacks (the SDK start-up list's
    `interpolator.parameter`) was lost."""
    path = FIXTURES / "vendor" / "isg_sdk_hochlauf.lis"
    model = build_list_model(path.read_bytes(), path.name, "startup")
    assert model.unknown
    again = build_list_model(text_bytes(dumps(model)), "again.lis", "startup")
    assert again == model


def test_strict_names_the_parameter_and_the_problem():
    with pytest.raises(Exception) as raised:
        achslint.loads("kenngr.achs_typ x\nEnde\n", strict=True)
    from pydantic import ValidationError

    assert isinstance(raised.value, ValidationError)
    (error,) = raised.value.errors()
    assert error["loc"] == ("kenngr", "achs_typ") and "LIS203" in error["msg"]
    lenient = achslint.loads("kenngr.achs_typ 1\nkenngr.gibts_nicht 5\nEnde\n")
    assert lenient.unknown == {"kenngr.gibts_nicht": "5"}


def test_a_list_of_another_kind_is_one_clear_error(tmp_path: Path):
    with pytest.raises(achslint.UnreadableInput, match="channel list"):
        achslint.load(FIXTURES / "kinds" / "sda_mds1.lis")
    with pytest.raises(achslint.UnreadableInput):
        achslint.loads("\x00\x01 garbage\n")


def test_validating_a_value_no_list_can_hold_fails():
    """The cross rules read the model as `dumps` writes it: `nan` was accepted (and written as `nan`, a
    word the CNC does not read as a number), a line break let a value write further assignments."""
    from pydantic import ValidationError

    drive_ident = [{"startup_value": math.nan}, {}, {}, {}]
    with pytest.raises(ValidationError, match=r"startup_value: nan cannot be written"):
        axis_model().model_validate({"antr": {"fixed_stop": {"drive_ident": drive_ident}}})
    with pytest.raises(ValidationError, match="line break"):
        axis_model().model_validate({"kopf": {"log_achs_name": "X\nEnde"}})
