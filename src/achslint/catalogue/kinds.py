"""List kinds: which catalogue a list is checked against, named by the start-up list or told by content.

The CNC reads a dozen kinds of list in the same text format. Each kind has a parameter catalogue generated
from the vendor's parameter table (`tools/build_kinds.py` writes `data/kinds/<table>.json`); the axis kinds
use the axis catalogue (`achslint.catalogue`). A kind's catalogue is read the first time it is asked for,
so linting axis lists never reads the others.

| kind                      | list                            | ids    | table                   |
|---------------------------|---------------------------------|--------|-------------------------|
| `axis`, `default_axis`    | axis list, default axis list    | P-AXIS | the axis catalogue      |
| `channel`,                | channel list,                   | P-CHAN | params-chan.tsv         |
| `default_channel`         | default channel list            |        |                         |
| `startup`                 | start-up list                   | P-STUP | params-stup.tsv         |
| `tools`                   | tool data list                  | P-TOOL | params-tool.tsv         |
| `zero_offsets`            | zero offset list                | P-ZERO | params-zero.tsv         |
| `clamp_offsets`           | clamp position offset list      | P-CLMP | params-clmp.tsv         |
| `compensation`            | axis compensation list          | P-COMP | params-comp.tsv         |
| `manual`                  | manual mode list                | P-MANU | params-manu.tsv         |
| `external_variables`      | external variable list          | P-EXTV | params-extv.tsv         |
| `realtime`                | real-time configuration list    | P-RTCF | params-rtcf.tsv         |
| `scene`                   | scene configuration list        | P-SECO | params-seco.tsv         |
| `volumetric_compensation` | volumetric compensation list    | P-VOLC | params-volc.tsv         |
| `hardware`                | hardware configuration list     | P-HWCF | params-hwcf.tsv         |
| `cmld`                    | P-CMLD list (`ddl[i]` entries)  | P-CMLD | params-cmld.tsv         |
| `hmi_objects`,            | HMI / channel object lists,     | -      | none (not checked yet)  |
| `channel_objects`,        | cam table list                  |        |                         |
| `cam_tables`              |                                 |        |                         |

A default list cannot be told from its content (it holds the same parameters as the list it lies under):
only the start-up list's entry (`default_achs_mds`, `default_sda_mds`) makes a list a default list. The
reference tables do not say which start-up entry names a P-CMLD list, so `cmld` is known by content only.
"""

from __future__ import annotations

import json
import re
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from functools import cache
from pathlib import Path

from ..syntax.parser import ASSIGNMENT, COMMENT, ListFile, path_pattern
from . import Catalogue, catalogue

DATA = Path(__file__).resolve().parent / "data" / "kinds"
INDEX_FILE = "index.json"  # every kind table's parameter paths, for telling a list's kind from its content


@dataclass(frozen=True)
class Kind:
    """A kind of list: `id` as configuration and output spell it, `name` for people, the parameter-id
    prefix its catalogue uses (`P-CHAN`), and the reference table its catalogue is built from (`chan`;
    None for the axis kinds, which use the axis catalogue, and for kinds without a catalogue yet)."""

    id: str
    name: str
    prefix: str | None = None
    table: str | None = None

    @property
    def a_name(self) -> str:
        """The name after its article, for messages: "an axis list", "a channel list"."""
        return f"{'an' if self.name[0] in 'aeiou' else 'a'} {self.name}"

    @property
    def has_catalogue(self) -> bool:
        return self.table is not None or self.prefix == AXIS_PREFIX

    def catalogue(self) -> Catalogue | None:
        """This kind's parameters, read on first use (None for a kind achslint has no catalogue of)."""
        if self.table is not None:
            return load_table(self.table)
        return catalogue() if self.prefix == AXIS_PREFIX else None


AXIS_PREFIX = "P-AXIS"

