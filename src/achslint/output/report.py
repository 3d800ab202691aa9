"""`achslint report MACHINE` as one self-contained HTML page, or as a Markdown summary for CI job pages.

The page (`as_html`) holds only inline CSS and inline SVG: no script, no font, no image and no style sheet
from anywhere else, so it opens from a file:// URL without a network and prints as it shows (print CSS:
each axis, the timeline, the findings and the comparison start a new page; table rows are never split and
table heads repeat). The only addresses in it are the links to the rule docs. Everything that comes from the
user's files (names, values, messages, list lines) is escaped. The same run gives the same bytes: the
figures carry no date and fixed ids.

Every number and word on the page comes from the data objects of the other commands (`report.py` gathers
them): `explain` (per axis: effective parameters with units and sources, corrections with their P-ERR id,
parameters without effect grouped by why), `lint` (findings by severity and rule, with the lines they point
at), the dry-run (`output.dryrun.trace_json` and `output.machine.machine_json`, the documents of
`dry-run --format json`) and `diff`. The figures are drawn by `output.svgplot`, as `--plot FILE.svg` draws them.
"""

from __future__ import annotations

import html
from collections import defaultdict
from collections.abc import Callable, Iterable, Sequence
from typing import TYPE_CHECKING, Any

from ..catalogue.units import unit_label
from ..core.diagnostics import Severity, rule_url
from ..core.display import printable
from ..core.version import __version__
from . import markdown as md
from .diff import _mapped
from .explain import strategy_words
from .figuredata import ASSUMED_GEOMETRY
from .machine import OUTCOME_WORDS, machine_json
from .svgplot import machine_svg, trace_svg

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from ..explanation import ListReport, ParameterRow
    from ..listdiff import Comparison
    from ..report import AxisSection, CommissioningReport

SEVERITY_TITLES = {Severity.ERROR: "Errors", Severity.WARNING: "Warnings", Severity.INFO: "Advice (info)"}
EXCERPT = 2  # lines of the list shown before and after a finding's line

CSS = """
:root { --ink: #1b1f24; --muted: #5b6570; --line: #d0d7de; --soft: #f4f6f8; --bad: #b42318;
  --warn: #9a6700; --info: #0b5cad; --good: #1a7f37; --assumed: #8a2c6f; }
* { box-sizing: border-box; }
body { font: 14px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, Helvetica, Arial, sans-serif;
  color: var(--ink); margin: 0 auto; max-width: 1100px; padding: 24px; }
h1 { font-size: 24px; margin: 0 0 4px; } h2 { font-size: 20px; margin: 28px 0 8px;
  border-bottom: 2px solid var(--line); padding-bottom: 4px; } h3 { font-size: 16px; margin: 18px 0 6px; }
h4 { font-size: 14px; margin: 14px 0 4px; }
.meta, .muted { color: var(--muted); }
nav ol { columns: 3; padding-left: 20px; margin: 8px 0; }
table { border-collapse: collapse; width: 100%; margin: 6px 0 12px; table-layout: auto; }
th, td { border: 1px solid var(--line); padding: 3px 6px; text-align: left; vertical-align: top;
  overflow-wrap: break-word; }
th { background: var(--soft); font-weight: 600; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
code, pre { font: 12px/1.4 ui-monospace, "SFMono-Regular", Menlo, Consolas, monospace; }
pre.excerpt { background: var(--soft); border: 1px solid var(--line); padding: 4px 6px; margin: 4px 0 10px;
  white-space: pre-wrap; overflow-wrap: anywhere; }
pre.excerpt .hit { background: #fff1c2; display: block; }
.badge { display: inline-block; border-radius: 3px; padding: 0 5px; font-size: 12px; font-weight: 600;
  border: 1px solid currentColor; }
.error { color: var(--bad); } .warning { color: var(--warn); } .info { color: var(--info); }
.good { color: var(--good); }
.assumed { color: var(--assumed); font-weight: 600; }
tr.assumed td { background: #fbeff8; }
.note { border-left: 4px solid var(--assumed); background: #fbeff8; padding: 6px 10px; margin: 8px 0; }
.failure { border-left: 4px solid var(--bad); background: #fdecea; padding: 6px 10px; margin: 8px 0; }
svg.figure { width: 100%; height: auto; display: block; margin: 6px 0 12px; }
figure { margin: 0; } figcaption { color: var(--muted); font-size: 12px; }
.signoff td { height: 34px; } .signoff td.notes { height: 120px; }
ul.plain { padding-left: 18px; margin: 4px 0; }
@page { size: A4; margin: 14mm 12mm; }
@media print {
  body { max-width: none; padding: 0; font-size: 11px; }
  nav { display: none; }
  .page { break-before: page; }
  h2, h3, h4 { break-after: avoid; }
  tr, pre.excerpt, figure, .signoff { break-inside: avoid; }
  thead { display: table-header-group; }
  a { color: inherit; text-decoration: none; }
}
"""


