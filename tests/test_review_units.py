"""Review of the units achslint shows: list unit, human conversion, rounding, axis type."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from achslint.catalogue.units import describe, to_human
from achslint.linting.linter import lint_file

RULES = Path(__file__).resolve().parents[1] / "fixtures" / "rules"


def _as_axis_type(code: str, axis_type: int, tmp_path: Path) -> Path:
    """The bad fixture of a rule with `kenngr.achs_typ` set to `axis_type`."""
    lines = (RULES / code / "bad.lis").read_text(encoding="latin-1").splitlines()
    out = [f"kenngr.achs_typ {axis_type}" if line.startswith("kenngr.achs_typ") else line for line in lines]
    if not any(line.startswith("kenngr.achs_typ") for line in lines):
        out.insert(0, f"kenngr.achs_typ {axis_type}")
    path = tmp_path / f"{code}_{axis_type}.lis"
    path.write_text("\n".join(out) + "\n", encoding="latin-1")
    return path


def _messages(path: Path, code: str) -> list[str]:
    return [d.message for d in lint_file(path.read_bytes(), path.name).diagnostics if d.code == code]


# -- the number formatting of units.py ----------------------------------------------------------------


@pytest.mark.parametrize(
    ("value", "unit", "expected"),
    [
        (1, "um/s", "0.001 mm/s = 0.00006 m/min"),  # no 6e-05
        (0.4, "um/s", "0.0004 mm/s = 0.000024 m/min"),
        (1, "0.001deg/s", "0.001 °/s = 0.0001667 rpm"),
        (1, "0.1um", "0.0001 mm"),
        (0.4, "0.1um", "0.00004 mm"),  # no 4e-05
        (123456789, "0.0001deg", "12345.6789 °"),  # no 1.235e+04
        (12345678, "0.1um", "1234.5678 mm"),  # not 1235 mm: half a millimetre off
        (83333, "0.001deg/s", "83.333 °/s = 13.89 rpm"),  # as dry-run shows 83.333
        (-100000, "um/s", "-100 mm/s = -6 m/min"),
        (10000050, "um/s", "10000.05 mm/s = 600 m/min"),
    ],
)
def test_human_form_is_plain_and_exact(value: float, unit: str, expected: str) -> None:
    assert to_human(value, unit) == expected


def test_a_real_raw_value_keeps_its_digits() -> None:
    # 100000.5 µm/s used to show as `1e+05 µm/s`
    assert describe(100000.5, "um/s") == "100000.5 µm/s (= 100.0005 mm/s = 6 m/min)"
    assert describe(0.0004, "um/s").startswith("0.0004 µm/s (= 0.0000004 mm/s")


def test_zero_and_negative() -> None:
    assert describe(0, "um/s") == "0 µm/s"
    assert describe(-0.0, "0.1um") == "0 [0.1 µm]"
    assert describe(-5, "0.1um") == "-5 [0.1 µm] (= -0.0005 mm)"


# -- rule messages on rotary axes and spindles ---------------------------------------------------------


def test_lis403_rotary_tolerance_in_degrees(tmp_path: Path) -> None:
    [message] = _messages(_as_axis_type("LIS403", 2, tmp_path), "LIS403")
    assert "0.001°" not in message.replace("[0.001°/s]", "")  # no `100 0.001°`
    assert "about 0.1°" in message and "tolerance 0.01°" in message


def test_lis403_linear_unchanged(tmp_path: Path) -> None:
    [message] = _messages(RULES / "LIS403" / "bad.lis", "LIS403")
    assert "about 100 µm" in message and "tolerance 20 µm" in message


def test_lis317_rotary_in_degrees_not_deg(tmp_path: Path) -> None:
    [message] = _messages(_as_axis_type("LIS317", 2, tmp_path), "LIS317")
    assert " deg" not in message and "57.5°" in message.replace(" °", "°")


def test_lis309_spindle_sum_has_its_unit(tmp_path: Path) -> None:
    [message] = _messages(_as_axis_type("LIS309", 4, tmp_path), "LIS309")
    assert "= 7200000)" not in message
    assert "7200000 [0.0001°] (= 720 °)" in message


# -- dry-run: its text writes degrees as lint does -----------------------------------------------------


def test_dry_run_writes_degrees_as_lint_does(cli, tmp_path: Path) -> None:
    path = _as_axis_type("LIS403", 2, tmp_path)
    text = cli("dry-run", str(path)).stdout.decode()
    assert "83.333" in text  # the same speed lint and explain show (83.333 °/s)
    assert " deg" not in text and "°" in text
    assert "500 °/s²" in text and "at °" in text  # the acceleration and the events' position column


def test_the_report_writes_degrees_as_lint_does(cli, tmp_path: Path) -> None:
    import re

    path = _as_axis_type("LIS403", 2, tmp_path)
    page = tmp_path / "report.html"
    cli("report", str(path), "-o", str(page))
    text = re.sub(r"<[^>]+>", " ", page.read_text(encoding="utf-8"))  # the words, without the markup
    assert "stands at" in text and "°" in text
    assert not re.search(r"[0-9] deg\b|\bdeg/s|\(deg\)", text)


def test_dry_run_json_keeps_deg_as_its_machine_readable_unit(cli, tmp_path: Path) -> None:
    path = _as_axis_type("LIS403", 2, tmp_path)
    document = json.loads(cli("dry-run", str(path), "--format", "json").stdout)
    assert document["units"] == {
        "position": "deg",
        "velocity": "deg/s",
        "time": "s",
        "acceleration": "deg/s^2",
    }
