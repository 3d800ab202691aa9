from __future__ import annotations

import ast
import functools
import gc
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import pytest

from achslint.core import codecache

# The test processes keep the dataclass code they compile to themselves: importing the CLI (as the in-process
# CLI tests do) installs the per-user cache of core/codecache.py, and a test process makes thousands of
# classes a command-line run never makes; saved there, they grew the file every `achslint` run reads at its
# start to its 2 MB limit (2,200 texts, where a lint uses 450: +6 M instructions, about 1 %, on every cold
# lint). The child processes the tests start (the real CLI, the language server) still use the cache.
codecache._installed = True

# Keep compiled bytecode even where PYTHONDONTWRITEBYTECODE=1 is set (as in many containers): without it
# every run compiles the test modules (with pytest's assertion rewriting) and achslint again in each xdist
# worker, and every child `python -m achslint` the tests start compiles achslint once more: about 5 s per
# worker and 0.2-0.3 s per child. The files go to the __pycache__ folders git ignores.
sys.dont_write_bytecode = False

# Hypothesis loads the plugins other packages register for it: trio (installed for selenium, which drives
# the browser test) registers one that imports trio, ~0.1 s in every test process that imports hypothesis.
# No test uses trio.
os.environ.setdefault("HYPOTHESIS_NO_PLUGINS", "1")

ROOT = Path(__file__).resolve().parents[1]
FIXTURES = ROOT / "fixtures"
# The portal machine of the fixtures, and LIS605's gantry (Z, Y and its slave Y2, no channel list): the machines
# the program tests check NC programs against, built once per test module that asks for them.
PORTAL_STARTUP = FIXTURES / "machines" / "portal" / "listen" / "hochlauf.lis"
GANTRY_STARTUP = FIXTURES / "rules" / "LIS605" / "gantry" / "hochlauf.lis"


@pytest.fixture(scope="module")
def portal() -> Any:
    from achslint.machine.build import build_machine

    return build_machine(PORTAL_STARTUP)


@pytest.fixture(scope="module")
def gantry() -> Any:
    from achslint.machine.build import build_machine

    return build_machine(GANTRY_STARTUP)


# Property tests run a bounded number of examples so the suite stays fast; ACHSLINT_THOROUGH=1 runs each
# test's full budget (for a nightly job or before a release).
THOROUGH = os.environ.get("ACHSLINT_THOROUGH", "") not in ("", "0")


# The cyclic garbage collector ran about 1,700 times in a run of a few test files, a tenth of their time;
# a test process makes lots of short-lived objects and little cyclic garbage. Collect the young generation
# after 20,000 allocations instead of 700, and leave what collection built (catalogue, parsed modules, test
# items) out of later full collections. The child processes (CLI, language server) keep their own settings.
gc.set_threshold(20_000, 20, 20)


def pytest_collection_finish(session: pytest.Session) -> None:
    gc.collect()
    gc.freeze()


@pytest.hookimpl(tryfirst=True)
def pytest_unconfigure(config: pytest.Config) -> None:
    """At the end pytest collects garbage twice to report exceptions raised in finalizers (at unconfigure and
    at cleanup), each time through every object the tests left alive: 0.3-0.5 s each per process. Collect
    once here, while its hook still reports them, and freeze the survivors: its two collections then have
    only what was made since to look at."""
    gc.collect()
    gc.freeze()


@pytest.hookimpl(tryfirst=True)
def pytest_cmdline_main(config: pytest.Config) -> None:
    """Run on every core unless told otherwise: `-n N` / `-n 0` choose the workers, `-p no:xdist` runs in
    this process. (In addopts, `-n` would be an unknown option to a pytest without xdist.) Called before
    xdist's own hook, which turns `auto` into the number of cores.

    Work stealing: each worker starts with one half of the tests, in file order, and a worker that runs out
    takes tests from the end of the other's queue, so both finish together; a file stays in one worker
    unless its tests are taken at the end (its module-scoped fixtures, such as test_lsp's language servers,
    are then made once more). One file per worker (loadfile) left a worker idle for seconds at the end."""
    if not config.pluginmanager.hasplugin("xdist") or hasattr(config, "workerinput"):
        return  # xdist not loaded, or this is one of its workers
    if config.option.numprocesses is None and not config.option.collectonly:
        config.option.numprocesses = "auto"
        if config.option.dist == "no":
            config.option.dist = "worksteal"


