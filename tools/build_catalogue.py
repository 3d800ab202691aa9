"""Build src/achslint/catalogue/data/catalogue.json from the parameter table kept in this repository.

Usage:
    python tools/build_catalogue.py            # tools/catalogue/params.tsv -> catalogue.json (+ model)
    python tools/build_catalogue.py --check    # exit 1 when the committed files are not what it builds
    python tools/build_catalogue.py --import-table GATHERED.tsv
                                               # replace tools/catalogue/params.tsv from a gathered table

`tools/catalogue/params.tsv` holds facts only, one row per axis parameter: id, path, old or misspelt
name, data type, range, units per axis type, default, drive type codes (P-AXIS-00020), CNC error ids,
short title, array bounds, axis types, restart flag and the manual page. Its range column keeps the
manual's range notation; this script turns it into structured bounds once, so that the linter never
parses it at run time. Everything the table cannot express (our own one-line descriptions, extra
aliases, known misspellings, achs_mode bits, parameters the table lacks) comes from
`tools/catalogue_overrides.toml`. The typed model (`src/achslint/model/generated.py`) is generated
from the catalogue in the same run. Runs on Python 3.10 and later.
"""

from __future__ import annotations

import argparse
import csv
import json
import re
import sys
from pathlib import Path

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from achslint.catalogue import TYPE_LIMITS  # noqa: E402  (the one table of integer type limits)

TABLE = ROOT / "tools" / "catalogue" / "params.tsv"
OVERRIDES = ROOT / "tools" / "catalogue_overrides.toml"
OUTPUT = ROOT / "src" / "achslint" / "catalogue" / "data" / "catalogue.json"
COLUMNS = (
    "id",
    "path",
    "alias",
    "alias_kind",
    "type",
    "range",
    "unit_T",
    "unit_R",
    "unit_S",
    "default",
    "drive_types",
    "errors",
    "title",
    "array_bounds",
    "axis_types",
    "restart",
    "source",
)

# Drive-type names used in the table's drive_types column -> P-AXIS-00020 codes.
DRIVE_CODES = {
    "conventional": [1],
    "sercos": [2],
    "profidrive": [3],
    "simulation": [4],
    "lightbus": [5],
    "terminal": [6],
    "rt-ethernet": [7],
    "canopen": [8],
    # The fixed-stop pages call the KUKA interface "DSE"; it appears as code 9
    # (generic drive interface) on one page and 17 in list comments.
    "kuka": [9, 17],
    "dse": [9, 17],
}

# Parameters the CNC only takes over at a restart (format facts §10 and notes).
RESTART_IDS = {
    "P-AXIS-00016",
    "P-AXIS-00018",
    "P-AXIS-00020",
    "P-AXIS-00036",
    "P-AXIS-00041",
    "P-AXIS-00048",
    "P-AXIS-00136",
    "P-AXIS-00230",
    "P-AXIS-00233",
    "P-AXIS-00234",
    "P-AXIS-00371",
    "P-AXIS-00426",
}

_NUMBER = r"[+-]?(?:0[xX][0-9A-Fa-f]+|\d+(?:\.\d*)?(?:[eE][+-]?\d+)?)"


def parse_number(text: str) -> int | float | None:
    text = text.strip().replace("'", "")
    if re.fullmatch(r"[+-]?0[xX][0-9A-Fa-f]+", text):
        return int(text, 16)
    if re.fullmatch(r"[+-]?\d+", text):
        return int(text)
    if re.fullmatch(r"[+-]?(\d+\.\d*|\.\d+|\d+)([eE][+-]?\d+)?", text):
        value = float(text)
        return int(value) if value.is_integer() and abs(value) < 2**63 and "e" not in text.lower() else value
    return None


def bound_value(text: str):
    """A range bound: a number, a type limit, a parameter reference or an expression string."""
    text = text.strip().strip("[]").strip()
    # "1000 (1000 = not active)", "0..3: 0 step-shaped, ..." and "200 (*)" carry
    # a remark after the number; an "application-specific" preset is no limit.
    remark = re.fullmatch(r"(\S+?)(?::.*|\s+\(.*\)|\s+Default value:.*)", text)
    if remark and "application-specific" not in text:
        text = remark.group(1)
    number = parse_number(text)
    if number is not None:
        return number
    match = re.fullmatch(r"(MIN|MAX)\s*\(?\s*(UNS|SGN)(\d+)\s*\)?", text)
    if match:
        kind = f"{match.group(2)}{int(match.group(3)):02d}"
        if kind == "SGN23":  # a typo for SGN32 on one manual page
            kind = "SGN32"
        limits = TYPE_LIMITS.get(kind)
        if limits:
            return limits[0] if match.group(1) == "MIN" else limits[1]
    if re.fullmatch(r"MAX\(REAL64\)", text):
        return None
    match = re.fullmatch(r"P[-.]AXIS-(\d{5})", text)
    if match:
        return f"P-AXIS-{match.group(1)}"
    return text or None