def h(value: object) -> str:
    """A value as HTML text: control characters shown escaped, markup characters as entities."""
    return html.escape(printable("" if value is None else str(value)), quote=True)


def _cells(cells: Iterable[object], tag: str = "td") -> str:
    out = []
    for cell in cells:
        if isinstance(cell, _Raw):
            out.append(f"<{tag}{cell.attributes}>{cell.markup}</{tag}>")
        else:
            out.append(f"<{tag}>{h(cell)}</{tag}>")
    return "".join(out)


class _Raw:
    """A table cell made here (markup, not text), with optional attributes of its own."""

    def __init__(self, markup: str, css: str | None = None) -> None:
        self.markup = markup
        self.attributes = f' class="{css}"' if css else ""


def _num(value: float | None, digits: int = 4) -> _Raw:
    return _Raw(h(_number(value, digits)), "num")


def _number(value: float | None, digits: int = 4) -> str:
    """A number as the page shows it. Rounded to 9 decimals first, as `--format json` rounds, so that a
    value read from the run (6.30249999…) and the same value read from its JSON document (6.3025) show alike."""
    if value is None:
        return ""
    text = f"{round(value, 9):.{digits}f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _table(header: Sequence[str], rows: Iterable[Sequence[object]], css: str = "") -> str:
    body = "".join(f"<tr>{_cells(row)}</tr>" for row in rows)
    attribute = f' class="{css}"' if css else ""
    return f"<table{attribute}><thead><tr>{_cells(header, 'th')}</tr></thead><tbody>{body}</tbody></table>"


def _section(anchor: str, title: str, body: Iterable[str], page: bool = True) -> str:
    css = ' class="page"' if page else ""
    return f'<section id="{anchor}"{css}><h2>{h(title)}</h2>{"".join(body)}</section>'


def _figure(svg: str, caption: str) -> str:
    return f"<figure>{svg}<figcaption>{h(caption)}</figcaption></figure>"


# --- the page -------------------------------------------------------------------------------------


def as_html(report: CommissioningReport, docs_url: str | None = None) -> str:
    """The whole page."""
    title = f"Commissioning report: {report.target}"
    program = machine_json(report.run) if report.run is not None else None
    in_program = {axis["name"]: axis for axis in program["axes"]} if program is not None else {}
    sections = [_summary(report)]
    if program is not None:
        sections.append(_timeline(report, program))
    sections += [
        _axis(section, number, in_program.get(section.name)) for number, section in enumerate(report.axes, 1)
    ]
    sections.append(_findings(report, docs_url))
    if report.against is not None:
        sections.append(_comparison(report))
    sections.append(_signoff())
    toc = [("summary", "Summary")]
    if report.run is not None:
        toc.append(("timeline", "Homing program"))
    toc += [(f"axis-{n}", f"Axis {s.name}") for n, s in enumerate(report.axes, 1)]
    toc.append(("findings", "Findings"))
    if report.against is not None:
        toc.append(("comparison", "Changes against the backup"))
    toc.append(("sign-off", "Sign-off"))
    links = "".join(f'<li><a href="#{anchor}">{h(words)}</a></li>' for anchor, words in toc)
    return (
        "<!DOCTYPE html>\n"
        '<html lang="en"><head><meta charset="utf-8">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        f'<meta name="generator" content="achslint {h(__version__)}">'
        f"<title>{h(title)}</title><style>{CSS}</style></head>\n<body>"
        f'<header><h1>Commissioning report</h1><p class="meta">{h(report.target)} — made by achslint '
        f"{h(__version__)} from the lists as they are on disk</p></header>"
        f'<nav aria-label="contents"><ol>{links}</ol></nav>\n' + "\n".join(sections) + "\n</body></html>\n"
    )


