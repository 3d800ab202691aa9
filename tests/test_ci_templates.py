"""The CI wiring shipped in the repository runs for real: the GitHub Action (action.yml) step by step as the
runner runs a composite action, on a fixture machine.

The runner is imitated closely enough for these steps: `${{ ... }}` expressions in `env:`, `with:` and `if:`
are evaluated (inputs with their defaults, `github.action_path`, the outputs of earlier steps, `always()`),
each `run:` goes to `bash --noprofile --norc -eo pipefail` in the workspace with GITHUB_OUTPUT / GITHUB_PATH
files of its own, a failed step skips the later ones unless their condition says `always()`, and `uses:`
steps are recorded (with their evaluated `with:`) instead of run. The install step needs a fresh virtual
environment and pip, so the default tests run the steps after it with this checkout's achslint on PATH, and
one `slow` test runs them all.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from .conftest import FIXTURES, ROOT

yaml = pytest.importorskip("yaml")

ACTION = ROOT / "action.yml"


def workspace(tmp_path: Path, broken: bool = False) -> Path:
    """A repository with the SDK machine (three axes and a start-up list; infos only). `broken` puts an
    error into the spindle's list: a homing type that does not exist (LIS203, P-AXIS-00299)."""
    root = tmp_path / "repo"
    shutil.copytree(FIXTURES / "machines" / "sdk", root)
    if broken:
        spindle = root / "listen" / "achsmds3.lis"
        data = spindle.read_bytes()
        assert b"DRIVE_CONTROLLED" in data
        spindle.write_bytes(data.replace(b"DRIVE_CONTROLLED", b"DRIVE_CONROLLED"))
    return root


# --- a small imitation of the runner's expression language ---------------------------------------------

EXPRESSION = re.compile(r"\$\{\{\s*(.*?)\s*\}\}")
TOKEN = re.compile(
    r"\s*(?:(?P<call>always\(\)|success\(\)|failure\(\))|(?P<string>'[^']*')|(?P<op>==|!=|&&|\|\||!|\(|\))"
    r"|(?P<name>[A-Za-z_][\w.-]*))"
)


@dataclass
class Context:
    inputs: dict[str, str]
    action_path: Path
    steps: dict[str, dict[str, str]] = field(default_factory=dict)
    failed: bool = False

    def value(self, name: str) -> str:
        parts = name.split(".")
        if parts[0] == "inputs" and len(parts) == 2:
            return self.inputs[parts[1]]  # KeyError: an input the action does not declare
        if parts == ["github", "action_path"]:
            return str(self.action_path)
        if parts[0] == "steps" and len(parts) == 4 and parts[2] == "outputs":
            return self.steps.get(parts[1], {}).get(parts[3], "")
        raise AssertionError(f"the test runner does not know `{name}`")

    def evaluate(self, expression: str) -> str | bool:
        """`a == 'x' && !b || always()` and the like: the part of the expression language the action uses."""
        python: list[str] = []
        position = 0
        while position < len(expression.rstrip()):
            match = TOKEN.match(expression, position)
            assert match, f"the test runner cannot read {expression[position:]!r}"
            position = match.end()
            if match["call"]:
                python.append(
                    {"always()": "True", "success()": str(not self.failed), "failure()": str(self.failed)}[
                        match["call"]
                    ]
                )
            elif match["string"]:
                python.append(repr(match["string"][1:-1]))
            elif match["op"]:
                python.append({"&&": " and ", "||": " or ", "!": " not "}.get(match["op"], match["op"]))
            else:
                python.append(repr(self.value(match["name"])))
        return eval("".join(python), {"__builtins__": {}})  # built from the tokens above only

    def substitute(self, text: str) -> str:
        return EXPRESSION.sub(lambda m: str(self.evaluate(m[1])), str(text))

    def runs(self, step: dict) -> bool:
        condition = str(step.get("if", "success()"))
        condition = EXPRESSION.fullmatch(condition)[1] if EXPRESSION.fullmatch(condition) else condition
        if not re.search(r"always\(\)|failure\(\)|success\(\)", condition):
            condition = f"success() && ({condition})"  # what the runner adds to a condition without one
        return bool(self.evaluate(condition))