def normalise_range(text: str) -> str:
    text = text.split(";")[0].strip()
    text = text.replace("<=", "≤").replace(">=", "≥").replace("≤≤", "≤")
    text = re.sub(r"\s*(…|\.{2,4})\s*", " .. ", text)
    text = re.sub(r"MAX_(UNS|SGN)(\d+)", r"MAX(\1\2)", text)
    text = re.sub(r"MIN_(UNS|SGN)(\d+)", r"MIN(\1\2)", text)
    text = re.sub(r"\(\s*(UNS|SGN)", r"(\1", text)
    text = re.sub(r"MAX \(", "MAX(", text)
    return text


def parse_range(raw: str, ptype: str) -> dict:
    """Structured range from the free-text range column.

    Returns keys: min, max (number, "P-AXIS-nnnnn" or expression text),
    min_strict, max_strict, allowed (explicit value list), symbols, max_length.
    """
    result: dict = {}
    if not raw:
        return result
    length = re.search(r"max string length (\d+)", raw)
    if length:
        result["max_length"] = int(length.group(1))
    else:
        length = re.search(r"Maximum(?: of)? (\d+) characters", raw)
        if length:
            result["max_length"] = int(length.group(1))
    symbols = re.match(r"symbols:\s*(.+)$", raw)
    if symbols:
        names, codes = [], {}
        for item in symbols.group(1).split("|"):
            name, _, code = item.strip().partition("=")
            names.append(name)
            if code:
                codes[name] = int(code)
        result["symbols"] = names
        if codes:
            result["symbol_codes"] = codes
        return result
    text = normalise_range(raw)
    if re.fullmatch(r"0/1(\s*\(FALSE/TRUE\))?|0 / 1", text):
        return result
    if re.fullmatch(r"\d+(\s*[|,]\s*\d+)+(\s*\(.*\))?", text):
        result["allowed"] = [int(x) for x in re.findall(r"\d+", text.split("(")[0])]
        return result
    name = r"[A-Za-z_][\w .()-]*?|P[-.]AXIS-\d{5}|x"
    # A <= name <= B, also with strict comparisons.
    match = re.fullmatch(rf"(.+?)\s*(≤|<)\s*(?:{name})\s*(≤|<)\s*(.+?)", text)
    if match and not re.search(r"[<≤]", match.group(4)):
        low, high = bound_value(match.group(1)), bound_value(match.group(4))
        if _usable(low) or _usable(high):
            result.update(
                min=low, min_strict=match.group(2) == "<", max=high, max_strict=match.group(3) == "<"
            )
            return result
    match = re.fullmatch(rf"(.+?)\s*(≥|>)\s*(?:{name})\s*(≥|>)\s*(.+?)", text)
    if match:
        result.update(
            max=bound_value(match.group(1)),
            max_strict=match.group(2) == ">",
            min=bound_value(match.group(4)),
            min_strict=match.group(3) == ">",
        )
        return result
    match = re.fullmatch(r"\[?\s*(\S+(?:\(\w+\))?)\s*\.\.\s*(.+?)\]?", text)
    if match:
        low, high = bound_value(match.group(1)), bound_value(match.group(2))
        if isinstance(low, (int, float)):
            result.update(min=low, max=high)
            return result
    match = re.fullmatch(rf"({_NUMBER})\s*(≤|<)\s*(?:{name})", text)
    if match:
        result.update(min=bound_value(match.group(1)), min_strict=match.group(2) == "<")
        return result
    match = re.fullmatch(rf"(?:{name})?\s*>\s*({_NUMBER})", text)
    if match:
        result.update(min=bound_value(match.group(1)), min_strict=True)
        return result
    return result


def _usable(bound) -> bool:
    return isinstance(bound, (int, float)) or (isinstance(bound, str) and bound.startswith("P-AXIS-"))


def parse_default(raw: str, ptype: str, symbols: list[str] | None):
    """The default column as a value: a number, a symbol, text, a parameter reference or None."""
    raw = raw.strip()
    if raw in ("", "-"):
        return None
    if raw == "(empty string)":
        return ""
    match = re.fullmatch(r"([01]) \((FALSE|TRUE)\)", raw)
    if match:
        return int(match.group(1))
    if re.fullmatch(r"P-AXIS-\d{5}", raw):
        return raw
    number = parse_number(raw)
    if number is not None and ptype != "STRING":
        return number
    if ptype == "REAL64" and number is None:
        try:
            return float(raw)
        except ValueError:
            return None
    return raw


