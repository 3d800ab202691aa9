"""Build the catalogue of every list kind (src/achslint/catalogue/data/kinds/) from the reference tables.

Usage:
    python tools/build_kinds.py                       # ../shared/reference/params-<table>.tsv -> <table>.json
    python tools/build_kinds.py --reference DIR       # the tables from another folder
    python tools/build_kinds.py --check               # exit 1 when the committed files are not what it builds
    python tools/build_kinds.py --output DIR          # write (or check) somewhere else

The tables (one per kind of list: chan, stup, tool, zero, clmp, comp, manu, extv, rtcf, seco, volc, hwcf,
cmld; which kind each one is lives in `achslint.catalogue.kinds`) have the columns id, path (`[]` for each
index), type, default, unit, max_number, restart, symbols, range and title. Each table becomes one JSON
file with one parameter per line, in the entry layout of the axis catalogue (`Parameter`): paths with `[i]`,
the range text turned into numeric bounds where it is a bound (`1 ... 32`, `0 < x ≤ MAX(UNS32)`, a
parameter id of the same table), integer types bounded by their type limits otherwise, symbols as a
list, units per axis type (T linear, R rotary, S spindle) in the axis catalogue's spelling. A range text is
kept only when a bound or a length was read from it; the descriptive ones (value meanings in the vendor's
words) are left out. `index.json` holds every table's paths, which is all the kind detection reads.

Only the tables found in the reference folder are built, so a folder with two tables builds two files and
an index of those two. `--check` without the reference folder checks nothing and says so (exit 0): the
tables are not part of this repository. Runs on Python 3.10 and later.
"""

from __future__ import annotations

import argparse
import csv
import json
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))
sys.path.insert(0, str(ROOT / "tools"))

from achslint.catalogue import TYPE_LIMITS  # noqa: E402  (the one table of integer type limits)
from achslint.catalogue.kinds import BY_TABLE, INDEX_FILE, TABLES  # noqa: E402
from build_catalogue import parse_default, parse_range  # noqa: E402  (one reader of range and default texts)

REFERENCE = ROOT.parent / "shared" / "reference"
OUTPUT = ROOT / "src" / "achslint" / "catalogue" / "data" / "kinds"
COLUMNS = ("id", "path", "type", "default", "unit", "max_number", "restart", "symbols", "range", "title")

# The tables' unit ids -> the axis catalogue's unit spelling (catalogue/units.py). A parameter with two
# units has the first for linear axes and the second for rotary axes and spindles.
UNITS = {
    "UNIT_0_1_MICROMETER": "0.1um",
    "UNIT_0_1_MILLIDEGREE": "0.0001deg",
    "UNIT_MICROMETER_PER_SECOND": "um/s",
    "UNIT_MILLIDEGREE_PER_SECOND": "0.001deg/s",
    "UNIT_MILLIMETER_PER_SECOND_SQUARED": "mm/s^2",
    "UNIT_DEGREE_PER_SECOND_SQUARED": "deg/s^2",
    "UNIT_MILLIMETER_PER_SECOND_CUBED": "mm/s^3",
    "UNIT_DEGREE_PER_SECOND_CUBED": "deg/s^3",
    "UNIT_MILLIMETER": "mm",
    "UNIT_DEGREE": "deg",
    "UNIT_MILLIMETER_PER_MINUTE": "mm/min",
    "UNIT_MICROSECOND": "us",
    "UNIT_SECOND": "s",
    "UNIT_PERMILLE": "0.1%",
    "UNIT_PERCENT": "%",
    "UNIT_INCREMENT": "increments",
    "UNIT_REVOLUTION": "rev",
    "UNIT_REVOLUTION_PER_MINUTE": "rev/min",
    "UNIT_HERTZ": "Hz",
    "UNIT_TICK": "ticks",
    "UNIT_0_1_MICROMETER_PER_METER": "0.1um/m",
    "UNIT_0_1_MICROMETER_OR_MICROSECOND": "0.1um or us",
}
INTEGER_TYPES = {name for name in TYPE_LIMITS if name != "BOOLEAN"}
NUMERIC_TYPES = {*TYPE_LIMITS, "REAL64"}  # the types a range bounds (STRING, CHAR, ADDRESS, STRUCT have none)
_REFERENCE_ID = re.compile(r"P-[A-Z]{4}-[0-9]{5}")
_RUN_ON = re.compile(r"[a-z][A-Z][a-z]")  # "charactersThe ...": a lost line break, prose follows
_DASHED = re.compile(r"\s*([+-]?[0-9]+)\s+[-–]\s+([+-]?[0-9]+)\s*")  # "1 - 12": a range written with a dash
_INDEXED_NAME = re.compile(r"(\w)\[[a-z]\]")  # "0 ≤ time[i] ≤ ...": the compared name's index, dropped
# "1 ... 800 bytes": a range with the unit after its upper bound
_TRAILING_UNIT = re.compile(r"\s*([+-]?[0-9]+)\s*\.\.\.\s*([+-]?[0-9]+)\s+(?:bytes|characters)\s*")
STRING_TYPES = {"STRING", "CHAR"}  # the types a "Maximum of N characters" bounds