def _summary(report: CommissioningReport) -> str:
    found = md.counts(d for r in report.lint.results for d in r.diagnostics)
    facts: list[tuple[str, object]] = [("machine" if report.machine else "axis list", report.target)]
    machine = report.machine
    if machine is not None:
        channel = f"channel {machine['channel']}" if machine.get("channel") else "names from the axis lists"
        if machine.get("channel_list"):
            channel += f" ({machine['channel_list']})"
        facts.append(("channel", channel))
    if report.run is not None:
        run = report.run
        facts.append(("homing program", run.program.name))
        if run.failure is None:
            facts.append(("homing time", f"{_number(run.total_time, 3)} s, every block done"))
        else:
            facts.append(
                ("homing time", f"FAILED at {_number(run.failure.time, 3)} s (line {run.failure.at.line})")
            )
    facts.append(
        (
            "findings",
            f"{md.counts_words(found)} in {len(report.lint.results)} checked files",
        )
    )
    if report.against is not None:
        facts.append(("compared with", report.against))
    rows = "".join(f"<tr><th>{h(key)}</th>{_cells([value])}</tr>" for key, value in facts)
    body = [f'<table class="facts"><tbody>{rows}</tbody></table>']
    body.append("<h3>Axes</h3>")
    body.append(
        _table(
            ("axis", "logical no.", "type", "drive", "homing strategy", "G74 runs", "dry-run"),
            [_axis_row(section, number) for number, section in enumerate(report.axes, 1)],
            "axes",
        )
    )
    body.append("<h3>Lists</h3>")
    body.append(
        _table(("kind", "start-up entry", "file"), [(f.kind, f.entry or "", f.path) for f in report.lists])
    )
    problems = [r.error for r in report.lint.results if r.error] + list(report.lint.errors)
    for note in [*report.notes, *problems]:
        body.append(f'<p class="note">{h(note)}</p>')
    return _section("summary", "Summary", body, page=False)


def _axis_row(section: AxisSection, number: int) -> list[object]:
    explained = section.explained
    axis = explained["axis"]
    link = _Raw(f'<a href="#axis-{number}">{h(section.name)}</a>')
    return [
        link,
        section.logical_number if section.logical_number is not None else "",
        axis["axis_type"],
        f"{axis['drive_type']} {axis['drive']}",
        _strategy_words(explained),
        explained["commanded"]["title"],
        _outcome(section),
    ]


def _strategy_words(explained: ListReport) -> str:
    """The strategy's title, with the homing type when the title does not name it already."""
    return strategy_words(explained["strategy"]["title"], explained["axis"]["homing_type"])


def _outcome(section: AxisSection) -> str:
    if section.program_run is not None:
        return OUTCOME_WORDS.get(section.program_run.outcome, section.program_run.outcome)
    if section.dry_run is not None:
        trace = section.dry_run.trace
        return trace.outcome.replace("_", " ") + (
            f" in {_number(trace.total_time, 3)} s" if trace.phases else ""
        )
    return "refused" if section.dry_run_refused else "not simulated"


# --- one axis -------------------------------------------------------------------------------------


