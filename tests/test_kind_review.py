"""Lists of the other kinds (channel, start-up, tools, compensation ...) as the reference tables describe them:
findings that agree with `explain`, no rename of a correct list into an axis list, catalogue bounds as the
range texts state them."""

from __future__ import annotations

import json
from pathlib import Path

from achslint import lint

from .conftest import run_cli

# The head of a channel list: enough channel parameters for its content to show its kind.
CHANNEL = b"".join(
    b"gruppe[0].achse[%d].bezeichnung %s\ngruppe[0].achse[%d].log_achs_nr %d\n" % (i, name, i, i + 1)
    for i, name in enumerate((b"X", b"Y", b"Z"))
)


def test_a_short_list_of_another_kind_is_not_renamed_into_axis_parameters(tmp_path: Path) -> None:
    # Two channel-list lines (P-CHAN-00191/00192) are too little to show the list's kind, so the list is read
    # as an axis list; the nearest axis names (`dynamic_weighting.param[0].…`) must not be written over them
    channel = tmp_path / "kanal.lis"
    text = "dynamic_weighting[0].path_limit 5\ndynamic_weighting[0].velocity_fact 20\nEnde\n"
    channel.write_text(text)
    result = run_cli("lint", "--fix", str(channel), "--format", "json")
    assert channel.read_text() == text
    messages = [d["message"] for d in json.loads(result.stdout)["diagnostics"] if d["code"] == "LIS101"]
    assert len(messages) == 2
    assert "`dynamic_weighting[0].path_limit` is no axis-list parameter" in messages[0]
    assert "channel list (P-CHAN-00191)" in messages[0] and "`sda_mds[i]`" in messages[0]
    assert "did you mean" not in messages[0]


def test_an_unknown_axis_name_of_another_kind_says_what_explain_says() -> None:
    # `achslint explain wz[1].laenge` describes P-TOOL-00003; the finding on it must not call it unknown and
    # offer an axis parameter instead (it suggested `antr.sercos.ident[1].laenge`)
    [finding] = lint(b"wz[1].laenge 1000\nEnde\n", name="werkzeug.lis", select="LIS101")
    assert "tool data list (P-TOOL-00003)" in finding.message and "`werkz_data[i]`" in finding.message
    assert finding.fix is None
    # a name no catalogue has keeps its suggestion
    [typo] = lint(b"kenngr.ref_ricth 1\nEnde\n", name="achsmds1.lis", select="LIS101")
    assert "did you mean `kenngr.ref_richt`" in typo.message


def test_explain_shows_the_range_lis202_checks_and_a_default_of_zero() -> None:
    # P-CHAN-00034 `0 < lin_aufloes < MAX(REAL64)`: LIS202 refuses 0, so the card must not say "0 .. None"
    shown = run_cli("explain", "lin_aufloes", "--kind", "channel").stdout.decode()
    assert "checked range    above 0\n" in shown and "None" not in shown
    [finding] = lint(CHANNEL + b"lin_aufloes 0\nEnde\n", name="sda_mds1.lis", select="LIS202")
    assert "must be greater than 0" in finding.message
    card = json.loads(run_cli("explain", "lin_aufloes", "--kind", "channel", "--format", "json").stdout)
    assert card["checked_range"] == {"min": 0, "max": None, "min_exclusive": True}
    # P-CHAN-00019 defaults to 0: the card shows it (a 0 was dropped as if it were no value)
    shown = run_cli("explain", "syn_chk.errors_total", "--kind", "channel").stdout.decode()
    assert "  default          0\n" in shown


def _built(tmp_path: Path, table: str, rows: list[str]) -> list[dict]:
    """The catalogue entries tools/build_kinds.py makes of reference table rows (the tables are not part of
    the repository: the rows are written here in the table's columns)."""
    import sys

    from .conftest import ROOT

    if str(ROOT / "tools") not in sys.path:
        sys.path.insert(0, str(ROOT / "tools"))
    import build_kinds

    folder = tmp_path / "reference"
    folder.mkdir()
    header = "id\tpath\ttype\tdefault\tunit\tmax_number\trestart\tsymbols\trange\ttitle\n"
    (folder / f"params-{table}.tsv").write_text(header + "\n".join(rows) + "\n", encoding="utf-8")
    return [
        json.loads(line.rstrip(",")) for line in build_kinds.build(folder)[f"{table}.json"].splitlines()[5:-2]
    ]


