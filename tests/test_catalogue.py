"""The packaged catalogue is complete and consistent."""

from __future__ import annotations

import re

from achslint.catalogue import BOOL, INTEGER, REAL, SYMBOL, catalogue

# Parameters whose documented default lies outside the documented range: the
# default is a "not set" marker (0 or -1). Documented inconsistencies C.24/C.25
# and the parameter pages.
SENTINEL_DEFAULTS = {
    "P-AXIS-00003",
    "P-AXIS-00013",
    "P-AXIS-00019",
    "P-AXIS-00040",
    "P-AXIS-00043",
    "P-AXIS-00045",
    "P-AXIS-00046",
    "P-AXIS-00053",
    "P-AXIS-00070",
    "P-AXIS-00072",
    "P-AXIS-00075",
    "P-AXIS-00100",
    "P-AXIS-00101",
    "P-AXIS-00130",
    "P-AXIS-00243",
    "P-AXIS-00275",
    "P-AXIS-00280",
    "P-AXIS-00281",
    "P-AXIS-00282",
    "P-AXIS-00283",
    "P-AXIS-00284",
    "P-AXIS-00295",
    "P-AXIS-00296",
    "P-AXIS-00301",
    "P-AXIS-00311",
    "P-AXIS-00314",
    "P-AXIS-00316",
    "P-AXIS-00317",
    "P-AXIS-00332",
    "P-AXIS-00333",
    "P-AXIS-00334",
    "P-AXIS-00335",
    "P-AXIS-00355",
    "P-AXIS-00371",
    "P-AXIS-00383",
    "P-AXIS-00387",
    "P-AXIS-00390",
    "P-AXIS-00420",
    "P-AXIS-00425",
    "P-AXIS-00432",
    "P-AXIS-00433",
    "P-AXIS-00434",
    "P-AXIS-00435",
    "P-AXIS-00438",
    "P-AXIS-00450",
    "P-AXIS-00451",
    "P-AXIS-00484",
    "P-AXIS-00495",
    "P-AXIS-00541",
    "P-AXIS-00750",
    "P-AXIS-00751",
    "P-AXIS-00752",
    "P-AXIS-00756",
    "P-AXIS-00770",
    "P-AXIS-00771",
    "P-AXIS-00775",
    "P-AXIS-00850",
}


def test_all_787_parameters_with_unique_ids_and_paths():
    cat = catalogue()
    assert len(cat.parameters) == 787
    assert len({p.id for p in cat.parameters}) == 787
    assert len({p.path for p in cat.parameters}) == 787
    for p in cat.parameters:
        assert re.fullmatch(r"P-AXIS-\d{5}", p.id)
        assert re.fullmatch(r"[a-z_][a-z0-9_]*(\[i\])?(\.[a-z_][a-z0-9_]*(\[i\])?)*", p.path, re.I), p.path
        assert p.path.count("[i]") == len(p.index_bounds), p.id
        assert p.summary


# The homing parameters of the TF5200 homing manual (§4.1 overview) carry our own descriptions.
HOMING_IDS = [
    "P-AXIS-00014",
    "P-AXIS-00015",
    "P-AXIS-00036",
    "P-AXIS-00038",
    "P-AXIS-00064",
    "P-AXIS-00074",
    "P-AXIS-00084",
    "P-AXIS-00152",
    "P-AXIS-00156",
    "P-AXIS-00157",
    "P-AXIS-00158",
    "P-AXIS-00161",
    "P-AXIS-00218",
    "P-AXIS-00219",
    "P-AXIS-00285",
    "P-AXIS-00299",
    "P-AXIS-00321",
    "P-AXIS-00333",
    "P-AXIS-00344",
    "P-AXIS-00345",
    "P-AXIS-00346",
    "P-AXIS-00348",
    "P-AXIS-00349",
    "P-AXIS-00354",
    "P-AXIS-00355",
    "P-AXIS-00386",
    "P-AXIS-00387",
    "P-AXIS-00388",
    "P-AXIS-00412",
    "P-AXIS-00425",
    "P-AXIS-00426",
    "P-AXIS-00494",
]


def test_homing_parameters_have_own_descriptions():
    cat = catalogue()
    missing = [pid for pid in HOMING_IDS if not cat.by_id[pid].description]
    assert missing == []


def test_alias_and_misspelling_targets_exist():
    cat = catalogue()
    for alias, (parameter, info) in cat.aliases.items():
        assert parameter.id in cat.by_id
        assert alias != parameter.path
        assert info.kind in ("old", "alternative", "misspelling")
    assert cat.resolve("kenngr.homing_type").parameter.id == "P-AXIS-00299"
    assert cat.resolve("antr_simu.rpf_weg_bis_nip").alias.kind == "misspelling"


def test_ranges_parse_and_defaults_lie_inside_them():
    outside = set()
    for p in catalogue().parameters:
        for bound in (p.min, p.max):
            assert bound is None or isinstance(bound, (int, float, str))
        if p.min is not None and not isinstance(p.min, (int, float)):
            assert isinstance(p.min, str)
        default = p.typed_default
        if p.kind in (INTEGER, REAL) and isinstance(default, (int, float)) and not isinstance(default, bool):
            low = p.min if isinstance(p.min, (int, float)) else None
            high = p.max if isinstance(p.max, (int, float)) else None
            strict_low = p.min_strict and low == 0
            if (low is not None and (default < low or (strict_low and default == low))) or (
                high is not None and default > high
            ):
                outside.add(p.id)
        if p.allowed and isinstance(default, int) and default not in p.allowed:
            outside.add(p.id)
    assert outside == SENTINEL_DEFAULTS


