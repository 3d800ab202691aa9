"""Build src/achslint/data/catalogue.json from the project's parameter table.

Usage:
    python tools/build_catalogue.py PARAMS_TSV [--overrides tools/catalogue_overrides.toml]

The TSV (one row per axis parameter: id, path, aliases, type, range, units,
default, drive types, error ids, source, notes) is the collected fact base.
Its range and default columns are free text written for people; this script
turns them into structured data once, so that the linter never parses prose
at run time. Everything the table cannot express (our own one-line
descriptions, extra aliases, known misspellings, achs_mode bits) comes from
the overrides file.
"""

from __future__ import annotations

import argparse
import csv
import json
import re
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUTPUT = ROOT / "src" / "achslint" / "data" / "catalogue.json"

TYPE_LIMITS = {
    "BOOLEAN": (0, 1),
    "UNS08": (0, 2**8 - 1),
    "UNS16": (0, 2**16 - 1),
    "UNS32": (0, 2**32 - 1),
    "UNS64": (0, 2**64 - 1),
    "SGN08": (-(2**7), 2**7 - 1),
    "SGN16": (-(2**15), 2**15 - 1),
    "SGN32": (-(2**31), 2**31 - 1),
    "SGN64": (-(2**63), 2**63 - 1),
}

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
    "P-AXIS-00016", "P-AXIS-00018", "P-AXIS-00020", "P-AXIS-00036", "P-AXIS-00041",
    "P-AXIS-00048", "P-AXIS-00136", "P-AXIS-00230", "P-AXIS-00233", "P-AXIS-00234",
    "P-AXIS-00371", "P-AXIS-00426",
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
            result.update(min=low, min_strict=match.group(2) == "<", max=high, max_strict=match.group(3) == "<")
            return result
    match = re.fullmatch(rf"(.+?)\s*(≥|>)\s*(?:{name})\s*(≥|>)\s*(.+?)", text)
    if match:
        result.update(
            max=bound_value(match.group(1)), max_strict=match.group(2) == ">",
            min=bound_value(match.group(4)), min_strict=match.group(3) == ">",
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
        info["not_for_spindles"] = True
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


def index_bounds(path: str, array_bounds: dict, overrides: dict) -> list[list[int]]:
    """Bounds for each `[i]` placeholder of the path, in order."""
    result = []
    for member in re.findall(r"(\w+)\[i\]", path):
        bound = array_bounds.get(member) or overrides.get(member)
        if bound is None:
            raise SystemExit(f"no array bounds known for {member!r} in {path}")
        result.append(list(bound))
    return result


def build(tsv: Path, overrides_path: Path) -> dict:
    overrides = tomllib.loads(overrides_path.read_text(encoding="utf-8"))
    default_bounds = overrides.get("array_bounds", {})
    per_param = overrides.get("parameter", {})
    entries = []
    with tsv.open(encoding="utf-8", newline="") as handle:
        for row in csv.DictReader(handle, delimiter="\t"):
            pid = row["p_axis_id"].strip()
            path = clean_path(row["path"])
            ptype = row["type"].strip()
            notes = parse_notes(row["notes"])
            rng = parse_range(row["range"].strip(), ptype)
            extra = per_param.get(pid, {})
            entry: dict = {"id": pid, "path": path, "type": ptype}
            aliases = []
            if row["aliases"].strip():
                alias = clean_path(row["aliases"])
                if alias != path:
                    kind = "misspelling" if "spelling" in row["aliases"] else "old"
                    aliases.append({"path": alias, "kind": kind})
            aliases.extend(extra.get("aliases", []))
            if aliases:
                entry["aliases"] = aliases
            bounds = index_bounds(path, notes.get("array_bounds", {}), default_bounds)
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
            entry["range_text"] = row["range"].strip()
            entry["default"] = parse_default(row["default"], ptype, entry.get("symbols"))
            units = {axis: unit_of(row[f"unit_{axis}"]) for axis in "TRS"}
            if any(units.values()):
                entry["units"] = units
            codes = drive_codes(row["drive_types"])
            if codes:
                entry["drive_types"] = codes
            for prefix, group_codes in overrides.get("drive_groups", {}).items():
                if path.startswith(prefix):
                    entry["drive_group"] = group_codes
            if "axis_types" in notes:
                entry["axis_types"] = notes["axis_types"]
            if notes.get("not_for_spindles"):
                entry["axis_types"] = [a for a in entry.get("axis_types", ["T", "R", "S"]) if a != "S"]
            if notes.get("restart") or pid in RESTART_IDS:
                entry["restart"] = True
            if row["error_ids"].strip():
                entry["errors"] = row["error_ids"].split()
            if notes.get("title"):
                entry["title"] = notes["title"]
            if extra.get("description"):
                entry["description"] = extra["description"]
            urls = row["source_url"].split()
            if urls:
                entry["source"] = urls[0]
            entry.update(extra.get("set", {}))
            for key in extra.get("drop", []):
                entry.pop(key, None)
            entries.append(entry)
    return {
        "version": 1,
        "parameters": entries,
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
    rest = [f' "{key}": {json.dumps(catalogue[key], ensure_ascii=False)}' for key in ("misspellings", "bitfields", "drive_types")]
    parts.append(",\n".join(rest))
    parts.append("}")
    return "\n".join(parts) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("tsv", type=Path)
    parser.add_argument("--overrides", type=Path, default=ROOT / "tools" / "catalogue_overrides.toml")
    parser.add_argument("--output", type=Path, default=OUTPUT)
    args = parser.parse_args(argv)
    catalogue = build(args.tsv, args.overrides)
    args.output.parent.mkdir(parents=True, exist_ok=True)
    args.output.write_text(dump(catalogue), encoding="utf-8")
    print(f"wrote {len(catalogue['parameters'])} parameters to {args.output}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
