"""The LIS0/1/2 families for every list kind (issue 25 item 2): a list of a kind with a catalogue is checked
against that kind's catalogue by the rules that declare its kind, the axis-only rules (homing, drive, the
resolved axis) never run on it, and a name the kind's partial catalogue lacks is only an info."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from achslint.catalogue import BOOL, INTEGER, REAL, STRING, SYMBOL, Parameter
from achslint.catalogue.kinds import AXIS, BY_ID, CHANNEL, CONTENT_KINDS, Kind, load_table
from achslint.core.diagnostics import Severity
from achslint.linting.engine import enabled_checks
from achslint.linting.linter import FileSettings, lint_file, list_kind
from achslint.rules import ALL_KINDS, Scope, registry
from achslint.rules.context import Context
from achslint.syntax.parser import parse_bytes, parse_text

from .conftest import FIXTURES, examples, run_cli

GOOD = FIXTURES / "kinds"
BAD = FIXTURES / "kind_rules"

# The good list of every kind with a catalogue (written by the kinds fixture set), by kind id.
GOOD_LISTS = {
    "channel": "sda_mds1.lis",
    "startup": "hochlauf.lis",
    "tools": "werkz_d1.lis",
    "zero_offsets": "nullp_d1.lis",
    "clamp_offsets": "pzv_d1.lis",
    "compensation": "achskw1.lis",
    "manual": "hand_mds.lis",
    "external_variables": "ext_var1.lis",
    "realtime": "rtconf.lis",
    "scene": "scene.lis",
    "volumetric_compensation": "volcomp.lis",
    "hardware": "hw_conf.lis",
    "cmld": "ddl.lis",
}
OTHER_KINDS = [kind for kind in CONTENT_KINDS if kind.id != AXIS.id]

# What each bad list must give, exactly: (code, line, severity, a fragment of the message).
UNKNOWN = "not in achslint's catalogue of this kind"
EXPECTED: dict[str, list[tuple[str, int, Severity, str]]] = {
    "channel": [
        ("LIS202", 3, Severity.ERROR, "`grp_anzahl` = 2 is above the maximum 1"),
        ("LIS101", 6, Severity.INFO, "did you mean `gruppe[0].achse[0].bezeichnung`?"),
        ("LIS203", 10, Severity.ERROR, "`MOSS` is not a value of `m_synch[3]` (did you mean `MOS`?)"),
    ],
    "startup": [
        ("LIS202", 3, Severity.ERROR, "`kanal_anzahl` = 13 is above the maximum 12"),
        ("LIS101", 6, Severity.INFO, "did you mean `sda_mds[0]`?"),
        ("LIS203", 7, Severity.ERROR, "(did you mean `FCT_TIME_OPT`?)"),
    ],
    "tools": [
        ("LIS101", 6, Severity.INFO, "did you mean `wz[1].radius`?"),
        ("LIS202", 7, Severity.ERROR, "`wz[1].srk_lage` = 12 is above the maximum 9"),
        ("LIS203", 8, Severity.ERROR, "(did you mean `GEAR_CHANGE_NO_STOP`?)"),
    ],
    "zero_offsets": [
        ("LIS202", 4, Severity.ERROR, "`default_index` = -1 is below the minimum 0"),
        ("LIS101", 6, Severity.INFO, "did you mean `np_grp[1].achse[1].versch`?"),
    ],
    "clamp_offsets": [
        ("LIS202", 3, Severity.ERROR, "is above the maximum 2147483647"),
        ("LIS101", 4, Severity.INFO, "did you mean `pzv_grp[1].achse[0].versatz`?"),
    ],
    "compensation": [
        ("LIS202", 3, Severity.ERROR, "`kopf.achs_nr` = -1 is below the minimum 1"),
        ("LIS101", 6, Severity.INFO, "did you mean `kw.ssfk.interval`?"),
        ("LIS203", 8, Severity.ERROR, "`SQUARE` is not a value of `kw.crosscomp2.grid`"),
    ],
    "manual": [
        ("LIS202", 3, Severity.ERROR, "`hr_anzahl` = -1 is below the minimum 0"),
        ("LIS101", 4, Severity.INFO, "did you mean `hr_data[0].log_hr_nr`?"),
    ],
    "external_variables": [
        ("LIS202", 5, Severity.ERROR, "`var[0].byte_offset` = -4 is below the minimum 0"),
        ("LIS101", 7, Severity.INFO, "did you mean `var[1].name`?"),
        ("LIS203", 8, Severity.ERROR, "`GLOBLA` is not a value of `var[1].scope` (did you mean `GLOBAL`?)"),
    ],
    "realtime": [
        ("LIS202", 3, Severity.ERROR, "`cycle_time` = 0 µs is below the minimum 1 µs"),
        ("LIS101", 6, Severity.INFO, "did you mean `thread[0].priority`?"),
        ("LIS203", 7, Severity.ERROR, "`STANDART` is not a value of `schedule` (did you mean `STANDARD`?)"),
    ],
    "scene": [
        ("LIS101", 5, Severity.INFO, "did you mean `gobject[0].name`?"),
        ("LIS202", 7, Severity.ERROR, "`gobject[0].cs.orientation[0][0]` = 1.5 is above the maximum 1"),
    ],
    "volumetric_compensation": [
        ("LIS202", 3, Severity.ERROR, "`x` = -1 is below the minimum 0"),
        ("LIS101", 6, Severity.INFO, "so it is not checked"),  # `chian`: no name close enough to suggest
        ("LIS203", 9, Severity.ERROR, "`GRIDS` is not a value of `interpolation` (did you mean `GRID`?)"),
    ],
    "hardware": [
        ("LIS203", 3, Severity.ERROR, "(did you mean `HW_DEVICE_SIMULATION`?)"),
        ("LIS101", 4, Severity.INFO, "did you mean `device[0].name`?"),
        ("LIS202", 6, Severity.ERROR, "`device[0].length` = -8 is below the minimum 0"),
    ],
    "cmld": [
        ("LIS202", 3, Severity.ERROR, "`ddl[0].type` = -1 is below the minimum 0"),
        ("LIS101", 5, Severity.INFO, "did you mean `ddl[1].token`?"),
    ],
}


def lint(path: Path, kind: str | None = None) -> tuple[list[tuple[str, int, Severity, str]], str | None]:
    result = lint_file(path.read_bytes(), str(path), FileSettings(kind=kind))
    assert result.error is None
    return [(d.code, d.line, d.severity, d.message) for d in result.diagnostics], result.note


def test_every_kind_with_a_catalogue_has_a_good_and_a_bad_list() -> None:
    kinds = {kind.id for kind in OTHER_KINDS}
    assert set(GOOD_LISTS) == kinds == set(EXPECTED)
    assert {folder.name for folder in BAD.iterdir()} == kinds


@pytest.mark.parametrize("kind_id", sorted(GOOD_LISTS))
def test_a_good_list_of_each_kind_is_told_by_content_and_gives_no_finding(kind_id: str) -> None:
    path = GOOD / GOOD_LISTS[kind_id]
    assert list_kind(parse_bytes(path.read_bytes(), path.name), str(path)).id == kind_id
    found, note = lint(path)
    assert note is None  # checked, not skipped
    assert found == []


@pytest.mark.parametrize("kind_id", sorted(EXPECTED))
def test_a_bad_list_of_each_kind_gives_exactly_its_findings(kind_id: str) -> None:
    path = BAD / kind_id / "bad.lis"
    # the kind is told by content as when the list is passed alone, and is the same when the start-up says it
    assert list_kind(parse_bytes(path.read_bytes(), path.name), str(path)).id == kind_id
    for given_kind in (None, kind_id):
        found, note = lint(path, given_kind)
        assert note is None
        assert [(code, line, severity) for code, line, severity, _ in found] == [
            (code, line, severity) for code, line, severity, _ in EXPECTED[kind_id]
        ]
        for (code, _, _, message), (_, _, _, fragment) in zip(found, EXPECTED[kind_id], strict=True):
            assert fragment in message, (code, message)
            if code == "LIS101":  # the finding names the list kind and why it is not an error
                assert f"in this {BY_ID[kind_id].name}: {UNKNOWN}" in message


def test_only_the_rules_of_the_list_kind_run() -> None:
    # the registry exposes every rule's kinds; for a channel list the engine picks the LIS0/1/2 families
    # except the axis-only LIS105 (drive type) and LIS204 (achs_mode bits), and the channel's kind rules
    rules = registry()
    every_kind = {code for code, rule in rules.items() if rule.kinds == ALL_KINDS}
    families = {code for code in rules if code[:4] in ("LIS0", "LIS1", "LIS2")}
    assert every_kind == families - {"LIS105", "LIS204"}
    channel_rules = {"LIS701", "LIS702", "LIS703", "LIS706"}
    assert {code for code, _ in enabled_checks(Scope.LIST, None, False, "channel")} == (
        every_kind - {"LIS009"}
    ) | channel_rules
    assert {code for code, _ in enabled_checks(Scope.LIST, None, False, "compensation")} == (
        every_kind - {"LIS009"}
    ) | {"LIS704", "LIS705"}
    # a default channel list lies under the channel lists: its counts and slots are not a channel's own
    assert not channel_rules & {
        code for code, _ in enabled_checks(Scope.LIST, None, False, "default_channel")
    }
    assert {code for code, _ in enabled_checks(Scope.AFTER, None, False, "tools")} == {"LIS009"}
    # an axis list still runs every list rule (homing, drive, achs_mode)
    axis = {code for code, _ in enabled_checks(Scope.LIST, None, True, "axis")}
    assert {"LIS105", "LIS204", "LIS301", "LIS401"} <= axis
    assert all(not rules[code].applies_to("channel") for code in ("LIS105", "LIS204", "LIS301", "LIS404"))


def test_a_list_of_another_kind_resolves_no_axis() -> None:
    file = parse_text("grp_anzahl 1\nEnde\n", "kanal.lis")
    ctx = Context("kanal.lis", file, catalogue=CHANNEL.catalogue() or pytest.fail(), kind=CHANNEL)
    assert not ctx.axis_list and [s.canonical for s in ctx.settings] == ["grp_anzahl"]
    with pytest.raises(TypeError, match="channel list, not an axis list"):
        _ = ctx.values
    # and the linter asks for none: no machine summary; the editor keeps the Context for its kind (hover,
    # completion from the channel catalogue), which resolves no axis either
    result = lint_file(b"grp_anzahl 1\nEnde\n", "kanal.lis", FileSettings(kind="channel", keep_context=True))
    assert result.diagnostics == [] and result.summary is None
    assert result.context is not None and result.context.kind is CHANNEL and not result.context.axis_list


def test_an_axis_parameter_in_a_channel_list_is_unknown_there() -> None:
    # `kenngr.antr_typ` belongs to the axis catalogue: a channel list is not checked against it
    found, _ = lint_from(b"grp_anzahl 1\nkenngr.antr_typ 99\nEnde\n", "channel")
    assert [(code, line, severity) for code, line, severity, _ in found] == [("LIS101", 2, Severity.INFO)]


def test_references_in_other_kinds_are_read_not_resolved() -> None:
    # a reference names a P-AXIS parameter, which the channel catalogue does not hold: only an unreadable
    # one is reported
    text = b"vector.acceleration P-AXIS-00212.0\nprog_start.slope.acceleration P-AXIS-123456789\nEnde\n"
    found, _ = lint_from(text, "channel")
    assert [(code, line) for code, line, _, _ in found] == [("LIS205", 2)]


def test_unknown_parameters_ignore_silences_other_kinds_too(tmp_path: Path) -> None:
    channel = tmp_path / "sda_mds1.lis"
    shutil.copy(BAD / "channel" / "bad.lis", channel)
    (tmp_path / "achslint.toml").write_text('unknown-parameters = "ignore"\n')
    result = run_cli("lint", str(channel), "--format", "json", "--select", "LIS101")
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["diagnostics"] == []
    (tmp_path / "achslint.toml").write_text('unknown-parameters = "error"\n')
    result = run_cli("lint", str(channel), "--format", "json", "--select", "LIS101")
    found = json.loads(result.stdout)["diagnostics"]
    # a partial catalogue cannot tell a typo from a parameter it lacks: info, even when the setting says error
    assert [(d["code"], d["line"], d["severity"]) for d in found] == [("LIS101", 6, "info")]


def test_a_noqa_for_an_axis_rule_in_a_channel_list_is_not_called_unused() -> None:
    text = b"grp_anzahl 1 # noqa: LIS301\ngrp_anzahl 1 # noqa: LIS005\nEnde\n"
    found, _ = lint_from(text, "channel")
    # LIS005 is suppressed; LIS301 does not look at channel lists, so its noqa is not judged
    assert found == []
    found, _ = lint_from(b"grp_anzahl 1 # noqa: LIS005\nEnde\n", "channel")
    assert [code for code, *_ in found] == ["LIS009"]


def test_fix_on_a_channel_list_fixes_the_list_family_and_keeps_unsure_renames(tmp_path: Path) -> None:
    channel = tmp_path / "sda_mds1.lis"
    source = (BAD / "channel" / "bad.lis").read_text().replace("Ende", "End")
    channel.write_text(source)
    result = run_cli("lint", str(channel), "--fix", "--format", "json")
    fixed = channel.read_text()
    # LIS004 fixed; the rename LIS101 suggests from a partial catalogue is unsafe (--fix alone leaves the
    # name), and `MOSS` is as close to two symbols (MOS, MVS...) for a safe fix: nothing else changed
    assert fixed == source[: -len("End\n")] + "Ende\n"
    remaining = [(d["code"], d["line"]) for d in json.loads(result.stdout)["diagnostics"]]
    assert remaining == [("LIS202", 3), ("LIS101", 6), ("LIS203", 10)]


def test_a_kind_without_catalogue_keeps_its_skip_note(tmp_path: Path) -> None:
    result = lint_file(b"cam[0].name A\nEnde\n", "cams.lis", FileSettings(kind="cam_tables"))
    assert result.diagnostics == []
    assert (
        result.note
        == "cams.lis: skipped, it is a cam table list; achslint has no catalogue of its parameters yet"
    )


def test_the_fixture_machines_channel_lists_lint_clean() -> None:
    # the channel lists of the SDK-style machines, now checked against the channel catalogue, and passed
    # alone (told by content) or with their start-up list (named by it)
    for machine in ("sdk4", "portal"):
        folder = FIXTURES / "machines" / machine / "listen"
        for name in ("sda_mds1.lis", "default_sda.lis"):
            result = run_cli("lint", str(folder / name), "--format", "json", "--select", "LIS0,LIS1,LIS2")
            assert result.returncode == 0, result.stderr
            assert json.loads(result.stdout)["diagnostics"] == [], (machine, name)
            assert "skipped" not in result.stderr.decode()


def lint_from(data: bytes, kind: str) -> tuple[list[tuple[str, int, Severity, str]], str | None]:
    result = lint_file(data, "list.lis", FileSettings(kind=kind))
    return [(d.code, d.line, d.severity, d.message) for d in result.diagnostics], result.note


# --- any catalogue path with an in-range value: no LIS1/LIS2 finding --------------------------------------


# (parameter, its strategy) by the parameter's identity (a Parameter holds dictionaries: it has no hash).
_VALUES: dict[int, tuple[Parameter, st.SearchStrategy[str]]] = {}


def _value(parameter: Parameter) -> st.SearchStrategy[str]:
    """`_values_of(parameter)`, made once per parameter: hypothesis builds and checks a strategy at its first
    draw, which a new strategy at every draw repeated."""
    kept = _VALUES.get(id(parameter))
    if kept is None:
        kept = _VALUES[id(parameter)] = (parameter, _values_of(parameter))
    return kept[1]


def _values_of(parameter: Parameter) -> st.SearchStrategy[str]:
    """Values the parameter accepts, as a list writes them."""
    kind = parameter.kind
    if kind == BOOL:
        return st.sampled_from(["0", "1"])
    if kind == SYMBOL:
        return st.sampled_from(parameter.symbols)
    if kind == INTEGER:
        if parameter.allowed:
            return st.sampled_from([str(code) for code in parameter.allowed])
        low, high = parameter.limits
        return st.integers(
            int(low if low is not None else -(2**31)), int(high if high is not None else 2**31)
        ).map(str)
    if kind == REAL:
        low, high = parameter.limits
        low = max(low if low is not None else -1e9, -1e9)
        high = min(high if high is not None else 1e9, 1e9)
        if parameter.strict_positive_real:
            low = max(low, 1e-3)
        return (
            st.integers(0, 1000)
            .map(lambda step: f"{low + (high - low) * step / 1000:.6f}")
            .filter(lambda text: low <= float(text) <= high)
        )
    assert kind == STRING
    longest = parameter.max_length if parameter.max_length is not None else 24
    return st.text("ABCXYZ_019", min_size=1, max_size=max(1, min(longest, 24)))


@st.composite
def _assignments(draw: st.DrawFn, kind: Kind) -> list[str]:
    cat = kind.catalogue()
    assert cat is not None
    chosen = draw(
        st.lists(st.sampled_from(cat.parameters), min_size=1, max_size=6, unique_by=lambda p: p.path)
    )
    lines = []
    for parameter in chosen:
        path = parameter.path
        while "[i]" in path:
            path = path.replace("[i]", f"[{draw(st.integers(0, 9))}]", 1)
        lines.append(f"{path}    {draw(_value(parameter))}")
    return lines


@pytest.mark.parametrize("kind", OTHER_KINDS, ids=lambda kind: kind.id)
def test_any_catalogue_path_with_an_in_range_value_gives_no_lis1_or_lis2_finding(kind: Kind) -> None:
    @settings(max_examples=examples(60, 15), deadline=None, suppress_health_check=[HealthCheck.too_slow])
    @given(_assignments(kind))
    def check(lines: list[str]) -> None:
        data = ("\n".join(lines) + "\nEnde\n").encode()
        found, note = lint_from(data, kind.id)
        assert note is None
        assert [(code, message) for code, _, _, message in found if code[:4] in ("LIS1", "LIS2")] == []

    check()


def test_or_combined_flags_of_a_start_up_list_are_each_checked() -> None:
    # the SDK's start-up list combines flags with `|` and free spacing; before, the rest of the line was
    # "text after a string" (LIS007) and `A|B` an unknown symbol
    text = (
        b"error_protocol_mode          REPORT | REPORT_EXTENDED |PRINT   ( flags | combined\n"
        b"configuration.channel[0].path_preparation.function   FCT_DEFAULT|FCT_M_PRE_OUTPUT\n"
        b"error_filter[0].action       HIDE | HIDE_PRNT\n"
        b"error_filter[1].action       HIDE_PRNT | HIDE\n"
        b"Ende\n"
    )
    result = lint_file(text, "hochlauf.lis", FileSettings(kind="startup"))
    found = [(d.code, d.line, d.fix is not None) for d in result.diagnostics]
    # the misspelt flag is named; a fix would rewrite the first token only, so a later flag gets none
    assert found == [("LIS203", 3, False), ("LIS203", 4, True)]
    assert all("`HIDE_PRNT` is not a value of" in d.message for d in result.diagnostics)
    fix = result.diagnostics[1].fix
    assert fix is not None and [edit.content for edit in fix.edits] == ["HIDE_PRINT"]
    # an axis list reads no flags: the same text after a symbol is still LIS007 there
    axis = lint_file(b"kenngr.homing.homing_type CNC_CONTROLLED | TORQ\nEnde\n", "achsmds1.lis")
    assert [d.code for d in axis.diagnostics] == ["LIS007"]


def test_linting_an_axis_list_reads_no_other_catalogue_and_a_tool_list_only_its_own() -> None:
    load_table.cache_clear()
    axis = lint_file((GOOD / "achsmds_z.lis").read_bytes(), "achsmds_z.lis")
    assert axis.note is None and axis.summary is not None  # an axis, resolved for the machine step
    assert load_table.cache_info().currsize == 0
    lint(GOOD / GOOD_LISTS["tools"], "tools")
    assert load_table.cache_info().currsize == 1
