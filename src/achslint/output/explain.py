"""`achslint explain` as text or JSON: an axis list, a parameter card, a machine (start-up list).

The reports are built by `explain.explain_list`, `explain.parameter_card` and
`machineexplain.explain_machine`; their JSON is the report itself. One registry per kind of report maps
each of `FORMATS` to its renderer.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from . import Screen, write_json

if TYPE_CHECKING:
    from ..explanation import ListReport, ParameterCard
    from . import Registry


def list_text(report: ListReport, screen: Screen) -> None:
    """`explain LIST`: the axis, its homing strategy and phases in words, the CNC's corrections, then a
    table of every homing parameter with its source and whether it takes effect."""
    from rich.table import Table
    from rich.text import Text

    console = screen.console
    axis = report["axis"]
    console.print(Text(f"{report['file']}", style="bold"))
    if report.get("loaded_under"):
        console.print(f"Read as the CNC loads it: {report['loaded_under']}")
    drive_note = "" if axis["drive_type_set"] else " (not set in the list: CNC default)"
    console.print(
        f"Axis {axis['name']} (logical axis {axis['number']}): {axis['axis_type']} axis, "
        f"drive type {axis['drive_type']} = {axis['drive']}{drive_note}"
    )
    type_note = "" if axis["homing_type_set"] else " (not set: the drive type's default)"
    strategy = report["strategy"]
    console.print(
        Text(f"Homing: {strategy['title']}", style="bold")
        + Text(f" — homing_type {axis['homing_type']}{type_note}")
    )
    console.print(strategy["description"])
    for variant in strategy["variants"]:
        console.print(f"  • {variant}")
    commanded = report["commanded"]
    if commanded["id"] != strategy["id"]:
        console.print(Text(f"A G74 that names the axis runs: {commanded['title']}", style="bold"))
        console.print(commanded["description"])
        for phase in commanded["phases"]:
            console.print("  " + phase["text"])
    if report["phases"]:
        console.print(Text(f"Phases (gear stage {report['gear']}):", style="bold"))
        for phase in report["phases"]:
            console.print("  " + phase["text"])
        if strategy["ends_with_braking"]:
            console.print(
                "  After the reference event the axis brakes, so it stops beyond the reference position "
                "by its braking distance."
            )
    for correction in report["corrections"]:
        console.print(
            Text(f"CNC correction {correction['error']}: ", style="yellow")
            + Text(
                f"`{correction['parameter']}` {correction['written']} is used as {correction['used']}: "
                f"{correction['reason']}"
            )
        )
    table = Table(
        title=f"Homing parameters (gear stage {report['gear']})", title_justify="left", show_lines=False
    )
    for column in ("parameter", "id", "value", "unit", "human", "source", "effective", "why"):
        table.add_column(column, overflow="fold")
    for row in report["parameters"]:
        kind, line = row["source"]["kind"], row["source"]["line"]
        source = (
            "default"
            if kind == "default"
            else f"line {line}"
            if kind == "list"
            else f"default list line {line}"
        )
        table.add_row(
            row["parameter"],
            row["p_axis"],
            str(row["value"])
            + (f" (written {row['written']}, {row['correction']})" if row["correction"] else ""),
            row["unit"] or "",
            row["human"] or "",
            source,
            Text("yes", style="green") if row["effective"] else Text("no", style="red"),
            row["reason"],
        )
    console.print(table)


def card_text(card: ParameterCard, screen: Screen) -> None:
    """`explain PARAM`: the parameter's id and path, its description, then one line per fact it has (the
    first: the kind of list it belongs to)."""
    from rich.text import Text

    from ..explanation import outside_range, range_words

    console = screen.console
    console.print(Text(f"{card['p_axis']}  {card['path']}", style="bold"))
    console.print(card["description"])
    checked = card["checked_range"] and range_words(card["checked_range"])
    if checked and card["checked_range"] and outside_range(card["checked_range"], card["default"]):
        checked += f"; the default {card['default']} is accepted too"
    rows = [
        ("list", card["list"]),
        ("type", card["type"]),
        ("range (manual)", card["range"]),
        ("checked range", checked),
        ("accepted values", card["accepted_values"] and ", ".join(map(str, card["accepted_values"]))),
        ("symbols", card["symbols"] and ", ".join(card["symbols"])),
        ("max length", card["max_length"]),
        ("default", card["default"]),
        ("units", card["units"] and ", ".join(f"{k}: {v}" for k, v in card["units"].items())),
        ("indices", card["index_bounds"] and ", ".join(f"{a}..{b}" for a, b in card["index_bounds"])),
        ("aliases", ", ".join(f"{a['path']} ({a['kind']})" for a in card["aliases"])),
        ("drive types", card["drive_types"] and ", ".join(card["drive_types"])),
        ("axis types", card["axis_types"] and ", ".join(card["axis_types"])),
        ("restart", "a change needs a CNC restart" if card["restart_required"] else None),
        (
            "matters for",
            card["strategies"] is not None
            and (", ".join(s["title"] for s in card["strategies"]) or "no homing strategy"),
        ),
        ("checked by", card["rules"] and ", ".join(card["rules"])),
        ("CNC messages", card["errors"] and ", ".join(card["errors"])),
        ("manual title", card["manual_title"]),
        ("manual", card["manual"]),
    ]
    width = max(len(k) for k, _ in rows)
    for key, value in rows:
        if value is not False and value not in (None, "", [], {}):  # a default of 0 is shown (0 == False)
            console.print(Text(f"  {key:<{width}}  ", style="bold") + Text(str(value)))


def machine_text(report: dict[str, Any], screen: Screen) -> None:
    """`explain hochlauf.lis`: a table of the machine's axes, then the homing order of the program."""
    from rich.table import Table
    from rich.text import Text

    console = screen.console
    where = (
        f"channel {report['channel']} ({report['channel_list']})" if report["channel_list"] else "axis lists"
    )
    console.print(Text(f"{report['startup']}", style="bold") + Text(f" — names from {where}"))
    program = report["program"]
    table = Table(show_lines=False)
    columns = ["name", "no.", "axis", "drive", "homing", "gantry"] + (["homed"] if program else [])
    for column in columns:
        table.add_column(column, overflow="fold")
    for row in report["axes"]:
        names = row["name"] + (
            f" ({row['log_achs_name']})"
            if row["log_achs_name"] and row["log_achs_name"].upper() != row["name"]
            else ""
        )
        cells = [
            names,
            str(row["logical_number"]),
            row["axis_type"],
            f"{row['drive_type']} {row['drive']}",
            strategy_words(row["strategy"]["title"], row["homing_type"])
            + (f"; a G74 runs {row['commanded']['title']}" if row["commanded"] != row["strategy"] else ""),
            _gantry_words(row["gantry"]),
        ]
        if program:
            cells.append(row.get("homed", ""))
        table.add_row(*cells)
    console.print(table)
    for row in report["other_axes"]:
        if row["gantry"] is not None and row["gantry"]["role"] == "slave":
            homed = " and is homed with it" if row["gantry"]["homes_with_master"] else ""
            console.print(
                f"Gantry slave, no axis of this channel: {row['name']} ({row['list']}, logical axis "
                f"{row['logical_number']}) moves with its master {row['gantry']['master']}"
                + (f"; homed: {row['homed']}" if "homed" in row else homed)
            )
            continue
        console.print(
            f"Not named in this channel: {row['list']} (logical axis {row['logical_number']}, "
            f"kopf.log_achs_name {row['log_achs_name']})"
        )
    for note in report["notes"]:
        console.print(Text("note: ", style="yellow") + Text(note))
    if program is None:
        return
    console.print(Text(f"Homing order of {program['name']}:", style="bold"))
    runs = list(_runs(program["blocks"]))
    for first, last, count, words in runs[:PROGRAM_LINES]:
        where = _block_label(first) + (f" to {_block_label(last)}, {count:,} blocks" if count > 1 else "")
        console.print(f"  {where}: {words}")
    if len(runs) > PROGRAM_LINES:
        hidden = sum(run[2] for run in runs[PROGRAM_LINES:])
        console.print(f"  … {hidden:,} more blocks not shown (`--format json` lists every block)")
    for finding in program["findings"]:
        style = {"error": "red", "warning": "yellow"}.get(finding["severity"], "")
        console.print(
            Text(f"  {finding['code']} {finding['severity']}", style=style)
            + Text(f" line {finding['line']}:{finding['column']}: {finding['message']}")
        )


