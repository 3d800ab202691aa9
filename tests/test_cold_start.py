"""What keeps a cold `achslint lint` fast (issue 23; measured by `benchmarks/run --only cold`).

The budget itself is a timing and lives in the benchmark; these tests pin the mechanisms behind it: the
CLI builds only the command it runs, the catalogue makes a parameter when it is first asked for, and the
code `dataclasses` compiles is kept between runs without ever changing what a class does.
"""

from __future__ import annotations

import json
import marshal
import os
import subprocess
import sys
import typing
from collections.abc import Iterator
from pathlib import Path

import pytest
import typer.main

from achslint import cli
from achslint.catalogue import Catalogue
from achslint.core import codecache

from .conftest import FIXTURES, ROOT

CATALOGUE_JSON = ROOT / "src" / "achslint" / "catalogue" / "data" / "catalogue.json"


# -- the command tree ----------------------------------------------------------------------------------


@pytest.fixture
def built_commands(monkeypatch: pytest.MonkeyPatch) -> Iterator[list[str]]:
    """The names of the commands typer builds from their functions while a test runs (none cached)."""
    names: list[str] = []
    build = typer.main.get_command_from_info

    def recording(command_info: typer.models.CommandInfo, **options: typing.Any) -> typing.Any:
        command = build(command_info, **options)
        names.append(command.name or "")
        return command

    monkeypatch.setattr(typer.main, "get_command_from_info", recording)
    cli._command_tree.cache_clear()
    yield names
    cli._command_tree.cache_clear()


