"""The rdjson (reviewdog) and azure (Azure Pipelines logging commands) output formats: rdjson against our
strict schema of reviewdog's format (tests/schemas/rdjson.schema.json, origin in tests/schemas/README.md),
columns in UTF-8 bytes, fixes as suggestions; azure one escaped `task.logissue` per finding."""

from __future__ import annotations

import json
import re
from pathlib import Path

from .conftest import FIXTURES, ROOT
from .test_ci_formats import EVERYTHING, checked_validator

SCHEMA = json.loads((ROOT / "tests" / "schemas" / "rdjson.schema.json").read_text(encoding="utf-8"))


def schema_errors(document: object) -> list[str]:
    return [f"{list(e.absolute_path)}: {e.message}" for e in checked_validator(SCHEMA).iter_errors(document)]


def test_rdjson_of_every_finding_is_valid(cli):
    result = cli(*EVERYTHING, "--format", "rdjson")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    assert schema_errors(document) == []
    diagnostics = document["diagnostics"]
    assert len(diagnostics) > 50
    assert document["severity"] == "ERROR"  # the worst finding of the run
    codes = {d["code"]["value"] for d in diagnostics}
    assert {"LIS203", "LIS101", "LIS501"} <= codes
    assert all(d["code"]["url"].endswith("#" + d["code"]["value"].lower()) for d in diagnostics)
    assert any("suggestions" in d for d in diagnostics)


def test_the_schema_refuses_broken_documents():
    good = {"diagnostics": [{"message": "m", "location": {"path": "a.lis", "range": {"start": {"line": 1}}}}]}
    assert schema_errors(good) == []
    broken = [
        {},  # no diagnostics
        {"diagnostics": [{"message": "m"}]},  # no location
        {"diagnostics": [{"message": "m", "location": {"path": "a"}, "severity": "FATAL"}]},
        {"diagnostics": [{"message": "m", "location": {"path": "a", "range": {"start": {"line": 0}}}}]},
        {"diagnostics": [], "extra": 1},
    ]
    for document in broken:
        assert schema_errors(document), document


def test_rdjson_counts_columns_in_utf8_bytes_and_suggests_fixes(cli, tmp_path: Path):
    # µ (one character, two bytes in UTF-8) stands before the unused noqa LIS009 reports
    (tmp_path / "achsmds1.lis").write_bytes(
        b"kopf.achs_nr  1\ngetriebe[0].vb_reflow  10000  ( \xb5m/s noqa: LIS302\nEnd\n"
    )
    result = cli(
        "lint", str(tmp_path / "achsmds1.lis"), "--format", "rdjson", "--select", "LIS009,LIS004,LIS302"
    )
    document = json.loads(result.stdout)
    assert schema_errors(document) == []
    by_code = {d["code"]["value"]: d for d in document["diagnostics"]}
    concise = cli("lint", str(tmp_path / "achsmds1.lis"), "--format", "concise", "--select", "LIS009,LIS302")
    column = int(re.search(r":2:(\d+): LIS009", concise.stdout.decode())[1])  # counted in characters
    assert by_code["LIS009"]["location"]["range"]["start"] == {"line": 2, "column": column + 1}
    assert by_code["LIS009"]["severity"] == "WARNING"
    (suggestion,) = by_code["LIS004"]["suggestions"]  # End -> Ende
    assert suggestion["text"] == "Ende"
    assert suggestion["range"]["start"] == {"line": 3, "column": 1}


def test_rdjson_reports_an_unreadable_file_as_an_error(cli, tmp_path: Path):
    (tmp_path / "achsmds1.lis").write_bytes("kopf.achs_nr 1\n".encode("utf-16"))
    document = json.loads(cli("lint", str(tmp_path / "achsmds1.lis"), "--format", "rdjson").stdout)
    assert schema_errors(document) == []
    (only,) = document["diagnostics"]
    assert only["severity"] == "ERROR" and only["location"] == {"path": str(tmp_path / "achsmds1.lis")}


AZURE = re.compile(r"^##vso\[task\.logissue (?P<properties>[^\]]*)\](?P<message>.*)$")


def azure_issues(text: str) -> list[tuple[dict[str, str], str]]:
    issues = []
    for line in text.splitlines():
        match = AZURE.match(line)
        assert match, line
        properties = dict(part.split("=", 1) for part in match["properties"].split(";"))
        issues.append((properties, match["message"]))
    return issues


def test_azure_writes_one_logissue_per_finding(cli):
    bad = FIXTURES / "rules" / "LIS203" / "bad.lis"
    concise = cli("lint", str(bad), "--format", "concise", "-q").stdout.decode().splitlines()
    issues = azure_issues(cli("lint", str(bad), "--format", "azure").stdout.decode())
    assert len(issues) == len(concise) > 0
    for (properties, message), line in zip(issues, concise, strict=True):
        path, number, column, rest = line.split(":", 3)
        code = rest.split()[0]
        assert properties == {
            "type": "error" if "[error]" in rest else "warning",
            "sourcepath": path,
            "linenumber": number,
            "columnnumber": column,
            "code": code,
        }
        assert message.startswith(code)


def test_azure_escapes_and_names_info_findings(cli, tmp_path: Path):
    folder = tmp_path / "a;b]%"
    folder.mkdir()
    (folder / "achsmds1.lis").write_bytes((FIXTURES / "rules" / "LIS401" / "bad.lis").read_bytes())
    issues = azure_issues(cli("lint", str(folder / "achsmds1.lis"), "--format", "azure").stdout.decode())
    infos = [(p, m) for p, m in issues if p["code"] == "LIS401"]
    assert infos and all(p["type"] == "warning" and m.startswith("LIS401 (info) ") for p, m in infos)
    assert all(p["sourcepath"].endswith("a%3Bb%5D%AZP25/achsmds1.lis") for p, _ in issues)
