"""Review of the lists of other kinds and the machine rules about them: each test is a small list or machine
that gave a finding the CNC has no reason for (or missed one), with the reason in a comment."""

from __future__ import annotations

from achslint.linting.linter import FileSettings, lint_file


def codes(text: str, kind: str, select: tuple[str, ...] = ()) -> list[tuple[str, int]]:
    """(code, line) of the findings on a list of `kind` (only the chosen codes when some are given)."""
    result = lint_file((text + "Ende\n").encode(), "list.lis", FileSettings(kind=kind))
    assert result.error is None
    return [(d.code, d.line) for d in result.diagnostics if not select or d.code in select]


def test_an_empty_slot_shares_no_name_with_an_axis() -> None:
    # log_achs_nr 0 leaves a path-axis slot empty (P-CHAN-00035): LIS508, LIS701 and LIS703 count no axis
    # there, so its name is no second axis of that name (error 20424 is about two axes of the channel)
    text = (
        "gruppe[0].achs_anzahl 2\n"
        "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 1\n"
        "gruppe[0].achse[1].bezeichnung Y\ngruppe[0].achse[1].log_achs_nr 2\n"
        "gruppe[0].achse[2].bezeichnung Y\ngruppe[0].achse[2].log_achs_nr 0\n"
    )
    assert codes(text, "channel", ("LIS701", "LIS702", "LIS703")) == []
    # two axes that are defined still clash
    clash = text.replace("achse[2].log_achs_nr 0", "achse[2].log_achs_nr 3").replace(
        "achs_anzahl 2", "achs_anzahl 3"
    )
    assert codes(clash, "channel", ("LIS702",)) == [("LIS702", 6)]
