"""List kinds (issue 24 items 1-2, issue 25 item 1): the catalogue of every kind, built reproducibly from the
reference tables, and a list's kind told from its content whatever its file name."""

from __future__ import annotations

import json
import shutil
import sys
from pathlib import Path

import pytest

from achslint.catalogue import catalogue
from achslint.catalogue import kinds as kinds_module
from achslint.catalogue.kinds import (
    AXIS,
    BY_ID,
    BY_TABLE,
    CHANNEL,
    COMPENSATION,
    CONTENT_KINDS,
    DEFAULT_AXIS,
    DEFAULT_CHANNEL,
    ENTRY_KINDS,
    KINDS,
    REALTIME,
    SAMPLE_LINES,
    STARTUP,
    TABLES,
    TOOLS,
    ZERO_OFFSETS,
    entry_kind,
    kind_of,
    load_table,
)
from achslint.syntax.parser import parse_bytes, parse_text

from .conftest import FIXTURES, ROOT

KINDS_FIXTURES = FIXTURES / "kinds"
REFERENCE = FIXTURES / "reference"

# One small list of each kind, written for these tests.
OWN_LISTS = {
    "achsmds_z.lis": "axis",
    "sda_mds1.lis": "channel",
    "hochlauf.lis": "startup",
    "werkz_d1.lis": "tools",
    "nullp_d1.lis": "zero_offsets",
    "pzv_d1.lis": "clamp_offsets",
    "achskw1.lis": "compensation",
    "hand_mds.lis": "manual",
    "ext_var1.lis": "external_variables",
    "rtconf.lis": "realtime",
    "scene.lis": "scene",
    "volcomp.lis": "volumetric_compensation",
    "hw_conf.lis": "hardware",
    "ddl.lis": "cmld",
}


def guess(name: str, text: str | None = None) -> str:
    data = (KINDS_FIXTURES / name).read_bytes() if text is None else text.encode("ascii")
    return kind_of(parse_bytes(data, name)).id


# --- telling a list's kind from its content ----------------------------------------------------------


@pytest.mark.parametrize(("name", "kind"), sorted(OWN_LISTS.items()))
def test_a_list_of_each_kind_is_recognised(name, kind):
    assert guess(name) == kind


def test_every_kind_with_a_catalogue_has_a_list_above():
    assert {kind.id for kind in CONTENT_KINDS} == set(OWN_LISTS.values())


@pytest.mark.parametrize("name", sorted(OWN_LISTS))
def test_the_file_name_plays_no_part(name, tmp_path):
    """The same bytes under a name that says nothing (or the name of another kind) give the same kind."""
    for other in ("list.lis", "achsmds7.lis", "hochlauf.lis"):
        renamed = tmp_path / other
        shutil.copyfile(KINDS_FIXTURES / name, renamed)
        assert kind_of(parse_bytes(renamed.read_bytes(), str(renamed))).id == OWN_LISTS[name], other


def test_a_start_up_list_named_basis_is_a_start_up_list():
    result = kind_of(parse_bytes((KINDS_FIXTURES / "basis.lis").read_bytes(), "basis.lis"))
    assert result.kind is STARTUP
    # 13 assignments, every one a start-up parameter (achs_mds[0] and zahl_mds among them), nothing else.
    assert result.paths == {"startup": 13}
    assert result.unknown == 0


def test_an_axis_list_with_a_few_unknown_parameters_is_still_an_axis_list():
    result = kind_of(
        parse_bytes((KINDS_FIXTURES / "achsmds_unknown.lis").read_bytes(), "achsmds_unknown.lis")
    )
    assert result.kind is AXIS
    # 9 assignments: 6 axis parameters (kopf.achs_nr and kopf.log_achs_name are compensation-list names
    # too), 3 nobody knows.
    assert result.paths == {"axis": 6, "compensation": 2}
    assert result.unknown == 3


@pytest.mark.parametrize(
    ("pattern", "kind"),
    [
        ("*/listen/hochlauf*.lis", "startup"),
        ("extschedule/listen/ExtSchedule/hochlauf.lis", "startup"),
        ("*/listen/achsmds*.lis", "axis"),
        ("*/listen/default_mds.lis", "axis"),  # a default list reads like the list it lies under
        ("*/listen/default_sda.lis", "channel"),
        ("*/listen/sda_mds1.lis", "channel"),
        ("*/listen/rtconf.lis", "realtime"),
    ],
)
def test_the_example_machines_lists(pattern, kind):
    files = sorted((FIXTURES / "machines").glob(pattern))
    assert files
    assert {str(path.relative_to(FIXTURES)): guess_path(path) for path in files} == {
        str(path.relative_to(FIXTURES)): kind for path in files
    }


