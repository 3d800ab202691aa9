"""--jobs: parallel output equals serial output, in input order."""

from __future__ import annotations

from .conftest import FIXTURES


def test_parallel_equals_serial(cli, tmp_path):
    rule_lists = sorted((FIXTURES / "rules").glob("*/bad.lis"))
    for number, source in enumerate(rule_lists * 2):
        (tmp_path / f"achsmds{number:03d}.lis").write_bytes(source.read_bytes())
    serial = cli("lint", str(tmp_path), "--format", "concise", "--jobs", "1")
    parallel = cli("lint", str(tmp_path), "--format", "concise", "--jobs", "2")
    assert serial.returncode == parallel.returncode == 1
    assert serial.stdout == parallel.stdout
    assert serial.stdout.count(b"\n") > 80


def test_github_format_is_chosen_under_github_actions(cli):
    result = cli("lint", str(FIXTURES / "rules" / "LIS202" / "bad.lis"), env={"GITHUB_ACTIONS": "true"})
    assert result.stdout.startswith(b"::error file=")


def test_without_jobs_processes_start_only_for_enough_text(tmp_path, monkeypatch):
    # Small folders are linted in this process (a process pool costs more than it saves); from
    # PARALLEL_MIN_BYTES of text on, the default is all cores. An explicit --jobs always gets its processes.
    import concurrent.futures
    import os

    from achslint.linting import run as api
    from achslint.linting.config import Overrides

    started: list[int] = []

    class CountingPool:  # stands in for ProcessPoolExecutor: records the start, runs the work here
        def __init__(self, max_workers: int, initializer=None) -> None:
            started.append(max_workers)

        def map(self, function, items, chunksize=1):
            return map(function, items)

        def shutdown(self, cancel_futures=False) -> None:
            pass

    monkeypatch.setattr(concurrent.futures, "ProcessPoolExecutor", CountingPool)
    monkeypatch.setattr(os, "cpu_count", lambda: 2)
    source = (FIXTURES / "rules" / "LIS202" / "bad.lis").read_bytes()
    for number in range(api.PARALLEL_THRESHOLD):
        (tmp_path / f"achsmds{number}.lis").write_bytes(source)

    def lint(jobs=None):
        return api.run_lint(api.LintRequest([str(tmp_path)], Overrides(), jobs=jobs))

    small = lint()
    assert started == [] and len(small.results) == api.PARALLEL_THRESHOLD
    assert lint(jobs=2) and started == [2]
    comment = b"# " + b"x" * 1000 + b"\n"  # comment lines: the findings stay the same
    share = api.PARALLEL_MIN_BYTES // api.PARALLEL_THRESHOLD
    for number in range(api.PARALLEL_THRESHOLD):
        (tmp_path / f"achsmds{number}.lis").write_bytes(comment * (share // len(comment) + 1) + source)
    big = lint()
    assert started == [2, 2]
    assert [len(r.diagnostics) for r in big.results] == [len(r.diagnostics) for r in small.results]
