"""The README (and docs/*.md) as tests (issue 27 item 5): every shell command and every Python example is run
on the bundled fixtures, and every sample output (a block that starts with `$ command`) is compared with
what the command prints.

How a document's code is read:
- a ```sh block: one command a line (`#` starts a comment; `cd DIR &&` and `< FILE` are understood);
- a ```python block: run as one program;
- a block whose first line is `$ command`: the command, then its output (standard output, then standard
  error). The output must match line by line; `...` in a line stands for any text, and a line that is only
  `...` for any number of lines: a sample with `...` is abridged on purpose, one without must match whole.

Each runs in a fresh folder holding the files it names of those the documents use (`achsmds1.lis`,
`machine/`, `listen/hochlauf.lis` ...), copied from the fixtures (`SANDBOX`), so a `--fix` or `fmt` changes
copies.
`achslint` commands run in this process (the entry point, as the console script calls it); an exit code
of 2 (a usage error, a missing file) fails the test, 0 and 1 are what lint, diff and dry-run say about
the example. Commands that need the network, an editor or a long run are skipped, each with its reason
(`SKIPPED`); a command the runner does not know fails, so a new README command cannot go untested.
"""

from __future__ import annotations

import re
import shlex
import shutil
from dataclasses import dataclass
from pathlib import Path

import pytest

from .conftest import FIXTURES, ROOT, run_cli

DOCUMENTS = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]

# Where each file or folder the documents name comes from (the sandbox every command runs in).
SANDBOX = {
    "fixtures/lists": FIXTURES / "lists",
    "fixtures/rules/LIS203": FIXTURES / "rules" / "LIS203",
    "docs/dry-run": ROOT / "docs" / "dry-run",
    "achsmds1.lis": FIXTURES / "lists" / "achsmds1.lis",
    "achsmds1_new.lis": FIXTURES / "lists" / "achsmds2.lis",
    "default_mds.lis": FIXTURES / "machines" / "sdk" / "listen" / "default_mds.lis",
    "sda_mds1.lis": FIXTURES / "kinds" / "sda_mds1.lis",
    "machine": FIXTURES / "machines" / "sdk",
    "backup": FIXTURES / "machines" / "sdk4",
    "listen": ROOT / "docs" / "dry-run" / "machine" / "listen",
    "rfp.nc": ROOT / "docs" / "dry-run" / "machine" / "rfp.nc",
    "machine.toml": ROOT / "docs" / "dry-run" / "machine" / "machine.toml",
    "Axis_X.xti": FIXTURES / "machines" / "twincat_export" / "Axis_X.xti",
    "project.tsproj": FIXTURES / "machines" / "twincat_export" / "Axis_Y.xti",
    "ax_mds_1.xml": FIXTURES / "lsp" / "axis.xml",
}
# The README's own single-axis scenario (the ```toml block after "A scenario") is written as scenario.toml.
SCENARIO_BLOCK = "start_position = 50.0"

# Commands not run, with the reason (matched at the start of the command).
SKIPPED = {
    "python3 -m venv": "creates a virtual environment (the tests run in one)",
    "pip install": "installs packages from the network",
    "coverage run": "the test suite itself, under coverage (minutes)",
    "coverage combine": "the coverage of the two runs above",
    "ruff check": "a check of the sources, run by .ci/run",
    "mypy": "a check of the sources, run by .ci/run",
}


@dataclass(frozen=True)
class Example:
    document: str
    line: int
    kind: str  # "command", "python" or "sample"
    text: str  # the command, or the program
    output: str = ""  # a sample's output

    @property
    def id(self) -> str:
        return f"{self.document}:{self.line}:{self.text.splitlines()[0][:60]}"


FENCE = re.compile(r"^```(\w*)[^\n]*\n(.*?)^```", re.MULTILINE | re.DOTALL)


def examples(path: Path) -> list[Example]:
    text = path.read_text(encoding="utf-8")
    name = str(path.relative_to(ROOT))
    found = []
    for block in FENCE.finditer(text):
        language, body = block.group(1), block.group(2)
        line = text.count("\n", 0, block.start(2)) + 1
        if language == "sh":
            for offset, command in enumerate(body.splitlines()):
                words = shlex.split(command, comments=True)
                if words:
                    found.append(Example(name, line + offset, "command", shlex.join(words)))
        elif language == "python":
            found.append(Example(name, line, "python", body))
        elif language == "" and body.startswith("$ "):
            command, _, output = body.partition("\n")
            found.append(Example(name, line, "sample", command[2:], output))
    return found


EXAMPLES = [example for document in DOCUMENTS for example in examples(document)]
# Drawing a plot imports matplotlib (about a second): those examples run with `pytest -m slow`.
SLOW = ("--plot",)


def parameters() -> list[object]:
    return [
        pytest.param(e, id=e.id, marks=[pytest.mark.slow] if any(w in e.text for w in SLOW) else [])
        for e in EXAMPLES
    ]


def needed(text: str) -> list[str]:
    """The files and folders of SANDBOX an example names (a path starting with the name: `machine/`, not
    `machine.toml`, nor `listen` in `machine/listen/`): only those are copied (all of them for every
    example were 2,300 copies a run). A file an example reaches without naming it would be missing, and
    its command exit 2, which fails the test."""
    return [
        name
        for name in [*SANDBOX, "scenario.toml"]
        if re.search(rf"(?<![\w./-]){re.escape(name)}(?![\w.-])", text)
    ]


