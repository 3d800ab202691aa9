"""The typed pydantic model: types, defaults, sources, default lists, schema."""

from __future__ import annotations

import pytest
from pydantic import ValidationError

import achslint
from achslint.core.diagnostics import Diagnostic, Severity
from achslint.model import axis_model, json_schema, rule_errors

from .conftest import FIXTURES


def test_load_bundled_list_types_and_sources():
    path = FIXTURES / "lists" / "achsmds1.lis"
    axis = achslint.load(path)
    assert axis.kopf.achs_nr == 1
    assert axis.kenngr.achs_mode == 0x400001
    assert axis.kenngr.homing.homing_type == "CNC_CONTROLLED"
    assert axis.kenngr.ref_richt is False
    assert axis.kenngr.achs_typ == "ACHSTYP_TRANSLATOR"  # written as 1
    assert axis.getriebe[0].vb_reflow == 10000
    assert axis.getriebe[0].pos_refpkt == -9500000
    assert len(axis.getriebe) == 6 and axis.getriebe[1].vb_reflow == 16666  # untouched stage: default
    source = axis.source_of("getriebe[0].vb_reflow")
    assert (source.kind, source.line, source.column) == ("list", 34, 1)
    assert source.file == str(path)
    assert axis.source_of("getriebe[1].vb_reflow").kind == "default"
    assert axis.get("lr_hw[0].cam_level") is True


def test_unknown_parameters_are_kept_and_aliases_resolved():
    axis = achslint.load("kenngr.homing_type TORQ\nkenngr.gibts_nicht 5\nEnde\n")
    assert axis.kenngr.homing.homing_type == "TORQ"
    assert axis.unknown == {"kenngr.gibts_nicht": "5"}


def test_default_list_is_applied_under_the_axis_list():
    defaults = b"getriebe[0].vb_reflow 12345\ngetriebe[0].vb_refmax 99000\nEnde\n"
    axis = achslint.load(b"getriebe[0].vb_reflow 20000\nEnde\n", defaults=defaults)
    assert axis.getriebe[0].vb_reflow == 20000
    assert axis.getriebe[0].vb_refmax == 99000
    assert axis.source_of("getriebe[0].vb_refmax").kind == "default list"
    assert axis.source_of("getriebe[0].vb_reflow").kind == "list"


def test_invalid_values_fall_back_to_the_default():
    axis = achslint.load(b"kenngr.ref_richt 2\nantr.encoder_bit_range 40\nEnde\n")
    assert axis.kenngr.ref_richt is False
    assert axis.antr.encoder_bit_range == 0


def test_model_enforces_types_and_ranges():
    model = axis_model()
    with pytest.raises(ValidationError):
        model.model_validate({"antr": {"encoder_bit_range": 40}})
    with pytest.raises(ValidationError):
        model.model_validate({"kenngr": {"homing": {"homing_type": "DRIVE_CONROLLED"}}})
    with pytest.raises(ValidationError):
        model.model_validate({"getriebe": [{}] * 7})
    with pytest.raises(ValidationError):
        model.model_validate({"kenngr": {"no_such_parameter": 1}})


def test_schema_has_descriptions_units_and_bounds():
    schema = json_schema()
    defs = schema["$defs"]
    gear = defs["Getriebe"]["properties"]
    assert "P-AXIS-00218" in gear["vb_reflow"]["description"] and "[um/s]" in gear["vb_reflow"]["description"]
    assert schema["properties"]["getriebe"]["maxItems"] == 6
    bit_range = defs["Antr"]["properties"]["encoder_bit_range"]
    assert bit_range["maximum"] == 31


def test_a_rule_error_names_the_field_a_parameter_is_in_the_model():
    """The error's location is the model's own path: indices as numbers, and a parameter below another
    parameter (P-AXIS-00560 beside `kenngr.swe_pos`) as the one field that joins the rest."""
    findings = [
        Diagnostic("a.lis", 3, 1, 3, 9, "LIS302", Severity.ERROR, "too fast", "getriebe[2].vb_reflow"),
        Diagnostic("a.lis", 4, 1, 4, 9, "LIS313", Severity.ERROR, "outside", "kenngr.swe_pos.zero_limit"),
        Diagnostic("a.lis", 1, 1, 1, 2, "LIS002", Severity.ERROR, "no end", None),
    ]
    errors = rule_errors(findings).errors()
    assert [error["loc"] for error in errors] == [
        ("getriebe", 2, "vb_reflow"),
        ("kenngr", "swe_pos_zero_limit"),
        ("list",),
    ]
    assert errors[1]["msg"] == "LIS313: outside"
