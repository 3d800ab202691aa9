"""[names] in a machine scenario: programmed names for a machine without a channel list (issue 16, item 1)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest


def machine(tmp_path: Path) -> Path:
    """Two linear axes named X and Y by kopf.log_achs_name, no channel list in the start-up list."""
    listen = tmp_path / "listen"
    listen.mkdir()
    for number, name in ((1, "X"), (2, "Y")):
        (listen / f"achsmds{number}.lis").write_text(
            f"kopf.achs_nr {number}\nkopf.log_achs_name {name}\nkenngr.antr_typ 5\nEnde\n", encoding="latin-1"
        )
    startup = listen / "hochlauf.lis"
    startup.write_text("achs_mds[0] ./listen/achsmds1.lis\nachs_mds[1] ./listen/achsmds2.lis\nEnde\n")
    return startup


def run(cli, tmp_path: Path, program: str, scenario: str):
    startup = machine(tmp_path)
    (tmp_path / "rfp.nc").write_text(program)
    (tmp_path / "machine.toml").write_text(scenario)
    return cli(
        "dry-run",
        str(startup),
        "--program",
        str(tmp_path / "rfp.nc"),
        "--scenario",
        str(tmp_path / "machine.toml"),
        "--format",
        "json",
    )


def test_names_give_the_axes_the_programs_names(cli, tmp_path):
    # The program calls the axes A and B; [names] says A is logical axis 1 (the list naming it X).
    result = run(cli, tmp_path, "N10 G74 A1 B2\nM30\n", "[names]\nA = 1\nB = 2\n")
    assert result.returncode == 0, result.stderr.decode()
    axes = {axis["name"]: axis["logical_number"] for axis in json.loads(result.stdout)["axes"]}
    assert axes == {"A": 1, "B": 2}


def test_without_names_the_list_names_count(cli, tmp_path):
    result = run(cli, tmp_path, "N10 G74 X1 Y2\nM30\n", "")
    assert result.returncode == 0, result.stderr.decode()
    axes = {axis["name"]: axis["logical_number"] for axis in json.loads(result.stdout)["axes"]}
    assert axes == {"X": 1, "Y": 2}


@pytest.mark.parametrize(
    ("scenario", "expected"),
    [
        ("[names]\nA = 3\n", "the machine has no axis 3 (it has 1, 2)"),
        ("[names]\nA = 1\nB = 1\n", "gives logical axis 1 two names, A and B"),
        ("[names]\nA = 0\n", "give the logical axis number"),
        ('[names]\n"1A" = 1\n', "is not an axis name"),
        ("names = 5\n", "maps programmed axis names to logical axis numbers"),
    ],
)
def test_bad_names_are_exit_2_naming_the_file(cli, tmp_path, scenario, expected):
    result = run(cli, tmp_path, "N10 G74 A1\nM30\n", scenario)
    assert result.returncode == 2
    message = result.stderr.decode()
    assert expected in message and "machine.toml" in message