def guess_path(path: Path) -> str:
    return kind_of(parse_bytes(path.read_bytes(), str(path))).id


def test_every_example_list_is_covered_above():
    patterns = (
        "*/listen/hochlauf*.lis",
        "*/listen/*/hochlauf.lis",
        "*/listen/achsmds*.lis",
        "*/listen/default_mds.lis",
        "*/listen/default_sda.lis",
        "*/listen/sda_mds1.lis",
        "*/listen/rtconf.lis",
    )
    covered = {path for pattern in patterns for path in (FIXTURES / "machines").glob(pattern)}
    assert covered == set((FIXTURES / "machines").glob("*/listen/**/*.lis"))


def test_an_empty_list_is_an_axis_list_as_before():
    for text in ("", "Ende\n", "# only a comment\n\nEnde\n"):
        assert guess("empty.lis", text) == "axis", repr(text)


def test_a_tiny_axis_list_stays_an_axis_list():
    """`kopf.*` names are in the compensation list's catalogue too: the tie goes to the axis kind."""
    result = kind_of(parse_text("kopf.achs_nr 1\nkopf.log_achs_name X\nEnde\n"))
    assert (result.id, result.paths) == ("axis", {"axis": 2, "compensation": 2})


def test_a_list_nobody_knows_is_unknown():
    result = kind_of(parse_text("foo.bar 1\nbaz[2].qux 3\nEnde\n"))
    assert (result.id, result.kind, result.unknown) == ("unknown", None, 2)


def test_two_other_kinds_tied_is_unknown():
    """One tool-data path and one zero-offset path: nothing to choose between them."""
    result = kind_of(parse_text("wz[1].laenge 1000\nnp_grp[0].achse[0].versch 5\nEnde\n"))
    assert result.paths == {"tools": 1, "zero_offsets": 1}
    assert result.id == "unknown"


def test_parameter_ids_in_comments_are_strong_evidence():
    """Paths no catalogue has, but the vendor's comments name zero-offset parameters: a zero-offset list.
    Each id counts twice: 3 ids outweigh 5 axis paths (6 > 5)."""
    text = (
        "".join(f"np_grp[{group}].new_member 0   ( P-ZERO-00003 : offset\n" for group in range(3))
        + "kopf.achs_nr 1\nkopf.log_achs_name X\nkenngr.achs_typ 1\nkenngr.antr_typ 4\ngetriebe[0].vb_reflow 9\n"
        + "Ende\n"
    )
    result = kind_of(parse_text(text))
    assert result.ids == {"zero_offsets": 3}
    assert result.score("zero_offsets") == 6
    assert result.score("axis") == 5
    assert result.kind is ZERO_OFFSETS


def test_ids_are_read_from_comment_lines_and_unknown_prefixes_ignored():
    text = "# P-CHAN-00036 tells the spindle's number\n# P-ABCD-00001 is no kind's id\nfoo 1 ( P-XYZ\nEnde\n"
    result = kind_of(parse_text(text))
    assert (result.id, result.ids, result.unknown) == ("channel", {"channel": 1}, 1)


def test_what_follows_the_end_marker_is_not_read():
    text = "wz[1].laenge 1000\nEnde\n" + "kopf.achs_nr 1\n" * 5
    result = kind_of(parse_text(text))
    assert (result.id, result.paths) == ("tools", {"tools": 1})


def test_only_the_head_of_a_long_list_is_read():
    """A list shows its kind at its head: past SAMPLE_LINES lines nothing is read (a 50,000-line list costs
    what a 4,096-line one does; benchmarks/kinds.py)."""
    head = "wz[1].laenge 1000\n" * SAMPLE_LINES
    result = kind_of(parse_text(head + "kopf.achs_nr 1\n" * 10 + "Ende\n"))
    assert (result.id, result.paths, result.lines) == ("tools", {"tools": SAMPLE_LINES}, SAMPLE_LINES)


def test_telling_an_axis_list_reads_no_other_catalogue():
    """Cold start of axis linting: the other kinds' catalogues are read on first use only."""
    load_table.cache_clear()
    assert guess("achsmds_z.lis") == "axis"
    assert load_table.cache_info().currsize == 0
    CHANNEL.catalogue()
    DEFAULT_CHANNEL.catalogue()  # the same table: read once
    assert load_table.cache_info().currsize == 1


# --- the kinds and the start-up list's entries ---------------------------------------------------------


def test_kinds_are_unique_and_named():
    assert len(BY_ID) == len(KINDS)
    assert all(kind.name.endswith("list") or "list" in kind.name for kind in KINDS)
    assert sorted(BY_TABLE) == sorted(TABLES)
    assert len(TABLES) == 13


