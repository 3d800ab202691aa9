"""The editors open every list achslint recognises (issue 25 item 6): the VS Code extension's language and
the README's Neovim, Emacs and Helix snippets associate each file name the code itself knows a list by
(the default include pattern, the start-up list and default list names) and the names start-up lists give
the lists of every other kind (a start-up list may call its tool data or channel list anything: the kind
then comes from its entry or content, so every `.lis` is a list, as the pre-commit hooks take it)."""

from __future__ import annotations

import fnmatch
import json
import re
from pathlib import Path

from achslint.linting.config import Settings
from achslint.machine.startup import STARTUP_NAMES, is_default_list, read_startup

from .conftest import FIXTURES, ROOT

PACKAGE = ROOT / "editors" / "vscode" / "package.json"
README = ROOT / "README.md"


def _example(pattern: str) -> str:
    return pattern.replace("*", "1")


def names() -> list[str]:
    """File names of lists as the code and the repository's start-up lists know them."""
    found = [_example(p) for p in (*Settings().include, *STARTUP_NAMES)]
    found += ["default_mds.lis", "default_sda_mds.lis", "ACHSMDS2.LIS"]
    assert all(is_default_list(Path(n)) for n in ("default_mds.lis", "default1mds1.lis"))
    for startup in (
        FIXTURES / "kinds" / "hochlauf.lis",
        FIXTURES / "machines" / "sdk4" / "listen" / "hochlauf.lis",
    ):
        read = read_startup(startup)
        entries = [*read.axes, *read.channels, *read.compensations, *read.others]
        entries += [e for e in (read.default, read.default_channel) if e is not None]
        found += [Path(entry.raw.strip().strip('"').replace("\\", "/")).name for entry in entries]
    assert {"werkz_d1.lis", "nullp_d1.lis", "sda_mds1.lis", "rtconf.lis"} <= set(found)
    return sorted(set(found))


def test_the_names_cover_every_kind_a_start_up_list_names() -> None:
    assert len(names()) >= 12


def test_vs_code_opens_every_list_as_the_achsmds_language() -> None:
    package = json.loads(PACKAGE.read_text(encoding="utf-8"))
    language = next(lang for lang in package["contributes"]["languages"] if lang["id"] == "achsmds")
    extensions, patterns = language.get("extensions", []), language.get("filenamePatterns", [])

    def opened(name: str) -> bool:
        return any(name.endswith(e) for e in extensions) or any(
            fnmatch.fnmatchcase(name, p) for p in patterns
        )

    missing = [name for name in names() if not opened(name)]
    assert missing == []
    assert not opened("README.md") and not opened("Axis_X.xti")
    activation = package["activationEvents"]
    assert "workspaceContains:**/*.lis" in activation and "onLanguage:achsmds" in activation


def _block(language: str, after: str) -> str:
    text = README.read_text(encoding="utf-8")
    start = text.index(after)
    match = re.compile(rf"```{language}\n(.*?)```", re.S).search(text, start)
    assert match is not None, (language, after)
    return match.group(1)


def test_neovim_snippet_associates_every_list() -> None:
    lua = _block("lua", "Neovim (")
    table = re.search(r"vim\.filetype\.add\(\{ extension = \{([^}]*)\}", lua)
    assert table is not None, lua
    extensions = set(re.findall(r'(\w+) = "achsmds"', table.group(1)))
    missing = [name for name in names() if name.rsplit(".", 1)[-1] not in extensions]
    assert missing == []


def test_emacs_snippet_associates_every_list() -> None:
    elisp = _block("elisp", "Emacs (")
    written = re.search(r"auto-mode-alist '\(\"(.*?)\" \. achsmds-mode\)", elisp)
    assert written is not None, elisp
    # the string as the Lisp reader reads it, then Emacs regex syntax as Python's (\' is the end of the text)
    regex = written.group(1).replace("\\\\", "\\")
    for emacs, python in (("\\'", r"\Z"), ("\\(", "("), ("\\)", ")"), ("\\|", "|")):
        regex = regex.replace(emacs, python)
    pattern = re.compile(regex, re.IGNORECASE)  # auto-mode-case-fold is on by default
    assert [name for name in names() if not pattern.search(name)] == []
    assert not pattern.search("notes.list")


def test_helix_snippet_associates_every_list() -> None:
    try:
        import tomllib
    except ModuleNotFoundError:  # Python 3.10
        import tomli as tomllib

    languages = tomllib.loads(_block("toml", "Helix ("))
    types = languages["language"][0]["file-types"]
    extensions = {t for t in types if isinstance(t, str)}
    globs = [t["glob"] for t in types if isinstance(t, dict)]

    def opened(name: str) -> bool:
        return name.rsplit(".", 1)[-1] in extensions or any(fnmatch.fnmatchcase(name, g) for g in globs)

    assert [name for name in names() if not opened(name)] == []