AXIS = Kind("axis", "axis list", AXIS_PREFIX)
DEFAULT_AXIS = Kind("default_axis", "default axis list", AXIS_PREFIX)
CHANNEL = Kind("channel", "channel list", "P-CHAN", "chan")
DEFAULT_CHANNEL = Kind("default_channel", "default channel list", "P-CHAN", "chan")
STARTUP = Kind("startup", "start-up list", "P-STUP", "stup")
TOOLS = Kind("tools", "tool data list", "P-TOOL", "tool")
ZERO_OFFSETS = Kind("zero_offsets", "zero offset list", "P-ZERO", "zero")
CLAMP_OFFSETS = Kind("clamp_offsets", "clamp position offset list", "P-CLMP", "clmp")
COMPENSATION = Kind("compensation", "axis compensation list", "P-COMP", "comp")
MANUAL = Kind("manual", "manual mode list", "P-MANU", "manu")
EXTERNAL_VARIABLES = Kind("external_variables", "external variable list", "P-EXTV", "extv")
REALTIME = Kind("realtime", "real-time configuration list", "P-RTCF", "rtcf")
SCENE = Kind("scene", "scene configuration list", "P-SECO", "seco")
VOLUMETRIC_COMPENSATION = Kind("volumetric_compensation", "volumetric compensation list", "P-VOLC", "volc")
HARDWARE = Kind("hardware", "hardware configuration list", "P-HWCF", "hwcf")
CMLD = Kind("cmld", "P-CMLD list (ddl[i] entries)", "P-CMLD", "cmld")
HMI_OBJECTS = Kind("hmi_objects", "HMI object list")
CHANNEL_OBJECTS = Kind("channel_objects", "channel object list")
CAM_TABLES = Kind("cam_tables", "cam table list")

KINDS: tuple[Kind, ...] = (
    AXIS,
    DEFAULT_AXIS,
    CHANNEL,
    DEFAULT_CHANNEL,
    STARTUP,
    TOOLS,
    ZERO_OFFSETS,
    CLAMP_OFFSETS,
    COMPENSATION,
    MANUAL,
    EXTERNAL_VARIABLES,
    REALTIME,
    SCENE,
    VOLUMETRIC_COMPENSATION,
    HARDWARE,
    CMLD,
    HMI_OBJECTS,
    CHANNEL_OBJECTS,
    CAM_TABLES,
)
BY_ID: dict[str, Kind] = {kind.id: kind for kind in KINDS}

# The kinds content can tell apart: one per catalogue (a default list reads like the list it lies under).
CONTENT_KINDS: tuple[Kind, ...] = (
    AXIS,
    *(kind for kind in KINDS if kind.table and kind.id != "default_channel"),
)
BY_PREFIX: dict[str, Kind] = {kind.prefix: kind for kind in CONTENT_KINDS if kind.prefix}
BY_TABLE: dict[str, Kind] = {kind.table: kind for kind in CONTENT_KINDS if kind.table}
TABLES: tuple[str, ...] = tuple(BY_TABLE)  # the reference tables a kind catalogue is built from

# Start-up list entries that name a list file -> the kind of that list (P-STUP titles "Name of the list
# file ..."; spellings as the SDK's hochlauf.lis writes them, indices as `[i]`).
ENTRY_KINDS: dict[str, Kind] = {
    "achs_mds[i]": AXIS,  # P-STUP-00015
    "default_achs_mds": DEFAULT_AXIS,  # P-STUP-00035
    "sda_mds[i]": CHANNEL,  # P-STUP-00009
    "default_sda_mds": DEFAULT_CHANNEL,  # P-STUP-00034
    "werkz_data[i]": TOOLS,  # P-STUP-00010
    "nullp_data[i]": ZERO_OFFSETS,  # P-STUP-00011
    "pzv_data[i]": CLAMP_OFFSETS,  # P-STUP-00012
    "hand_mds": MANUAL,  # P-STUP-00013
    "achs_kw[i]": COMPENSATION,  # P-STUP-00017 (axis assignment in achs_kw_log_ax_nr[i], P-STUP-00036)
    "ve_var[i]": EXTERNAL_VARIABLES,  # P-STUP-00146
    "rtconf_lis": REALTIME,  # P-STUP-00135
    "hw_configuration_list": HARDWARE,  # P-STUP-00136
    "scene_mds[i]": SCENE,  # P-STUP-00137
    "vol_comp[i].file_name": VOLUMETRIC_COMPENSATION,  # P-STUP-00101
    "hmi[i].objects": HMI_OBJECTS,  # P-STUP-00024
    "channel[i].objects": CHANNEL_OBJECTS,  # P-STUP-00026
    "cam_table_loader": CAM_TABLES,  # P-STUP-00130
}