def test_range_texts_naming_an_indexed_parameter_or_a_unit_give_their_bounds(tmp_path: Path) -> None:
    # P-CHAN-00324 `0 ≤ time[i] ≤ MAX_REAL64` and P-EXTV-00021 `1 ... 800 bytes`: their bounds were lost
    # (a negative time, a 1,000-byte element passed LIS202)
    time, size = _built(
        tmp_path,
        "chan",
        [
            "P-CHAN-00324\tesa.time[]\tREAL64\t0.0\t\t\tfalse\t\t0 ≤ time[i] ≤ MAX_REAL64\tt",
            "P-CHAN-00325\tstruct[].size\tUNS32\t0\t\t\tfalse\t\t1 ... 800 bytes\tt",
        ],
    )
    assert (time["min"], time.get("max")) == (0, None)
    assert (size["min"], size["max"]) == (1, 800)


def test_a_length_is_no_bound_of_an_integer_parameter(tmp_path: Path) -> None:
    # P-CHAN-00447 is a UNS16 group id (`trafo[0].group[0].id 100` in the vendor's example) whose range cell
    # says "Maximum of 16 characters": explain showed a max length and LIS206 for a number
    [group] = _built(
        tmp_path,
        "chan",
        ["P-CHAN-00447\ttrafo[].group[].id\tUNS16\t0\t\t\tfalse\t\tMaximum of 16 characters\tt"],
    )
    assert "max_length" not in group and (group["min"], group["max"]) == (0, 65535)
    card = json.loads(run_cli("explain", "P-CHAN-00447", "--format", "json").stdout)
    assert card["max_length"] is None and "LIS206" not in card["rules"]


def test_the_packaged_catalogues_check_the_bounds_their_tables_state() -> None:
    esa = CHANNEL + b"esa.time[0] -1.5\nEnde\n"
    assert [d.code for d in lint(esa, name="sda_mds1.lis", select="LIS202")] == ["LIS202"]


def test_a_max_points_written_as_zero_is_not_called_unset() -> None:
    # P-COMP-00062: 0 means the default (20); the finding said the list did not set what its last line sets
    text = b"kopf.achs_nr 1\nfrict_comp.table_entries 50\nfrict_comp.mode 3\nfrict_comp.max_points 0\nEnde\n"
    [finding] = lint(text, name="achskw1.lis", select="LIS705")
    assert "`frict_comp.max_points` = 0, which means its default 20" in finding.message
    assert [related.line for related in finding.related] == [4]


def test_a_channel_entry_no_channel_count_reaches_is_not_asked_to_raise_the_count(tmp_path: Path) -> None:
    # kanal_anzahl ranges 1 ... 12 (P-STUP-00001): raising it to 13 is what LIS202 calls an error
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr 1\nkopf.log_achs_name X\nEnde\n")
    (tmp_path / "sda_mds1.lis").write_text(CHANNEL.decode() + "Ende\n")
    (tmp_path / "hochlauf.lis").write_text(
        "kanal_anzahl 1\nsda_mds[0] ./sda_mds1.lis\nsda_mds[12] ./sda_mds1.lis\nsda_mds[3] ./sda_mds1.lis\n"
        "zahl_mds 1\nachs_mds[0] ./achsmds1.lis\nEnde\n"
    )
    found = {d.line: d.message for d in lint(tmp_path / "hochlauf.lis", select="LIS522")}
    assert sorted(found) == [3, 4]
    assert "no kanal_anzahl reaches it (kanal_anzahl is at most 12" in found[3] and "raise" not in found[3]
    assert "raise kanal_anzahl to 4 if the channel is meant" in found[4]
