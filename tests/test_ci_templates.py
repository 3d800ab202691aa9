"""The CI wiring shipped in the repository runs for real, on a fixture machine: the GitHub Action
(action.yml) step by step as the runner runs a composite action, and the GitLab CI template (ci/gitlab.yml)
as a GitLab runner runs its job.

The runner is imitated closely enough for these steps: `${{ ... }}` expressions in `env:`, `with:` and `if:`
are evaluated (inputs with their defaults, `github.action_path`, the outputs of earlier steps, `always()`),
each `run:` goes to `bash --noprofile --norc -eo pipefail` in the workspace with GITHUB_OUTPUT / GITHUB_PATH
files of its own, a failed step skips the later ones unless their condition says `always()`, and `uses:`
steps are recorded (with their evaluated `with:`) instead of run. The install step needs a fresh virtual
environment and pip, so the default tests run the steps after it with this checkout's achslint on PATH, and
one `slow` test runs them all. The GitLab job's `script` runs the same way (one shell, `-eo pipefail`, in
`$CI_PROJECT_DIR`, its variables in the environment, later ones overriding the template's); its
`before_script` installs, so only the slow test runs it. Without the install, the `achslint` the steps call
is a warm one (tests/warm_cli.py: this checkout's CLI forked from a process that has loaded it, with the
caller's streams, arguments, folder and environment), not a cold process for each of the ~40 calls.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from .conftest import FIXTURES, ROOT, jenkins_junit_errors
from .warm_cli import warm_achslint

yaml = pytest.importorskip("yaml")

ACTION = ROOT / "action.yml"
GITLAB = ROOT / "ci" / "gitlab.yml"

# The folder of the warm `achslint` (tests/warm_cli.py) the steps find first on PATH unless they install.
WARM: list[Path] = []


@pytest.fixture(autouse=True, scope="module")
def _warm_achslint(tmp_path_factory):
    with warm_achslint(tmp_path_factory.mktemp("warm")) as folder:
        WARM.append(folder)
        yield
        WARM.remove(folder)


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
        path = os.pathsep.join([*map(str, WARM), str(Path(sys.executable).parent), path])
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
            "GITHUB_STEP_SUMMARY": str(temp / "step-summary.md"),
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


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_the_action_is_a_composite_action_that_installs_its_own_checkout():
    action = yaml.safe_load(ACTION.read_text(encoding="utf-8"))
    install = next(step for step in action["runs"]["steps"] if step.get("id") == "install")
    assert install["env"]["ACHSLINT_ACTION_PATH"] == "${{ github.action_path }}"
    assert {"paths", "args", "version", "sarif", "annotations"} <= set(action["inputs"])
    assert action["inputs"]["annotations"]["default"] == "true"
    assert action["inputs"]["sarif"]["default"] == "false"
    uploads = [step for step in action["runs"]["steps"] if "upload-sarif" in step.get("uses", "")]
    assert len(uploads) == 1 and uploads[0]["uses"].startswith("github/codeql-action/upload-sarif@v")


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_annotations_by_default_and_the_step_fails_on_an_error(tmp_path):
    repo = workspace(tmp_path, broken=True)
    run = run_action(repo, tmp_path)
    assert run.returncode == 1, run.stderr
    errors = [line for line in run.stdout.splitlines() if line.startswith("::error ")]
    assert len(errors) == 1 and "file=listen/achsmds3.lis" in errors[0] and "LIS203" in errors[0]
    assert any(line.startswith("::notice ") for line in run.stdout.splitlines())  # the infos too
    assert run.used == [] and run.outputs["sarif-file"] == ""  # nothing uploaded without `sarif`


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
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


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_args_decide_the_result(tmp_path):
    repo = workspace(tmp_path)  # infos only: passes by default, fails with --fail-on info
    assert run_action(repo, tmp_path).returncode == 0
    strict = run_action(repo, tmp_path, {"args": "--fail-on info"})
    assert strict.returncode == 1 and "::notice " in strict.stdout


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
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


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
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


# --- the GitLab CI template -----------------------------------------------------------------------------


@dataclass
class JobRun:
    returncode: int
    stdout: str
    stderr: str


def run_gitlab_job(
    project: Path, tmp_path: Path, variables: dict[str, str] | None = None, *, install: bool = False
) -> JobRun:
    """Run the template's `achslint` job in `project` ($CI_PROJECT_DIR) as a shell runner would: the job's
    variables (the template's, then the including project's) in the environment, `before_script` (only
    with `install`: it builds a venv) and `script` in one shell that stops at the first failing command."""
    job = yaml.safe_load(GITLAB.read_text(encoding="utf-8"))["achslint"]
    declared = job["variables"]
    unknown = set(variables or {}) - set(declared)
    assert not unknown, f"the template has no variable {unknown}"
    temp = tmp_path / "job-temp"
    temp.mkdir(exist_ok=True)
    env = {**os.environ, **{k: str(v) for k, v in declared.items()}, **(variables or {})}
    env.update({"CI": "true", "GITLAB_CI": "true", "CI_PROJECT_DIR": str(project), "TMPDIR": str(temp)})
    env["NO_COLOR"] = "1"
    env.pop("PYTHONPATH", None)
    env.pop("GITHUB_ACTIONS", None)
    ours = str(Path(sys.executable).parent)
    others = [p for p in env["PATH"].split(os.pathsep) if Path(p) != Path(ours)]
    env["PATH"] = os.pathsep.join(others if install else [*map(str, WARM), ours, *others])
    lines = [*(job["before_script"] if install else []), *job["script"]]
    script = temp / "job.sh"
    script.write_text("\n".join(lines) + "\n", encoding="utf-8")
    done = subprocess.run(
        ["bash", "--noprofile", "--norc", "-eo", "pipefail", str(script)],
        cwd=project,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
    )
    return JobRun(done.returncode, done.stdout, done.stderr)


def reports(project: Path) -> tuple[list[dict], ET.Element]:
    """The job's artifacts, read from the names the template declares."""
    declared = yaml.safe_load(GITLAB.read_text(encoding="utf-8"))["achslint"]["artifacts"]
    assert declared["when"] == "always"  # reports of a failing job are kept: that is when they matter
    quality = json.loads((project / declared["reports"]["codequality"]).read_text(encoding="utf-8"))
    junit = ET.parse(project / declared["reports"]["junit"]).getroot()
    return quality, junit


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_the_gitlab_job_fails_on_an_error_and_keeps_both_reports(tmp_path):
    project = workspace(tmp_path, broken=True)
    job = run_gitlab_job(project, tmp_path)
    assert job.returncode == 1, job.stderr
    assert "listen/achsmds3.lis:8:34: LIS203 [error]" in job.stdout and job.stderr == ""
    quality, junit = reports(project)
    majors = [issue for issue in quality if issue["severity"] == "major"]
    assert [(i["check_name"], i["location"]["path"]) for i in majors] == [("LIS203", "listen/achsmds3.lis")]
    assert junit.get("failures") == "1" and jenkins_junit_errors(junit) == []


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_an_absolute_path_gives_paths_relative_to_the_project(tmp_path):
    project = workspace(tmp_path, broken=True)
    relative = run_gitlab_job(project, tmp_path)
    first, _ = reports(project)
    absolute = run_gitlab_job(project, tmp_path, {"ACHSLINT_PATHS": f"{project}/listen"})
    assert absolute.returncode == relative.returncode == 1 and absolute.stderr == ""
    second, _ = reports(project)
    assert {issue["location"]["path"] for issue in second} == {"listen/achsmds2.lis", "listen/achsmds3.lis"}
    # the same findings under the same fingerprints, however the path was given
    assert sorted(i["fingerprint"] for i in second) == sorted(i["fingerprint"] for i in first)


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_the_gitlab_job_passes_a_clean_machine_and_takes_arguments(tmp_path):
    project = workspace(tmp_path)  # infos only
    assert run_gitlab_job(project, tmp_path).returncode == 0
    strict = run_gitlab_job(project, tmp_path, {"ACHSLINT_ARGS": "--fail-on info --select LIS102"})
    assert strict.returncode == 1
    quality, junit = reports(project)
    assert {issue["check_name"] for issue in quality} == {"LIS102"}
    assert int(junit.get("failures")) == len(quality) == 2


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_the_gitlab_job_says_what_to_install(tmp_path):
    project = workspace(tmp_path)
    job = run_gitlab_job(project, tmp_path, install=True)  # ACHSLINT_REQUIREMENT not set: stops at once
    assert job.returncode == 2 and "set ACHSLINT_REQUIREMENT" in job.stderr
    assert not (tmp_path / "job-temp" / "achslint-venv").exists()


