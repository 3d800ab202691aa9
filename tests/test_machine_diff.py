"""`achslint diff A B` of two machines (issue 24 item 6): A and B are start-up lists, or folders holding
one. Every test goes through the CLI's entry point; the variants of the fixture mill
(fixtures/machine_diff/mill: axes X 1, Y 2, Z 3, channel 1, a default list) are copies with one line
changed, so each test shows the one change it is about."""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

from .conftest import FIXTURES, ROOT, run_cli

MILL = FIXTURES / "machine_diff" / "mill"
BACKUP = FIXTURES / "machine_diff" / "mill_backup"  # the same machine: other file names, order, spelling


def _copy(tmp_path: Path, name: str, *changes: tuple[str, str, str]) -> Path:
    """A copy of the mill in tmp_path/name with `changes`: (file in listen/, start of a line, its new text)."""
    target = tmp_path / name
    shutil.copytree(MILL, target)
    for file, start, new in changes:
        path = target / "listen" / file
        lines = path.read_text(encoding="ascii").splitlines()
        found = [i for i, line in enumerate(lines) if line.startswith(start)]
        assert len(found) == 1, (file, start)
        lines[found[0]] = new
        path.write_text("\n".join(lines) + "\n", encoding="ascii")
    return target


def _json(*args: str) -> tuple[int, dict[str, Any]]:
    done = run_cli("diff", *args, "--format", "json")
    return done.returncode, json.loads(done.stdout)


def _text(*args: str) -> tuple[int, str]:
    done = run_cli("diff", *args)
    return done.returncode, done.stdout.decode("utf-8")


def _axis(report: dict[str, Any], name: str) -> dict[str, Any]:
    (row,) = [row for row in report["axes"] if (row["a"] or row["b"])["name"] == name]
    return row


def test_the_same_machine_written_differently_is_no_difference() -> None:
    """The backup names its lists under other file names and in another order, with an old parameter name,
    a decimal achs_mode and other comments: the CNC loads the same machine."""
    code, out = _text(str(MILL), str(BACKUP))
    assert code == 0
    assert out == (
        f"no difference: {MILL / 'listen' / 'hochlauf.lis'} and {BACKUP / 'listen' / 'hochlauf.lis'} load the "
        "same machine (3 axes, 1 channel)\n"
    )
    code, report = _json(str(MILL / "listen" / "hochlauf.lis"), str(BACKUP))
    assert code == 0 and report["differ"] is False
    assert [
        (row["status"], row["matched_by"], row["a"]["entry"], row["b"]["entry"]) for row in report["axes"]
    ] == [
        ("same", "logical axis number", "achs_mds[0]", "achs_mds[1]"),
        ("same", "logical axis number", "achs_mds[1]", "achs_mds[2]"),
        ("same", "logical axis number", "achs_mds[2]", "achs_mds[0]"),
    ]
    assert [(row["channel"], row["status"]) for row in report["channels"]] == [(1, "same")]


def test_a_changed_value_behind_the_start_up_list_is_shown_with_its_unit(tmp_path: Path) -> None:
    a = _copy(tmp_path, "a")
    b = _copy(tmp_path, "b", ("achsmds2.lis", "getriebe[0].vb_refmax", "getriebe[0].vb_refmax 45000"))
    # The start-up lists themselves are byte for byte the same.
    assert (a / "listen" / "hochlauf.lis").read_bytes() == (b / "listen" / "hochlauf.lis").read_bytes()
    code, report = _json(str(a / "listen" / "hochlauf.lis"), str(b / "listen" / "hochlauf.lis"))
    assert code == 1 and report["differ"] is True
    y = _axis(report, "Y")
    assert (y["status"], y["matched_by"], y["homing_differs"]) == ("changed", "logical axis number", False)
    assert [
        (row["parameter"], row["p_axis"], row["a"], row["b"], row["unit"], row["b_human"])
        for row in y["differences"]
    ] == [("getriebe[0].vb_refmax", "P-AXIS-00219", 40000, 45000, "µm/s", "45 mm/s = 2.7 m/min")]
    assert [_axis(report, name)["status"] for name in ("X", "Z")] == ["same", "same"]
    code, out = _text(str(a), str(b))
    assert code == 1
    assert "~ axis 2 Y: A achs_mds[1]" in out
    row = next(line for line in out.splitlines() if "getriebe[0].vb_refmax" in line)
    assert all(part in row for part in ("P-AXIS-00219", "40000", "45000", "µm/s", "45 mm/s = 2.7 m/min"))


