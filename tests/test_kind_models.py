"""Typed models of channel lists and start-up lists (issue 25 item 5), generated like the axis model by
tools/gen_model.py from the kind catalogues, and `achslint schema --kind channel|startup|axis`.

The reference tables give no array sizes, so the arrays of these models are open: `gruppe[0].achse[2]` of a
channel list (P-CHAN-00006 `gruppe[i].achse[i].bezeichnung`) makes a list of three axes. A symbol value may
OR-combine flags, as the SDK's start-up list does (`error_protocol_mode  REPORT | REPORT_EXTENDED`,
P-STUP-00167), exactly as the linter reads it."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest
from pydantic import BaseModel, ValidationError

from achslint import cli
from achslint.catalogue.kinds import CHANNEL, STARTUP, Kind
from achslint.model import (
    MODELS,
    ListBase,
    build_list_model,
    dumps,
    field_name,
    inner_model,
    json_schema,
    list_model,
    model_parts,
)

from .conftest import FIXTURES, ROOT, run_cli

KINDS = FIXTURES / "kinds"


def _gen_model():  # tools/ is no package: the generator is imported as the tools do
    tools = str(ROOT / "tools")
    if tools not in sys.path:
        sys.path.insert(0, tools)
    import gen_model

    return gen_model


def test_every_generated_model_is_what_the_generator_builds() -> None:
    """The committed modules are exactly what tools/gen_model.py makes of the catalogues (regenerate with
    `python tools/build_kinds.py`, which runs it, or `python tools/gen_model.py`)."""
    gen_model = _gen_model()
    outputs = {target.output.name for target in gen_model.TARGETS}
    assert outputs == {"generated.py", "generated_channel.py", "generated_startup.py"}
    for target in gen_model.TARGETS:
        assert target.output.read_text(encoding="utf-8") == gen_model.model_source(target), target.output
    assert gen_model.main(["--check"]) == 0


def test_a_stale_module_is_named_by_the_check(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    gen_model = _gen_model()
    stale = tmp_path / "generated_channel.py"
    stale.write_text("# an old model\n", encoding="utf-8")
    target = next(t for t in gen_model.TARGETS if t.kind is CHANNEL)
    monkeypatch.setattr(gen_model, "TARGETS", (type(target)(CHANNEL, stale, target.root, target.base, "x"),))
    assert gen_model.main(["--check"]) == 1


def _field_of(model: type[BaseModel], path: str) -> bool:
    """Whether every member of a concrete path is a field of the model (groups walked into)."""
    group: type[BaseModel] | None = model
    for name, _ in model_parts(model, path):
        if group is None or field_name(name) not in group.model_fields:
            return False
        group = inner_model(group.model_fields[field_name(name)].annotation)
    return True


@pytest.mark.parametrize("kind", [CHANNEL, STARTUP], ids=lambda kind: kind.id)
def test_every_parameter_of_the_kind_is_a_field_of_its_model(kind: Kind) -> None:
    model = list_model(kind.id)
    cat = kind.catalogue()
    assert cat is not None and kind.id == model.KIND
    missing = [p.path for p in cat.parameters if not _field_of(model, p.path.replace("[i]", "[0]"))]
    assert missing == []
    # a member that starts with a digit (P-CHAN-00396) is a field all the same, under a Python name
    assert field_name("2nd_path_on_actual_1st_path") == "p_2nd_path_on_actual_1st_path"


def test_a_channel_list_becomes_its_model() -> None:
    path = KINDS / "sda_mds1.lis"
    model = build_list_model(path.read_bytes(), path.name, "channel")
    assert type(model).__name__ == "ChannelParameters" and isinstance(model, ListBase)
    assert [axis.bezeichnung for axis in model.gruppe[0].achse] == ["X", "Z", "C"]  # type: ignore[attr-defined]
    assert model.get("spindel[0].log_achs_nr") == 3 and model.get("grp_anzahl") == 1
    line = next(
        n for n, text in enumerate(path.read_text().splitlines(), 1) if text.startswith("spindel[0].log")
    )
    assert str(model.source_of("spindel[0].log_achs_nr")) == f"sda_mds1.lis:{line}:1"
    assert (
        str(model.source_of("spdl_anzahl")) != "default"
        and str(model.source_of("vector.velocity")) == "default"
    )
    assert model.unknown == {}


def test_gaps_problems_and_unknown_names() -> None:
    text = (
        b"gruppe[0].achse[2].bezeichnung  C\n"  # axes 0 and 1 not written: default groups
        b"h_synch[1]  MOS\n"  # an open array of values: the gap is None
        b"grp_anzahl  7\n"  # out of range (P-CHAN-00023: at most 1): keeps its default, the lint says why
        b"gruppe[0].nothing  1\n"
        b"m_synch[5000]  MOS\n"  # an index far beyond any channel: not built, kept as written
        b"trafo[0].linkage[1][2]  0.5\n"  # an array of arrays (P-CHAN-00295)
        b"Ende\n"
    )
    model = build_list_model(text, "kanal.lis", "default_channel")  # a default channel list: the same model
    achse = model.get("gruppe[0].achse[2].bezeichnung")
    assert achse == "C" and model.get("gruppe[0].achse[0].bezeichnung") is None
    assert model.get("h_synch[0]") is None and model.get("h_synch[1]") == "MOS"
    assert model.get("grp_anzahl") == 1
    assert model.unknown == {"gruppe[0].nothing": "1", "m_synch[5000]": "MOS"}
    assert model.get("trafo[0].linkage[1][2]") == 0.5 and model.get("trafo[0].linkage") == [
        [],
        [None, None, 0.5],
    ]
    assert "trafo[0].linkage[1][2]                          0.5" in dumps(model)


def test_a_start_up_list_with_combined_flags_round_trips() -> None:
    path = FIXTURES / "vendor" / "isg_sdk_hochlauf.lis"
    model = build_list_model(path.read_bytes(), path.name, "startup")
    assert model.get("error_protocol_mode") == (
        "REPORT | REPORT_EXTENDED | PRINT | PRINT_EXTENDED | LOG | LOG_EXTENDED"
    )
    assert model.get("configuration.channel[0].path_preparation.function") == (
        "FCT_DEFAULT | FCT_M_PRE_OUTPUT | FCT_SURFACE"
    )
    written = dumps(model)
    # written bare, as the CNC reads flags, and a long path keeps a blank before its value
    assert "\nerror_protocol_mode                             REPORT | REPORT_EXTENDED | PRINT" in written
    assert "configuration.channel[0].path_preparation.function FCT_DEFAULT | FCT_M_PRE_OUTPUT" in written
    again = build_list_model(written.encode(), "again.lis", "startup")
    assert again.model_dump() == model.model_dump()  # the name the table does not have is written back too
    assert model.unknown == {"configuration.channel[0].interpolator.parameter": "200"}  # not in the table


def test_a_flag_that_is_no_symbol_is_refused() -> None:
    model = list_model("startup")
    assert (
        model.model_validate({"error_protocol_mode": "REPORT|PRINT"}).get("error_protocol_mode")
        == "REPORT|PRINT"
    )
    for wrong in ("REPORT | NOPE", "REPORT |", "report"):
        with pytest.raises(ValidationError, match="error_protocol_mode"):
            model.model_validate({"error_protocol_mode": wrong})
    with pytest.raises(ValidationError):
        model.model_validate({"kanal_anzahl": 13})  # P-STUP-00001: at most 12 channels


def test_schema_command_prints_the_model_of_each_kind() -> None:
    assert {kind.value for kind in cli.SchemaKind} == set(MODELS)
    for kind, title in (
        ("axis", "AxisParameters"),
        ("channel", "ChannelParameters"),
        ("startup", "StartupParameters"),
    ):
        done = run_cli("schema", "--kind", kind)
        assert done.returncode == 0, done.stderr
        schema = json.loads(done.stdout)
        assert schema == json_schema(kind) and schema["title"] == title
    assert json.loads(run_cli("schema").stdout)["title"] == "AxisParameters"  # the default
    channel = json_schema("channel")
    assert {"gruppe", "spindel", "grp_anzahl", "unknown"} <= set(channel["properties"])
    assert (
        channel["properties"]["gruppe"]["type"] == "array"
        and "maxItems" not in channel["properties"]["gruppe"]
    )
    wrong = run_cli("schema", "--kind", "tools")
    assert wrong.returncode == 2


def test_a_model_dump_validates_against_its_schema() -> None:
    jsonschema = pytest.importorskip("jsonschema")
    for kind, name in (("channel", "sda_mds1.lis"), ("startup", "hochlauf.lis")):
        model = build_list_model((KINDS / name).read_bytes(), name, kind)
        validator = jsonschema.Draft202012Validator(json_schema(kind))
        document = model.model_dump(mode="json", by_alias=True)
        assert list(validator.iter_errors(document)) == []
        if kind == "startup":
            document["error_protocol_mode"] = "REPORT | NOPE"
            assert len(list(validator.iter_errors(document))) == 1  # the schema can fail