def test_symbols_and_kinds():
    cat = catalogue()
    homing = cat.by_id["P-AXIS-00299"]
    assert (
        homing.kind == SYMBOL
        and "DRIVE_CONTROLLED" in homing.symbols
        and "DRIVE_CONROLLED" not in homing.symbols
    )
    assert cat.by_id["P-AXIS-00018"].symbol_codes == {
        "ACHSTYP_TRANSLATOR": 1,
        "ACHSTYP_ROTATOR": 2,
        "ACHSTYP_SPINDEL": 4,
    }
    assert cat.by_id["P-AXIS-00014"].kind == BOOL
    assert cat.by_id["P-AXIS-00219"].unit("R") == "0.001deg/s"
    assert cat.by_id["P-AXIS-00218"].index_bounds == ((0, 5),)
    # 1..31 as the manual says; its default 0 (C.24) is accepted as such, not the values up to 1
    assert cat.by_id["P-AXIS-00355"].limits == (1, 31) and cat.by_id["P-AXIS-00355"].outside_default == 0


def test_drive_types_use_p_axis_00020_codes():
    valid = set(catalogue().by_id["P-AXIS-00020"].allowed)
    for p in catalogue().parameters:
        assert set(p.drive_types) <= valid, p.id


def test_lookup_by_id_name_alias_and_member():
    cat = catalogue()
    assert cat.find("P-AXIS-00218").path == "getriebe[i].vb_reflow"
    assert cat.find("vb_reflow").id == "P-AXIS-00218"
    assert cat.find("getriebe[0].vb_reflow").id == "P-AXIS-00218"
    assert cat.find("kenngr.homing_type").id == "P-AXIS-00299"
    assert cat.find("no_such_thing") is None


def _tools():
    import sys
    from pathlib import Path

    tools = Path(__file__).resolve().parents[1] / "tools"
    if str(tools) not in sys.path:
        sys.path.insert(0, str(tools))
    import build_catalogue
    import gen_model

    return build_catalogue, gen_model


def test_catalogue_and_model_are_rebuilt_from_the_repository():
    """The committed catalogue.json and model_generated.py are exactly what the tools build from
    tools/catalogue/params.tsv and the overrides (regenerate with `python tools/build_catalogue.py`)."""
    build_catalogue, gen_model = _tools()
    assert build_catalogue.OUTPUT.read_text(encoding="utf-8") == build_catalogue.catalogue_text()
    assert gen_model.OUTPUT.read_text(encoding="utf-8") == gen_model.model_source()


def test_overrides_can_add_a_parameter_the_table_lacks(tmp_path):
    import pytest

    build_catalogue, _ = _tools()
    overrides = build_catalogue.OVERRIDES.read_text(encoding="utf-8") + (
        '\n[add."P-AXIS-09999"]\npath = "kenngr.made_up_limit"\ntype = "UNS16"\nrange = "0 ≤ made_up_limit ≤ 500"\n'
        'unit_T = "mm"\ndefault = "7"\ndrive_types = "1 4"\ntitle = "A limit for the test"\n'
    )
    path = tmp_path / "overrides.toml"
    path.write_text(overrides, encoding="utf-8")
    entry = [
        e
        for e in build_catalogue.build(
            build_catalogue.read_table(build_catalogue.TABLE), build_catalogue.tomllib.loads(overrides)
        )["parameters"]
        if e["id"] == "P-AXIS-09999"
    ]
    assert entry == [
        {
            "id": "P-AXIS-09999",
            "path": "kenngr.made_up_limit",
            "type": "UNS16",
            "min": 0,
            "max": 500,
            "range_text": "0 ≤ made_up_limit ≤ 500",
            "default": 7,
            "units": {"T": "mm", "R": None, "S": None},
            "drive_types": [1, 4],
            "title": "A limit for the test",
        }
    ]
    # Adding a parameter the table already has is a mistake the tool names.
    with pytest.raises(SystemExit, match="already a row"):
        build_catalogue.build(
            build_catalogue.read_table(build_catalogue.TABLE),
            build_catalogue.tomllib.loads(overrides.replace("P-AXIS-09999", "P-AXIS-00001")),
        )


def test_every_parameter_is_a_field_of_the_typed_model():
    """No catalogue parameter is dropped by the generated model (P-AXIS-00560 `kenngr.swe_pos.zero_limit`
    sits next to the parameter `kenngr.swe_pos` and becomes the field `swe_pos_zero_limit`)."""
    from achslint.model import axis_model

    axis = axis_model()()
    for parameter in catalogue().parameters:
        path = parameter.path.replace("[i]", "[0]")
        assert axis.get(path) == parameter.typed_default or parameter.typed_default is None, path
    assert axis.kenngr.swe_pos_zero_limit == catalogue().by_id["P-AXIS-00560"].typed_default
