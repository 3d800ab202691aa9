"""Pathological input: huge lines, floods of duplicates, deep indices, files that change under us.

Time is not measured here (machines are noisy); `benchmarks/run --only robustness`
shows that each of these grows linearly. These tests check that the answers are
right and readable at sizes far beyond any real list.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from achslint.api import LintRequest, LintRun
from achslint.core.files import ChangedOnDisk, write_atomically
from achslint.linting.linter import lint_file

MB = 1 << 20
MESSAGE_LIMIT = 400  # a message names a huge line, it does not repeat it


def codes(data: bytes) -> list[str]:
    result = lint_file(data, "achsmds1.lis")
    assert result.error is None
    for diagnostic in result.diagnostics:
        assert len(diagnostic.message) < MESSAGE_LIMIT, diagnostic.message[:200]
    return [d.code for d in result.diagnostics]


@pytest.mark.parametrize(
    ("label", "data", "expected"),
    [
        ("comment", b"kopf.achs_nr 1 ( " + b"x" * MB + b"\nEnde\n", []),
        ("string value", b'kopf.log_achs_name "' + b"x" * MB + b'"\nEnde\n', ["LIS206"]),
        ("unknown path", b"a" * MB + b" 1\nEnde\n", ["LIS101"]),
        ("dotted path", b"a." * (MB // 2) + b"b 1\nEnde\n", ["LIS101"]),
        ("blanks", b"kopf.achs_nr" + b" " * MB + b"1\nEnde\n", []),
        ("brackets", b"[" * MB + b"\nEnde\n", ["LIS001"]),
        ("quotes", b'"' * MB + b"\nEnde\n", ["LIS001"]),
        ("digits of an integer", b"kopf.achs_nr " + b"1" * MB + b"\nEnde\n", ["LIS202"]),
        ("digits of an index", b"getriebe[" + b"1" * MB + b"].vb_reflow 1\nEnde\n", ["LIS104"]),
        (
            "nested indices",
            b"getriebe" + b"[" * (MB // 2) + b"0" + b"]" * (MB // 2) + b".x 1\nEnde\n",
            ["LIS001"],
        ),
        ("repeated indices", b"getriebe" + b"[0]" * (MB // 3) + b".vb_reflow 1\nEnde\n", ["LIS101"]),
    ],
)
def test_a_one_megabyte_line_gets_a_short_precise_finding(label, data, expected):
    assert codes(data) == expected, label


def test_huge_integer_is_reported_by_its_digit_count_not_converted():
    message = lint_file(b"kopf.achs_nr " + b"7" * 5000 + b"\nEnde\n", "a.lis").diagnostics[0].message
    assert "5,000 digits" in message and "UNS16" in message
    assert "…" in message  # the value itself is shortened


def test_a_flood_of_duplicates_is_reported_once_per_repetition():
    count = 5_000  # real lists have a few hundred lines; growth with size is benchmarks/run's business
    result = lint_file(b"kopf.achs_nr 1\n" * count + b"Ende\n", "achsmds1.lis")
    duplicates = [d for d in result.diagnostics if d.code == "LIS005"]
    assert len(duplicates) == count - 1
    assert {d.line for d in duplicates} == set(range(2, count + 1))


def test_many_lines_after_the_end_marker_are_one_finding():
    result = lint_file(b"Ende\n" + b"kopf.achs_nr 1\n" * 10_000, "achsmds1.lis")
    assert [d.code for d in result.diagnostics] == ["LIS003"]
    assert "10000 parameter lines" in result.diagnostics[0].message


def write_lists(folder: Path, count: int) -> list[Path]:
    paths = []
    for number in range(1, count + 1):
        path = folder / f"achsmds{number}.lis"
        path.write_bytes(f"kopf.achs_nr {number}\nkopf.log_achs_name A{number}\nEnde\n".encode())
        paths.append(path)
    return paths


def test_a_list_that_vanishes_during_the_run_is_an_error_for_that_list_only(tmp_path):
    first, second, third = write_lists(tmp_path, 3)
    seen = []

    def progress(total):  # called after each list: remove the next one before it is read
        seen.append(total)
        if len(seen) == 1:
            second.unlink()

    outcome = LintRun(LintRequest(paths=[str(tmp_path)], jobs=1)).run(progress=progress)
    assert len(outcome.errors) == 1
    assert str(second) in outcome.errors[0] and "cannot read" in outcome.errors[0]
    linted = {Path(r.name).name for r in outcome.results if r.error is None}
    assert linted == {first.name, third.name}


def test_the_cli_names_an_unreadable_list_and_lints_the_others(cli, tmp_path):
    write_lists(tmp_path, 2)
    (tmp_path / "achsmds3.lis").symlink_to(tmp_path / "gone.lis")  # listed in the folder, unreadable
    (tmp_path / "achsmds2.lis").write_bytes(b"kopf.achs_nr 2\nkopf.achs_nr 2\nEnde\n")
    result = cli("lint", str(tmp_path), "--format", "json")
    assert result.returncode == 2
    assert b"cannot read" in result.stderr and b"achsmds3.lis" in result.stderr
    assert b"Traceback" not in result.stderr
    report = json.loads(result.stdout)
    found = {(Path(d["path"]).name, d["code"]) for d in report["diagnostics"]}
    assert ("achsmds2.lis", "LIS005") in found  # the readable lists were still linted


def test_fix_never_overwrites_an_edit_made_meanwhile(tmp_path):
    path = tmp_path / "achsmds1.lis"
    original = b"kopf.achs_nr 1\n"
    path.write_bytes(b"kopf.achs_nr 1 ( edited by someone else\n")
    with pytest.raises(ChangedOnDisk, match="changed while achslint was working"):
        write_atomically(path, b"kopf.achs_nr 1\nEnde\n", expected=original)
    assert path.read_bytes() == b"kopf.achs_nr 1 ( edited by someone else\n"
    assert [p.name for p in tmp_path.iterdir()] == ["achsmds1.lis"]  # no temporary file left behind


def test_fix_does_not_recreate_a_list_removed_meanwhile(tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(b"x")
    path.unlink()
    with pytest.raises(ChangedOnDisk, match="removed"):
        write_atomically(path, b"kopf.achs_nr 1\nEnde\n", expected=b"kopf.achs_nr 1\n")
    assert list(tmp_path.iterdir()) == []


def test_unchanged_file_is_written(tmp_path):
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(b"kopf.achs_nr 1\n")
    write_atomically(path, b"kopf.achs_nr 1\nEnde\n", expected=b"kopf.achs_nr 1\n")
    assert path.read_bytes() == b"kopf.achs_nr 1\nEnde\n"


def test_a_start_up_entry_too_long_for_the_file_system_is_a_missing_list(cli, tmp_path):
    startup = tmp_path / "hochlauf.lis"
    startup.write_text("achs_mds[0] ./" + "x" * 5000 + ".lis\nEnde\n")
    result = cli("lint", str(startup), "--format", "json")
    assert b"Traceback" not in result.stderr and b"internal error" not in result.stderr
    found = {d["code"]: d for d in json.loads(result.stdout)["diagnostics"]}
    assert sorted(found) == ["LIS206", "LIS504"]  # the CNC stores 256 characters of an entry (P-STUP-00015)
    finding = found["LIS504"]
    assert len(finding["message"]) < MESSAGE_LIMIT and "5,006 characters" in finding["message"]
    assert len(found["LIS206"]["message"]) < MESSAGE_LIMIT


DEEP = "[" * 5000 + "]" * 5000


@pytest.mark.parametrize(
    ("name", "text", "args"),
    [
        ("achslint.toml", f"x = {DEEP}\n", ("lint", "achsmds1.lis")),
        ("pyproject.toml", f"[tool.achslint]\nx = {DEEP}\n", ("lint", "achsmds1.lis")),
        (
            "scenario.toml",
            f"start_position = {DEEP}\n",
            ("dry-run", "achsmds1.lis", "--scenario", "scenario.toml"),
        ),
    ],
    ids=["config", "pyproject", "scenario"],
)
def test_a_toml_file_nested_thousands_deep_is_a_one_line_error(cli, tmp_path, monkeypatch, name, text, args):
    """Found by review: tomllib reads nested arrays recursively, and 5,000 `[` ended the run in
    `internal error: RecursionError` that named no file."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr 1\nEnde\n")
    (tmp_path / name).write_text(text)
    done = cli(*args)
    assert done.returncode == 2
    assert f"{name}: " in done.stderr.decode() and "too deeply" in done.stderr.decode()
    assert b"internal error" not in done.stderr and b"Traceback" not in done.stderr
