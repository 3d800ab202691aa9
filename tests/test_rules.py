"""Every rule against its fixtures: `bad.*` must produce exactly the findings of
its snapshot `bad.snap`, `good.*` none of them."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from achslint.api import lint
from achslint.rules import registry

from .conftest import FIXTURES

RULE_DIRS = sorted(p for p in (FIXTURES / "rules").iterdir() if p.is_dir())


def _snapshots():
    tools = Path(__file__).resolve().parents[1] / "tools"
    if str(tools) not in sys.path:
        sys.path.insert(0, str(tools))
    import update_snapshots

    return update_snapshots


fixture = _snapshots().fixture
selection = _snapshots().selection


def machine_findings(folder, select):
    """Lint a machine folder (through its start-up list when it has one), as the CLI does."""
    return sorted((Path(d.path).name, d.line, d.code) for d in _snapshots().lint_fixture(folder, select))


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=[p.name for p in RULE_DIRS])
def test_bad_fixture_matches_its_snapshot(rule_dir):
    """Every finding of the rule on `bad.*` — position, end, severity, message, related locations and the
    fix as a diff — is exactly what `bad.snap` holds (`python tools/update_snapshots.py CODE` rewrites it)."""
    snapshots = _snapshots()
    if snapshots.is_dry_run_rule(rule_dir):
        assert snapshots.dry_run_warnings(rule_dir), (
            f"{rule_dir.name}: the dry-run of the bad fixture must report it"
        )
    else:
        assert snapshots.findings(rule_dir), f"{rule_dir.name}: the bad fixture must trigger the rule"
    snap = rule_dir / "bad.snap"
    assert snap.exists(), f"no {snap}: run python tools/update_snapshots.py {rule_dir.name}"
    assert snapshots.render(rule_dir) == snap.read_text(encoding="utf-8"), (
        f"{rule_dir.name} changed: run python tools/update_snapshots.py {rule_dir.name} and review the diff"
    )


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=[p.name for p in RULE_DIRS])
def test_good_fixture_is_clean_for_rule(rule_dir):
    code = rule_dir.name
    if _snapshots().is_dry_run_rule(rule_dir):
        assert _snapshots().dry_run_warnings(rule_dir, "good") == []
        return
    good = fixture(rule_dir, "good")
    if good.is_dir() or good.suffix == ".nc":
        assert [row for row in machine_findings(good, selection(rule_dir)) if row[2] == code] == []
        return
    assert [d for d in lint(good, select=selection(rule_dir)) if d.code == code] == []


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=[p.name for p in RULE_DIRS])
def test_good_fixture_has_no_errors_at_all(rule_dir):
    """The good variant is a correct list: no rule reports an error or warning on it."""
    good = fixture(rule_dir, "good")
    if good.is_dir() or good.suffix == ".nc":
        assert [row for row in machine_findings(good, None)] == []
        return
    found = [d for d in lint(good) if d.severity.value != "info"]
    assert found == []


def test_every_rule_has_fixtures():
    missing = [code for code in registry() if not list((FIXTURES / "rules" / code).glob("bad.*"))]
    assert missing == []


def test_lis203_similarity_is_what_difflib_would_choose():
    # The rule scores each written word once (message and fix share it); the choice must stay the one
    # difflib.get_close_matches makes for the message (cutoff 0.6) and for the fix (two at 0.8).
    import difflib
    import random

    from achslint.rules.lis203_unknown_symbol import _similar

    accepted = ("TORQ", "IGNORE_ABS_POS", "DISABLED", "CONTINUOUS", "ZERO_PULSE", "NO_ZERO_PULSE", "TORQUE")
    rnd = random.Random(7)
    for _ in range(2000):
        text = "".join(rnd.choice("TORQUEZEROPULSAB_ICDN") for _ in range(rnd.randint(1, 14)))
        chosen = tuple(rnd.sample(accepted, rnd.randint(1, len(accepted))))
        for n, cutoff in ((1, 0.6), (2, 0.8)):
            expected = difflib.get_close_matches(text, chosen, n=n, cutoff=cutoff)
            assert [s for score, s in _similar(text, chosen) if score >= cutoff][:n] == expected


@pytest.mark.parametrize(
    ("name", "number", "expected"),
    [
        ("default_mds.lis", "0", []),  # what the CNC requires of a default list (P-ERR-110300)
        ("default_mds.lis", "-1", [("LIS506", "error")]),  # one finding: LIS202 leaves it to LIS506
        ("default_mds.lis", "7", [("LIS506", "error")]),
        ("achsmds1.lis", "0", [("LIS202", "error")]),  # an axis needs a logical number of at least 1
        ("achsmds1.lis", "7", []),
    ],
)
def test_the_logical_axis_number_of_a_default_list_and_of_an_axis(name, number, expected):
    found = lint(f"kopf.achs_nr  {number}\nEnde\n".encode(), name=name)
    assert [(d.code, d.severity.value) for d in found if d.code in ("LIS202", "LIS506")] == expected