class TableError(SystemExit):
    """A table the tool cannot read: the message names the file, the line and what to fix."""

    def __init__(self, table: Path, line: int, problem: str):
        super().__init__(f"{table}:{line}: {problem}")


def read_rows(table: Path) -> list[tuple[int, dict[str, str]]]:
    """(line number, row) for every row of a reference table."""
    with table.open(encoding="utf-8", newline="") as handle:
        reader = csv.reader(handle, delimiter="\t", quoting=csv.QUOTE_NONE)
        header = next(reader, None)
        if header is None or tuple(name.strip() for name in header) != COLUMNS:
            raise TableError(table, 1, f"expected the header {' '.join(COLUMNS)} (tab-separated)")
        rows = []
        for number, cells in enumerate(reader, start=2):
            if not any(cell.strip() for cell in cells):
                continue
            if len(cells) != len(COLUMNS):
                raise TableError(
                    table, number, f"expected {len(COLUMNS)} tab-separated columns, found {len(cells)}"
                )
            rows.append((number, dict(zip(COLUMNS, cells, strict=True))))
    return rows


def bound(value: object, ptype: str) -> int | float | str | None:
    """A parsed range end as the catalogue keeps it: a number (integral for integer types, inside the
    type's limits), a parameter id, or None when the text was no bound ("application-specific", prose)."""
    if isinstance(value, str):
        return value if _REFERENCE_ID.fullmatch(value) else None
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        return None
    if ptype in TYPE_LIMITS:
        if isinstance(value, float) and not value.is_integer():
            return None  # "0 ... .1800000" for an integer: a rendering fault, not a bound
        low, high = TYPE_LIMITS[ptype]
        return min(max(int(value), low), high)
    return value


def units_of(text: str, table: Path, line: int) -> dict[str, str] | None:
    names = text.split()
    if not names:
        return None
    unknown = [name for name in names if name not in UNITS]
    if unknown:
        raise TableError(
            table, line, f"unit {unknown[0]} is not known to the tool: add it to UNITS in {__file__}"
        )
    if len(names) > 2:
        raise TableError(table, line, "expected one unit, or two (linear, then rotary)")
    linear, rotary = UNITS[names[0]], UNITS[names[-1]]
    return {"T": linear, "R": rotary, "S": rotary}


def index_bounds(text: str, path: str, table: Path, line: int) -> list[list[int]] | None:
    """`max_number` as bounds of the path's indices: one size for a path with one index, else one size per
    index (space-separated)."""
    sizes = text.split()
    if not sizes:
        return None
    placeholders = path.count("[i]")
    if not all(size.isdigit() and int(size) > 0 for size in sizes) or len(sizes) != placeholders:
        raise TableError(
            table, line, f"max_number {text.strip()!r} does not give one size per index of {path}"
        )
    return [[0, int(size) - 1] for size in sizes]


def _plain_range(text: str) -> str:
    """A range text in the spelling the range reader knows: `1 - 12` and `1 ... 800 bytes` as `1 ... 12`
    and `1 ... 800`, `0 ≤ time[i] ≤ MAX` without the compared name's index."""
    for spelling in (_DASHED, _TRAILING_UNIT):
        match = spelling.fullmatch(text)
        if match:
            return f"{match.group(1)} ... {match.group(2)}"
    return _INDEXED_NAME.sub(r"\1", text)


# Entries a table contradicts itself on, as its own text documents them (a documented value must not be
# called an error). Parameter id -> the fields that replace those the row gives.
OVERRIDES: dict[str, dict[str, object]] = {
    # P-CHAN-00145 kin_trafo_display is typed BOOLEAN, yet its range text documents 2 as well: "2: MCS
    # display function active (only for multistep transformation)"
    "P-CHAN-00145": {"type": "UNS16", "min": 0, "max": 2, "range_text": "0 ... 2"},
}


def entry_of(row: dict[str, str], table: Path, line: int) -> dict[str, object]:
    """One catalogue entry (keys in the order of the axis catalogue's entries)."""
    pid, ptype = row["id"].strip(), row["type"].strip()
    path = row["path"].strip().replace("[]", "[i]")
    if not pid or not path or not ptype:
        raise TableError(table, line, "id, path and type must not be empty")
    entry: dict[str, object] = {"id": pid, "path": path, "type": ptype}
    bounds = index_bounds(row["max_number"], path, table, line)
    if bounds:
        entry["index_bounds"] = bounds
    symbols = [symbol.strip() for symbol in row["symbols"].split(",") if symbol.strip()]
    if symbols:
        entry["symbols"] = symbols
    text = row["range"].strip()
    parsed = parse_range(_plain_range(text), ptype)
    taken = False
    if "max_length" in parsed and ptype in STRING_TYPES:  # "Maximum of 16 characters" of a UNS16: a doc slip
        entry["max_length"] = parsed["max_length"]
        taken = True
    for end in ("min", "max") if ptype in NUMERIC_TYPES else ():
        value = bound(parsed.get(end), ptype)
        if value is None:
            if ptype in INTEGER_TYPES:
                entry[end] = TYPE_LIMITS[ptype][0 if end == "min" else 1]
            continue
        entry[end] = value
        taken = True
        if parsed.get(f"{end}_strict"):
            entry[f"{end}_strict"] = True
    if taken:
        run_on = _RUN_ON.search(text)
        entry["range_text"] = text[: run_on.start() + 1] if run_on else text
    default = parse_default(row["default"], ptype, symbols or None)
    if ptype != "STRING" and default in ("FALSE", "TRUE"):
        default = int(default == "TRUE")
    if default is not None:
        entry["default"] = default
    units = units_of(row["unit"], table, line)
    if units:
        entry["units"] = units
    restart = row["restart"].strip().lower()
    if restart not in ("true", "false", ""):
        raise TableError(table, line, f"restart is {row['restart']!r}: expected true or false")
    if restart == "true":
        entry["restart"] = True
    title = row["title"].strip()
    if title:
        entry["title"] = title
    entry.update(OVERRIDES.get(pid, {}))
    return entry


