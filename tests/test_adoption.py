"""Gradual adoption like ruff (issue 27 item 4): `rules --format json`, `--show-files`, `--show-settings`,
`extend`, `fixable`/`unfixable`, `--add-noqa` and `--watch`."""

from __future__ import annotations

import json

from achslint.rules import registry


def test_rules_json_lists_every_rule_as_the_table_and_rule_do(cli):
    result = cli("rules", "--format", "json")
    assert result.returncode == 0
    rules = json.loads(result.stdout)
    assert [rule["code"] for rule in rules] == list(registry())
    table = {line.split()[0]: line.split()[1:4] for line in cli("rules").stdout.decode().splitlines()[2:]}
    for rule in rules:
        assert table[rule["code"]] == [rule["name"], rule["severity"], rule["fix"]]
        assert rule["url"].endswith("#" + rule["code"].lower())
        assert set(rule["scopes"]) <= {"list", "machine", "program", "after"}
        assert bool(rule["scopes"]) == (rule["produced_by"] == "lint"), rule["code"]
    by_code = {rule["code"]: rule for rule in rules}
    assert by_code["LIS202"]["explanation"] == cli("rule", "LIS202").stdout.decode().rstrip("\n")
    assert by_code["LIS501"]["scopes"] == ["machine"] and by_code["LIS501"]["lists"] is None