def parse_notes(notes: str) -> dict:
    """The facts in the gathered table's notes column (title, array bounds, axis types, restart)."""
    info: dict = {}
    title = re.search(r"title: ([^;]+)", notes)
    if title:
        info["title"] = title.group(1).strip()
    bounds = re.search(r"array bounds: ([^;]+)", notes)
    if bounds:
        info["array_bounds"] = {
            m.group(1): [int(m.group(2)), int(m.group(3))]
            for m in re.finditer(r"(\w+)\[(\d+)\.\.(\d+)\]", bounds.group(1))
        }
    axis = re.search(r"axis types ([TRS,]+)", notes)
    if axis:
        info["axis_types"] = axis.group(1).split(",")
    if re.search(r"not for spindles", notes):
        info["axis_types"] = [a for a in info.get("axis_types", ["T", "R", "S"]) if a != "S"]
    if re.search(r"not taken over on list update|change needs restart|ChangeRequiresRestart", notes):
        info["restart"] = True
    return info


def drive_codes(raw: str) -> list[int] | None:
    raw = raw.split("(page)")[0] if "(page)" in raw else raw
    codes: list[int] = []
    for part in re.split(r"[,;]", raw):
        word = part.strip().lower().split(" ")[0]
        if word in DRIVE_CODES:
            codes.extend(DRIVE_CODES[word])
    return sorted(set(codes)) or None


def unit_of(raw: str) -> str | None:
    raw = raw.strip()
    return None if raw in ("", "-") else raw


def clean_path(raw: str) -> str:
    return raw.strip().split(" ")[0]


def import_table(gathered: Path) -> list[dict[str, str]]:
    """Rows of our facts table from a gathered parameter table (columns p_axis_id, path, aliases, type,
    range, unit_T/R/S, default, drive_types, error_ids, source_url, notes): drive type names become
    P-AXIS-00020 codes, the notes become columns, only the first source address is kept."""
    rows = []
    with gathered.open(encoding="utf-8", newline="") as handle:
        for row in csv.DictReader(handle, delimiter="\t"):
            path = clean_path(row["path"])
            notes = parse_notes(row["notes"])
            alias = clean_path(row["aliases"]) if row["aliases"].strip() else ""
            codes = drive_codes(row["drive_types"]) or []
            restart = notes.get("restart") or row["p_axis_id"].strip() in RESTART_IDS
            rows.append(
                {
                    "id": row["p_axis_id"].strip(),
                    "path": path,
                    "alias": alias if alias != path else "",
                    "alias_kind": ("misspelling" if "spelling" in row["aliases"] else "old")
                    if alias and alias != path
                    else "",
                    "type": row["type"].strip(),
                    "range": row["range"].strip(),
                    **{f"unit_{axis}": unit_of(row[f"unit_{axis}"]) or "" for axis in "TRS"},
                    "default": row["default"].strip(),
                    "drive_types": " ".join(str(code) for code in codes),
                    "errors": " ".join(row["error_ids"].split()),
                    "title": notes.get("title", ""),
                    "array_bounds": " ".join(
                        f"{name}={low}..{high}" for name, (low, high) in notes.get("array_bounds", {}).items()
                    ),
                    "axis_types": ",".join(notes.get("axis_types", [])),
                    "restart": "1" if restart else "",
                    "source": (row["source_url"].split() or [""])[0],
                }
            )
    return rows