def test_the_axis_kinds_use_the_axis_catalogue():
    assert AXIS.catalogue() is catalogue()
    assert DEFAULT_AXIS.catalogue() is catalogue()
    assert BY_ID["hmi_objects"].catalogue() is None
    assert not BY_ID["cam_tables"].has_catalogue


@pytest.mark.parametrize(
    ("key", "kind"),
    [
        ("achs_mds[0]", AXIS),
        ("achs_mds[31]", AXIS),
        ("default_achs_mds", DEFAULT_AXIS),
        ("sda_mds[1]", CHANNEL),
        ("default_sda_mds", DEFAULT_CHANNEL),
        ("werkz_data[0]", TOOLS),
        ("nullp_data[0]", ZERO_OFFSETS),
        ("achs_kw[2]", COMPENSATION),
        ("rtconf_lis", REALTIME),
        ("vol_comp[0].file_name", BY_ID["volumetric_compensation"]),
        ("zahl_mds", None),
        ("achs_kw_log_ax_nr[0]", None),
        ("konf_path", None),
    ],
)
def test_start_up_entries_name_the_kind_of_their_list(key, kind):
    assert entry_kind(key) is kind


def test_every_entry_is_a_start_up_parameter_naming_a_file():
    startup = STARTUP.catalogue()
    assert startup is not None
    for key in ENTRY_KINDS:
        parameter = startup.by_pattern[key]
        assert parameter.type == "STRING", key
        assert "file" in parameter.title.lower(), key


def test_every_list_entry_of_the_sdk_style_start_up_list_has_its_kind():
    """Each entry of our start-up fixture whose value is a list file is mapped, to the kind its list is."""
    listed = {
        line.path: entry_kind(line.path or "")
        for line in parse_bytes((KINDS_FIXTURES / "hochlauf.lis").read_bytes()).assignments()
        if (line.value or "").endswith(".lis")
    }
    assert {key: kind.id if kind else None for key, kind in listed.items()} == {
        "default_sda_mds": "default_channel",
        "sda_mds[0]": "channel",
        "werkz_data[0]": "tools",
        "nullp_data[0]": "zero_offsets",
        "hand_mds": "manual",
        "rtconf_lis": "realtime",
        "default_achs_mds": "default_axis",
        "achs_mds[0]": "axis",
        "achs_mds[1]": "axis",
    }


# --- the packaged catalogues ---------------------------------------------------------------------------


@pytest.mark.parametrize("table", TABLES)
def test_each_kind_catalogue_loads_and_answers(table):
    kind = BY_TABLE[table]
    data = json.loads((kinds_module.DATA / f"{table}.json").read_text(encoding="utf-8"))
    assert (data["table"], data["prefix"]) == (table, kind.prefix)
    loaded = kind.catalogue()
    assert loaded is not None and loaded.parameters
    for parameter in loaded.parameters:
        assert parameter.id.startswith(f"{kind.prefix}-")
        written = parameter.path.replace("[i]", "[0]")
        resolved = loaded.resolve(written)
        assert resolved is not None and resolved.parameter is parameter, written
    index = json.loads((kinds_module.DATA / kinds_module.INDEX_FILE).read_text(encoding="utf-8"))
    assert index["paths"][table] == [parameter.path for parameter in loaded.parameters]


@pytest.mark.parametrize(
    ("kind", "path", "bounds", "limits"),
    [
        (STARTUP, "kanal_anzahl", (1, 12), (1, 12)),  # "1 - 12"; the default 0 is accepted as such
        (STARTUP, "zahl_mds", (1, 32), (1, 32)),  # "1 ... 32", default 0
        (STARTUP, "sercos_hochlauf", (-(2**15), 2**15 - 1), (-(2**15), 2**15 - 1)),  # "0 or .1": no bound
        (REALTIME, "cycle_time", (0, 2**32 - 1), (1, 2**32 - 1)),  # "0 < cycle_time < MAX(UNS32)", no default
        (TOOLS, "wz[i].srk_lage", (0, 9), (1, 9)),  # "0 < srk_lage ≤ 9", default 0
        (CHANNEL, "gruppe[i].achs_anzahl", (0, 2**16 - 1), (0, 2**16 - 1)),  # "0 ... 32 (...)"
    ],
)
def test_range_texts_become_bounds_where_they_are_bounds(kind, path, bounds, limits):
    """`min`/`max` as the range text gives them (else the type's limits), and the limits the range check
    applies with the axis catalogue's rules (a strict 0 is 1; a default outside them is accepted itself)."""
    parameter = kind.catalogue().by_pattern[path]
    assert (parameter.min, parameter.max) == bounds
    assert parameter.limits == limits
    low, high = limits
    default = parameter.default if isinstance(parameter.default, int) else None
    outside = default is not None and not low <= default <= high
    assert parameter.outside_default == (default if outside else None)