def entry_kind(key: str) -> Kind | None:
    """The kind of list a start-up entry names (`sda_mds[0]` -> channel), None for other entries."""
    return ENTRY_KINDS.get(path_pattern(key)[0])


@cache
def load_table(table: str) -> Catalogue:
    """The catalogue generated from one reference table (`chan`), read once per process."""
    text = (DATA / f"{table}.json").read_text(encoding="utf-8")
    return Catalogue(json.loads(text))


@cache
def path_index() -> dict[str, tuple[str, ...]]:
    """Index-normalised path (`gruppe[i].achse[i].bezeichnung`) -> the kinds whose table has it (not the
    axis kinds: the axis catalogue answers for those)."""
    data = json.loads((DATA / INDEX_FILE).read_text(encoding="utf-8"))
    owners: dict[str, list[str]] = {}
    for table, paths in data["paths"].items():
        for path in paths:
            owners.setdefault(path, []).append(BY_TABLE[table].id)
    return {path: tuple(kinds) for path, kinds in owners.items()}


UNKNOWN = "unknown"
ID_WEIGHT = 2  # a parameter id in a comment counts as much as two recognised paths
SAMPLE_LINES = 4096  # the lines kind_of reads


@dataclass(frozen=True)
class KindGuess:
    """What a list's content says about its kind.

    `kind` is None ("unknown") when nothing in the list belongs to any catalogue, or when two kinds other
    than the axis kind have the same score. `paths` counts, per kind id, the assignments whose parameter
    is in that kind's catalogue (a path several catalogues share counts for each); `ids` counts the lines
    whose comment carries a parameter id of that kind (`( P-CHAN-00036 :`); `unknown` counts assignments
    no catalogue knows; `lines` is how many lines were read.
    """

    kind: Kind | None
    paths: Mapping[str, int] = field(default_factory=dict)
    ids: Mapping[str, int] = field(default_factory=dict)
    unknown: int = 0
    lines: int = 0

    @property
    def id(self) -> str:
        return self.kind.id if self.kind is not None else UNKNOWN

    def score(self, kind_id: str) -> int:
        return self.paths.get(kind_id, 0) + ID_WEIGHT * self.ids.get(kind_id, 0)


_INDEX = re.compile(r"\[[0-9]+\]")  # an index as written; `path_pattern` without collecting the numbers

# Written path -> the content kinds whose catalogue has it; shared by every call (lists repeat paths).
_owners: dict[str, tuple[str, ...]] = {}


def _owners_of(path: str) -> tuple[str, ...]:
    found = _owners.get(path)
    if found is None:
        if len(_owners) > 1 << 16:
            _owners.clear()  # bounded: pathological inputs with endless distinct names
        owners = path_index().get(_INDEX.sub("[i]", path) if "[" in path else path, ())
        if catalogue().resolve(path) is not None:
            owners = (AXIS.id, *owners)
        found = _owners[path] = owners
    return found