def test_a_value_the_cnc_caps_to_the_same_speed_is_written_differs_effective_same(tmp_path: Path) -> None:
    """X: getriebe[0].vb_not_referenced 50000 µm/s. A writes vb_refmax 50000 (at the limit, used as written),
    B 80000, which the CNC lowers to 50000 (P-AXIS-00268, P-ERR-110421): the axes run alike, the lists
    differ."""
    a = _copy(tmp_path, "a")
    b = _copy(tmp_path, "b", ("achsmds1.lis", "getriebe[0].vb_refmax", "getriebe[0].vb_refmax 80000"))
    code, report = _json(str(a), str(b))
    assert code == 1
    x = _axis(report, "X")
    assert x["status"] == "changed" and x["differences"] == []
    assert x["written_differences"] == [
        {
            "parameter": "getriebe[0].vb_refmax",
            "p_axis": "P-AXIS-00219",
            "a": 50000,
            "b": 80000,
            "used": 50000,
            "unit": "µm/s",
            "a_human": "50 mm/s = 3 m/min",
            "b_human": "80 mm/s = 4.8 m/min",
            "used_human": "50 mm/s = 3 m/min",
            "a_error": None,
            "b_error": "P-ERR-110421",
            "a_source": "line 16",
            "b_source": "line 16",
        }
    ]
    code, out = _text(str(a), str(b))
    assert code == 1
    assert (
        "    getriebe[0].vb_refmax (P-AXIS-00219): written differs, effective same: 50000 → 80000 µm/s, the CNC "
        "uses 50000 µm/s (= 50 mm/s = 3 m/min) in both (B: P-ERR-110421)"
    ) in out.splitlines()
    # One comparison: `diff` of the two axis lists reports the same row.
    listen_a, listen_b = a / "listen", b / "listen"
    code, lists = _json(
        str(listen_a / "achsmds1.lis"),
        str(listen_b / "achsmds1.lis"),
        "--defaults",
        str(listen_a / "default_mds.lis"),
    )
    assert (
        code == 1 and lists["differences"] == [] and lists["written_differences"] == x["written_differences"]
    )


def test_an_axis_list_added_and_removed(tmp_path: Path) -> None:
    a = _copy(tmp_path, "a")
    b = _copy(
        tmp_path,
        "b",
        (
            "hochlauf.lis",
            "achs_mds[2]",
            "achs_mds[2] ./listen/achsmds3.lis\nachs_mds[3] ./listen/achsmds4.lis",
        ),
        ("hochlauf.lis", "zahl_mds", "zahl_mds 4"),  # the CNC loads four lists (P-STUP-00014)
    )
    code, report = _json(str(a), str(b))
    assert code == 1
    added = _axis(report, "A")
    assert (added["status"], added["matched_by"], added["a"]) == ("added", None, None)
    assert (added["b"]["entry"], added["b"]["logical_number"], added["b"]["homing"]) == (
        "achs_mds[3]",
        4,
        "cam_zero_pulse",
    )
    assert [row["status"] for row in report["axes"]] == ["same", "same", "same", "added"]
    code, out = _text(str(b), str(a))
    assert code == 1
    assert f"- axis 4 A (achs_mds[3] {b / 'listen' / 'achsmds4.lis'}): only in A" in out.splitlines()


