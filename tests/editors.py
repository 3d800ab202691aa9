"""What the real-editor tests share: the README's snippets, the lists they open, installing the editor."""

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

BIN = Path(sys.executable).parent  # `achslint` (the snippets start `achslint server`) is installed here


def snippet(language: str) -> str:
    """The README's configuration for an editor: the `language` code block of its editor section."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text[text.index("### In the editor") :]
    section = section[: section.index("\n## ")]
    found = re.findall(rf"```{language}\n(.*?)```", section, re.DOTALL)
    assert len(found) == 1, f"one {language} snippet in the README's editor section, found {len(found)}"
    return found[0]


def environment(home: Path) -> dict[str, str]:
    """An editor's environment: a home of its own (no user configuration), `achslint` on the PATH."""
    env = {key: value for key, value in os.environ.items() if not key.startswith(("XDG_", "NVIM", "VIM"))}
    env.update(
        HOME=str(home),
        XDG_CONFIG_HOME=str(home / "config"),
        XDG_DATA_HOME=str(home / "data"),
        XDG_STATE_HOME=str(home / "state"),
        XDG_CACHE_HOME=str(home / "cache"),
        PATH=f"{BIN}{os.pathsep}{env.get('PATH', '')}",
    )
    return env


def machine(folder: Path) -> dict[str, Path]:
    """A machine folder to edit: an axis list with a misspelt symbol (LIS203, a quick fix), a reference to
    jump from, and a TwinCAT export of three axes two of which share an axis number (LIS501)."""
    folder.mkdir(parents=True, exist_ok=True)
    text = (FIXTURES / "lists" / "achsmds1.lis").read_bytes().decode("latin-1")
    assert "CNC_CONTROLLED        (" in text
    text = text.replace("CNC_CONTROLLED        (", "CNC_CONROLLED         (")
    axis = folder / "achsmds1.lis"
    axis.write_bytes(text.encode("latin-1"))
    export = folder / "export"
    shutil.copytree(FIXTURES / "machines" / "xml_export", export)
    return {"axis": axis, "xml": export / "Axis_Z.xti"}


def lint_codes(path: Path) -> set[str]:
    """The codes `achslint lint PATH` reports for the list (its machine's findings included)."""
    run = subprocess.run(
        [sys.executable, "-m", "achslint", "lint", str(path), "--output-format", "json"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    return {d["code"] for d in json.loads(run.stdout)["diagnostics"]}


def installed(program: str, install: list[list[str]], reason: str) -> str:
    """The path of `program`, installed by the first command of `install` that works; the test is skipped
    with `reason` (printed) when none does."""
    found = shutil.which(program, path=f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}")
    for command in install:
        if found is not None:
            break
        try:
            subprocess.run(command, check=True, capture_output=True, timeout=600)
        except (OSError, subprocess.SubprocessError):
            continue
        found = shutil.which(program, path=f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}")
    if found is None:
        print(f"SKIPPED: {reason}")
        pytest.skip(reason)
    return found
