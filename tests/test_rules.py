"""Every rule against its fixtures: `bad.lis` must produce exactly the expected
diagnostics of that rule, `good.lis` none of them."""

from __future__ import annotations

import pytest

from achslint.api import lint
from achslint.rules import registry

from .conftest import FIXTURES

RULE_DIRS = sorted(p for p in (FIXTURES / "rules").iterdir() if p.is_dir())


def fixture(rule_dir, kind: str):
    """The `bad` or `good` fixture of a rule: a list (.lis) or, for XML rules, an XML file."""
    for suffix in (".lis", ".xml"):
        candidate = rule_dir / f"{kind}{suffix}"
        if candidate.exists():
            return candidate
    raise FileNotFoundError(f"{rule_dir} has no {kind}.lis or {kind}.xml")


def selection(rule_dir):
    """The rule itself, plus the codes in `also_select` (LIS009 needs the rules its suppressions name)."""
    extra = rule_dir / "also_select"
    return [rule_dir.name, *(extra.read_text().split() if extra.exists() else [])]


def expected(path):
    rows = []
    for line in path.read_text().splitlines():
        if line.strip():
            number, code = line.split()
            rows.append((int(number), code))
    return sorted(rows)


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=[p.name for p in RULE_DIRS])
def test_bad_fixture_triggers_rule(rule_dir):
    code = rule_dir.name
    found = [d for d in lint(fixture(rule_dir, "bad"), select=selection(rule_dir)) if d.code == code]
    assert sorted((d.line, d.code) for d in found) == expected(rule_dir / "bad.expected")
    for diagnostic in found:
        assert diagnostic.message, "every diagnostic explains itself"
        assert diagnostic.severity is not None


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=[p.name for p in RULE_DIRS])
def test_good_fixture_is_clean_for_rule(rule_dir):
    code = rule_dir.name
    assert [d for d in lint(fixture(rule_dir, "good"), select=selection(rule_dir)) if d.code == code] == []


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=[p.name for p in RULE_DIRS])
def test_good_fixture_has_no_errors_at_all(rule_dir):
    """The good variant is a correct list: no rule reports an error or warning on it."""
    found = [d for d in lint(fixture(rule_dir, "good")) if d.severity.value != "info"]
    assert found == []


def test_every_rule_has_fixtures():
    missing = [code for code in registry() if not list((FIXTURES / "rules" / code).glob("bad.*"))]
    assert missing == []
