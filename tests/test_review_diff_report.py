"""Review of `diff` and `report`: what each says changes must be what changes for the CNC.

Every case runs the real CLI (or `build_report`, what `achslint report` runs) on copies of the fixtures.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from achslint.output.report import as_html
from achslint.report import ReportRequest, build_report

from .conftest import FIXTURES, run_cli

MILL = FIXTURES / "machine_diff" / "mill"  # default_mds.lis writes getriebe[0].vb_reflow 5000


def _mill(tmp_path: Path, name: str = "mill") -> Path:
    target = tmp_path / name
    shutil.copytree(MILL, target)
    return target


def _without(path: Path, start: bytes) -> bytes:
    """The list's bytes without its line starting with `start` (there is exactly one)."""
    lines = path.read_bytes().splitlines(keepends=True)
    kept = [line for line in lines if not line.startswith(start)]
    assert len(kept) == len(lines) - 1
    return b"".join(kept)


def test_report_of_an_axis_list_compares_with_the_default_list_it_explains_with(tmp_path: Path) -> None:
    """The report explains an axis list of a machine with the machine's default list underneath; its
    comparison with a backup must do the same. The backup does not write vb_reflow, so the CNC would run it
    at the default list's 5000 µm/s, not at the built-in 16666 µm/s the comparison used to show."""
    machine = _mill(tmp_path)
    current = machine / "listen" / "achsmds1.lis"  # writes vb_reflow 10000
    backup = tmp_path / "backup" / "achsmds1.lis"
    backup.parent.mkdir()
    backup.write_bytes(_without(current, b"getriebe[0].vb_reflow"))
    report = build_report(ReportRequest(current, against=backup))
    assert report.list_diff is not None
    (row,) = [d for d in report.list_diff["differences"] if d["parameter"] == "getriebe[0].vb_reflow"]
    assert (row["a"], row["b"]) == (5000, 10000)
    assert "(default list)" in row["a_source"]
    comparison = as_html(report)
    comparison = comparison[comparison.index('id="comparison"') :]
    assert "<td>5000</td>" in comparison and "16666" not in comparison


def test_report_of_an_axis_list_and_a_backup_alike_but_for_a_value_the_default_list_gives(
    tmp_path: Path,
) -> None:
    """The reverse: the backup writes the default list's own value (5000), the current list leaves it to
    the default list: the CNC runs both at 5000, so nothing changed."""
    machine = _mill(tmp_path)
    current = machine / "listen" / "achsmds1.lis"
    backup = tmp_path / "backup" / "achsmds1.lis"
    backup.parent.mkdir()
    backup.write_bytes(
        current.read_bytes().replace(b"vb_reflow                     10000", b"vb_reflow 5000")
    )
    current.write_bytes(_without(current, b"getriebe[0].vb_reflow"))
    report = build_report(ReportRequest(current, against=backup))
    assert report.list_diff is not None
    assert report.list_diff["differences"] == []


def _startup_with_tool_list(machine: Path) -> None:
    """Give the mill's channel a tool data list and a zero offset list (werkz_data[0], nullp_data[0])."""
    for name in ("werkz_d1.lis", "nullp_d1.lis"):
        shutil.copy(FIXTURES / "kinds" / name, machine / "listen" / name)
    startup = machine / "listen" / "hochlauf.lis"
    text = startup.read_text(encoding="ascii")
    text = text.replace(
        "#\nzahl_mds",
        "werkz_data[0]                             ./listen/werkz_d1.lis\n"
        "nullp_data[0]                             ./listen/nullp_d1.lis\n#\nzahl_mds",
        1,
    )
    startup.write_text(text, encoding="ascii")


def test_machine_diff_reports_a_removed_tool_list(tmp_path: Path) -> None:
    a, b = _mill(tmp_path, "a"), _mill(tmp_path, "b")
    _startup_with_tool_list(a)
    _startup_with_tool_list(b)
    same = run_cli("diff", str(a), str(b))
    assert same.returncode == 0, same.stdout
    startup = b / "listen" / "hochlauf.lis"
    startup.write_bytes(_without(startup, b"werkz_data[0]"))
    done = run_cli("diff", str(a), str(b))
    assert done.returncode == 1, done.stdout
    assert b"werkz_data[0]" in done.stdout
    report = json.loads(run_cli("diff", str(a), str(b), "--format", "json").stdout)
    assert report["differ"] is True


def test_list_diff_names_the_default_list_a_value_comes_from(tmp_path: Path) -> None:
    """The source of a value from `--defaults D` read "default list line 1 (default list)"; it names D."""
    defaults = tmp_path / "defs.lis"
    defaults.write_bytes(b"getriebe[0].kv 2000\r\nEnde\r\n")
    a = FIXTURES / "lists" / "achsmds1.lis"
    b = tmp_path / "b.lis"
    b.write_bytes(a.read_bytes().replace(b"#\r\nEnde", b"getriebe[0].kv 1000\r\n#\r\nEnde"))
    done = run_cli("diff", str(a), str(b), "--defaults", str(defaults), "--format", "json")
    (row,) = json.loads(done.stdout)["differences"]
    assert row["a_source"] == f"{defaults} line 1 (default list)"