def kind_of(file: ListFile) -> KindGuess:
    """The kind of list `file` is, told from its content: its first `SAMPLE_LINES` lines before the end
    marker (a list shows its kind at its head; a 50,000-line list costs what a 4,096-line one does).

    Each assignment's path is looked up once per distinct spelling (indices normalised), and a parameter
    id in a line's comment is strong evidence. The kind with the highest score wins; a tie involving the
    axis kind goes to the axis kind (a list of `kopf.*` lines is read as an axis list, as before). A list
    without assignments or ids is an axis list, as an empty list always was.
    """
    lines = file.lines
    stop = min(file.end_index if file.end_index is not None else len(lines), SAMPLE_LINES)
    tally: dict[tuple[str, ...], int] = {}
    prefixes: dict[str, int] = {}
    owners_of = _owners.get
    for index in range(stop):
        line = lines[index]
        if line.kind == ASSIGNMENT:
            path = line.path
            if path:
                owners = owners_of(path)
                if owners is None:
                    owners = _owners_of(path)
                tally[owners] = tally.get(owners, 0) + 1
            text = line.rest
        elif line.kind == COMMENT:
            text = line.comment
        else:
            continue
        if text:
            at = text.find("P-")
            if at >= 0:  # `( P-CHAN-00036 :`: the prefix and its dash are enough (cheaper than a regex)
                prefix = text[at : at + 7]
                prefixes[prefix] = prefixes.get(prefix, 0) + 1
    ids = {
        BY_PREFIX[key[:6]].id: count
        for key, count in prefixes.items()
        if key[:6] in BY_PREFIX and key[6:] == "-"
    }
    paths: dict[str, int] = {}
    unknown = 0
    for owners, count in tally.items():
        if not owners:
            unknown += count
        for kind_id in owners:
            paths[kind_id] = paths.get(kind_id, 0) + count
    guess = KindGuess(None, paths, ids, unknown, stop)
    if not paths and not ids:
        return replace(guess, kind=None if unknown else AXIS)
    scores = {kind.id: guess.score(kind.id) for kind in CONTENT_KINDS}
    best = max(scores.values())
    leaders = [kind_id for kind_id, score in scores.items() if score == best]
    if AXIS.id in leaders:
        return replace(guess, kind=AXIS)
    return replace(guess, kind=BY_ID[leaders[0]] if len(leaders) == 1 else None)


AXIS_PROBE = 64  # lines looked at before the other kinds' catalogues are asked
EVIDENCE = 3  # parameter ids in comments, or paths of another kind (at least half the list), that decide


def content_kind(file: ListFile) -> Kind | None:
    """The kind `file`'s content clearly shows, None when it is not clear (too short, a tie, names of no
    catalogue). Lint reads an unclear list as an axis list (`linting.linter.list_kind`); LIS523 compares a
    clear kind with the start-up entry that names the file.

    A list whose first assignments are all axis parameters is an axis list without asking the other
    catalogues (they are read only for a list that may be of another kind). Only clear evidence makes a list
    another kind: an axis list full of typos must still be checked (and its typos found), so a few names
    another catalogue happens to have are not enough. An axis list is clear from `EVIDENCE` axis names (or
    P-AXIS ids in comments) on.
    """
    axis = catalogue()
    head = [line.path for line in file.lines[:AXIS_PROBE] if line.kind == ASSIGNMENT and line.path]
    if all(axis.resolve(path) is not None for path in head):
        return AXIS if len(head) >= EVIDENCE else None
    guess = kind_of(file)
    kind = guess.kind
    if kind is None:
        return None
    assignments = sum(1 for line in file.lines[: guess.lines] if line.kind == ASSIGNMENT)
    paths, ids = guess.paths.get(kind.id, 0), guess.ids.get(kind.id, 0)
    axis_paths = guess.paths.get(AXIS.id, 0)
    if kind.id == AXIS.id or axis_paths >= paths or 2 * axis_paths >= assignments:
        # mostly axis parameters, whatever comments cite
        clear = max(axis_paths, guess.ids.get(AXIS.id, 0)) >= EVIDENCE
        return AXIS if clear else None
    if ids >= EVIDENCE or (paths >= EVIDENCE and 2 * paths >= assignments):
        return kind
    return None