def _axis(section: AxisSection, number: int, in_program: dict[str, Any] | None) -> str:
    explained = section.explained
    axis = explained["axis"]
    strategy = explained["strategy"]
    body = [
        f'<p class="meta">{h(explained["file"])}'
        + (
            f" — read as the CNC loads it: {h(explained['loaded_under'])}"
            if explained["loaded_under"]
            else ""
        )
        + "</p>",
        f"<p>{h(axis['axis_type'])} axis, drive type {h(axis['drive_type'])} = {h(axis['drive'])}"
        + ("" if axis["drive_type_set"] else " (not set in the list: the CNC's default)")
        + f". Homing: <strong>{h(strategy['title'])}</strong> (homing_type {h(axis['homing_type'])}"
        + ("" if axis["homing_type_set"] else ", not set: the drive type's default")
        + ")</p>",
        f"<p>{h(strategy['description'])}</p>",
    ]
    if strategy["variants"]:
        body.append(
            '<ul class="plain">' + "".join(f"<li>{h(v)}</li>" for v in strategy["variants"]) + "</ul>"
        )
    commanded = explained["commanded"]
    if commanded["id"] != strategy["id"]:
        body.append(
            f"<p>A G74 that names the axis runs <strong>{h(commanded['title'])}</strong>: "
            f"{h(commanded['description'])}</p>"
        )
    if explained["phases"]:
        body.append(f"<h3>Phases (gear stage {h(explained['gear'])})</h3>")
        body.append(
            "<ol>"
            + "".join(f"<li>{h(p['text'].split('. ', 1)[-1])}</li>" for p in explained["phases"])
            + "</ol>"
        )
    if strategy["acceleration"] is not None:
        acceleration = strategy["acceleration"]
        unit = next(
            (r["unit"] for r in explained["parameters"] if r["parameter"].endswith(acceleration["source"])),
            None,
        )
        body.append(
            f"<p>Homing acceleration {h(_number(acceleration['value']))}{h(' ' + unit if unit else '')} "
            f"({h(acceleration['source'])})</p>"
        )
    if explained["corrections"]:
        body.append("<h3>What the CNC corrects when it loads the list</h3>")
        body.append(
            _table(
                ("parameter", "written", "used", "error", "why", "line"),
                [
                    (c["parameter"], c["written"], c["used"], c["error"], c["reason"], c["line"] or "")
                    for c in explained["corrections"]
                ],
            )
        )
    effective = [row for row in explained["parameters"] if row["effective"]]
    body.append(f"<h3>Effective homing parameters ({len(effective)})</h3>")
    body.append(
        _table(
            ("parameter", "id", "value", "unit", "human", "from"),
            [
                (
                    row["parameter"],
                    row["p_axis"],
                    row["value"] if row["value"] is not None else "",
                    row["unit"] or "",
                    row["human"] or "",
                    _source(row),
                )
                for row in effective
            ],
            "parameters",
        )
    )
    body.append(_without_effect(explained))
    body.append(_dry_run(section, number, in_program))
    title = f"Axis {section.name}" + (
        f" (logical axis {section.logical_number})" if section.logical_number is not None else ""
    )
    return (
        f'<section id="axis-{number}" class="page axis" data-axis="{h(section.name)}">'
        f"<h2>{h(title)}</h2>" + "".join(body) + "</section>"
    )


def _source(row: ParameterRow) -> str:
    """Where the value the CNC uses comes from: a line of the list, of the default list, the default, or
    the CNC's correction of what was written."""
    kind, line = row["source"]["kind"], row["source"]["line"]
    words = {"list": f"list line {line}", "default list": f"default list line {line}"}.get(kind, "default")
    if row["correction"]:
        return f"CNC correction {row['correction']} (written {row['written']} at {words})"
    return words


def _without_effect(explained: ListReport) -> str:
    """The parameters without effect, grouped by why; those the list sets (what LIS401 reports) marked."""
    groups: dict[str, list[ParameterRow]] = defaultdict(list)
    for row in explained["parameters"]:
        if not row["effective"]:
            groups[row["reason"]].append(row)
    if not groups:
        return ""
    items = []
    for why, rows in groups.items():
        names = ", ".join(
            f"<code>{h(r['parameter'])}</code>"
            + (f" <strong>(set, {h(_source(r))})</strong>" if r["source"]["kind"] != "default" else "")
            for r in rows
        )
        items.append(f"<li>{h(why)}: {names}</li>")
    count = sum(len(rows) for rows in groups.values())
    return f'<h3>Without effect under this strategy ({count})</h3><ul class="plain">{"".join(items)}</ul>'


