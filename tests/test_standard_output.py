"""Standard output that cannot take the report (a full disk, a file-size limit) ends the run with one line and
exit 2; Python's own stream cut such a report at the limit and exited 0. A closed pipe stays quiet."""

from __future__ import annotations

import os
import resource
import subprocess
import sys
from pathlib import Path

import pytest

from .conftest import FIXTURES

AXIS = str(FIXTURES / "kinds" / "achsmds_z.lis")
pytestmark = pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full (Linux)")


def achslint(*args: str, stdout: object, limit: int | None = None) -> subprocess.CompletedProcess[bytes]:
    def limited() -> None:
        if limit is not None:
            resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    env = {**os.environ, "NO_COLOR": "1"}
    if limit is not None:  # the limit holds for every file the child writes: coverage's data file too
        env = {key: value for key, value in env.items() if not key.startswith("COVERAGE")}
    return subprocess.run(
        [sys.executable, "-m", "achslint", *args],
        stdout=stdout,
        stderr=subprocess.PIPE,
        env=env,
        preexec_fn=limited,
        timeout=60,
        check=False,
    )


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_a_full_disk_and_a_file_size_limit_are_told_in_one_line(tmp_path: Path) -> None:
    with open("/dev/full", "wb") as full:
        result = achslint("explain", AXIS, stdout=full)
    assert result.returncode == 2
    assert result.stderr.decode() == "achslint: cannot write standard output: No space left on device\n"
    out = tmp_path / "out.txt"
    with out.open("wb") as limited:  # 1,024 bytes: less than the explanation
        result = achslint("explain", AXIS, stdout=limited, limit=1024)
    assert result.returncode == 2
    assert result.stderr.decode() == "achslint: cannot write standard output: File too large\n"
    assert out.stat().st_size == 1024  # as far as the limit let it go, and said so


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_output_that_fits_is_written_whole(tmp_path: Path) -> None:
    out = tmp_path / "out.txt"
    with out.open("wb") as target:
        result = achslint("explain", AXIS, stdout=target, limit=1 << 20)
    assert result.returncode == 0 and result.stderr == b""
    text = out.read_text(encoding="utf-8")
    assert text.startswith(AXIS) and "Axis Z (logical axis 3)" in text and len(text) > 1024


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_a_reader_that_goes_away_gets_no_message() -> None:
    # `achslint schema | head -c 10`: the schema (~250 KB) is more than a pipe holds, so the write meets the
    # closed pipe; as click has it, the run ends quietly with exit 1.
    reader = subprocess.Popen(["head", "-c", "10"], stdin=subprocess.PIPE, stdout=subprocess.DEVNULL)
    assert reader.stdin is not None
    result = achslint("schema", stdout=reader.stdin)
    reader.stdin.close()
    reader.wait(timeout=30)
    assert result.returncode == 1 and result.stderr == b""
