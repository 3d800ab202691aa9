"""The version is written in one place (core/version.py): the build reads it from there, `achslint
--version` prints it, and CHANGELOG.md's newest release is it."""

from __future__ import annotations

import re
import sys
from importlib import metadata

import pytest

from achslint import __version__

from .conftest import ROOT, run_real_cli, source_tree

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

VERSION_FILE = ROOT / "src" / "achslint" / "core" / "version.py"


def test_the_version_is_written_once():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    assert "version" not in project["project"] and "version" in project["project"]["dynamic"]
    assert project["tool"]["hatch"]["version"]["path"] == VERSION_FILE.relative_to(ROOT).as_posix()
    assert re.fullmatch(r"\d+\.\d+\.\d+(?:(?:a|b|rc)\d+)?", __version__)
    # no other module of the package writes a version of its own
    for module in (ROOT / "src" / "achslint").rglob("*.py"):
        if module != VERSION_FILE and "generated" not in module.name:
            text = module.read_text(encoding="utf-8")
            assert f'"{__version__}"' not in text and "__version__ =" not in text, module
    assert any(
        "__version__" in getattr(target, "id", "")
        for node in source_tree(VERSION_FILE).body
        for target in getattr(node, "targets", [])
    )


def test_the_installed_metadata_carries_it():
    assert metadata.version("achslint") == __version__


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_version_from_the_entry_point():
    done = run_real_cli("--version")
    assert done.returncode == 0 and done.stdout.decode() == f"achslint {__version__}\n"
    assert done.stderr == b""


def test_the_changelog_names_the_version():
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    releases = re.findall(r"^## (\d+\.\d+\.\d+\S*)\s*$", text, flags=re.MULTILINE)
    assert releases and releases[0] == __version__  # the newest release heading
    assert text.index("## Unreleased") < text.index(f"## {__version__}")