def _dry_run(section: AxisSection, number: int, in_program: dict[str, Any] | None) -> str:
    if section.program_run is not None and in_program is not None:
        return _program_axis(section, number, in_program)
    if section.dry_run is None:
        return f'<h3>Dry-run</h3><p class="note">{h(section.refused or "not simulated")}</p>'
    from .dryrun import trace_json

    document = trace_json(section.dry_run)
    unit = unit_label(document["units"]["position"])  # degrees shown as °, as elsewhere
    trace = section.dry_run.trace
    body = ["<h3>Dry-run of the configured homing</h3>", _scenario(document["scenario"], unit)]
    body.append(_phases(document["phases"], unit))
    body.append(_result(document, unit))
    body.append(_warnings(document["warnings"]))
    if trace.phases or trace.failure:
        body.append(
            _figure(trace_svg(trace, f"a{number}"), f"{section.name}: position and velocity over time")
        )
    return "".join(body)


def _program_axis(section: AxisSection, number: int, document: dict[str, Any]) -> str:
    run = section.program_run
    assert run is not None
    unit = unit_label(document["unit"])
    body = ["<h3>In the homing program</h3>", _scenario(document["scenario"], unit)]
    body.append(_phases(document["phases"], unit, machine_time=True))
    body.append(_result(document, unit))
    body.append(_warnings(document["warnings"]))
    for index, (start, trace) in enumerate(run.traces, 1):
        body.append(
            _figure(
                trace_svg(trace, f"a{number}t{index}"),
                f"{section.name}: its homing from {_number(start, 3)} s of the program, position and velocity "
                "(time from the start of the homing)",
            )
        )
    return "".join(body)


SCENARIO_WORDS = {
    "start_position": "start position",
    "cam": "reference cam",
    "zero_pulse_period": "zero pulse every",
    "zero_pulse_phase": "a zero pulse at",
    "hardware_latch": "hardware latch",
    "limit_switches": "limit switches",
    "fixed_stop": "fixed stop",
    "cam_jitter": "cam jitter",
    "modulo": "modulo range",
    "start_velocity": "turning at the start",
    "cycle_time_ms": "cycle time (ms)",
    "drive": "drive's homing method",
}


def _scenario(scenario: dict[str, Any], unit: str) -> str:
    """The geometry the run used; each value the user did not give is marked ASSUMED."""
    assumed = set(scenario.get("assumed", []))
    geometry = sorted(assumed & set(ASSUMED_GEOMETRY))
    rows = []
    for key, words in SCENARIO_WORDS.items():
        value = scenario.get(key)
        if value is None or (key == "cam_jitter" and not value and key not in assumed):
            continue
        shown = ", ".join(_number(v) for v in value) if isinstance(value, list) else value
        if isinstance(value, float):
            shown = _number(value)
        mark = _Raw('<span class="badge assumed">ASSUMED</span>') if key in assumed else "given"
        rows.append((words, shown, mark))
    note = ""
    if geometry:
        note = (
            f'<p class="note"><span class="assumed">Assumed geometry:</span> {h(", ".join(geometry))} '
            "not given; the run and its figure show the default scenario there, not the machine. Give them in "
            "the scenario file.</p>"
        )
    body = "".join(
        ('<tr class="assumed">' if isinstance(mark, _Raw) else "<tr>")
        + _cells((words, shown, mark))
        + "</tr>"
        for words, shown, mark in rows
    )
    return (
        f'{note}<table class="scenario"><thead><tr><th>scenario ({h(unit)})</th><th>value</th>'
        f"<th>source</th></tr></thead><tbody>{body}</tbody></table>"
    )


def _phases(phases: list[dict[str, Any]], unit: str, machine_time: bool = False) -> str:
    if not phases:
        return '<p class="muted">No motion.</p>'
    when = "program time" if machine_time else "time"
    return _table(
        (
            "phase",
            "direction",
            f"speed {unit}/s",
            f"from {unit}",
            f"to {unit}",
            f"{when} from s",
            "to s",
            "ended by",
        ),
        [
            (
                p["name"],
                p["direction"] or "",
                _num(p["velocity"]),
                _num(p["start_position"]),
                _num(p["end_position"]),
                _num(p["start_time"], 3),
                _num(p["end_time"], 3),
                p["ended_by"],
            )
            for p in phases
        ],
        "phases",
    )