@dataclass
class ActionRun:
    returncode: int
    stdout: str
    stderr: str
    outputs: dict[str, str]
    used: list[tuple[str, dict[str, str]]]  # the `uses:` steps that ran, with their `with:`
    ran: list[str]  # the names of the `run:` steps that ran


def run_action(
    repo: Path, tmp_path: Path, inputs: dict[str, str] | None = None, *, install: bool = False
) -> ActionRun:
    """Run action.yml's steps as the runner would, in `repo` (the workspace). Without `install` the install
    step is left out and this checkout's achslint stands in for what it installs."""
    action = yaml.safe_load(ACTION.read_text(encoding="utf-8"))
    assert action["runs"]["using"] == "composite"
    declared = action["inputs"]
    unknown = set(inputs or {}) - set(declared)
    assert not unknown, f"action.yml has no input {unknown}"
    values = {name: str(spec.get("default", "")) for name, spec in declared.items()}
    values.update(inputs or {})
    context = Context(values, ROOT)
    temp = tmp_path / "runner-temp"
    temp.mkdir(exist_ok=True)
    path = os.environ["PATH"]
    if not install:
        path = f"{Path(sys.executable).parent}{os.pathsep}{path}"
    else:  # the achslint of this test environment must not answer for the installed one
        path = os.pathsep.join(p for p in path.split(os.pathsep) if Path(p) != Path(sys.executable).parent)
    stdout, stderr, used, ran = [], [], [], []
    for number, step in enumerate(action["runs"]["steps"]):
        if not context.runs(step):
            continue
        if "uses" in step:
            used.append((step["uses"], {k: context.substitute(v) for k, v in step.get("with", {}).items()}))
            continue
        if step.get("id") == "install" and not install:
            continue
        assert step.get("shell") == "bash", "a composite run step names its shell"
        output_file, path_file = temp / f"output-{number}", temp / f"path-{number}"
        output_file.touch()
        path_file.touch()
        env = {
            **os.environ,
            "PATH": path,
            "NO_COLOR": "1",
            "GITHUB_ACTIONS": "true",
            "GITHUB_WORKSPACE": str(repo),
            "GITHUB_ACTION_PATH": str(ROOT),
            "GITHUB_OUTPUT": str(output_file),
            "GITHUB_PATH": str(path_file),
            "RUNNER_TEMP": str(temp),
            **{k: context.substitute(v) for k, v in step.get("env", {}).items()},
        }
        env.pop("PYTHONPATH", None)
        script = temp / f"step-{number}.sh"
        script.write_text(step["run"], encoding="utf-8")
        done = subprocess.run(
            ["bash", "--noprofile", "--norc", "-eo", "pipefail", str(script)],
            cwd=repo,
            env=env,
            capture_output=True,
            text=True,
            timeout=600,
        )
        ran.append(step["name"])
        stdout.append(done.stdout)
        stderr.append(done.stderr)
        if "id" in step:
            context.steps[step["id"]] = dict(
                line.split("=", 1) for line in output_file.read_text().splitlines() if "=" in line
            )
        for added in path_file.read_text().splitlines():
            path = f"{added}{os.pathsep}{path}"
        if done.returncode != 0:
            context.failed = True
    outputs = {name: context.substitute(spec["value"]) for name, spec in action.get("outputs", {}).items()}
    return ActionRun(int(context.failed), "".join(stdout), "".join(stderr), outputs, used, ran)


# --- the action -----------------------------------------------------------------------------------------