def test_a_changed_channel_mapping(tmp_path: Path) -> None:
    """Channel 1 of B swaps the names X and Y: the axis lists are the same, what a program moves is not."""
    a = _copy(tmp_path, "a")
    b = _copy(
        tmp_path,
        "b",
        ("sda_mds1.lis", "gruppe[0].achse[0].log_achs_nr", "gruppe[0].achse[0].log_achs_nr 2"),
        ("sda_mds1.lis", "gruppe[0].achse[1].log_achs_nr", "gruppe[0].achse[1].log_achs_nr 1"),
    )
    code, report = _json(str(a), str(b))
    assert code == 1
    assert all(row["status"] == "same" for row in report["axes"])
    (channel,) = report["channels"]
    assert (channel["channel"], channel["status"], channel["pairs"]) == (1, "changed", [])
    assert channel["names"] == [
        {
            "name": "X",
            "a": {"logical_number": 1, "spindle": False},
            "b": {"logical_number": 2, "spindle": False},
        },
        {
            "name": "Y",
            "a": {"logical_number": 2, "spindle": False},
            "b": {"logical_number": 1, "spindle": False},
        },
    ]
    code, out = _text(str(a), str(b))
    assert "channel 1 (sda_mds[0]): changed" in out
    assert "    X: logical axis 1 → logical axis 2" in out.splitlines()


def test_a_changed_homing_strategy_and_an_axis_paired_by_name(tmp_path: Path) -> None:
    """B's Y homes without a cam and has the logical number 5 (its channel entry follows): paired by its
    name, with the number and the strategy among its differences."""
    a = _copy(tmp_path, "a")
    b = _copy(
        tmp_path,
        "b",
        ("achsmds2.lis", "kenngr.ref_ohne_nocken", "kenngr.ref_ohne_nocken 1"),
        ("achsmds2.lis", "kopf.achs_nr", "kopf.achs_nr 5"),
        ("sda_mds1.lis", "gruppe[0].achse[1].log_achs_nr", "gruppe[0].achse[1].log_achs_nr 5"),
    )
    code, report = _json(str(a), str(b))
    assert code == 1
    y = _axis(report, "Y")
    assert (y["matched_by"], y["homing_differs"], y["a"]["homing"], y["b"]["homing"]) == (
        "axis name",
        True,
        "cam_zero_pulse",
        "zero_pulse_only",
    )
    assert [(row["parameter"], row["a"], row["b"]) for row in y["differences"]] == [
        ("kenngr.ref_ohne_nocken", 0, 1),
        ("kopf.achs_nr", 2, 5),
    ]
    code, out = _text(str(a), str(b))
    assert "axes in both: 2 by logical axis number, 1 by axis name; 0 only in B, 0 only in A" in out
    assert "    renumbered or renamed: axis 2 Y → axis 5 Y" in out.splitlines()
    assert any(line.startswith("    homing strategy: cam_zero_pulse (") for line in out.splitlines())


def _keys(value: dict[str, Any]) -> list[str]:
    return sorted(value)