def build_table(table: Path, name: str) -> dict[str, object]:
    """The catalogue of one reference table (`params-chan.tsv`, `chan`)."""
    prefix = BY_TABLE[name].prefix or ""
    parameters: list[dict[str, object]] = []
    seen: dict[str, int] = {}
    for line, row in read_rows(table):
        entry = entry_of(row, table, line)
        pid, path = str(entry["id"]), str(entry["path"])
        if not pid.startswith(prefix + "-"):
            raise TableError(table, line, f"{pid} is not a {prefix} id: is this the {name} table?")
        for key in (pid, path):
            if key in seen:
                raise TableError(table, line, f"{key} is already on line {seen[key]}")
            seen[key] = line
        parameters.append(entry)
    return {"version": 1, "table": name, "prefix": prefix, "parameters": parameters}


def dump(catalogue: dict[str, object]) -> str:
    """JSON with one parameter per line: compact, and diffs show which parameter changed."""
    head = [f" {json.dumps(key)}: {json.dumps(catalogue[key])}," for key in ("version", "table", "prefix")]
    entries = catalogue["parameters"]
    assert isinstance(entries, list)
    rows = ",\n".join("  " + json.dumps(entry, ensure_ascii=False) for entry in entries)
    return "\n".join(["{", *head, ' "parameters": [', rows, " ]", "}"]) + "\n"


def dump_index(paths: dict[str, list[str]]) -> str:
    """Every table's paths, one table per line."""
    rows = ",\n".join(
        f"  {json.dumps(name)}: {json.dumps(names, ensure_ascii=False)}" for name, names in paths.items()
    )
    return "\n".join(["{", ' "version": 1,', ' "paths": {', rows, " }", "}"]) + "\n"


def build(reference: Path) -> dict[str, str]:
    """File name -> text of every file the tables in `reference` give (each kind's JSON and the index)."""
    files: dict[str, str] = {}
    paths: dict[str, list[str]] = {}
    for name in TABLES:
        table = reference / f"params-{name}.tsv"
        if not table.is_file():
            continue
        catalogue = build_table(table, name)
        files[f"{name}.json"] = dump(catalogue)
        entries = catalogue["parameters"]
        assert isinstance(entries, list)
        paths[name] = [str(entry["path"]) for entry in entries]
    if not files:
        raise SystemExit(f"{reference}: no reference table (params-<table>.tsv for {', '.join(TABLES)})")
    files[INDEX_FILE] = dump_index(paths)
    return files


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--reference", type=Path, default=REFERENCE, help="folder with params-<table>.tsv")
    parser.add_argument("--output", type=Path, default=OUTPUT, help="folder the JSON files go to")
    parser.add_argument(
        "--check",
        action="store_true",
        help="change nothing; exit 1 if a committed file is not what the tables give",
    )
    args = parser.parse_args(argv)
    if not args.reference.is_dir():
        if args.check:
            print(f"{args.reference}: no reference folder, nothing checked (--reference DIR names one)")
            return 0
        raise SystemExit(f"{args.reference}: no such folder; --reference DIR names the folder of the tables")
    files = build(args.reference)
    if args.check:
        stale = [
            name
            for name, text in files.items()
            if not (args.output / name).is_file() or (args.output / name).read_text(encoding="utf-8") != text
        ]
        for name in stale:
            print(f"{args.output / name} is stale: run python tools/build_kinds.py", file=sys.stderr)
        return 1 if stale else _models(args.output, ["--check"])
    args.output.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (args.output / name).write_text(text, encoding="utf-8", newline="\n")
    print(f"wrote {len(files) - 1} kind catalogues and {INDEX_FILE} to {args.output}", file=sys.stderr)
    return _models(args.output, [])


def _models(output: Path, flags: list[str]) -> int:
    """The typed models of channel and start-up lists are generated from the packaged catalogues (those in
    OUTPUT): rebuilt, or checked, after them (tools/gen_model.py)."""
    if output.resolve() != OUTPUT.resolve():
        return 0
    import gen_model  # after the catalogues exist: the models are generated from them

    return int(gen_model.main(flags))


if __name__ == "__main__":
    sys.exit(main())
