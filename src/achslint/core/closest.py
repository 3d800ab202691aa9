"""The known names closest to a misspelt one: `difflib.get_close_matches`, answered fast.

difflib compares the word with every known name in Python, which costs milliseconds per word;
a list with a thousand distinct unknown names took seconds. Here rapidfuzz (C++) first bounds
every name's score, and difflib's own ratio is computed only for the few names whose bound can
still reach the result, best bound first. The answer is the one difflib gives, tie-breaking
included: difflib's ratio counts the characters of matching blocks, which always form a common
subsequence, so it never exceeds the Indel similarity 2 * LCS / (len(a) + len(b)) that
rapidfuzz computes exactly.
"""

from __future__ import annotations

import difflib
import heapq
from collections.abc import Sequence

_MARGIN = 0.05  # below the cutoff for rapidfuzz's rough float pass; the exact bound decides after it


def ratio_bound(a: str, b: str) -> float:
    """A number `difflib.SequenceMatcher(None, a, b).ratio()` never exceeds (either order), computed fast."""
    from rapidfuzz.distance import Indel  # imported here: only lists with unknown names pay for it

    length = len(a) + len(b)
    # The same arithmetic as difflib's ratio (2.0 * matches / length), with LCS for the matches.
    return Indel.similarity(a, b) / length if length else 1.0


def close_matches(word: str, candidates: Sequence[str], n: int = 3, cutoff: float = 0.6) -> list[str]:
    """What `difflib.get_close_matches(word, candidates, n, cutoff)` returns, in the same order."""
    return [name for _, name in scored_matches(word, candidates, n, cutoff)]


def scored_matches(
    word: str, candidates: Sequence[str], n: int = 3, cutoff: float = 0.6
) -> list[tuple[float, str]]:
    """`close_matches` with each name's ratio, `difflib.SequenceMatcher(None, name, word).ratio()`."""
    if n <= 0 or not candidates:
        return []
    from rapidfuzz import process
    from rapidfuzz.distance import Indel

    rough = process.extract(
        word,
        candidates,
        scorer=Indel.normalized_similarity,
        score_cutoff=max(cutoff - _MARGIN, 0.0),
        limit=None,
    )
    bounded = []
    for name, _, _ in rough:
        bound = ratio_bound(word, name)
        if bound >= cutoff:
            bounded.append((bound, name))
    bounded.sort(reverse=True)
    matcher = difflib.SequenceMatcher()
    matcher.set_seq2(word)  # as difflib does: the word is the second sequence (its junk heuristics)
    # A min-heap of the n best (ratio, name), compared as difflib's nlargest compares them.
    best: list[tuple[float, str]] = []
    for bound, name in bounded:
        if len(best) == n and bound < best[0][0]:
            break  # no later name can beat the n-th best, not even on a tie (bounds only fall from here)
        matcher.set_seq1(name)
        ratio = matcher.ratio()
        if ratio < cutoff:
            continue
        if len(best) < n:
            heapq.heappush(best, (ratio, name))
        elif (ratio, name) > best[0]:
            heapq.heapreplace(best, (ratio, name))
    return sorted(best, reverse=True)