@pytest.mark.slow  # a fresh virtual environment and pip install of this checkout
def test_the_whole_gitlab_job_installs_what_it_is_told(tmp_path):
    project = workspace(tmp_path, broken=True)
    job = run_gitlab_job(project, tmp_path, {"ACHSLINT_REQUIREMENT": str(ROOT)}, install=True)
    assert job.returncode == 1 and "LIS203" in job.stdout, job.stderr
    assert (tmp_path / "job-temp" / "achslint-venv" / "bin" / "achslint").is_file()
    quality, _ = reports(project)
    assert any(issue["check_name"] == "LIS203" for issue in quality)


def test_code_quality_paths_outside_a_gitlab_job(tmp_path, monkeypatch):
    from .conftest import run_cli

    project = workspace(tmp_path, broken=True)
    monkeypatch.chdir(project / "listen")  # no $CI_PROJECT_DIR: relative to the working directory, as ruff
    monkeypatch.delenv("CI_PROJECT_DIR", raising=False)
    here = run_cli("lint", str(project / "listen" / "achsmds3.lis"), "--format", "gitlab")
    assert {issue["location"]["path"] for issue in json.loads(here.stdout)} == {"achsmds3.lis"}
    elsewhere = project.parent / "elsewhere"  # a file outside the project keeps the path it was given
    shutil.copytree(project / "listen", elsewhere)
    outside = run_cli(
        "lint", str(elsewhere / "achsmds3.lis"), "--format", "gitlab", env={"CI_PROJECT_DIR": str(project)}
    )
    assert {issue["location"]["path"] for issue in json.loads(outside.stdout)} == {
        str(elsewhere / "achsmds3.lis")
    }


