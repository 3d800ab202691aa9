"""Configuration and discovery as a user meets them: found in a review of the real command line on real
folders (each test names what went wrong before its fix)."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from .conftest import FIXTURES, run_cli

AXIS = FIXTURES / "lists" / "achsmds2.lis"  # findings of several families (LIS102, LIS401)


def listed(folder: Path, *args: str) -> list[str]:
    """The files `lint --show-files` lists (their names, relative to `folder`)."""
    result = run_cli("lint", "--show-files", *args)
    assert result.returncode == 0, text(result.stderr)
    names = [line.split("\t")[0] for line in text(result.stdout).splitlines() if line]
    return [Path(os.path.relpath(name, folder)).as_posix() if os.path.isabs(name) else name for name in names]


def linted(*args: str) -> set[str]:
    """The files `lint --format json` reports findings for."""
    import json

    result = run_cli("lint", "--format", "json", "--exit-zero", *args)
    assert result.returncode == 0, result.stderr
    return {d["path"] for d in json.loads(result.stdout)["diagnostics"]}


def text(out: str | bytes) -> str:
    return out.decode() if isinstance(out, bytes) else out


def project(root: Path, *names: str) -> Path:
    for name in names:
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(AXIS, root / name)
    return root


# -- exclude: a folder's name, and files matched by the name they are found under ---------------------------


@pytest.mark.parametrize("pattern", ["archive", "archive/", "./archive", "**/archive", "archive/*"])
def test_exclude_names_a_folder_as_gitignore_and_ruff_do(tmp_path: Path, monkeypatch, pattern: str) -> None:
    """Before: `exclude = ["archive"]` (or `./archive`, `**/archive`) excluded nothing below archive/."""
    project(tmp_path, "listen/achsmds1.lis", "archive/achsmds1.lis", "archive/old/achsmds2.lis")
    (tmp_path / "achslint.toml").write_text(f'exclude = ["{pattern}"]\n', encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    assert listed(tmp_path, ".") == ["listen/achsmds1.lis"]
    assert linted(".") == {"listen/achsmds1.lis"}


def test_a_name_pattern_excludes_a_folder_of_that_name_at_any_depth(tmp_path: Path, monkeypatch) -> None:
    project(tmp_path, "m1/listen/achsmds1.lis", "m1/backup/achsmds1.lis", "m2/backup/achsmds1.lis")
    (tmp_path / "achslint.toml").write_text('exclude = ["backup"]\n', encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    assert listed(tmp_path, ".") == ["m1/listen/achsmds1.lis"]


def test_per_file_ignores_takes_a_folder_name_too(tmp_path: Path, monkeypatch) -> None:
    project(tmp_path, "legacy/achsmds1.lis")
    (tmp_path / "achslint.toml").write_text('[per-file-ignores]\n"legacy" = ["LIS"]\n', encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    assert linted(".") == set()


def test_a_link_is_excluded_by_the_name_it_is_found_under(tmp_path: Path, monkeypatch) -> None:
    """Before: exclude matched a link by its target: `backup/achsmds1.lis -> ../listen/achsmds1.lis` was
    linted despite `backup/*`, and `listen/achsmds2.lis -> ../archive/...` was left out by `archive/*`."""
    project(tmp_path, "listen/achsmds1.lis", "archive/achsmds2.lis")
    (tmp_path / "backup").mkdir()
    (tmp_path / "backup" / "achsmds1.lis").symlink_to("../listen/achsmds1.lis")
    (tmp_path / "listen" / "achsmds2.lis").symlink_to("../archive/achsmds2.lis")
    (tmp_path / "achslint.toml").write_text('exclude = ["backup/*", "archive/*"]\n', encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    assert listed(tmp_path, ".") == ["listen/achsmds1.lis", "listen/achsmds2.lis"]


def test_a_dangling_link_in_an_excluded_folder_is_no_error(tmp_path: Path, monkeypatch) -> None:
    """Before: exit 2, `cannot read archive/achsmds9.lis: a symbolic link to a file that does not exist`."""
    project(tmp_path, "listen/achsmds1.lis")
    (tmp_path / "archive").mkdir()
    (tmp_path / "archive" / "achsmds9.lis").symlink_to("/nonexistent/achsmds9.lis")
    (tmp_path / "achslint.toml").write_text('exclude = ["archive"]\n', encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    result = run_cli("lint", ".", "--format", "concise", "--exit-zero")
    assert result.returncode == 0, result.stderr


def test_an_excluded_folder_is_not_searched(tmp_path: Path, monkeypatch) -> None:
    """Before: the files of an excluded folder were looked at one by one, and what is wrong in there (a link
    leading outside, a folder that cannot be read: exit 2) was reported."""
    project(tmp_path / "proj", "listen/achsmds1.lis")
    project(tmp_path / "outside", "achsmds1.lis")
    (tmp_path / "proj" / "archive").mkdir()
    (tmp_path / "proj" / "archive" / "elsewhere").symlink_to(tmp_path / "outside")
    (tmp_path / "proj" / "achslint.toml").write_text('exclude = ["archive/*"]\n', encoding="utf-8")
    monkeypatch.chdir(tmp_path / "proj")
    result = run_cli("lint", ".", "--format", "concise", "--exit-zero")
    assert result.returncode == 0, text(result.stderr)
    assert "archive" not in text(result.stderr)


def test_exclude_through_a_linked_working_folder(tmp_path: Path, monkeypatch) -> None:
    project(tmp_path / "real", "listen/achsmds1.lis", "archive/achsmds1.lis")
    (tmp_path / "real" / "achslint.toml").write_text('exclude = ["archive"]\n', encoding="utf-8")
    (tmp_path / "link").symlink_to("real")
    monkeypatch.chdir(tmp_path / "link")
    assert listed(tmp_path / "link", ".") == ["listen/achsmds1.lis"]
    assert listed(tmp_path, str(tmp_path / "link")) == ["link/listen/achsmds1.lis"]


# -- --force-exclude: standard input, and a run whose named files are all excluded -----------------------


def test_force_exclude_applies_to_standard_input_by_its_stdin_filename(tmp_path: Path, monkeypatch) -> None:
    """Before: `lint - --stdin-filename archive/x.lis --force-exclude` linted the text (an editor's save hook
    reported findings for a file the project excludes)."""
    (tmp_path / "achslint.toml").write_text('exclude = ["archive"]\n', encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    args = ("lint", "-", "--stdin-filename", "archive/achsmds1.lis", "--format", "concise")
    result = run_cli(*args, "--force-exclude", stdin=AXIS.read_bytes())
    assert result.returncode == 0, text(result.stderr)
    assert "achsmds1.lis:" not in text(result.stdout)
    assert run_cli(*args, "--exit-zero", stdin=AXIS.read_bytes()).stdout  # without it: linted
    shown = run_cli(
        "lint", "-", "--stdin-filename", "archive/achsmds1.lis", "--force-exclude", "--show-files"
    )
    assert text(shown.stdout).strip() == ""


def test_named_files_all_force_excluded_say_so(tmp_path: Path, monkeypatch) -> None:
    """Before: exit 2 `no axis list found in archive/achsmds1.lis (folders are searched for the include
    patterns ...); check the path or --include`: the file was there, the configuration excluded it. Still
    exit 2 (test_ruff_habits: a run that checks nothing fails), but the message says why."""
    project(tmp_path, "archive/achsmds1.lis")
    (tmp_path / "achslint.toml").write_text('exclude = ["archive"]\n', encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    result = run_cli("lint", "archive/achsmds1.lis", "--force-exclude", "--format", "concise")
    assert result.returncode == 2
    message = text(result.stderr)
    assert "no axis list found" in message and "--force-exclude" in message and "exclude" in message
    assert "folders are searched" not in message
    assert len(message.strip().splitlines()) == 1


def test_force_excluded_standard_input_comes_back_unchanged_under_fix(tmp_path: Path, monkeypatch) -> None:
    """`--fix -` prints the fixed list; for an excluded one it must print the list as it came, not nothing
    (an editor replacing its buffer with the output would be left with an empty file)."""
    (tmp_path / "achslint.toml").write_text('exclude = ["archive"]\n', encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    data = AXIS.read_bytes()
    args = ("lint", "-", "--stdin-filename", "archive/achsmds1.lis", "--fix", "--force-exclude")
    result = run_cli(*args, stdin=data)
    assert result.returncode == 0, text(result.stderr)
    assert result.stdout == data if isinstance(result.stdout, bytes) else result.stdout.encode() == data


# -- configuration files that cannot be used --------------------------------------------------------------


def test_a_pyproject_toml_that_cannot_be_read_is_an_error_not_the_defaults(
    tmp_path: Path, monkeypatch
) -> None:
    """Before: a pyproject.toml achslint may not read (mode 600 of another user) was passed over and the
    run used the built-in defaults (exit 0), where an unreadable achslint.toml, or a pyproject.toml that
    is not valid TOML, stop the run: it may hold the project's [tool.achslint]."""
    from achslint.core import files

    project(tmp_path, "achsmds1.lis")
    pyproject = tmp_path / "pyproject.toml"
    pyproject.write_text('[tool.achslint]\nselect = ["LIS0"]\n', encoding="utf-8")
    real = files.read_list

    def refused(path, *args, **kwargs):
        if Path(path).name == "pyproject.toml":
            raise PermissionError(13, "Permission denied", str(path))
        return real(path, *args, **kwargs)

    monkeypatch.setattr(files, "read_list", refused)
    monkeypatch.chdir(tmp_path)
    result = run_cli("lint", ".", "--format", "concise")
    assert result.returncode == 2
    message = text(result.stderr).strip()
    assert str(pyproject) in message and "permission denied" in message and len(message.splitlines()) == 1


