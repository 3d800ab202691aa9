"""The VS Code extension (editors/vscode, issue 28 item 5) agrees with the code and the README it fronts: its
`debounceMs` default and bounds are the language server's, `achslint.xml` hands over every XML suffix the
code reads lists from, it starts in a workspace of TwinCAT exports and XML lists named as the README names
them, the .vsix holds one bundled script and nothing from node_modules, and its Node tests read copies of
the repository's example lists that are the same bytes (so `npm test` needs nothing outside the folder).

The Node tests in editors/vscode/test (run by .ci/run) load the bundle itself and list the .vsix."""

from __future__ import annotations

import fnmatch
import json
import re
from pathlib import Path
from typing import Any

from achslint.core.files import XML_SUFFIXES
from achslint.lsp.session import ClientSettings

from .conftest import FIXTURES, ROOT

VSCODE = ROOT / "editors" / "vscode"
EXAMPLES = VSCODE / "test" / "fixtures" / "examples"
README = ROOT / "README.md"


def package() -> dict[str, Any]:
    loaded: dict[str, Any] = json.loads((VSCODE / "package.json").read_text(encoding="utf-8"))
    return loaded


def setting(key: str) -> dict[str, Any]:
    found: dict[str, Any] = package()["contributes"]["configuration"]["properties"][f"achslint.{key}"]
    return found


def test_debounce_default_and_bounds_are_the_servers() -> None:
    debounce = setting("debounceMs")
    assert (
        debounce["default"] == ClientSettings().debounce_ms == ClientSettings.from_dict({}).debounce_ms == 0
    )
    low, high = debounce["minimum"], debounce["maximum"]
    assert ClientSettings.from_dict({"debounceMs": low}).debounce_ms == low
    assert ClientSettings.from_dict({"debounceMs": high}).debounce_ms == high
    for outside in (low - 1, high + 1):  # the server falls back to its default, as the setting's bounds say
        assert ClientSettings.from_dict({"debounceMs": outside}).debounce_ms == debounce["default"]
    assert f"{debounce['default']}, the default" in debounce["description"]


def test_the_xml_setting_covers_every_suffix_the_code_reads_lists_from() -> None:
    source = (VSCODE / "src" / "extension.js").read_text(encoding="utf-8")
    written = re.search(r"const XML_SUFFIXES = \[([^\]]*)\];", source)
    assert written is not None
    suffixes = {f".{name}" for name in re.findall(r'"(\w+)"', written.group(1))}
    assert suffixes == set(XML_SUFFIXES)
    xml = setting("xml")
    assert xml["default"] is True
    assert [s for s in XML_SUFFIXES if f"`*{s}`" not in xml["markdownDescription"]] == []


def _readme_exports() -> list[str]:
    """The TwinCAT exports and XML lists the README's "Whole machines, XML" section names."""
    text = README.read_text(encoding="utf-8")
    start = text.index("### Whole machines, XML")
    section = text[start : text.index("\n### ", start + 1)]
    return sorted(set(re.findall(r"\b[\w-]+\.(?:xml|xti|tsproj)\b", section)))


def test_a_workspace_of_twincat_exports_or_xml_lists_starts_the_extension() -> None:
    events = package()["activationEvents"]
    globs = [e.removeprefix("workspaceContains:**/") for e in events if e.startswith("workspaceContains:**/")]
    assert {"*.xti", "*.tsproj", "*.lis"} <= set(globs)
    exports = _readme_exports()
    assert {"Axis_X.xti", "project.tsproj", "ax_mds_1.xml", "achsmds1-Update.xml"} <= set(exports)
    exports += [p.name for p in FIXTURES.glob("machines/*/**/*") if p.suffix.lower() in XML_SUFFIXES]
    assert [n for n in exports if not any(fnmatch.fnmatchcase(n, g) for g in globs)] == []
    # any other XML does not start it (a workspace with a pom.xml or a .csproj is no CNC machine)
    assert not any(fnmatch.fnmatchcase(name, g) for g in globs for name in ("pom.xml", "web.xml"))


def _packaged(folder: Path) -> list[str]:
    """The files `.vscodeignore` lets into the .vsix: it ignores everything (`**`) and lets in the `!`
    lines, each one file."""
    lines = [
        line.strip()
        for line in (folder / ".vscodeignore").read_text(encoding="utf-8").splitlines()
        if line.strip() and not line.startswith("#")
    ]
    assert lines[0] == "**", lines
    assert all(line.startswith("!") and "*" not in line for line in lines[1:]), lines
    return [line[1:] for line in lines[1:]]


def test_the_vsix_holds_the_bundle_and_nothing_from_node_modules() -> None:
    manifest = package()
    files = _packaged(VSCODE)
    main = manifest["main"].removeprefix("./")
    assert [f for f in files if f.endswith(".js")] == [main] and main.startswith("dist/")
    assert [f for f in files if "node_modules" in f.split("/")] == []
    assert "--outfile=" + main in manifest["scripts"]["build"] and "--bundle" in manifest["scripts"]["build"]
    assert manifest["scripts"]["vscode:prepublish"] == "npm run build"
    assert manifest.get("dependencies", {}) == {}  # the language client is inside the bundle
    assert all((VSCODE / f).is_file() for f in files if f != main), files
    assert manifest["license"] == "MIT" and "LICENSE" in files


def _wanted_examples() -> set[Path]:
    folders = ("lists", "kinds", "machines/sdk4/listen")
    wanted = {p.relative_to(FIXTURES) for folder in folders for p in (FIXTURES / folder).glob("*.lis")}
    return wanted | {Path("vendor/isg_sdk_hochlauf.lis")}


def test_the_extensions_example_lists_are_the_repositorys() -> None:
    copies = {p.relative_to(EXAMPLES) for p in EXAMPLES.rglob("*") if p.is_file()}
    wanted = _wanted_examples()
    assert len(wanted) >= 20
    how = "copy fixtures/<path> to editors/vscode/test/fixtures/examples/<path>"
    assert sorted(map(str, wanted - copies)) == [], how
    assert sorted(map(str, copies - wanted)) == [], "no longer in fixtures/: remove the copy"
    assert (
        sorted(str(p) for p in wanted if (EXAMPLES / p).read_bytes() != (FIXTURES / p).read_bytes()) == []
    ), how


def test_the_node_tests_read_nothing_outside_the_extension_folder() -> None:
    for test in (VSCODE / "test").glob("*.js"):
        source = test.read_text(encoding="utf-8")
        assert not re.search(r'"\.\.",\s*"\.\."', source), test.name
        assert "../.." not in source, test.name