def examples(full: int, quick: int = 20) -> int:
    """The number of hypothesis examples a property test runs: `full` when thorough, else at most `quick`."""
    return full if THOROUGH else min(full, quick)


@functools.cache
def _syntax_tree(source: str, filename: str) -> ast.Module:
    return ast.parse(source, filename)


def source_tree(path: Path, source: str | None = None) -> ast.Module:
    """The syntax tree of a Python file (`source` when given: its text), parsed once per test process: several
    tests walk every module of src/achslint (about 1 s to parse them all). Read it, never change it."""
    return _syntax_tree(path.read_text(encoding="utf-8") if source is None else source, str(path))


def jenkins_junit_errors(document: str | ET.Element) -> list[str]:
    """Why a JUnit document is not what Jenkins reads (tests/schemas/jenkins-junit.xsd, origin in
    tests/schemas/README.md); empty when it is."""
    pytest.importorskip("xmlschema")
    if isinstance(document, str):
        document = ET.fromstring(document.encode("utf-8"))
    return [str(error.reason) for error in _jenkins_schema().iter_errors(document)]


@functools.cache
def _jenkins_schema() -> Any:
    import xmlschema

    return xmlschema.XMLSchema(str(ROOT / "tests" / "schemas" / "jenkins-junit.xsd"))


def run_cli(*args: str, stdin: bytes | None = None, env: dict | None = None) -> subprocess.CompletedProcess:
    """Run the CLI's entry point (`achslint.cli.main`, what the console script calls) in this process, with
    its own stdin, stdout, stderr and environment; the result looks like a finished subprocess."""
    from typer.testing import CliRunner

    from achslint.cli import main
    from achslint.linting.config import forget_cached

    forget_cached()  # each run starts like a new process: configurations are read again
    full_env = {"NO_COLOR": "1", "FORCE_COLOR": None, **(env or {})}
    runner = CliRunner()
    with runner.isolation(input=stdin, env=full_env) as streams:
        code = main(list(args))
        sys.stdout.flush()
        sys.stderr.flush()
        out, err = streams[0].getvalue(), streams[1].getvalue()
    return subprocess.CompletedProcess(["achslint", *args], code, out, err)


def run_real_cli(
    *args: str, stdin: bytes | None = None, env: dict | None = None
) -> subprocess.CompletedProcess:
    """Run the real entry point (`python -m achslint`) in a subprocess: for the smoke tests of the entry
    point itself (exit codes, stdin, signals, parallel runs)."""
    full_env = {**os.environ, "NO_COLOR": "1", **(env or {})}
    full_env.pop("FORCE_COLOR", None)
    return subprocess.run(
        [sys.executable, "-m", "achslint", *args],
        input=stdin,
        capture_output=True,
        env=full_env,
        timeout=120,
    )


@pytest.fixture
def cli():
    return run_cli


def one_machine(folder: Path, *patterns: str) -> Path:
    """Declare the lists of `folder` one machine with a `[[machine]]` table in its `.achslint.toml` (lists no
    start-up list names are compared with no other list unless a configuration says they form a machine)."""
    folder.mkdir(parents=True, exist_ok=True)
    listed = ", ".join(f'"{p}"' for p in (patterns or ("*.lis",)))
    config = folder / ".achslint.toml"
    config.write_text(f"[[machine]]\nlists = [{listed}]\n", encoding="utf-8")
    return config
