"""Smoke tests of the real entry point in a separate process: everything else runs the CLI in-process
(`conftest.run_cli`), so these make sure `python -m achslint` and the console script behave the same."""

from __future__ import annotations

import json
import shutil

import pytest

from .conftest import FIXTURES, run_cli, run_real_cli


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_module_entry_point_exit_codes_and_output():
    bad = str(FIXTURES / "rules" / "LIS203" / "bad.lis")
    good = str(FIXTURES / "rules" / "LIS203" / "good.lis")
    found = run_real_cli("lint", bad, "--format", "concise")
    assert found.returncode == 1
    assert found.stdout.count(b" LIS203 [error] ") == 2
    assert run_real_cli("lint", good, "--select", "LIS203").returncode == 0
    usage = run_real_cli("lint", "--no-such-flag")
    assert usage.returncode == 2
    assert usage.stderr.decode().strip().startswith("achslint: error:")
    assert len(usage.stderr.decode().strip().splitlines()) == 1


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_stdin_through_the_entry_point_equals_in_process():
    data = (FIXTURES / "rules" / "LIS202" / "bad.lis").read_bytes()
    args = ("lint", "-", "--stdin-filename", "achsmds1.lis", "--format", "json")
    real = run_real_cli(*args, stdin=data)
    inside = run_cli(*args, stdin=data)
    assert real.returncode == inside.returncode == 1
    assert json.loads(real.stdout) == json.loads(inside.stdout)


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_parallel_run_in_a_real_process_equals_serial():
    folder = str(FIXTURES / "lists")
    # the serial run in this process: the one above shows the real entry point prints what it prints
    serial = run_cli("lint", folder, "--format", "json", "--jobs", "1", "--exit-zero")
    parallel = run_real_cli("lint", folder, "--format", "json", "--jobs", "2", "--exit-zero")
    assert serial.returncode == parallel.returncode == 0
    assert json.loads(serial.stdout) == json.loads(parallel.stdout)


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
@pytest.mark.skipif(
    shutil.which("achslint") is None, reason="the console script is not on PATH (package not installed)"
)
def test_console_script_is_the_same_program():
    script = shutil.which("achslint")
    assert script is not None
    import subprocess

    result = subprocess.run([script, "rule", "LIS203"], capture_output=True, timeout=60)
    module = run_real_cli("rule", "LIS203")
    assert result.returncode == module.returncode == 0
    assert result.stdout == module.stdout


def test_run_exits_with_the_code_of_main_after_freezing_the_collector(monkeypatch):
    # `run` is what the console script and `python -m achslint` call: main's exit code, and the objects
    # alive at the end handed to gc.freeze so the shutdown collection does not walk them again.
    import gc

    from achslint import cli

    calls: list[str] = []
    monkeypatch.setattr(cli, "main", lambda: calls.append("main") or 3)
    monkeypatch.setattr(gc, "freeze", lambda: calls.append("freeze"))
    with pytest.raises(SystemExit) as stopped:
        cli.run()
    assert stopped.value.code == 3
    assert calls == ["main", "freeze"]
