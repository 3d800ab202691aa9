"""Every rule against its fixtures: `bad.lis` must produce exactly the expected
diagnostics of that rule, `good.lis` none of them."""

from __future__ import annotations

import pytest

from pathlib import Path

from achslint.api import lint
from achslint.rules import registry

from .conftest import FIXTURES

RULE_DIRS = sorted(p for p in (FIXTURES / "rules").iterdir() if p.is_dir())


def fixture(rule_dir, kind: str):
    """The `bad` or `good` fixture of a rule: a list (.lis), an XML file, or a machine folder (LIS5xx)."""
    for suffix in (".lis", ".xml", ""):
        candidate = rule_dir / f"{kind}{suffix}"
        if candidate.exists():
            return candidate
    raise FileNotFoundError(f"{rule_dir} has no {kind}.lis or {kind}.xml")


def selection(rule_dir):
    """The rule itself, plus the codes in `also_select` (LIS009 needs the rules its suppressions name)."""
    extra = rule_dir / "also_select"
    return [rule_dir.name, *(extra.read_text().split() if extra.exists() else [])]


def expected(path):
    """Rows `LINE CODE`, or `FILE LINE CODE` for machine folders."""
    rows = []
    for line in path.read_text().splitlines():
        if line.strip():
            *where, number, code = line.split()
            rows.append((*where, int(number), code))
    return sorted(rows)


def machine_findings(folder, select):
    """Lint a machine folder (through its start-up list when it has one), as the CLI does."""
    from achslint.api import LintRequest, run_lint
    from achslint.config import Overrides

    startup = sorted(folder.glob("hochlauf*.lis"))
    target = str(startup[0]) if startup else str(folder)
    outcome = run_lint(LintRequest([target], Overrides(select=select), jobs=1))
    return sorted((Path(d.path).name, d.line, d.code) for r in outcome.results for d in r.diagnostics)


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=[p.name for p in RULE_DIRS])
def test_bad_fixture_triggers_rule(rule_dir):
    code = rule_dir.name
    bad = fixture(rule_dir, "bad")
    if bad.is_dir():
        assert machine_findings(bad, selection(rule_dir)) == expected(rule_dir / "bad.expected")
        return
    found = [d for d in lint(bad, select=selection(rule_dir)) if d.code == code]
    assert sorted((d.line, d.code) for d in found) == expected(rule_dir / "bad.expected")
    for diagnostic in found:
        assert diagnostic.message, "every diagnostic explains itself"
        assert diagnostic.severity is not None


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=[p.name for p in RULE_DIRS])
def test_good_fixture_is_clean_for_rule(rule_dir):
    code = rule_dir.name
    good = fixture(rule_dir, "good")
    if good.is_dir():
        assert [row for row in machine_findings(good, selection(rule_dir)) if row[2] == code] == []
        return
    assert [d for d in lint(good, select=selection(rule_dir)) if d.code == code] == []


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=[p.name for p in RULE_DIRS])
def test_good_fixture_has_no_errors_at_all(rule_dir):
    """The good variant is a correct list: no rule reports an error or warning on it."""
    good = fixture(rule_dir, "good")
    if good.is_dir():
        assert [row for row in machine_findings(good, None)] == []
        return
    found = [d for d in lint(good) if d.severity.value != "info"]
    assert found == []


def test_every_rule_has_fixtures():
    missing = [code for code in registry() if not list((FIXTURES / "rules" / code).glob("bad.*"))]
    assert missing == []