def _result(document: dict[str, Any], unit: str) -> str:
    outcome = document["outcome"]
    words = OUTCOME_WORDS.get(outcome, outcome).replace("_", " ")
    css = "good" if outcome == "homed" else "error" if outcome in ("failed", "aborted") else "warning"
    parts = [f'<p>Outcome: <strong class="{css}">{h(words)}</strong>']
    reference = document.get("reference")
    if reference is not None:
        parts.append(
            f"; reference ({h(reference['kind'])}) at {h(_number(reference['position']))} {h(unit)} "
            f"becomes {h(_number(reference['value']))} {h(unit)}"
        )
    if document.get("final_position") is not None:
        parts.append(f"; the axis stands at {h(_number(document['final_position']))} {h(unit)} (homed frame)")
    if document.get("total_time") is not None:
        parts.append(f"; {h(_number(document['total_time'], 3))} s")
    parts.append("</p>")
    if document.get("failure") and outcome in ("failed", "aborted"):
        parts.append(f'<p class="failure">{h(document["failure"])}</p>')
    return "".join(parts)


def _warnings(warnings: list[dict[str, Any]]) -> str:
    if not warnings:
        return ""
    items = "".join(
        f"<li>{h((w['code'] + ': ') if w.get('code') else 'note: ')}{h(w['message'])}</li>" for w in warnings
    )
    return f'<ul class="plain warnings">{items}</ul>'


# --- the program ----------------------------------------------------------------------------------


def _timeline(report: CommissioningReport, document: dict[str, Any]) -> str:
    run = report.run
    assert run is not None
    rows = []
    for block in document["blocks"]:
        groups = block["groups"] or [None]
        for index, group in enumerate(groups):
            rows.append(
                (
                    block["text"] if index == 0 else "",
                    _num(block["line"]) if index == 0 else "",
                    group["sequence"] if group else "",
                    " ".join(group["axes"] if group else block["axes"]),
                    _num((group or block)["start_time"], 3),
                    _num((group or block)["end_time"], 3),
                    ((group or block)["outcome"] or "").replace("_", " "),
                )
            )
    body = [
        f"<p>{h(run.program.name)}, cycle {h(_number(run.cycle_time * 1000))} ms: "
        + (
            f'<strong class="good">done in {h(_number(run.total_time, 3))} s</strong>'
            if run.failure is None
            else f'<strong class="error">FAILED at {h(_number(run.failure.time, 3))} s</strong>'
        )
        + "</p>"
    ]
    if run.failure is not None:
        body.append(f'<p class="failure">line {h(run.failure.at.line)}: {h(run.failure.reason)}</p>')
    body.append(_table(("block", "line", "group", "axes", "start s", "end s", "outcome"), rows, "blocks"))
    body.append(_warnings(document["warnings"]))
    body.append(
        _figure(
            machine_svg(run, "timeline"),
            "One lane per axis (phases coloured, moves grey, the reference starred, a failure crossed), then "
            "each moving axis's position over the program's time.",
        )
    )
    return _section("timeline", "Homing program", body)


# --- findings -------------------------------------------------------------------------------------


def _findings(report: CommissioningReport, docs_url: str | None) -> str:
    from ..rules import registry

    rules = registry()
    sources = report.lint.sources
    found = [d for r in report.lint.results for d in r.diagnostics]
    if not found:
        return _section("findings", "Findings", ['<p class="good">No findings: every check passed.</p>'])
    body = []
    for severity in md.ORDER:
        chosen = [d for d in found if d.severity is severity]
        if not chosen:
            continue
        body.append(f'<h3 class="{severity.value}">{SEVERITY_TITLES[severity]} ({len(chosen)})</h3>')
        by_rule: dict[str, list[Diagnostic]] = defaultdict(list)
        for d in sorted(chosen, key=lambda d: (d.code, d.path, d.line, d.column)):
            by_rule[d.code].append(d)
        for code, diagnostics in by_rule.items():
            rule = rules.get(code)
            name = f" {rule.name}" if rule is not None else ""
            body.append(
                f'<h4 id="rule-{h(severity.value)}-{h(code)}"><a href="{h(rule_url(code, docs_url))}">{h(code)}</a>'
                f"{h(name)} ({len(diagnostics)})</h4>"
            )
            for d in diagnostics:
                body.append(
                    f"<p><code>{h(d.path)}:{h(d.line)}:{h(d.column)}</code> {h(d.message)}</p>"
                    + _excerpt(sources.get(d.path, []), d.line)
                )
    return _section("findings", "Findings", body)