def test_the_action_is_a_composite_action_that_installs_its_own_checkout():
    action = yaml.safe_load(ACTION.read_text(encoding="utf-8"))
    install = next(step for step in action["runs"]["steps"] if step.get("id") == "install")
    assert install["env"]["ACHSLINT_ACTION_PATH"] == "${{ github.action_path }}"
    assert {"paths", "args", "version", "sarif", "annotations"} <= set(action["inputs"])
    assert action["inputs"]["annotations"]["default"] == "true"
    assert action["inputs"]["sarif"]["default"] == "false"
    uploads = [step for step in action["runs"]["steps"] if "upload-sarif" in step.get("uses", "")]
    assert len(uploads) == 1 and uploads[0]["uses"].startswith("github/codeql-action/upload-sarif@v")


def test_annotations_by_default_and_the_step_fails_on_an_error(tmp_path):
    repo = workspace(tmp_path, broken=True)
    run = run_action(repo, tmp_path)
    assert run.returncode == 1, run.stderr
    errors = [line for line in run.stdout.splitlines() if line.startswith("::error ")]
    assert len(errors) == 1 and "file=listen/achsmds3.lis" in errors[0] and "LIS203" in errors[0]
    assert any(line.startswith("::notice ") for line in run.stdout.splitlines())  # the infos too
    assert run.used == [] and run.outputs["sarif-file"] == ""  # nothing uploaded without `sarif`


def test_a_clean_machine_passes_with_plain_output(tmp_path):
    repo = workspace(tmp_path)
    run = run_action(
        repo,
        tmp_path,
        {
            "paths": "listen/achsmds1.lis\nlisten/achsmds3.lis",
            "annotations": "false",
            "args": "--select LIS102",
            "python-version": "3.12",
        },
    )
    assert run.returncode == 0, run.stderr
    assert run.used == [("actions/setup-python@v5", {"python-version": "3.12"})]
    assert "::" not in run.stdout
    assert run.stdout.splitlines()[0].startswith("listen/achsmds3.lis:8:1: LIS102 [info]")
    assert run.stdout.count("LIS102") == 1


def test_args_decide_the_result(tmp_path):
    repo = workspace(tmp_path)  # infos only: passes by default, fails with --fail-on info
    assert run_action(repo, tmp_path).returncode == 0
    strict = run_action(repo, tmp_path, {"args": "--fail-on info"})
    assert strict.returncode == 1 and "::notice " in strict.stdout


def test_sarif_is_written_and_uploaded_even_when_the_lint_fails(tmp_path):
    repo = workspace(tmp_path, broken=True)
    run = run_action(repo, tmp_path, {"sarif": "true", "sarif-file": "reports/achslint.sarif"})
    assert run.returncode == 1
    assert run.outputs["sarif-file"] == "reports/achslint.sarif"
    document = json.loads((repo / "reports" / "achslint.sarif").read_text(encoding="utf-8"))
    results = document["runs"][0]["results"]
    assert [r["ruleId"] for r in results if r["level"] == "error"] == ["LIS203"]
    location = results[0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
    assert location.startswith("listen/")  # relative to the checkout, as code scanning needs
    (uses, given), *rest = run.used
    assert rest == [] and "upload-sarif" in uses
    assert given == {"sarif_file": "reports/achslint.sarif", "category": "achslint"}


def test_a_usage_error_fails_the_step_before_any_upload(tmp_path):
    repo = workspace(tmp_path)
    run = run_action(repo, tmp_path, {"paths": "no-such-folder", "sarif": "true"})
    assert run.returncode == 1 and "no-such-folder" in run.stderr
    assert run.used == []  # no report was written, so there is nothing to upload


@pytest.mark.slow  # a fresh virtual environment and pip install of this checkout (~30 s, the build backend)
def test_the_whole_action_installs_achslint_from_its_checkout(tmp_path):
    from achslint import __version__

    repo = workspace(tmp_path, broken=True)
    run = run_action(repo, tmp_path, {"sarif": "true"}, install=True)
    assert run.ran == ["Install achslint", "Lint"], run.stderr
    assert run.outputs["version"] == __version__
    assert run.returncode == 1 and "LIS203" in run.stdout
    assert (repo / "achslint.sarif").is_file()
    assert (tmp_path / "runner-temp" / "achslint-venv").is_dir()
