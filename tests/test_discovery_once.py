"""Discovery does each thing once per run: every list is sniffed (read for start-up detection) at most once,
links are resolved once per folder rather than once per part of every path, and nothing it learnt survives
the run (the language server runs discovery again after files changed)."""

from __future__ import annotations

import os
import shutil
import subprocess
from collections import Counter
from pathlib import Path

import pytest

from achslint.core import files
from achslint.linting import discovery
from achslint.linting.config import Overrides
from achslint.linting.discovery import Finder

from .conftest import FIXTURES


def _folder(tmp_path: Path) -> Path:
    """A project of two machines (start-up list and axis lists) and loose lists in folders below."""
    project = tmp_path / "project"
    shutil.copytree(FIXTURES / "machines" / "sdk4", project / "sdk4")
    shutil.copytree(FIXTURES / "machines" / "variants", project / "variants")
    for number in range(3):
        loose = project / "loose" / f"part{number}"
        loose.mkdir(parents=True)
        for index in range(4):
            (loose / f"achsmds{index}.lis").write_text(f"kopf.achs_nr {index}\nkenngr.antr_typ 1\nEnde\n")
    return project


def _find(paths: list[str]) -> discovery.Discovery:
    return Finder(Overrides(include=["*.lis"])).find(paths)


def test_a_folder_lint_sniffs_each_list_once(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    project = _folder(tmp_path)
    reads: Counter[str] = Counter()
    real = discovery.read_list

    def counted(path: Path, *args: object, **kwargs: object) -> bytes:
        reads[os.path.abspath(path)] += 1
        return real(path, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(discovery, "read_list", counted)
    found = _find([str(project)])
    assert len(found.targets) > 12 and not found.errors
    lists = {os.path.abspath(p) for p in project.rglob("*.lis")}
    assert set(reads) <= lists and reads
    assert max(reads.values()) == 1, [name for name, count in reads.items() if count > 1]


def test_a_folder_lint_resolves_links_once_per_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    _folder(tmp_path)
    whole: list[str] = []
    real = os.path.realpath

    def counted(path: object, *args: object, **kwargs: object) -> str:
        whole.append(os.fspath(path))  # type: ignore[arg-type]
        return real(path, *args, **kwargs)  # type: ignore[call-overload,no-any-return]

    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(files.os.path, "realpath", counted)
    found = _find(["project"])
    assert len(found.targets) > 12 and not found.errors
    # Without a link in the tree, discovery resolves whole paths only for the roots it starts from; the
    # configuration's own resolution (`relative`, machine tables) is no business of discovery's.
    from_files = [p for p in whole if not os.path.isabs(p) or p in ("/", os.sep)]
    assert len(from_files) <= 4, from_files


@pytest.mark.parametrize(
    "spelling",
    [
        "a/b/c.lis",
        "link/c.lis",
        "link/../b/c.lis",
        "a/missing/x.lis",
        "broken/x.lis",
        "broken",
        "loop/x.lis",
        "loop",
        "filelink",
        ".",
        "..",
        "a/./b",
        "a/b/../b/c.lis",
        "dangling",
    ],
)
def test_links_held_resolve_as_realpath_does(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, spelling: str
) -> None:
    (tmp_path / "a" / "b").mkdir(parents=True)
    (tmp_path / "a" / "b" / "c.lis").write_text("Ende\n")
    (tmp_path / "link").symlink_to(tmp_path / "a" / "b")
    (tmp_path / "broken").symlink_to(tmp_path / "nowhere")
    (tmp_path / "loop").symlink_to(tmp_path / "loop")
    (tmp_path / "filelink").symlink_to("a/b/c.lis")
    (tmp_path / "dangling").symlink_to("a/none.lis")
    monkeypatch.chdir(tmp_path)
    for path in (Path(spelling), tmp_path / spelling):
        expected = Path(os.path.realpath(path))
        with files.links_held():
            files.real_path(path.parent)  # a folder resolved before the file, as discovery asks them
            assert files.real_path(path) == expected, path
            assert files.real_path(path) == expected, path  # and again, from what it holds


def test_nothing_is_kept_after_a_run(tmp_path: Path) -> None:
    project = _folder(tmp_path)
    plain = project / "loose" / "part0" / "achsmds0.lis"
    before = _find([str(project)])
    assert not any(s.path == plain for s in before.startups)
    assert discovery._LOOKED_AT.get() is None and files._RESOLVED.get() is None
    # The list becomes a start-up list by its content: the next run sees it as one.
    plain.write_text("zahl_mds 1\nachs_mds[0] ./achsmds1.lis\nEnde\n")
    after = _find([str(project)])
    assert any(os.path.samefile(s.path, plain) for s in after.startups)


def test_a_link_out_of_the_paths_given_is_still_skipped(tmp_path: Path) -> None:
    project = _folder(tmp_path)
    outside = tmp_path / "outside.lis"
    outside.write_text("kopf.achs_nr 9\nEnde\n")
    (project / "loose" / "part1" / "linked.lis").symlink_to(outside)
    found = _find([str(project)])
    assert not any(t.path is not None and t.path.name == "linked.lis" for t in found.targets)
    assert any(
        "linked.lis: skipped, it links to" in note and "outside the paths given" in note
        for note in found.notes
    )


def _git_calls(monkeypatch: pytest.MonkeyPatch) -> list[list[str]]:
    calls: list[list[str]] = []
    real = subprocess.run

    def counted(argv: list[str], *args: object, **kwargs: object) -> subprocess.CompletedProcess[bytes]:
        if argv[0] == "git":
            calls.append(argv)
        return real(argv, *args, **kwargs)  # type: ignore[call-overload,no-any-return]

    monkeypatch.setattr(subprocess, "run", counted)
    return calls


def _exports(tmp_path: Path) -> Path:
    """A git work tree holding TwinCAT exports (a machine of one folder's XML files), one of them ignored."""
    repo = tmp_path / "repo"
    shutil.copytree(FIXTURES / "machines" / "twincat_export", repo / "exports")
    subprocess.run(["git", "init", "-q", str(repo)], check=True, capture_output=True)
    (repo / ".gitignore").write_text("Axis_Z.xti\n")
    return repo


def _shown(found: discovery.Discovery) -> list[tuple[str, tuple[str, ...]]]:
    return sorted((t.name, t.machines) for t in found.targets)


@pytest.mark.skipif(shutil.which("git") is None, reason="needs git")
def test_git_is_asked_once_per_work_tree(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    repo = _exports(tmp_path)
    for name in ("GIT_DIR", "GIT_WORK_TREE", "GIT_COMMON_DIR", "GIT_CEILING_DIRECTORIES"):
        monkeypatch.delenv(name, raising=False)
    calls = _git_calls(monkeypatch)
    found = _find([str(repo)])
    assert len(calls) == 1  # the folder lint's question covers the folder machine's
    names = {Path(name).name for name, _ in _shown(found)}
    assert "Axis_X.xti" in names and "Axis_Z.xti" not in names
    # Told how far up to look, git is asked for the folder machine as well: the same lists and machines.
    monkeypatch.setenv("GIT_CEILING_DIRECTORIES", str(tmp_path / "elsewhere"))
    asked_again = _find([str(repo)])
    assert len(calls) == 3 and _shown(asked_again) == _shown(found)


@pytest.mark.skipif(shutil.which("git") is None, reason="needs git")
def test_a_repository_of_its_own_below_is_asked_itself(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    repo = _exports(tmp_path)
    subprocess.run(["git", "init", "-q", str(repo / "exports")], check=True, capture_output=True)
    (repo / "exports" / ".gitignore").write_text("Axis_Y.xti\n")
    calls = _git_calls(monkeypatch)
    _find([str(repo)])
    assert len(calls) == 2
    assert calls[1][2] == str(repo / "exports")