def _excerpt(lines: list[str], line: int) -> str:
    if not lines or not 1 <= line <= len(lines):
        return ""
    first = max(1, line - EXCERPT)
    last = min(len(lines), line + EXCERPT)
    width = len(str(last))
    shown = []
    for number in range(first, last + 1):
        text = h(f"{number:>{width}} │ {lines[number - 1].rstrip()}")
        shown.append(f'<span class="hit">{text}</span>' if number == line else text + "\n")
    return f'<pre class="excerpt">{"".join(shown)}</pre>'


# --- against the backup ---------------------------------------------------------------------------


def _comparison(report: CommissioningReport) -> str:
    body = []
    if report.machine_diff is not None:
        found = report.machine_diff
        body.append(
            f"<p>A: {h(found['a']['startup'])} (the backup), B: {h(found['b']['startup'])} (this report)</p>"
        )
        if not found["differ"]:
            body.append('<p class="good">No difference: both load the same machine.</p>')
        for row in found["axes"]:
            if row["status"] == "same":
                continue
            side = row["b"] or row["a"]
            assert side is not None
            words = {"added": "only in B (new)", "removed": "only in A (gone)"}.get(row["status"], "changed")
            body.append(f"<h3>Axis {h(side['logical_number'])} {h(side['name'])}: {h(words)}</h3>")
            if row["homing_differs"] and row["a"] is not None and row["b"] is not None:
                body.append(
                    f"<p>Homing strategy: {h(row['a']['homing_title'])} → {h(row['b']['homing_title'])}</p>"
                )
            body.append(_differences(row))
        for channel in found["channels"]:
            if channel["status"] == "same":
                continue
            body.append(f"<h3>Channel {h(channel['channel'])}: {h(channel['status'])}</h3>")
            body.append(
                _table(
                    ("name", "A", "B"),
                    [(n["name"], _mapped(n["a"]), _mapped(n["b"])) for n in channel["names"]],
                )
            )
            for pair in channel["pairs"]:
                body.append(
                    f"<p>Coupled pair master {h(pair['master'])} / slave {h(pair['slave'])}: only in "
                    f"{h(pair['only_in'].upper())}</p>"
                )
        from .diff import list_title

        for listed in found["lists"]:
            if listed["status"] == "same":
                continue
            words = {"added": "only in B (new)", "removed": "only in A (gone)"}.get(
                listed["status"], "changed"
            )
            title = list_title(listed)
            body.append(f"<h3>{h(title[0].upper() + title[1:])}: {h(words)}</h3>")
            shown = [
                (c["parameter"], *("not written" if v is None else v for v in (c["a"], c["b"])))
                for c in listed["changes"]
            ]
            body.append(_table(("parameter", "A", "B"), shown))
    elif report.list_diff is not None:
        found_list = report.list_diff
        body.append(f"<p>A: {h(found_list['a'])} (the backup), B: {h(found_list['b'])} (this report)</p>")
        body.append(_differences(found_list))
    return _section("comparison", "Changes against the backup", body)


