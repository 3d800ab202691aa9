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


def test_kin_trafo_display_2_is_a_documented_value() -> None:
    """params-chan.tsv types P-CHAN-00145 BOOLEAN, while its own range text documents a value 2 (display
    active for multistep transformations only): LIS201 called it an error and offered to make it 1. The kind
    catalogue's override (tools/build_kinds.py OVERRIDES) reads it as the text documents it: 0, 1, 2."""
    assert codes("kin_trafo_display 2\n", "channel", ("LIS201", "LIS202")) == []
    assert codes("kin_trafo_display TRUE\n", "channel", ("LIS201", "LIS202", "LIS203")) == []
    assert codes("kin_trafo_display 3\n", "channel", ("LIS201", "LIS202")) == [("LIS202", 1)]


AXES = "".join(
    f"gruppe[0].achse[{i}].bezeichnung {name}\ngruppe[0].achse[{i}].log_achs_nr {i + 1}\n"
    for i, name in enumerate("XYZ")
)


def pair(group: int, index: int, master: int, slave: int) -> str:
    head = f"synchro_data.koppel_gruppe[{group}].paar[{index}]"
    return f"{head}.log_achs_nr_master {master}\n{head}.log_achs_nr_slave {slave}\n"


def test_coupling_groups_are_separate_coupling_specifications() -> None:
    # koppel_gruppe[i] is one coupling specification, switched on as a whole; two groups may couple one
    # slave to different masters (or the other way round) without the list contradicting itself
    text = AXES + pair(0, 0, 1, 2) + pair(1, 0, 3, 2) + pair(2, 0, 2, 1)
    assert codes(text, "channel", ("LIS706",)) == []
    # within one group the pairs still have to hold together
    assert codes(AXES + pair(0, 0, 1, 2) + pair(0, 1, 3, 2), "channel", ("LIS706",)) == [("LIS706", 10)]
    assert codes(AXES + pair(1, 0, 1, 2) + pair(1, 1, 2, 1), "channel", ("LIS706",)) == [("LIS706", 10)]