# --- the README's blocks ---------------------------------------------------------------------------------

README = ROOT / "README.md"


def readme_yaml() -> list:
    """The YAML blocks of the README's CI section."""
    text = README.read_text(encoding="utf-8")
    section = text[text.index("### In CI") : text.index("### In the editor")]
    return [yaml.safe_load(block) for block in re.findall(r"```yaml\n(.*?)```", section, flags=re.DOTALL)]


def readme_block(key: str):
    return next(block for block in readme_yaml() if key in block)


def git(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True, check=False)


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_the_readme_pins_a_revision_that_exists_and_carries_the_wiring():
    workflow = readme_block("jobs")
    action_step = next(step for step in workflow["jobs"]["achslint"]["steps"] if "achslint@" in step["uses"])
    gitlab = readme_block("include")
    precommit = next(repo for repo in readme_block("repos")["repos"] if repo["repo"] != "local")
    revisions = {
        action_step["uses"].split("@")[1],
        gitlab["include"][0]["ref"],
        gitlab["achslint"]["variables"]["ACHSLINT_REQUIREMENT"].rsplit("@", 1)[1],
        str(precommit["rev"]),
    }
    assert len(revisions) == 1, revisions  # one revision everywhere
    revision = revisions.pop()
    assert re.fullmatch(r"[0-9a-f]{40}", revision)  # a commit id: it cannot move as a branch or tag can
    if shutil.which("git") is None or git("rev-parse", "--git-dir").returncode != 0:
        pytest.skip("not a git checkout of achslint (an sdist): the revision cannot be looked up")
    history = git("rev-list", "HEAD")
    if revision not in history.stdout.split():
        if git("rev-parse", "--is-shallow-repository").stdout.strip() == "true":
            pytest.skip("a shallow clone: the pinned revision may lie beyond its history")
        raise AssertionError(f"{revision} is not in this repository's history")
    for name in ("action.yml", "ci/gitlab.yml", ".pre-commit-hooks.yaml"):
        assert git("cat-file", "-e", f"{revision}:{name}").returncode == 0, name
    hooks = yaml.safe_load(git("show", f"{revision}:.pre-commit-hooks.yaml").stdout)
    assert [hook["id"] for hook in precommit["hooks"]] == [hook["id"] for hook in hooks]
    pinned_action = yaml.safe_load(git("show", f"{revision}:action.yml").stdout)
    assert set(action_step.get("with", {})) <= set(pinned_action["inputs"])
    pinned_job = yaml.safe_load(git("show", f"{revision}:ci/gitlab.yml").stdout)["achslint"]
    assert set(gitlab["achslint"]["variables"]) <= set(pinned_job["variables"])


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_the_readme_workflow_runs(tmp_path):
    """The README's workflow, copied as it is: its action step with its inputs, on a machine with an error."""
    workflow = readme_block("jobs")
    permissions = workflow["permissions"]
    assert permissions.get("security-events") == "write"  # upload-sarif needs it
    steps = workflow["jobs"]["achslint"]["steps"]
    assert steps[0]["uses"].startswith("actions/checkout@")
    inputs = {name: str(value).lower() for name, value in steps[1].get("with", {}).items()}
    repo = workspace(tmp_path, broken=True)
    run = run_action(repo, tmp_path, inputs)
    assert run.returncode == 1 and "::error file=listen/achsmds3.lis" in run.stdout
    assert [uses for uses, _ in run.used] == ["github/codeql-action/upload-sarif@v3"]
    assert (repo / run.outputs["sarif-file"]).is_file()


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_the_readme_gitlab_job_runs(tmp_path):
    """The README's GitLab block: its variables on the template's job (all but the install)."""
    gitlab = readme_block("include")
    assert gitlab["include"][0]["file"] == GITLAB.relative_to(ROOT).as_posix()
    variables = {k: str(v) for k, v in gitlab["achslint"]["variables"].items() if k != "ACHSLINT_REQUIREMENT"}
    project = workspace(tmp_path, broken=True)
    job = run_gitlab_job(project, tmp_path, variables)
    assert job.returncode == 1 and "LIS203" in job.stdout
    quality, _ = reports(project)
    assert {"listen/achsmds3.lis"} <= {issue["location"]["path"] for issue in quality}


