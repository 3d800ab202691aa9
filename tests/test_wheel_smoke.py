"""The wheel, installed in a fresh virtual environment outside the repository, runs every command (issue 27).

A green suite in the checkout can hide a file the wheel leaves out (a catalogue, a grammar, rule docs) or a
dependency only the test extra brings: this builds the wheel, installs it with its `plot` and `lsp` extras
into a venv in a temporary folder, and runs each command there from another folder, on copies of the
bundled fixtures. Slow (a build and an install from the package index): `pytest -m slow`.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from .conftest import FIXTURES, ROOT

pytestmark = pytest.mark.slow


def _run(args: list[str], cwd: Path, **kwargs: object) -> subprocess.CompletedProcess[str]:
    env = {key: value for key, value in os.environ.items() if key not in ("PYTHONPATH", "VIRTUAL_ENV")}
    return subprocess.run(
        args, cwd=cwd, env={**env, "NO_COLOR": "1"}, capture_output=True, text=True, timeout=900, **kwargs
    )  # type: ignore[call-overload]


@pytest.fixture(scope="module")
def installed(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The `bin` folder of a venv outside the repository with the wheel (and its extras) installed."""
    where = tmp_path_factory.mktemp("wheel")
    built = _run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "-w", str(where / "dist"), str(ROOT)], where
    )
    if built.returncode != 0:
        pytest.skip(f"the wheel could not be built here (no package index?): {built.stderr.strip()[-300:]}")
    [wheel] = (where / "dist").glob("achslint-*.whl")
    venv = where / "venv"
    assert _run([sys.executable, "-m", "venv", str(venv)], where).returncode == 0
    bin_ = venv / "bin"
    done = _run([str(bin_ / "python"), "-m", "pip", "install", "--quiet", f"{wheel}[plot,lsp]"], where)
    if done.returncode != 0:
        pytest.skip(f"the wheel's dependencies could not be installed here: {done.stderr.strip()[-300:]}")
    return bin_


@pytest.fixture
def work(tmp_path: Path) -> Path:
    """A folder outside the repository with a machine and two lists to run the commands on."""
    shutil.copytree(FIXTURES / "machines" / "portal", tmp_path / "portal")
    (tmp_path / "rfp.nc").write_text("N10 G74 X1 Y1 Z2\nM30\n")
    return tmp_path


def test_every_command_runs_from_the_installed_wheel(installed: Path, work: Path) -> None:
    achslint = str(installed / "achslint")
    listen = work / "portal" / "listen"
    # the package is the wheel's, not the checkout's
    where = _run([str(installed / "python"), "-c", "import achslint, sys; print(achslint.__file__)"], work)
    assert where.returncode == 0 and str(ROOT) not in where.stdout and "site-packages" in where.stdout
    version = _run([achslint, "--version"], work)
    assert version.returncode == 0 and version.stdout.startswith("achslint ")

    lint = _run([achslint, "lint", "portal", "--format", "json", "--exit-zero"], work)
    assert lint.returncode == 0, lint.stderr
    assert json.loads(lint.stdout)["summary"]["files"] >= 8
    assert _run([achslint, "fmt", "--check", "portal"], work).returncode in (0, 1)  # 1: would reformat
    explained = _run([achslint, "explain", str(listen / "achsmds1.lis"), "--format", "json"], work)
    assert explained.returncode == 0 and json.loads(explained.stdout)["strategy"]["id"], explained.stderr
    machine = _run([achslint, "explain", str(listen / "hochlauf.lis")], work)
    assert machine.returncode == 0 and "X" in machine.stdout, machine.stderr
    card = _run([achslint, "explain", "vb_reflow"], work)
    assert card.returncode == 0 and "P-AXIS-00218" in card.stdout

    for plot in ("axis.svg", "axis.png"):  # SVG drawn by achslint, PNG by matplotlib (the plot extra)
        done = _run([achslint, "dry-run", str(listen / "achsmds3.lis"), "--plot", plot], work)
        assert done.returncode in (0, 1), done.stderr  # 1: the simulated homing failed, still plotted
        assert (work / plot).stat().st_size > 1000
    program = _run([achslint, "dry-run", str(listen / "hochlauf.lis"), "--program", "rfp.nc"], work)
    assert program.returncode in (0, 1) and "G74" in program.stdout, program.stderr

    same = _run([achslint, "diff", str(listen / "achsmds1.lis"), str(listen / "achsmds1.lis")], work)
    assert same.returncode == 0, same.stderr
    rules = _run([achslint, "rules", "--format", "json"], work)
    assert rules.returncode == 0 and any(rule["code"] == "LIS504" for rule in json.loads(rules.stdout))
    rule = _run([achslint, "rule", "LIS202"], work)
    assert rule.returncode == 0 and "What" in rule.stdout
    for kind in ("axis", "channel", "startup"):
        schema = _run([achslint, "schema", "--kind", kind], work)
        assert schema.returncode == 0 and json.loads(schema.stdout)["type"] == "object", (kind, schema.stderr)
    report = _run([achslint, "report", str(listen / "hochlauf.lis"), "-o", "report.html"], work)
    assert report.returncode in (0, 1) and (work / "report.html").read_text().startswith("<!DOCTYPE html>")


def test_the_language_server_starts_and_stops_from_the_installed_wheel(installed: Path, work: Path) -> None:
    def frame(message: dict[str, object]) -> bytes:
        body = json.dumps(message).encode()
        return b"Content-Length: %d\r\n\r\n%s" % (len(body), body)

    messages = [
        {
            "jsonrpc": "2.0",
            "id": 1,
            "method": "initialize",
            "params": {"processId": None, "capabilities": {}},
        },
        {"jsonrpc": "2.0", "method": "initialized", "params": {}},
        {"jsonrpc": "2.0", "id": 2, "method": "shutdown"},
        {"jsonrpc": "2.0", "method": "exit"},
    ]
    done = subprocess.run(
        [str(installed / "achslint"), "server"],
        input=b"".join(frame(message) for message in messages),
        cwd=work,
        capture_output=True,
        timeout=120,
        check=False,
    )
    assert done.returncode == 0, done.stderr.decode()
    assert b'"id": 1' in done.stdout or b'"id":1' in done.stdout  # the initialize answer
    assert b"capabilities" in done.stdout