def test_a_run_builds_only_the_command_it_runs(
    built_commands: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    code = cli.main(["lint", str(FIXTURES / "lists" / "achsmds4.lis")])
    assert code in (cli.EXIT_OK, cli.EXIT_FINDINGS)
    assert built_commands == ["lint"]


def test_help_and_a_misspelt_command_see_every_command(
    built_commands: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    cli.main(["--help"])
    every = {
        info.name or typer.main.get_command_name(getattr(info.callback, "__name__", ""))
        for info in cli.app.registered_commands
    }
    assert set(built_commands) == every
    assert "lint" in capsys.readouterr().out
    assert cli.main(["lnt"]) == cli.EXIT_ERROR
    assert "did you mean 'lint'" in capsys.readouterr().err.lower()


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_linting_leaves_the_formatter_and_the_api_module_unloaded() -> None:
    """`lint` takes the lint run from `linting.run` itself: `api` re-exports it beside the format run."""
    probe = (
        "import contextlib, io, sys\n"
        "from achslint.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    code = main(['lint', {str(FIXTURES / 'lists' / 'achsmds4.lis')!r}])\n"
        "print(code, [m for m in ('achslint.api', 'achslint.fmt') if m in sys.modules])\n"
    )
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    code, unloaded = done.stdout.split(" ", 1)
    assert int(code) in (cli.EXIT_OK, cli.EXIT_FINDINGS)
    assert unloaded.strip() == "[]"


def test_the_options_are_annotated_with_types_not_strings() -> None:
    """typer reads each option's annotation; a string one would be compiled and evaluated on every run."""
    for name, command in cli._command_names().items():
        annotations = getattr(command.callback, "__annotations__", {})
        assert annotations, name
        assert not [k for k, value in annotations.items() if isinstance(value, str)], name


# -- the catalogue -------------------------------------------------------------------------------------


@pytest.fixture
def made(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The ids of the parameters the catalogue makes from their entries while a test runs."""
    ids: list[str] = []
    entry = Catalogue._entry

    def counting(raw: dict[str, typing.Any]) -> typing.Any:
        ids.append(raw["id"])
        return entry(raw)

    monkeypatch.setattr(Catalogue, "_entry", staticmethod(counting))
    return ids


def test_the_catalogue_makes_a_parameter_when_first_asked_for(made: list[str]) -> None:
    data = json.loads(CATALOGUE_JSON.read_text(encoding="utf-8"))
    entries = data["parameters"]
    by_path = {raw["path"]: raw["id"] for raw in entries}
    # The aliases table names the parameters that have aliases or known misspellings; no other is made yet.
    with_aliases = {raw["id"] for raw in entries if raw.get("aliases")}
    with_aliases |= {by_path[right] for right in data["misspellings"].values()}
    cat = Catalogue(data)
    assert set(made) == with_aliases
    first = next(raw for raw in entries if raw["id"] not in with_aliases)
    assert first["id"] in cat.by_id and first["path"] in cat.by_pattern
    assert first["id"] not in made  # `in` looks at the keys
    parameter = cat.by_id[first["id"]]
    assert parameter.path == first["path"] and parameter.type == first["type"]
    assert cat.by_pattern[first["path"]] is parameter and cat.by_id.get(first["id"]) is parameter
    assert made.count(first["id"]) == 1
    assert cat.by_id.get("P-AXIS-99999") is None and "P-AXIS-99999" not in cat.by_id
    with pytest.raises(KeyError):
        cat.by_pattern["no.such.path"]
    assert [p.id for p in cat.parameters] == [raw["id"] for raw in entries]
    assert all(cat.by_id[p.id] is p for p in cat.parameters)
    assert len(made) == len(entries)  # every parameter made once, however it was reached


def test_a_lint_makes_only_the_parameters_it_looks_at(made: list[str]) -> None:
    from achslint.axis.analysis import analyse
    from achslint.syntax.parser import parse_bytes

    data = json.loads(CATALOGUE_JSON.read_text(encoding="utf-8"))
    cat = Catalogue(data)
    listed = parse_bytes((FIXTURES / "lists" / "achsmds4.lis").read_bytes())
    analysis = analyse(listed, cat)
    known = {s.parameter.id for s in analysis.settings if s.parameter is not None}
    assert known
    assert len(set(made)) < len(data["parameters"]) / 2
    assert known <= set(made)


# -- the dataclass code cache ----------------------------------------------------------------------------

# A process that makes a few dataclasses through the cache and prints what they do and how much it compiled.
PROBE = """
import dataclasses, json, sys
from achslint.core import codecache
cache = codecache.install()

@dataclasses.dataclass(frozen=True)
class Point:
    x: int
    y: int = 2
    tags: tuple = ()

@dataclasses.dataclass(order=True)
class Count:
    name: str
    seen: list = dataclasses.field(default_factory=list)

p = Point(1)
try:
    p.x = 5
    frozen = False
except dataclasses.FrozenInstanceError:
    frozen = True
c = Count("a")
c.seen.append(1)
print(json.dumps({
    "compiled": cache.compiled if cache else None,
    "repr": [repr(p), repr(c)],
    "eq": [p == Point(1, 2), p == Point(2), Count("a") < Count("b")],
    "hash": hash(p) == hash(Point(1)),
    "frozen": frozen,
    "fields": [f.name for f in dataclasses.fields(Point)],
    "init": str(__import__("inspect").signature(Point)),
    "fresh_list": Count("b").seen,
}))
"""


def _probe(cache_home: Path) -> dict[str, typing.Any]:
    env = {**os.environ, "XDG_CACHE_HOME": str(cache_home)}
    done = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True, env=env, timeout=60)
    assert done.returncode == 0, done.stderr
    result: dict[str, typing.Any] = json.loads(done.stdout)
    return result


def _plain_dataclasses() -> dict[str, typing.Any]:
    done = subprocess.run(
        [sys.executable, "-c", PROBE.replace("cache = codecache.install()", "cache = None")],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 0, done.stderr
    result: dict[str, typing.Any] = json.loads(done.stdout)
    return result


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_the_second_run_compiles_no_dataclass_method_and_the_classes_are_the_same(tmp_path: Path) -> None:
    first = _probe(tmp_path)
    second = _probe(tmp_path)
    assert first["compiled"] > 0
    assert second["compiled"] == 0
    plain = _plain_dataclasses()
    for result in (first, second):
        assert {k: v for k, v in result.items() if k != "compiled"} == {
            k: v for k, v in plain.items() if k != "compiled"
        }
    assert first["frozen"] and first["eq"] == [True, False, True] and first["hash"]


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_a_damaged_or_foreign_cache_file_is_compiled_again(tmp_path: Path) -> None:
    folder = tmp_path / "achslint"
    folder.mkdir(mode=0o700)
    path = Path(codecache.cache_path(str(folder)))
    assert _probe(tmp_path)["compiled"] > 0
    texts = marshal.loads(path.read_bytes())
    damages = [b"", b"\x00garbage", b"{" * 100, marshal.dumps({"text": "not code", 1: 2})]
    damages.append(marshal.dumps(dict.fromkeys(texts, b"\x00not marshal")))  # the right texts, bad code
    damages.append(marshal.dumps(dict.fromkeys(texts, marshal.dumps("a string, not code"))))
    for damage in damages:
        path.write_bytes(damage)
        result = _probe(tmp_path)
        assert result["compiled"] > 0 and result["frozen"]
        assert _probe(tmp_path)["compiled"] == 0  # written again, whole


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_no_cache_in_a_folder_others_can_write(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    if os.name != "posix":
        pytest.skip("folder permissions are POSIX")
    folder = tmp_path / "achslint"
    folder.mkdir()
    folder.chmod(0o777)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert codecache.private_folder() is None
    assert _probe(tmp_path)["compiled"] is None  # install() declined: every text compiled as without it
    assert not list(folder.glob("dataclass-code-*"))


def test_the_cached_code_is_what_compiling_the_text_gives() -> None:
    text = "def __create_fn__(x):\n def f(self, a):\n  return (a, x)\n return f"
    cache = codecache.CodeCache(os.devnull)
    code = cache.code(text)
    assert cache.code(text) is code and cache.compiled == 1
    direct = compile(text, "<string>", "exec", dont_inherit=True)  # as `dataclasses` (no __future__) gets it
    assert code.co_code == direct.co_code and code.co_consts[0].co_code == direct.co_consts[0].co_code
    assert code.co_filename == "<string>" and code.co_flags == direct.co_flags


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_the_command_line_keeps_the_cache_and_a_calmer_collector(tmp_path: Path) -> None:
    env = {**os.environ, "XDG_CACHE_HOME": str(tmp_path)}
    shown = subprocess.run(
        [sys.executable, "-c", "import gc, achslint.cli; print(gc.get_threshold()[0])"],
        capture_output=True,
        text=True,
        env=env,
        timeout=60,
    )
    assert shown.returncode == 0, shown.stderr
    assert int(shown.stdout) >= 10_000
    assert list((tmp_path / "achslint").glob("dataclass-code-*.marshal"))


# -- what a lint loads ---------------------------------------------------------------------------------


def _loaded_after(code: str) -> list[str]:
    """What `code` prints in a fresh interpreter, then the achslint modules it holds at the end."""
    probe = code + "\nimport sys\nprint(' '.join(m for m in sys.modules if m.startswith('achslint')))\n"
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    return done.stdout.split()


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_classifying_an_axis_loads_the_strategies_up_to_its_own() -> None:
    """Classification takes the first strategy that matches; the ones after it are never imported."""
    from achslint.homing.registry import STRATEGY_MODULES

    axis_list = FIXTURES / "lists" / "achsmds4.lis"
    loaded = _loaded_after(
        "from achslint.axis.resolved import resolve_bytes\n"
        "from achslint.homing.registry import classify\n"
        f"data = open({str(axis_list)!r}, 'rb').read()\n"
        "print(classify(resolve_bytes(data, 'x')).definition.id)\n"
    )
    chosen, modules = loaded[0], loaded[1:]
    prefix = "achslint.homing.strategies."
    strategies = [m.removeprefix(prefix) for m in modules if m.startswith(prefix) and "._" not in m]
    position = STRATEGY_MODULES.index(chosen)
    assert position < len(STRATEGY_MODULES) - 1  # a strategy in the middle: some are left out
    assert strategies == list(STRATEGY_MODULES[: position + 1])


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_linting_an_axis_list_imports_only_the_rules_that_run_on_it() -> None:
    """The engine picks rules by the code table's scopes and kinds before importing any: a lint of axis lists
    imports no program rule (LIS6xx) and no rule of channel or compensation lists (LIS7xx)."""
    from achslint.rules import Scope, codes

    axis_list = FIXTURES / "lists" / "achsmds4.lis"
    loaded = _loaded_after(
        "import contextlib, io\n"
        "from achslint.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    main(['lint', {str(axis_list)!r}])\n"
    )
    rules = {m.removeprefix("achslint.rules.") for m in loaded if m.startswith("achslint.rules.lis")}
    runs = {
        codes.module_name(code)
        for code in codes.known_codes()
        if Scope.MACHINE in codes.scopes(code)
        or (
            {Scope.LIST, Scope.AFTER} & set(codes.scopes(code))
            and codes.applies_to(codes.kinds(code), "axis")
        )
    }
    assert rules == runs
    assert not [name for name in rules if name.startswith(("lis6", "lis7"))]


def test_the_code_table_declares_the_checks_of_every_rule_module() -> None:
    """A rule module has the check function of each scope its line in the code table names, and no other
    (the engine reads the table, never the module, to pick the rules of a scope)."""
    import importlib

    from achslint.rules import Scope, codes

    for code in codes.known_codes():
        module = importlib.import_module(f"achslint.rules.{codes.module_name(code)}")
        assert code == module.CODE
        present = {scope for scope in Scope if hasattr(module, scope.value)}
        assert present == set(codes.scopes(code)), code


def test_ctrl_c_while_the_cache_is_saved_leaves_no_temporary_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = str(tmp_path / "code.cache")
    cache = codecache.CodeCache(path)
    cache.code("x = 1\n")  # one text compiled: save writes the file

    def stopped(*_: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(codecache.os, "replace", stopped)
    with pytest.raises(KeyboardInterrupt):
        cache.save()
    assert list(tmp_path.iterdir()) == []  # neither the cache nor the process's temporary file