def test_the_readme_local_hook_is_the_published_one():
    repos = [repo for block in readme_yaml() if "repos" in block for repo in block["repos"]]
    local = next(repo for repo in repos if repo["repo"] == "local")
    (hook,) = local["hooks"]
    published = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text(encoding="utf-8"))[0]
    for key in ("id", "entry", "files", "require_serial"):
        assert hook[key] == published[key], key


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_a_markdown_summary_goes_to_the_job_page_unless_told_otherwise(tmp_path):
    repo = workspace(tmp_path, broken=True)
    summary = tmp_path / "runner-temp" / "step-summary.md"
    run = run_action(repo, tmp_path)
    assert run.returncode == 1  # the summary is written whatever the findings; the lint decides
    text = summary.read_text(encoding="utf-8")
    assert "LIS203" in text and "listen/achsmds3.lis" in text and "|" in text  # a Markdown table
    summary.unlink()
    run_action(repo, tmp_path, {"summary": "false"})
    assert not summary.exists()


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_a_path_named_like_an_option_is_linted_never_obeyed(tmp_path):
    """Found by review: the paths came before the options on the command line, so a file named like an
    option (as a changed-files list may hand over) was read as one: a file `-w` turned on --watch, which
    waits for changes until the job times out, and `-w.lis` ended in a usage error (`no such option: -`).
    The paths now follow `--`, in the action and in the GitLab job."""
    repo = workspace(tmp_path)
    data = (repo / "listen" / "achsmds3.lis").read_bytes().replace(b"DRIVE_CONTROLLED", b"DRIVE_CONROLLED")
    (repo / "-w.lis").write_bytes(data)
    run = run_action(repo, tmp_path, {"paths": "-w.lis", "annotations": "false", "summary": "false"})
    assert run.returncode == 1, run.stderr
    assert "-w.lis:8:34: LIS203 [error]" in run.stdout
    job = run_gitlab_job(repo, tmp_path, {"ACHSLINT_PATHS": "-w.lis"})
    assert job.returncode == 1, job.stderr
    assert "-w.lis:8:34: LIS203 [error]" in job.stdout
    quality, _ = reports(repo)
    assert [issue["location"]["path"] for issue in quality if issue["check_name"] == "LIS203"] == ["-w.lis"]
