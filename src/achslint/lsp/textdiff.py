"""Which lines changed between two versions of a document, in time that grows with its length.

The editor receives formatting and fix-all results as edits. difflib's SequenceMatcher finds
the fewest changed lines but can take time quadratic in the number of lines (97 s for a 1 MB
list); the formatter and the fixer change lines in place and drop or add a few, so a simpler
comparison finds the same edits for them:

1. lines that occur exactly once in each version are matched up (patience diff), keeping the
   longest run of such matches that is in order in both;
2. between two matched lines (and before the first, after the last), the lines both sides
   start and end with are unchanged; when both sides then have the same number of lines,
   each line is compared with its counterpart (the formatter keeps the line count), else the
   stretch is replaced as a whole.

The result is always correct (applying the blocks gives the new version); it is minimal for
changes in place and for inserted or removed lines between distinct lines.
"""

from __future__ import annotations

from bisect import bisect_left
from collections.abc import Sequence

Block = tuple[int, int, int, int]  # old[i1:i2] is replaced by new[j1:j2]


def changed_blocks(old: Sequence[str], new: Sequence[str]) -> list[Block]:
    """The replaced stretches that turn `old` into `new`, in order and not overlapping."""
    blocks: list[Block] = []
    after_i, after_j = 0, 0  # the first lines after the last matched pair
    for i, j in [*_unique_matches(old, new), (len(old), len(new))]:
        _compare(old, new, after_i, i, after_j, j, blocks)
        after_i, after_j = i + 1, j + 1
    return blocks


def _compare(
    old: Sequence[str], new: Sequence[str], i1: int, i2: int, j1: int, j2: int, out: list[Block]
) -> None:
    """Append the blocks that turn old[i1:i2] into new[j1:j2]."""
    while i1 < i2 and j1 < j2 and old[i1] == new[j1]:
        i1, j1 = i1 + 1, j1 + 1
    while i1 < i2 and j1 < j2 and old[i2 - 1] == new[j2 - 1]:
        i2, j2 = i2 - 1, j2 - 1
    if i1 == i2 and j1 == j2:
        return
    if i2 - i1 != j2 - j1:
        out.append((i1, i2, j1, j2))
        return
    run = None  # the first line of the current stretch of changed lines
    for offset in range(i2 - i1 + 1):
        same = offset == i2 - i1 or old[i1 + offset] == new[j1 + offset]
        if not same and run is None:
            run = offset
        elif same and run is not None:
            out.append((i1 + run, i1 + offset, j1 + run, j1 + offset))
            run = None


def _unique_matches(old: Sequence[str], new: Sequence[str]) -> list[tuple[int, int]]:
    """Pairs (i, j) with old[i] == new[j], a line found once in each, increasing in both i and j."""
    counts: dict[str, int] = {}
    for line in old:
        counts[line] = counts.get(line, 0) + 1
    where_old: dict[str, int] = {line: i for i, line in enumerate(old) if counts[line] == 1}
    seen: dict[str, int] = {}
    for j, line in enumerate(new):
        if line in where_old:
            seen[line] = -1 if line in seen else j
    pairs = sorted((where_old[line], j) for line, j in seen.items() if j >= 0)
    return _increasing(pairs)


def _increasing(pairs: list[tuple[int, int]]) -> list[tuple[int, int]]:
    """The longest run of `pairs` (sorted by i) whose j also increases (patience sorting)."""
    tails: list[int] = []  # tails[k]: the smallest last j of an increasing run of length k + 1
    tail_index: list[int] = []  # the pair that ends it
    previous: list[int] = [-1] * len(pairs)
    for index, (_, j) in enumerate(pairs):
        k = bisect_left(tails, j)
        if k == len(tails):
            tails.append(j)
            tail_index.append(index)
        else:
            tails[k] = j
            tail_index[k] = index
        previous[index] = tail_index[k - 1] if k else -1
    run = []
    index = tail_index[-1] if tail_index else -1
    while index >= 0:
        run.append(pairs[index])
        index = previous[index]
    return run[::-1]