def test_units_symbols_and_lengths_come_through():
    zero = ZERO_OFFSETS.catalogue().by_pattern["np_grp[i].achse[i].versch"]
    assert zero.unit("T") == "0.1um" and zero.unit("R") == "0.0001deg"
    assert REALTIME.catalogue().by_pattern["cycle_time"].unit("T") == "us"
    schedule = REALTIME.catalogue().by_pattern["schedule"]
    assert schedule.symbols == ("ALL", "STANDARD", "COMPLETE", "SWITCHED")
    assert STARTUP.catalogue().by_pattern["achs_mds[i]"].max_length == 256
    assert COMPENSATION.catalogue().by_id["P-COMP-00059"].restart


# --- the build tool ------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def build_kinds():
    tools = str(ROOT / "tools")
    if tools not in sys.path:
        sys.path.insert(0, tools)
    import build_kinds

    return build_kinds


def test_the_build_is_reproducible_and_gives_the_reviewed_files(build_kinds, tmp_path):
    first, second = tmp_path / "first", tmp_path / "second"
    for output in (first, second):
        assert build_kinds.main(["--reference", str(REFERENCE), "--output", str(output)]) == 0
    expected = REFERENCE / "expected"
    names = sorted(path.name for path in expected.iterdir())
    assert names == ["chan.json", "index.json", "stup.json"]
    for name in names:
        assert (
            (first / name).read_bytes() == (second / name).read_bytes() == (expected / name).read_bytes()
        ), name
    assert sorted(path.name for path in first.iterdir()) == names


def test_check_compares_with_a_fresh_build(build_kinds, tmp_path, capsys):
    output = tmp_path / "kinds"
    shutil.copytree(REFERENCE / "expected", output)
    assert build_kinds.main(["--check", "--reference", str(REFERENCE), "--output", str(output)]) == 0
    stale = output / "stup.json"
    stale.write_text(stale.read_text(encoding="utf-8").replace('"max": 32', '"max": 33'), encoding="utf-8")
    assert build_kinds.main(["--check", "--reference", str(REFERENCE), "--output", str(output)]) == 1
    assert f"{stale} is stale: run python tools/build_kinds.py" in capsys.readouterr().err


def test_check_without_the_reference_folder_skips(build_kinds, tmp_path, capsys):
    missing = tmp_path / "no-reference"
    assert build_kinds.main(["--check", "--reference", str(missing), "--output", str(tmp_path)]) == 0
    assert (
        capsys.readouterr().out
        == f"{missing}: no reference folder, nothing checked (--reference DIR names one)\n"
    )


def table_with(tmp_path: Path, row: str) -> Path:
    folder = tmp_path / "reference"
    folder.mkdir()
    header = "id\tpath\ttype\tdefault\tunit\tmax_number\trestart\tsymbols\trange\ttitle\n"
    (folder / "params-comp.tsv").write_text(header + row + "\n", encoding="utf-8")
    return folder


def test_array_sizes_and_restart_flags_are_taken(build_kinds, tmp_path):
    folder = table_with(
        tmp_path, "P-COMP-00016\tkw.crosscomp2.table[][].correction\tSGN32\t0\t\t101 21\ttrue\t\t\tt"
    )
    entry = json.loads(build_kinds.build(folder)["comp.json"].splitlines()[5])
    assert entry["index_bounds"] == [[0, 100], [0, 20]]
    assert entry["restart"] is True


@pytest.mark.parametrize(
    ("row", "problem"),
    [
        (
            "P-COMP-00001\tkopf.achs_nr\tUNS16\t0\tUNIT_FURLONG\t\tfalse\t\t\tt",
            "unit UNIT_FURLONG is not known",
        ),
        ("P-COMP-00001\tkopf.achs_nr\tUNS16\t0\t\t8\tfalse\t\t\tt", "does not give one size per index"),
        ("P-COMP-00001\tkopf.achs_nr\tUNS16\t0\t\t\tmaybe\t\t\tt", "restart is 'maybe'"),
        ("P-CHAN-00001\tkopf.achs_nr\tUNS16\t0\t\t\tfalse\t\t\tt", "P-CHAN-00001 is not a P-COMP id"),
        ("P-COMP-00001\tkopf.achs_nr\tUNS16\t0", "expected 10 tab-separated columns, found 4"),
    ],
)
def test_a_bad_table_row_is_named_with_its_line(build_kinds, tmp_path, row, problem):
    folder = table_with(tmp_path, row)
    with pytest.raises(SystemExit) as failure:
        build_kinds.build(folder)
    message = str(failure.value)
    assert message.startswith(f"{folder / 'params-comp.tsv'}:2: ")
    assert problem in message
    assert "\n" not in message
