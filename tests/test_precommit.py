"""pre-commit: the hook sees whole machines, follows the repository's configuration, and works for real."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from .conftest import FIXTURES, ROOT
from .test_editor_associations import names as list_names
from .test_strictness import run_in

HOOKS = ROOT / ".pre-commit-hooks.yaml"


def axis(number: int) -> str:
    return f"kopf.achs_nr                 {number}\nkopf.log_achs_name           AX{number}\nkenngr.antr_typ              4\nEnde\n"


def machine(folder: Path) -> Path:
    """Eight lists of one machine; the eighth reuses logical axis number 1 (LIS501, a warning)."""
    folder.mkdir(parents=True, exist_ok=True)
    for number in range(1, 9):
        (folder / f"achsmds{number}.lis").write_text(axis(1 if number == 8 else number))
    # the repository's own strictness, and its lists declared one machine (there is no start-up list)
    (folder / ".achslint.toml").write_text('fail-on = "warning"\n\n[[machine]]\nlists = ["achsmds*.lis"]\n')
    return folder


def lis501(result) -> list[str]:
    return [Path(d["path"]).name for d in json.loads(result.stdout)["diagnostics"] if d["code"] == "LIS501"]


def test_hook_definition_fits_whole_machines():
    text = HOOKS.read_text()
    hooks = {hook["id"]: hook for hook in pytest.importorskip("yaml").safe_load(text)}
    assert hooks["achslint"]["require_serial"] is True  # one process sees every list of a machine
    assert not hooks["achslint-fmt"].get("require_serial")  # fmt reads no neighbours: files may be shared out
    assert "--fail-on" not in text  # the repository's configuration decides
    patterns = re.findall(r"files: '(.*)'", text)
    assert patterns == [hooks["achslint"]["files"], hooks["achslint-fmt"]["files"]]
    lint_pattern = re.compile(patterns[0])
    for name in (
        "listen/achsmds1.lis",
        "listen/default_mds.lis",
        "listen/hochlauf.lis",
        "Axes/Axis_X.xti",
        "Project.tsproj",
        "Update/ax_mds_1.xml",
        "ACHSMDS2.LIS",
        "listen/sda_mds1.lis",  # every kind of list (issue 25): routed by its start-up entry or content
        "listen/werkz_d1.lis",
        "listen/basis.lis",
    ):
        assert lint_pattern.search(name), name
    assert not lint_pattern.search("README.md")
    fmt_pattern = re.compile(patterns[1])
    assert fmt_pattern.search("listen/sda_mds1.lis") and not fmt_pattern.search("Axes/Axis_X.xti")
    # every list of the repository's fixtures, of every kind, and every name the code knows a list by
    lists = [p.relative_to(FIXTURES).as_posix() for p in FIXTURES.rglob("*") if p.suffix.lower() == ".lis"]
    assert len(lists) > 100 and "kinds/werkz_d1.lis" in lists
    for name in [*lists, *list_names()]:
        assert lint_pattern.search(name) and fmt_pattern.search(name), name


def test_a_list_passed_alone_is_checked_against_its_neighbours(tmp_path):
    folder = machine(tmp_path / "m")
    alone = run_in(folder, "lint", "achsmds8.lis", "--format", "json")
    assert alone.returncode == 1 and lis501(alone) == ["achsmds8.lis"]
    other = run_in(folder, "lint", "achsmds3.lis", "--format", "json")
    assert (
        other.returncode == 0 and json.loads(other.stdout)["diagnostics"] == []
    )  # only passed files reported
    first = run_in(folder, "lint", "achsmds1.lis", "--format", "json")
    assert lis501(first) == ["achsmds1.lis"]  # reported on the passed list, with the neighbour related
    assert json.loads(first.stdout)["diagnostics"][0]["related"][0]["path"].endswith("achsmds8.lis")


def test_default_lists_are_not_axes_of_the_machine(tmp_path):
    folder = machine(tmp_path / "m")
    (folder / "achsmds8.lis").unlink()
    (folder / "default_mds.lis").write_text(axis(1))
    result = run_in(folder, "lint", "default_mds.lis", "achsmds1.lis", "--format", "json")
    assert lis501(result) == []


def test_a_default_list_passed_alone_is_not_judged_as_an_axis(tmp_path):
    """What pre-commit passes when only default_mds.lis changed: values for every axis, no axis itself."""
    folder = tmp_path / "listen"
    shutil.copytree(FIXTURES / "machines" / "sdk" / "listen", folder)
    alone = run_in(folder, "lint", "default_mds.lis", "--format", "json")
    assert alone.returncode == 0 and json.loads(alone.stdout)["diagnostics"] == []
    # The same lines as an axis list of their own: homing rules judge the (incomplete) axis.
    (folder / "achsmds9.lis").write_bytes((folder / "default_mds.lis").read_bytes())
    as_axis = run_in(folder, "lint", "achsmds9.lis", "--format", "json")
    assert {d["code"] for d in json.loads(as_axis.stdout)["diagnostics"]} & {"LIS303", "LIS401"}
    # What concerns the lines themselves is still checked in a default list.
    default = folder / "default_mds.lis"
    default.write_text(default.read_text().replace("getriebe[0].vb_reflow", "getriebe[0].vb_reflwo"))
    broken = run_in(folder, "lint", "default_mds.lis", "--format", "json")
    assert [d["code"] for d in json.loads(broken.stdout)["diagnostics"]] == ["LIS101"]


def _pre_commit() -> list[str]:
    try:
        import pre_commit  # noqa: F401
    except ImportError:
        pytest.skip("pre-commit is not installed (pip install -e '.[test]' brings it from the package index)")
    if shutil.which("git") is None:
        pytest.skip("git is not installed; pre-commit needs it")
    return [sys.executable, "-m", "pre_commit"]


def _git(cwd: Path, *args: str) -> None:
    subprocess.run(["git", *args], cwd=cwd, check=True, capture_output=True)


@pytest.fixture(scope="module")
def hook_repo(tmp_path_factory) -> Path:
    """This checkout as it is now (committed or not), as a git repository pre-commit can install from."""
    listed = subprocess.run(
        ["git", "ls-files", "-co", "--exclude-standard"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=False,
    )
    if listed.returncode != 0:
        pytest.skip("the tests do not run from a git checkout of achslint")
    repo = tmp_path_factory.mktemp("hook-repo")
    for name in listed.stdout.splitlines():
        source = ROOT / name
        if source.is_file():
            (repo / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, repo / name)
    _git(repo, "init", "-q")
    _git(repo, "add", "-A")
    _git(repo, "-c", "user.name=t", "-c", "user.email=t@example.invalid", "commit", "-qm", "snapshot")
    return repo


@pytest.mark.slow  # builds the hook's environment with pip (~20 s): run by `.ci/run` as `pytest -m slow`
def test_pre_commit_try_repo_reports_the_repeated_axis_number(tmp_path, hook_repo):
    """The case from the issue: 8 lists, one reusing axis 1. The hook fails as a direct run does, with all
    files and with only the changed list passed."""
    command = _pre_commit()
    project = tmp_path / "project"
    machine(project / "listen")
    _git(project, "init", "-q")
    _git(project, "add", "-A")
    env = {**os.environ, "PRE_COMMIT_HOME": str(hook_repo.parent / "pre-commit-home"), "NO_COLOR": "1"}
    env.pop("PYTHONPATH", None)

    def hook(*args: str) -> subprocess.CompletedProcess:
        return subprocess.run(
            [*command, "try-repo", str(hook_repo), "achslint", *args],
            cwd=project,
            env=env,
            capture_output=True,
            text=True,
            timeout=600,
            check=False,
        )

    every = hook("--all-files")
    if every.returncode == 3:  # pre-commit's "unexpected error": here, pip could not reach the package index
        pytest.skip(f"pre-commit could not install the hook environment: {every.stdout[-300:]}")
    assert every.returncode == 1, every.stdout
    assert "listen/achsmds8.lis" in every.stdout and "LIS501" in every.stdout
    changed = hook("--files", "listen/achsmds8.lis")
    assert changed.returncode == 1 and "LIS501" in changed.stdout
    unrelated = hook("--files", "listen/achsmds3.lis")
    assert unrelated.returncode == 0, unrelated.stdout