def test_the_json_shape(tmp_path: Path) -> None:
    """The documented shape (README, "Comparing lists and machines"): every key, with its type, in a report that has
    a row of every kind."""
    a = _copy(tmp_path, "a")
    b = _copy(
        tmp_path,
        "b",
        ("hochlauf.lis", "achs_mds[2]", "achs_mds[2] ./listen/achsmds4.lis"),
        ("achsmds1.lis", "getriebe[0].vb_refmax", "getriebe[0].vb_refmax 60000"),
        ("achsmds1.lis", "getriebe[0].vb_reflow", "getriebe[0].vb_reflow 12000"),
        ("achsmds1.lis", "kopf.log_achs_name", "kopf.log_achs_name X\nkenngr.not_a_parameter 1"),
        ("sda_mds1.lis", "gruppe[0].achse[2].bezeichnung", "gruppe[0].achse[2].bezeichnung W"),
        (
            "sda_mds1.lis",
            "gruppe[0].achse[2].log_achs_nr",
            "gruppe[0].achse[2].log_achs_nr 3\nsynchro_data.koppel_gruppe[0].paar[0].log_achs_nr_master 1\n"
            "synchro_data.koppel_gruppe[0].paar[0].log_achs_nr_slave 2",
        ),
    )
    for machine, length in ((a, "0x64"), (b, "120")):  # a tool data list on both, one length differs
        startup = machine / "listen" / "hochlauf.lis"
        startup.write_text(startup.read_text().replace("Ende", "werkz_data[0] ./listen/werkz_d1.lis\nEnde"))
        (machine / "listen" / "werkz_d1.lis").write_text(f"wz[1].typ 1\nwz[1].laenge {length}\nEnde\n")
    code, report = _json(str(a), str(b))
    assert code == 1
    assert _keys(report) == ["a", "axes", "b", "channels", "differ", "kind", "lists", "version"]
    startup_row, tools = report["lists"]
    assert (startup_row["entry"], startup_row["kind"], startup_row["status"]) == (
        "startup",
        "startup",
        "same",
    )
    assert _keys(tools) == ["a_list", "b_list", "changes", "entry", "kind", "status"]
    assert (tools["entry"], tools["kind"], tools["status"]) == ("werkz_data[0]", "tools", "changed")
    assert tools["changes"] == [{"parameter": "wz[1].laenge", "a": "0x64", "b": "120"}]
    assert (report["version"], report["kind"], report["differ"]) == (1, "machines", True)
    for side in (report["a"], report["b"]):
        assert _keys(side) == ["cnc_root", "default_channel_list", "default_list", "startup"]
    assert report["a"]["default_list"] == str(a / "listen" / "default_mds.lis")
    assert Path(report["b"]["cnc_root"]) == b
    statuses = {row["status"] for row in report["axes"]}
    assert statuses == {"same", "changed", "added", "removed"}
    for row in report["axes"]:
        assert _keys(row) == [
            "a",
            "b",
            "differences",
            "homing_differs",
            "matched_by",
            "status",
            "unknown_parameters",
            "written_differences",
        ]
        for side in (row["a"], row["b"]):
            if side is not None:
                assert _keys(side) == ["entry", "homing", "homing_title", "list", "logical_number", "name"]
    x = _axis(report, "X")
    assert _keys(x["differences"][0]) == [
        "a",
        "a_human",
        "a_source",
        "b",
        "b_human",
        "b_source",
        "p_axis",
        "parameter",
        "unit",
    ]
    assert _keys(x["written_differences"][0]) == [
        "a",
        "a_error",
        "a_human",
        "a_source",
        "b",
        "b_error",
        "b_human",
        "b_source",
        "p_axis",
        "parameter",
        "unit",
        "used",
        "used_human",
    ]
    (channel,) = report["channels"]
    assert _keys(channel) == ["a_list", "b_list", "channel", "names", "pairs", "status"]
    assert channel["names"] == [
        {"name": "Z", "a": {"logical_number": 3, "spindle": False}, "b": None},
        {"name": "W", "a": None, "b": {"logical_number": 3, "spindle": False}},
    ]
    assert channel["pairs"] == [{"master": 1, "slave": 2, "only_in": "b"}]
    assert x["unknown_parameters"] == [{"parameter": "kenngr.not_a_parameter", "a": None, "b": "1"}]
    # The README's example has exactly the keys of this report, at every level.
    assert _key_paths(_readme_example()) == _key_paths(report)


def _key_paths(value: Any, prefix: str = "") -> set[str]:
    """Every key of a JSON document as a path (`axes[].a.entry`), over all elements of each list."""
    if isinstance(value, dict):
        found = set()
        for key, item in value.items():
            found |= {f"{prefix}{key}"} | _key_paths(item, f"{prefix}{key}.")
        return found
    if isinstance(value, list):
        return set().union(*(_key_paths(item, prefix.removesuffix(".") + "[].") for item in value))
    return set()


def _readme_example() -> Any:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    section = readme[readme.index("#### Comparing lists and machines") :]
    block = section[section.index("```json\n") + len("```json\n") :]
    return json.loads(block[: block.index("```")])


