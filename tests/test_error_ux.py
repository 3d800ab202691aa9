"""Error messages as a user meets them (issue 27 item 7): one line on standard error, the right exit code, and
a did-you-mean where a name is mistyped; nothing on standard output that contradicts the failure."""

from __future__ import annotations

import shutil

import pytest

from .conftest import FIXTURES, run_cli

PORTAL = FIXTURES / "machines" / "portal"  # start-up list, eight axis lists, a homing program (rfp.nc)
STARTUP = PORTAL / "listen" / "hochlauf.lis"
AXIS = PORTAL / "listen" / "achsmds1.lis"
PROGRAM = PORTAL / "rfp.nc"


def one_line(result) -> str:
    err = result.stderr.decode()
    assert err.count("\n") == 1 and err.startswith("achslint: "), err
    assert "Traceback" not in err
    return err


@pytest.mark.parametrize("fmt", ["full", "concise", "json", "github"])
def test_a_missing_path_fails_without_passing(fmt, tmp_path):
    missing = tmp_path / "nope.lis"
    result = run_cli("lint", str(missing), "--format", fmt)
    assert result.returncode == 2
    assert "nope.lis: no such file or directory" in one_line(result)
    assert b"All checks passed" not in result.stdout
    beside = run_cli("lint", str(missing), str(AXIS), "--format", fmt)  # another list is fine: still 2
    assert beside.returncode == 2 and b"All checks passed" not in beside.stdout


def test_dry_run_of_a_start_up_list_asks_for_the_program():
    result = run_cli("dry-run", str(STARTUP))
    assert result.returncode == 2 and result.stdout == b""
    message = one_line(result)
    assert "hochlauf.lis is a start-up list" in message and "--program" in message


def test_dry_run_of_a_start_up_list_named_otherwise(tmp_path):
    machine = tmp_path / "portal"
    shutil.copytree(PORTAL, machine)
    renamed = machine / "listen" / "maschine.lis"
    (machine / "listen" / "hochlauf.lis").rename(renamed)
    result = run_cli("dry-run", str(renamed))
    assert result.returncode == 2 and "maschine.lis is a start-up list" in one_line(result)
    assert run_cli("dry-run", str(machine / "listen" / "achsmds1.lis")).returncode in (0, 1)  # an axis runs


def test_dry_run_program_needs_a_start_up_list():
    result = run_cli("dry-run", str(AXIS), "--program", str(PROGRAM))
    assert result.returncode == 2 and "start-up list" in one_line(result)


def test_machine_option_refuses_an_axis_list():
    result = run_cli("lint", str(PROGRAM), "--machine", str(AXIS), "--format", "concise")
    assert result.returncode == 2 and result.stdout == b""  # no findings against a machine of no axes
    message = one_line(result)
    assert "achsmds1.lis" in message and "not a start-up list" in message
    good = run_cli("lint", str(PROGRAM), "--machine", str(STARTUP), "--format", "concise")
    assert good.returncode in (0, 1) and b"its axes: none" not in good.stdout


@pytest.mark.parametrize(
    ("target", "meant"),
    [
        ("vb_reflw", "vb_reflow"),  # a bare member name
        ("getriebe[0].vb_reflwo", "getriebe[i].vb_reflow"),
        ("kopf.achs_nrr", "kopf.achs_nr"),
    ],
)
def test_explain_suggests_the_parameter_meant(target, meant):
    result = run_cli("explain", target)
    assert result.returncode == 2
    message = one_line(result)
    assert "did you mean" in message and f"`{meant}`" in message.split("did you mean", 1)[1]


@pytest.mark.parametrize(
    ("code", "meant"),
    [("LIS3011", "LIS301"), ("LIS3O2", "LIS302"), ("lis20", "LIS202"), ("LIS2033", "LIS203")],
)
def test_rule_suggests_the_code_meant(code, meant):
    result = run_cli("rule", code)
    assert result.returncode == 2 and result.stdout == b""
    message = one_line(result)
    assert f"unknown rule code {code!r}" in message and "did you mean" in message
    assert meant in message.split("did you mean", 1)[1]
    assert run_cli("rule", meant).returncode == 0  # the suggestion is a rule