def write_table(rows: list[dict[str, str]], path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w", encoding="utf-8", newline="") as handle:
        writer = csv.DictWriter(handle, COLUMNS, delimiter="\t", lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)


def read_table(path: Path) -> list[dict[str, str]]:
    with path.open(encoding="utf-8", newline="") as handle:
        rows = list(csv.DictReader(handle, delimiter="\t"))
    for number, row in enumerate(rows, start=2):
        if None in row or any(value is None for value in row.values()):
            raise SystemExit(f"{path}:{number}: expected {len(COLUMNS)} tab-separated columns")
    return rows


def index_bounds(path: str, array_bounds: dict, defaults: dict) -> list[list[int]]:
    """Bounds for each `[i]` placeholder of the path, in order."""
    result = []
    for member in re.findall(r"(\w+)\[i\]", path):
        bound = array_bounds.get(member) or defaults.get(member)
        if bound is None:
            raise SystemExit(f"no array bounds known for {member!r} in {path}")
        result.append(list(bound))
    return result


def entry_of(row: dict[str, str], overrides: dict) -> dict:
    """One catalogue entry from a row of the facts table and the overrides."""
    pid, path, ptype = row["id"], row["path"], row["type"]
    extra = overrides.get("parameter", {}).get(pid, {})
    rng = parse_range(row["range"], ptype)
    entry: dict = {"id": pid, "path": path, "type": ptype}
    aliases = [{"path": row["alias"], "kind": row["alias_kind"] or "old"}] if row["alias"] else []
    aliases.extend(extra.get("aliases", []))
    if aliases:
        entry["aliases"] = aliases
    array_bounds = {
        name: [int(low), int(high)]
        for name, low, high in re.findall(r"(\w+)=(\d+)\.\.(\d+)", row["array_bounds"])
    }
    bounds = index_bounds(path, array_bounds, overrides.get("array_bounds", {}))
    if bounds:
        entry["index_bounds"] = bounds
    for key in ("symbols", "symbol_codes", "allowed", "max_length"):
        if key in rng:
            entry[key] = rng[key]
    for key in ("min", "max"):
        if rng.get(key) is not None:
            entry[key] = rng[key]
            if rng.get(f"{key}_strict"):
                entry[f"{key}_strict"] = True
    entry["range_text"] = row["range"]
    entry["default"] = parse_default(row["default"], ptype, entry.get("symbols"))
    units = {axis: row[f"unit_{axis}"] or None for axis in "TRS"}
    if any(units.values()):
        entry["units"] = units
    if row["drive_types"]:
        entry["drive_types"] = [int(code) for code in row["drive_types"].split()]
    for prefix, group_codes in overrides.get("drive_groups", {}).items():
        if path.startswith(prefix):
            entry["drive_group"] = group_codes
    if row["axis_types"]:
        entry["axis_types"] = row["axis_types"].split(",")
    if row["restart"] == "1":
        entry["restart"] = True
    if row["errors"]:
        entry["errors"] = row["errors"].split()
    if row["title"]:
        entry["title"] = row["title"]
    if extra.get("description"):
        entry["description"] = extra["description"]
    if row["source"]:
        entry["source"] = row["source"]
    entry.update(extra.get("set", {}))
    for key in extra.get("drop", []):
        entry.pop(key, None)
    return entry


def build(rows: list[dict[str, str]], overrides: dict) -> dict:
    """The catalogue: every row of the table, then the parameters the overrides add (`[add."P-AXIS-…"]`,
    with the table's columns as keys)."""
    known = {row["id"] for row in rows}
    added = []
    for pid, fields in overrides.get("add", {}).items():
        if pid in known:
            raise SystemExit(
                f'{OVERRIDES.name}: [add."{pid}"] is already a row of the table; use [parameter."{pid}"]'
            )
        added.append({column: str(fields.get(column, "")) for column in COLUMNS} | {"id": pid})
    return {
        "version": 1,
        "parameters": [entry_of(row, overrides) for row in rows + added],
        "misspellings": overrides.get("misspellings", {}),
        "bitfields": overrides.get("bitfields", {}),
        "drive_types": overrides.get("drive_types", {}),
    }


def dump(catalogue: dict) -> str:
    """JSON with one parameter per line: compact, and diffs show which parameter changed."""
    parts = ["{", f' "version": {catalogue["version"]},', ' "parameters": [']
    rows = [json.dumps(entry, ensure_ascii=False) for entry in catalogue["parameters"]]
    parts.append(",\n".join("  " + row for row in rows))
    parts.append(" ],")
    rest = [
        f' "{key}": {json.dumps(catalogue[key], ensure_ascii=False)}'
        for key in ("misspellings", "bitfields", "drive_types")
    ]
    parts.append(",\n".join(rest))
    parts.append("}")
    return "\n".join(parts) + "\n"


def catalogue_text(table: Path = TABLE, overrides: Path = OVERRIDES) -> str:
    """What catalogue.json should hold, built from the repository's files."""
    return dump(build(read_table(table), tomllib.loads(overrides.read_text(encoding="utf-8"))))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--import-table",
        type=Path,
        metavar="GATHERED_TSV",
        help="rewrite tools/catalogue/params.tsv from a gathered parameter table first",
    )
    parser.add_argument(
        "--check", action="store_true", help="change nothing; exit 1 if a generated file is stale"
    )
    parser.add_argument("--output", type=Path, default=OUTPUT)
    args = parser.parse_args(argv)
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    if args.import_table:
        rows = import_table(args.import_table)
        write_table(rows, TABLE)
        print(f"wrote {len(rows)} rows to {TABLE}", file=sys.stderr)
    import gen_model  # after the catalogue exists: the model is generated from it

    text = catalogue_text()
    if args.check:
        current = args.output.read_text(encoding="utf-8") if args.output.exists() else ""
        if current != text:
            print(f"{args.output} is stale: run python tools/build_catalogue.py", file=sys.stderr)
            return 1
        return gen_model.main(["--check"])
    args.output.parent.mkdir(parents=True, exist_ok=True)
    args.output.write_text(text, encoding="utf-8")
    print(f"wrote {text.count(chr(10) + '  {')} parameters to {args.output}", file=sys.stderr)
    return gen_model.main([])


if __name__ == "__main__":
    sys.exit(main())