def test_unreadable_input_is_one_line_naming_the_file(tmp_path: Path) -> None:
    a = _copy(tmp_path, "a")
    missing = _copy(tmp_path, "missing")
    (missing / "listen" / "achsmds2.lis").unlink()
    two = tmp_path / "two"
    two.mkdir()
    for name in ("hochlauf_coe.lis", "hochlauf_soe.lis"):
        shutil.copy(MILL / "listen" / "hochlauf.lis", two / name)
    cases = [
        (
            (str(a), str(missing)),
            f"achslint: {missing / 'listen' / 'hochlauf.lis'}:11: `achs_mds[1]` names the axis list "
            "`./listen/achsmds2.lis`, which does not exist",
        ),
        (
            (str(two), str(a)),
            f"achslint: {two} holds 2 start-up lists (hochlauf_coe.lis, hochlauf_soe.lis): name the one meant",
        ),
        (
            (str(a), str(a / "listen" / "achsmds1.lis")),
            f"achslint: {a} is a machine (a start-up list) and {a / 'listen' / 'achsmds1.lis'} is not",
        ),
        ((str(tmp_path / "gone"), str(a)), f"achslint: {tmp_path / 'gone'}: no such file or directory"),
    ]
    for args, start in cases:
        for fmt in ("text", "json"):
            done = run_cli("diff", *args, "--format", fmt)
            err = done.stderr.decode("utf-8")
            assert (done.returncode, done.stdout) == (2, b""), args
            assert err.startswith(start) and err.count("\n") == 1 and "Traceback" not in err, err


def _outside_listen(machine: Path, config: bool = False) -> str:
    """Move the machine's start-up list to conf/ (its entries still say ./listen/…); `config`: with an
    achslint.toml that sets the machine's folder as the CNC root."""
    (machine / "conf").mkdir()
    (machine / "listen" / "hochlauf.lis").rename(machine / "conf" / "hochlauf.lis")
    if config:
        (machine / "achslint.toml").write_text('cnc-root = "."\n', encoding="utf-8")
    return str(machine / "conf" / "hochlauf.lis")


def test_the_cnc_root_of_the_command_line(tmp_path: Path) -> None:
    """A start-up list kept outside listen/ names ./listen/… against the folder above it: --cnc-root says
    so, once for both machines or twice for A, then B."""
    a = _copy(tmp_path, "a")
    b = _copy(tmp_path, "b", ("achsmds3.lis", "getriebe[0].vb_refmax", "getriebe[0].vb_refmax 31000"))
    startups = (_outside_listen(a), _outside_listen(b))
    done = run_cli("diff", *startups)
    assert done.returncode == 2 and "which does not exist" in done.stderr.decode("utf-8")
    code, report = _json(*startups, "--cnc-root", str(a), "--cnc-root", str(b))
    assert code == 1 and [row["status"] for row in report["axes"]] == ["same", "same", "changed"]
    code, report = _json(*startups, "--cnc-root", str(a))  # both start-up lists read A's lists
    assert code == 0 and Path(report["b"]["cnc_root"]) == a
    done = run_cli("diff", *startups, "--cnc-root", str(a), "--cnc-root", str(b), "--cnc-root", str(a))
    assert done.returncode == 2 and "--cnc-root is given once" in done.stderr.decode("utf-8")


def test_the_cnc_root_of_each_machines_configuration(tmp_path: Path) -> None:
    a = _copy(tmp_path, "a")
    b = _copy(tmp_path, "b", ("achsmds3.lis", "getriebe[0].vb_refmax", "getriebe[0].vb_refmax 31000"))
    startups = (_outside_listen(a, config=True), _outside_listen(b, config=True))
    code, report = _json(*startups)
    assert code == 1 and (Path(report["a"]["cnc_root"]), Path(report["b"]["cnc_root"])) == (a, b)
    assert [row["status"] for row in report["axes"]] == ["same", "same", "changed"]
    done = run_cli("diff", *startups, "--defaults", str(a / "listen" / "default_mds.lis"))
    assert done.returncode == 2 and "--defaults goes with axis lists" in done.stderr.decode("utf-8")