PROGRAM_LINES = 200  # lines of the text form's homing order; JSON has every block


def _block_label(block: dict[str, Any]) -> str:
    return f"line {block['line']}" + (f" N{block['number']}" if block.get("number") is not None else "")


def _block_words(block: dict[str, Any]) -> str:
    if block["kind"] == "homing":
        steps = "; then ".join(", ".join(group["axes"]) for group in block["groups"]) or "no axis"
        return f"G74 homes {steps}"
    if block["kind"] == "move":
        from ..machine.run import address, programmed  # as the program writes them: `Y2=5`, not `Y25`

        targets = " ".join(address(name) + programmed(value) for name, value in block["targets"].items())
        feed = block["feed_mm_min"]
        mode = "G00" if block["rapid"] else f"G01 F{programmed(feed)}" if feed else "G01"
        return f"{mode} {'G90' if block['absolute'] else 'G91'} {targets}"
    return f"not simulated — {block['reason']}"


def _runs(blocks: list[dict[str, Any]]) -> Iterator[tuple[dict[str, Any], dict[str, Any], int, str]]:
    """Consecutive blocks that read the same, as one: (first, last, how many, the words). A program that
    homes the same axes in a thousand blocks is one line, not a thousand."""
    run: list[Any] = []
    for block in blocks:
        words = _block_words(block)
        if run and run[3] == words and block["line"] == run[1]["line"] + 1:
            run[1], run[2] = block, run[2] + 1
            continue
        if run:
            yield run[0], run[1], run[2], run[3]
        run = [block, block, 1, words]
    if run:
        yield run[0], run[1], run[2], run[3]


