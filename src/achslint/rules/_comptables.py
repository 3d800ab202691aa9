"""The tables of an axis compensation list as LIS704 and LIS705 read them: each table's entries, the count
parameters that size it (P-COMP-00004, -00010/-00011, -00020, -00042), the members an entry needs, and the
largest size its `max_points` allows (P-COMP-00059 … -00062)."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from itertools import product
from typing import TYPE_CHECKING

from ._kindvalues import entries, whole

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from ._kindvalues import Values

GRID_LIMIT = 1 << 20  # larger tables are out of range (LIS705), not a million missing entries


@dataclass(frozen=True)
class TableKind:
    prefix: str  # `kw.ssfk.table[i].`
    counts: tuple[tuple[str, int], ...]  # (count parameter, 1 when it is a last index, 0 when a number)
    members: tuple[str, ...]  # what every entry needs
    max_points: str  # the parameter that bounds its size
    default_max: int  # its default


SSFK = TableKind("kw.ssfk.table[i].", (("kw.ssfk.kw_nr_max", 0),), ("pos",), "kw.ssfk.max_points", 1500)
TABLES = (
    SSFK,
    TableKind(
        "kw.crosscomp.table[i].",
        (("kw.crosscomp.last_index", 1),),
        ("setpoint", "correction"),
        "kw.crosscomp.max_points",
        1001,
    ),
    # table[j][i]: j runs over master axis 2, i over master axis 1 (P-COMP-00016)
    TableKind(
        "kw.crosscomp2.table[i][i].",
        (("kw.crosscomp2.last_index_master2", 1), ("kw.crosscomp2.last_index_master1", 1)),
        ("correction",),
        "kw.crosscomp2.max_points",
        10201,
    ),
    TableKind(
        "frict_comp.table[i].", (("frict_comp.table_entries", 0),), ("in", "out"), "frict_comp.max_points", 20
    ),
)


@dataclass(frozen=True)
class Table:
    """One table of a compensation list as written."""

    kind: TableKind
    sizes: tuple[int, ...]  # entries per index, from the counts
    counts: tuple[Setting | None, ...]  # the count assignments (None: not written)
    written: dict[tuple[int, ...], Values]  # the entries the list writes, by indices

    @property
    def size(self) -> int:
        total = 1
        for size in self.sizes:
            total *= size
        return total

    def counted(self, verb: str) -> str:
        """The counts as written, with `verb` in the right number: "`kw.ssfk.kw_nr_max` = 3 gives"."""
        words = []
        for (path, _), count in zip(self.kind.counts, self.counts, strict=True):
            value = f"{count.line.value}" if count is not None else "0 (not written)"
            words.append(f"`{path}` = {value}")
        return " and ".join(words) + f" {verb}{'s' if len(words) == 1 else ''}"

    def name(self, indices: tuple[int, ...]) -> str:
        """`kw.ssfk.table[3]`."""
        head = self.kind.prefix[:-1]
        for index in indices:
            head = head.replace("[i]", f"[{index}]", 1)
        return head

    def inside(self, indices: tuple[int, ...]) -> bool:
        return all(index < size for index, size in zip(indices, self.sizes, strict=True))

    def span(self) -> str:
        """The entries the counts give, in words: `kw.ssfk.table[0] … kw.ssfk.table[4]`."""
        if self.size == 0:
            return "no entry"
        first, last = self.name((0,) * len(self.sizes)), self.name(tuple(size - 1 for size in self.sizes))
        return first if first == last else f"{first} … {last}"

    def required(self, values: Values) -> tuple[str, ...]:
        """The members each entry needs: `neg` too for bilateral leadscrew compensation (P-COMP-00021) and
        `setpoint` too when its points are not equidistant (interval 0, P-COMP-00018)."""
        if self.kind is not SSFK:
            return self.kind.members
        needed = list(self.kind.members)
        bilateral = values.get("kw.ssfk.bilateral")
        if bilateral is not None and bilateral.value in (1, True):
            needed.append("neg")
        if not whole(values.get("kw.ssfk.interval")):
            needed.append("setpoint")
        return tuple(needed)

    def missing(self, values: Values) -> Iterator[str]:
        """Every member an entry inside the counts needs and the list does not write."""
        if self.size > GRID_LIMIT:
            return
        needed = self.required(values)
        for indices in product(*(range(size) for size in self.sizes)):
            members = self.written.get(indices, {})
            for member in needed:
                if member not in members:
                    yield f"{self.name(indices)}.{member}"

    def max_points(self, values: Values) -> tuple[int, Setting | None]:
        """The largest size the list allows, and its assignment (None: the default; a 0 written is the
        default too, P-COMP-00061)."""
        setting = values.get(self.kind.max_points)
        written = whole(setting)
        return (written, setting) if written else (self.kind.default_max, None)


def tables(values: Values, unusable: set[str]) -> Iterator[Table]:
    """The tables a compensation list writes an entry or a count of; not those with a count (or their
    max_points) written with a value the list family reports (`unusable`): that count is not known."""
    for kind in TABLES:
        counts = tuple(values.get(path) for path, _ in kind.counts)
        written = entries(values, kind.prefix)
        if not written and all(count is None for count in counts):
            continue
        if any(path in unusable for path, _ in kind.counts) or kind.max_points in unusable:
            continue
        if kind is SSFK and {"kw.ssfk.interval", "kw.ssfk.bilateral"} & unusable:
            continue  # which members an entry needs is not known
        if any(count is not None and whole(count) is None for count in counts):
            continue  # a count that is not a whole number: the list family's finding
        # a count not written has its default 0: no entry for a number, one entry (index 0) for a last index
        sizes = tuple(
            max((whole(count) or 0) + last, 0) for count, (_, last) in zip(counts, kind.counts, strict=True)
        )
        yield Table(kind, sizes, counts, written)