def sandbox(folder: Path, names: list[str]) -> Path:
    for name in names:
        if name == "scenario.toml":
            continue
        source, target = SANDBOX[name], folder / name
        target.parent.mkdir(parents=True, exist_ok=True)
        if source.is_dir():
            shutil.copytree(source, target)
        else:
            shutil.copyfile(source, target)
    if "scenario.toml" in names:
        readme = (ROOT / "README.md").read_text(encoding="utf-8")
        scenario = next(b.group(2) for b in FENCE.finditer(readme) if b.group(2).startswith(SCENARIO_BLOCK))
        scenario = scenario.split("\n[drive]")[0]  # the [drive] table is for drive-controlled homing only
        (folder / "scenario.toml").write_text(scenario, encoding="utf-8")
    return folder


def skip_reason(command: str) -> str | None:
    return next((why for start, why in SKIPPED.items() if command.startswith(start)), None)


def run_command(command: str, folder: Path, monkeypatch: pytest.MonkeyPatch) -> tuple[int, str]:
    """An `achslint` command in this process, in `folder`: (exit code, standard output then error)."""
    words = shlex.split(command)
    if words[:1] == ["cd"]:
        assert words[2] == "&&", f"only `cd DIR && command` is understood: {command}"
        folder, words = folder / words[1], words[3:]
    stdin = None
    if "<" in words:
        at = words.index("<")
        stdin, words = (folder / words[at + 1]).read_bytes(), words[:at] + words[at + 2 :]
    assert words[0] == "achslint", f"the runner knows achslint commands; mark this one in SKIPPED: {command}"
    monkeypatch.chdir(folder)
    result = run_cli(*words[1:], stdin=stdin, env={"COLUMNS": "100"})
    return result.returncode, result.stdout.decode() + result.stderr.decode()


def matches(expected: str, actual: str) -> bool:
    """Whether `actual` has the lines of `expected`, where `...` stands for any text in a line and a line of
    its own `...` for any number of lines."""
    pattern = []
    for line in expected.rstrip("\n").splitlines():
        if line.strip() in ("...", "…"):
            pattern.append(r"(?:[^\n]*\n)*?")
        else:
            pattern.append(".*?".join(re.escape(part) for part in line.rstrip().split("...")) + r"[ \t]*\n")
    shown = "".join(line.rstrip() + "\n" for line in actual.rstrip("\n").splitlines())  # as a page shows it
    return re.fullmatch("".join(pattern), shown) is not None


@pytest.mark.parametrize("example", parameters())
def test_readme_example(example: Example, tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    why = (
        skip_reason(example.text.removeprefix("cd docs/dry-run/machine && "))
        if example.kind != "python"
        else None
    )
    if why is not None:
        pytest.skip(why)
    folder = sandbox(tmp_path, needed(example.text))
    if example.kind == "python":
        monkeypatch.chdir(folder)
        exec(compile(example.text, example.id, "exec"), {"__name__": "readme"})
        return
    code, output = run_command(example.text, folder, monkeypatch)
    assert code in (0, 1), f"exit {code}: {output}"
    if example.kind == "sample":
        assert matches(example.output, output), (
            f"the README shows:\n{example.output}\nthe command prints:\n{output}"
        )


def test_every_document_has_examples_and_the_runner_knows_them():
    kinds = {(e.document, e.kind) for e in EXAMPLES}
    assert {("README.md", "command"), ("README.md", "python"), ("README.md", "sample")} <= kinds
    assert len([e for e in EXAMPLES if e.kind == "command"]) > 40
    used = {
        start
        for start in SKIPPED
        if any(e.text.removeprefix("cd docs/dry-run/machine && ").startswith(start) for e in EXAMPLES)
    }
    assert used == set(SKIPPED), "a skip reason for a command the documents no longer show"


def test_the_sample_matcher_can_fail():
    assert matches("a\n...\nd\n", "a\nb\nc\nd\n") and matches("x ... z\n", "x y z\n")
    assert not matches("a\nd\n", "a\nb\nd\n")  # without `...` the whole output is compared
    assert not matches("a ... z\n", "a y q\n") and not matches("a\n", "a\nb\n")


def test_an_example_gets_the_files_it_names():
    assert needed("achslint lint machine/listen/hochlauf.lis --fix") == ["machine"]
    assert needed("achslint dry-run listen/hochlauf.lis --program rfp.nc --scenario machine.toml") == [
        "listen",
        "rfp.nc",
        "machine.toml",
    ]
    assert needed("achslint diff achsmds1.lis achsmds1_new.lis") == ["achsmds1.lis", "achsmds1_new.lis"]
    assert needed("achslint dry-run achsmds1.lis --scenario scenario.toml") == [
        "achsmds1.lis",
        "scenario.toml",
    ]
    assert needed("achslint rules") == []


def test_the_sdist_holds_what_the_tests_read():
    """The source distribution's tests pass only if it holds every file they read: each top-level name
    the tests open below the project root is in the sdist's `include` (pyproject.toml)."""
    from achslint.core.tomlfile import read_toml

    hatch = read_toml(ROOT / "pyproject.toml", "pyproject", ValueError)["tool"]["hatch"]
    include = hatch["build"]["targets"]["sdist"]["include"]
    read = set()
    for test in (ROOT / "tests").glob("*.py"):
        read |= set(re.findall(r'(?:ROOT|parents\[1\]) / "([^"/]+)', test.read_text(encoding="utf-8")))
    assert {"README.md", "docs", "fixtures", ".pre-commit-hooks.yaml"} <= read
    top = {entry.split("/")[0] for entry in include}
    assert read - top == set()
    assert all((ROOT / entry).exists() for entry in include)


def test_help_shows_the_extras_the_readme_names(cli):
    """rich reads `[lsp]` as markup and dropped it: `pip install 'achslint'` in the help was no advice."""
    for args in (["--help"], ["server", "--help"]):
        shown = " ".join(cli(*args, env={"COLUMNS": "200"}).stdout.decode().split())
        assert "pip install '.[lsp]'" in shown, args