def _differences(comparison: Comparison) -> str:
    parts = []
    if comparison["differences"]:
        parts.append(
            _table(
                ("parameter", "id", "A", "B", "unit", "A human", "B human", "A from", "B from"),
                [
                    (
                        d["parameter"],
                        d["p_axis"],
                        d["a"],
                        d["b"],
                        d["unit"] or "",
                        d["a_human"] or "",
                        d["b_human"] or "",
                        d["a_source"],
                        d["b_source"],
                    )
                    for d in comparison["differences"]
                ],
                "differences",
            )
        )
    for written in comparison["written_differences"]:
        parts.append(
            f"<p>{h(written['parameter'])}: written {h(written['a'])} → {h(written['b'])}, the CNC uses "
            f"{h(written['used'])} in both</p>"
        )
    for unknown in comparison["unknown_parameters"]:
        parts.append(
            f"<p>unknown parameter {h(unknown['parameter'])}: {h(unknown['a'])} → {h(unknown['b'])}</p>"
        )
    if not parts:
        parts.append('<p class="muted">Effective values the same.</p>')
    return "".join(parts)


# --- sign-off -------------------------------------------------------------------------------------


def _signoff() -> str:
    rows = "".join(
        f"<tr><th>{h(role)}</th><td></td><td></td><td></td></tr>"
        for role in ("Controls engineer", "Mechanical engineer", "Customer")
    )
    return (
        '<section id="sign-off" class="signoff page"><h2>Sign-off</h2>'
        "<p>Reviewed: the axes and their homing, what the CNC corrects, the open findings and the homing "
        "time above.</p>"
        "<table><thead><tr><th>role</th><th>reviewer</th><th>date</th><th>signature</th></tr></thead>"
        f"<tbody>{rows}</tbody></table>"
        '<table><thead><tr><th>notes</th></tr></thead><tbody><tr><td class="notes"></td></tr></tbody></table>'
        "</section>"
    )


# --- Markdown -------------------------------------------------------------------------------------


def as_markdown(report: CommissioningReport, docs_url: str | None = None) -> str:
    """A compact summary: counts, the axes with their strategies and dry-run outcomes, the homing time,
    the worst findings."""
    found = md.counts(d for r in report.lint.results for d in r.diagnostics)
    lines = [f"## achslint report: {md.text(report.target)}", ""]
    lines.append(f"**Findings:** {md.counts_words(found)}")
    if report.run is not None:
        run = report.run
        lines[-1] += "  "
        lines.append(
            f"**Homing program** {md.text(run.program.name)}: "
            + (
                f"done in {_number(run.total_time, 3)} s"
                if run.failure is None
                else f"FAILED at {_number(run.failure.time, 3)} s (line {run.failure.at.line}): "
                f"{md.text(run.failure.reason)}"
            )
        )
    assumed = sorted({name for s in report.axes for name in _assumed(s)})
    if assumed:
        lines[-1] += "  "
        lines.append(f"**Assumed geometry** (not given): {md.text(', '.join(assumed))}")
    lines.append("")
    lines += md.table(
        ("axis", "no.", "type", "strategy", "dry-run"),
        [
            (
                s.name,
                s.logical_number if s.logical_number is not None else "",
                s.explained["axis"]["axis_type"],
                s.explained["strategy"]["title"],
                _outcome(s),
            )
            for s in report.axes
        ],
    )
    worst = md.findings_table(report.lint.results, docs_url)
    if worst:
        lines += ["", "### Worst findings", "", *worst]
    if report.machine_diff is not None:
        changed = [row for row in report.machine_diff["axes"] if row["status"] != "same"]
        lines += ["", f"**Against {md.text(report.against)}:** {len(changed)} axes differ"]
    elif report.list_diff is not None:
        lines += [
            "",
            f"**Against {md.text(report.against)}:** {len(report.list_diff['differences'])} values differ",
        ]
    return "\n".join(lines) + "\n"


def _assumed(section: AxisSection) -> list[str]:
    """The geometry the axis's run assumed (where it starts, its cam, zero pulses and limit switches)."""
    if section.program_run is not None:
        assumed = section.program_run.scenario.assumed if section.program_run.phases else []
    else:
        assumed = section.dry_run.trace.scenario.assumed if section.dry_run is not None else []
    return [name for name in assumed if name in ASSUMED_GEOMETRY]


RENDERERS: dict[str, Callable[[CommissioningReport, str | None], str]] = {
    "html": as_html,
    "markdown": as_markdown,
}
