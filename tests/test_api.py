"""The library API: paths are paths, text has its own functions, models round-trip."""

from __future__ import annotations

from pathlib import Path

import pytest

import achslint
from achslint.fmt import canonical_text

from .conftest import FIXTURES

LIST = FIXTURES / "lists" / "achsmds1.lis"


def test_a_missing_path_raises_file_not_found(tmp_path):
    with pytest.raises(FileNotFoundError):
        achslint.lint("nope.lis")
    with pytest.raises(FileNotFoundError):
        achslint.load(tmp_path / "nope.lis")


def test_paths_and_text_give_the_same_findings():
    by_path = [(d.line, d.code) for d in achslint.lint(str(LIST))]
    text = LIST.read_bytes().decode("latin-1")
    assert [(d.line, d.code) for d in achslint.lint_text(text, filename="achsmds1.lis")] == by_path


def test_loads_dumps_round_trip():
    model = achslint.load(LIST)
    text = achslint.dumps(model)
    assert achslint.loads(text) == achslint.loads(achslint.dumps(achslint.loads(text)))
    assert achslint.loads(text).model_dump() == model.model_dump()
    assert achslint.format_text(text) == canonical_text(text) == text  # dumps writes the canonical layout


def test_explain_dry_run_and_format_text():
    report = achslint.explain(LIST)
    assert (
        report["strategy"]["id"] and achslint.explain(LIST) == report
    )  # still the function after the first call
    run = achslint.dry_run(LIST, {"start_position": 50.0})
    assert run.trace.outcome in ("homed", "failed", "skipped") or run.trace.outcome
    assert achslint.format_text("kopf.achs_nr 1   \nEnde\n") == "kopf.achs_nr  1\nEnde\n"


def test_the_package_is_typed():
    assert (Path(achslint.__file__).parent / "py.typed").is_file()
