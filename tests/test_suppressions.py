"""`# noqa` suppressions and LIS009."""

from __future__ import annotations

from achslint.api import lint

BASE = "kenngr.antr_typ 1\ngetriebe[0].a_ref 500\ngetriebe[0].vb_refmax 20000\n"


def run(text: str, select=None):
    # The cam signal from the PLC (LIS321), last so that the lines above keep their numbers.
    return [
        (d.line, d.code)
        for d in lint((text + "lr_hw[0].cam_direct_access 0\nEnde\n").encode("latin-1"), select=select)
    ]


def test_end_of_line_noqa_with_codes():
    assert (4, "LIS302") in run(BASE + "getriebe[0].vb_reflow 100000\n")
    assert run(BASE + "getriebe[0].vb_reflow 100000   # noqa: LIS302\n") == []


def test_noqa_inside_a_paren_comment_and_several_codes():
    text = BASE + "getriebe[0].vb_reflow 100000   ( slow on purpose, noqa: LIS302, LIS403\n"
    found = lint((text + "lr_hw[0].cam_direct_access 0\nEnde\n").encode("latin-1"))
    assert [(d.line, d.code) for d in found] == [
        (4, "LIS009")
    ]  # LIS302 suppressed; LIS403 had nothing to suppress
    assert "LIS403" in found[0].message and "LIS302" not in found[0].message


def test_noqa_for_another_code_does_not_suppress():
    found = run(BASE + "getriebe[0].vb_reflow 100000   # noqa: LIS303\n")
    assert (4, "LIS302") in found and (4, "LIS009") in found


def test_bare_noqa_suppresses_everything_on_the_line():
    assert run(BASE + "getriebe[0].vb_reflow 100000   # noqa\n") == []


def test_file_level_noqa():
    text = "# achslint: noqa: LIS302\n" + BASE + "getriebe[0].vb_reflow 100000\n"
    assert run(text) == []
    assert run("# achslint: noqa\n" + BASE + "kenngr.ref_ricth 1\n") == []


def test_unused_file_level_noqa_is_reported():
    assert run("# achslint: noqa: LIS204\n" + BASE) == [(1, "LIS009")]


def test_codes_of_unselected_rules_are_not_unused():
    text = BASE + "getriebe[0].vb_reflow 1000   # noqa: LIS302\n"
    assert run(text, select=["LIS009"]) == []
    assert run(text) == [(4, "LIS009")]


def test_noqa_is_case_insensitive_and_not_part_of_a_word():
    assert run(BASE + "getriebe[0].vb_reflow 100000   # NOQA: lis302\n") == []
    assert (4, "LIS302") in run(BASE + "getriebe[0].vb_reflow 100000   ( see snoqa\n")