def test_a_machine_table_without_lists_is_a_configuration_error(tmp_path: Path, monkeypatch) -> None:
    """Before: `[[machine]]` with no `lists` (or `name` alone) was taken and declared nothing (exit 0)."""
    project(tmp_path, "listen/achsmds1.lis")
    (tmp_path / "achslint.toml").write_text('[[machine]]\nname = "mill"\n', encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    result = run_cli("lint", ".", "--format", "concise")
    assert result.returncode == 2
    message = text(result.stderr)
    assert "achslint.toml" in message and "machine" in message and "lists" in message


def test_extend_naming_a_pyproject_without_our_table_is_an_error(tmp_path: Path, monkeypatch) -> None:
    """Before: `extend = "../pyproject.toml"` naming a pyproject.toml without [tool.achslint] (a typo of the
    table's name, `[tool.achslnt]`) built on nothing, silently."""
    project(tmp_path, "m/achsmds1.lis")
    (tmp_path / ".git").mkdir()  # the repository the configuration may reach into
    (tmp_path / "pyproject.toml").write_text('[tool.achslnt]\nselect = ["LIS0"]\n', encoding="utf-8")
    (tmp_path / "m" / "achslint.toml").write_text('extend = "../pyproject.toml"\n', encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    result = run_cli("lint", "m", "--format", "concise")
    assert result.returncode == 2
    message = text(result.stderr)
    assert "extend" in message and "[tool.achslint]" in message and "pyproject.toml" in message