def _gantry_words(gantry: dict[str, Any] | None) -> str:
    if gantry is None:
        return ""
    if gantry["role"] == "master":
        return "master of " + ", ".join(gantry["slaves"])
    return f"slave of {gantry['master']}" + (" (homed with it)" if gantry["homes_with_master"] else "")


# --- Markdown (CI job pages) -----------------------------------------------------------------------


def list_markdown(report: ListReport, screen: Screen) -> None:
    """`explain LIST --format markdown`: the strategy and its phases, the corrections, the parameters the list
    sets without effect."""
    from . import markdown as md

    axis, strategy = report["axis"], report["strategy"]
    lines = [
        f"## {md.text(report['file'])}: axis {md.text(axis['name'])} (logical axis {md.text(axis['number'])})",
        "",
        f"**Homing:** {md.text(strategy['title'])} (homing\\_type {md.text(axis['homing_type'])}), "
        f"{md.text(axis['axis_type'])} axis, drive {md.text(axis['drive_type'])} {md.text(axis['drive'])}",
        "",
    ]
    lines += [f"{phase['number']}. {md.text(phase['text'].split('. ', 1)[-1])}" for phase in report["phases"]]
    corrections = [
        f"- CNC correction {md.text(c['error'])}: {md.text(c['parameter'])} {md.text(c['written'])} is used as "
        f"{md.text(c['used'])}"
        for c in report["corrections"]
    ]
    unused = [
        row for row in report["parameters"] if not row["effective"] and row["source"]["kind"] != "default"
    ]
    lines += ["", *corrections] if corrections else []
    if unused:
        lines += ["", "Set without effect under this strategy:", ""]
        lines += md.table(
            ("parameter", "value", "why"), [(r["parameter"], r["value"], r["reason"]) for r in unused]
        )
    screen.echo("\n".join(lines))


def card_markdown(card: ParameterCard, screen: Screen) -> None:
    """`explain PARAM --format markdown`: the parameter's id, path, description, type, range and default."""
    from . import markdown as md

    facts = [
        ("list", card["list"]),
        ("type", card["type"]),
        ("range", card["range"]),
        ("default", card["default"]),
    ]
    lines = [f"## {md.text(card['p_axis'])} {md.text(card['path'])}", "", md.text(card["description"]), ""]
    lines += [f"- {key}: {md.text(value)}" for key, value in facts if value not in (None, "")]
    screen.echo("\n".join(lines))


def machine_markdown(report: dict[str, Any], screen: Screen) -> None:
    """`explain hochlauf.lis --format markdown`: the axes with their strategies, and the program's findings."""
    from . import markdown as md

    lines = [f"## {md.text(report['startup'])}", ""]
    program = report["program"]
    rows = [
        (
            row["name"],
            row["logical_number"],
            row["axis_type"],
            f"{row['drive_type']} {row['drive']}",
            row["strategy"]["title"],
            row.get("homed", ""),
        )
        for row in report["axes"]
    ]
    header = ("axis", "no.", "type", "drive", "homing", *(["homed"] if program else []))
    lines += md.table(header, [r if program else r[:-1] for r in rows])
    if program is not None and program["findings"]:
        lines += ["", f"### {md.text(program['name'])}", ""]
        lines += [
            f"- {md.text(f['severity'])} {md.text(f['code'])} line {f['line']}: {md.text(f['message'])}"
            for f in program["findings"]
        ]
    screen.echo("\n".join(lines))


LIST: Registry[ListReport] = {"text": list_text, "json": write_json, "markdown": list_markdown}
PARAMETER: Registry[ParameterCard] = {"text": card_text, "json": write_json, "markdown": card_markdown}
MACHINE: Registry[dict[str, Any]] = {"text": machine_text, "json": write_json, "markdown": machine_markdown}


def strategy_words(title: str, homing_type: str) -> str:
    """A strategy's title with the homing type when the title does not name it already ("homing skipped
    (IGNORE_ABS_POS)" is not followed by "(IGNORE_ABS_POS)" again)."""
    return title if homing_type in title else f"{title} ({homing_type})"
