"""How the suite itself runs: on every core through pytest-xdist by default, in one process with
`pytest -p no:xdist` or `pytest -n 0` (README, "Developing")."""

from __future__ import annotations

import shlex
import subprocess
import sys
from types import SimpleNamespace

import pytest

from .conftest import ROOT, pytest_cmdline_main

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib


def test_addopts_leave_the_workers_to_the_conftest():
    """An xdist option in addopts makes `pytest -p no:xdist` fail with "unrecognized arguments: -n"."""
    with open(ROOT / "pyproject.toml", "rb") as stream:
        addopts = shlex.split(tomllib.load(stream)["tool"]["pytest"]["ini_options"]["addopts"])
    xdist_options = {"-n", "--numprocesses", "--dist", "-d", "--maxprocesses", "--tx"}
    assert not [word for word in addopts if word.split("=")[0] in xdist_options or word.startswith("-n")]


def _config(*, xdist: bool = True, numprocesses=None, dist: str = "no", worker: bool = False, collect=False):
    option = SimpleNamespace(numprocesses=numprocesses, dist=dist, collectonly=collect)
    config = SimpleNamespace(option=option, pluginmanager=SimpleNamespace(hasplugin=lambda name: xdist))
    if worker:
        config.workerinput = {"workerid": "gw0"}
    return config


@pytest.mark.parametrize(
    ("given", "expected"),
    [
        ({}, ("auto", "worksteal")),  # plain `pytest`: every core, an idle worker takes the other's tests
        ({"numprocesses": 0}, (0, "no")),  # `pytest -n 0`
        ({"numprocesses": 3}, (3, "no")),  # `-n 3`: xdist picks its default distribution
        ({"dist": "loadfile"}, ("auto", "loadfile")),  # a distribution asked for is kept
        ({"xdist": False}, (None, "no")),  # `-p no:xdist`
        ({"worker": True}, (None, "no")),  # a worker must not start workers of its own
        ({"collect": True}, (None, "no")),  # --collect-only: xdist stays out of it
    ],
)
def test_workers_unless_told_otherwise(given, expected):
    config = _config(**given)
    pytest_cmdline_main(config)  # type: ignore[arg-type]
    assert (config.option.numprocesses, config.option.dist) == expected


@pytest.mark.slow
@pytest.mark.parametrize("one_process", [("-p", "no:xdist"), ("-n", "0")])
def test_the_single_process_commands_run_tests(one_process):
    """The README's single-process commands, for real (a pytest in a child process)."""
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            *one_process,
            "-vv",  # one over addopts' -q: the summary line, and each test with the worker that ran it, if any
            "-p",
            "no:cacheprovider",
            "tests/test_numbers.py",
        ],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    assert " passed" in done.stdout and "PASSED" in done.stdout
    assert "workers" not in done.stdout and "[gw" not in done.stdout  # no xdist worker ran a test
