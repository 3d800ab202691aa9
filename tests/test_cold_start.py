"""What keeps a cold `achslint lint` fast (issue 23; measured by `benchmarks/run --only cold`).

The budget itself is a timing and lives in the benchmark; these tests pin the mechanisms behind it: the
CLI builds only the command it runs, and the catalogue makes a parameter when it is first asked for.
"""

from __future__ import annotations

import json
import typing
from collections.abc import Iterator

import pytest
import typer.main

from achslint import cli
from achslint.catalogue import Catalogue

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
