"""`closest.close_matches` answers exactly what difflib.get_close_matches answers (LIS101's suggestions)."""

from __future__ import annotations

import difflib

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from achslint.catalogue import catalogue
from achslint.core.closest import close_matches, ratio_bound
from achslint.rules.lis101_unknown_parameter import _clear_winner

from .conftest import examples

pytest.importorskip("rapidfuzz")

NAMES = list(catalogue()._candidates)
LETTERS = "abcdefghijklmnopqrstuvwxyz._[]0"


@st.composite
def misspelt(draw: st.DrawFn) -> str:
    """A catalogue name with a few characters replaced, dropped or added (or a random word)."""
    if draw(st.booleans()):
        return draw(st.text(LETTERS, max_size=40))
    word = draw(st.sampled_from(NAMES))
    for _ in range(draw(st.integers(1, 5))):
        at = draw(st.integers(0, len(word)))
        char = draw(st.sampled_from(LETTERS))
        edit = draw(st.sampled_from(["replace", "drop", "add"]))
        if edit == "replace":
            word = word[:at] + char + word[at + 1 :]
        elif edit == "drop":
            word = word[:at] + word[at + 1 :]
        else:
            word = word[:at] + char + word[at:]
    return word


@settings(max_examples=examples(400, 12), deadline=None)
@given(misspelt(), st.integers(1, 5), st.sampled_from([0.3, 0.6, 0.6, 0.75, 0.9, 1.0]))
def test_same_answer_as_difflib(word: str, n: int, cutoff: float) -> None:
    assert close_matches(word, NAMES, n, cutoff) == difflib.get_close_matches(word, NAMES, n, cutoff)


@settings(max_examples=examples(400, 30), deadline=None)
@given(misspelt(), st.lists(misspelt(), min_size=1, max_size=3))
def test_lis101_decides_as_with_the_exact_ratios(word: str, others: list[str]) -> None:
    # The bound is never below difflib's ratio (either order), so LIS101 skips exact ratios only where they
    # cannot change its decision: the best candidate at 0.85 or more and 0.05 ahead of the next one.
    candidates = close_matches(word, NAMES) or others
    for name in candidates:
        assert ratio_bound(word, name) >= difflib.SequenceMatcher(None, word, name).ratio()
        assert ratio_bound(word, name) >= difflib.SequenceMatcher(None, name, word).ratio()
    ratio = difflib.SequenceMatcher(None, word, candidates[0]).ratio()
    runner_up = difflib.SequenceMatcher(None, word, candidates[1]).ratio() if len(candidates) > 1 else 0.0
    assert _clear_winner(word, candidates) == (ratio >= 0.85 and ratio - runner_up >= 0.05)


def test_ties_and_the_exact_cutoff_are_difflibs() -> None:
    # 'kenngrranzeige' scores exactly 0.6 against 'kenngr.ref_richt' (18 of 30 characters): a rough
    # float cut at 0.6 drops it, difflib keeps it. Equal ratios are ordered by name, largest first.
    word = "kenngrranzeige"
    assert difflib.SequenceMatcher(None, "kenngr.ref_richt", word).ratio() == 0.6
    expected = ["kenngr.anzeige", "kenngr.swe_toleranz", "kenngr.ref_richt"]
    assert close_matches(word, NAMES) == difflib.get_close_matches(word, NAMES) == expected
    tied = ["ab", "ba", "aa", "bb"]
    assert close_matches("ab", tied, 4, 0.0) == difflib.get_close_matches("ab", tied, 4, 0.0)


def test_nothing_to_compare() -> None:
    assert close_matches("x", [], 3) == [] and close_matches("x", NAMES, 0) == []
    assert close_matches("", ["", "a"], 2, 0.0) == difflib.get_close_matches("", ["", "a"], 2, 0.0)
