"""`achslint report` (issue 29): the HTML page is well-formed, self-contained and deterministic, holds every
axis, every finding, the timeline and the assumed-geometry marks, escapes what comes from the user's files,
never overwrites an input; `--format markdown` of lint, explain and report renders as CommonMark.

The page is checked with html5lib's strict parser (a parse error fails) and by walking its elements with
the standard library's parser; the browser test (rendering, printing) is in test_report_browser.py."""

from __future__ import annotations

import html
import re
import shutil
import subprocess
from html.parser import HTMLParser

import pytest

from achslint.core.diagnostics import DOCS_URL
from achslint.linting.run import LintRequest, run_lint
from achslint.output.report import as_html, as_markdown
from achslint.report import ReportRequest, build_report

from .conftest import FIXTURES, ROOT
from .conftest import run_cli as run_bytes

html5lib = pytest.importorskip("html5lib")

EXAMPLE = ROOT / "docs" / "dry-run" / "machine"  # the README's example machine (six axes, rfp.nc)
DOCS = DOCS_URL.split("#", 1)[0]


def run_cli(*args: str) -> subprocess.CompletedProcess[str]:
    done = run_bytes(*args)
    return subprocess.CompletedProcess(done.args, done.returncode, done.stdout.decode(), done.stderr.decode())


class Page(HTMLParser):
    """Every element with its attributes, the sections by id, and the text of the page."""

    def __init__(self, text: str) -> None:
        super().__init__(convert_charrefs=True)
        self.elements: list[tuple[str, dict[str, str | None]]] = []
        self.text: list[str] = []
        self.feed(text)

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.elements.append((tag, dict(attrs)))

    def handle_startendtag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.elements.append((tag, dict(attrs)))

    def handle_data(self, data: str) -> None:
        self.text.append(data)

    def ids(self) -> set[str]:
        return {a["id"] for _, a in self.elements if a.get("id")}

    def words(self) -> str:
        return " ".join(" ".join(self.text).split())


def parse_strictly(text: str) -> None:
    """html5lib in strict mode raises on the first parse error (a stray tag, a bad attribute, ...)."""
    html5lib.HTMLParser(strict=True, namespaceHTMLElements=False).parse(text)


def assert_self_contained(text: str) -> None:
    page = Page(text)
    tags = {tag for tag, _ in page.elements}
    assert not tags & {"script", "link", "img", "iframe", "object", "embed", "base", "audio", "video"}
    for tag, attributes in page.elements:
        for name in ("src", "srcset", "poster", "action", "data"):
            assert name not in attributes, (tag, attributes)
        for name in ("href", "xlink:href"):
            target = attributes.get(name)
            if target is not None:
                assert target.startswith("#") or (tag == "a" and target.startswith(DOCS + "#")), target
        assert not any(key.startswith("on") for key in attributes), (tag, attributes)  # no event handlers
    outside = [m for m in re.findall(r"https?://[^\s\"'<>)]*", text) if not m.startswith(DOCS + "#")]
    assert outside == []
    assert "@import" not in text and "url(http" not in text and "@font-face" not in text


@pytest.fixture(scope="module")
def example(tmp_path_factory: pytest.TempPathFactory):
    """The example machine with its program and scenario, and the report of it."""
    request = ReportRequest(
        EXAMPLE / "listen" / "hochlauf.lis", program=EXAMPLE / "rfp.nc", scenario=EXAMPLE / "machine.toml"
    )
    report = build_report(request)
    return request, report, as_html(report)


@pytest.fixture(scope="module")
def example_page(example) -> Page:
    """The example's page read by `Page`, once for the tests that look through it."""
    return Page(example[2])


def test_the_page_is_well_formed_and_self_contained(example):
    _, _, text = example
    parse_strictly(text)
    assert_self_contained(text)
    assert text.startswith("<!DOCTYPE html>") and '<meta charset="utf-8">' in text


def test_the_page_holds_every_axis_with_its_parameters_and_run(example, example_page):
    _, report, text = example
    page = example_page
    axes = [(tag, a) for tag, a in page.elements if tag == "section" and "axis" in (a.get("class") or "")]
    assert [a["data-axis"] for _, a in axes] == ["X", "Y", "Z", "A", "B", "S"]
    words = page.words()
    for section in report.axes:
        effective = [row for row in section.explained["parameters"] if row["effective"]]
        assert f"Effective homing parameters ({len(effective)})" in words
        assert section.program_run is not None  # every axis of the channel is in the program's run
    # X's homing speed with its unit and where it comes from (listen/achsmds1.lis line 21)
    assert re.search(
        r"<td>getriebe\[0\]\.vb_refmax</td><td>P-AXIS-00219</td><td>100000</td><td>µm/s</td>"
        r"<td>100 mm/s = 6 m/min</td><td>list line 21</td>",
        text,
    )
    assert "Without effect under this strategy" in words
    assert "done in 29.21 s" in words  # the summary's homing time: the program's total time


def test_the_page_holds_the_timeline_and_the_plots_as_svg(example, example_page):
    _, report, text = example
    page = example_page
    assert "timeline" in page.ids()
    timeline = text[
        text.index('<section id="timeline"') : text.index("</section>", text.index('id="timeline"'))
    ]
    assert timeline.count("<svg") == 1 and "N20 G74 X1 Y1 A2 B2 S3" in timeline
    # one position/velocity figure per homing run of an axis, as --plot draws it
    runs = sum(len(section.program_run.traces) for section in report.axes if section.program_run)
    assert text.count("<svg") == 1 + runs
    assert "<image" not in text and "data:image" not in text  # drawn, not pasted as a bitmap
    ids = [a["id"] for _, a in page.elements if a.get("id")]
    assert len(ids) == len(set(ids))  # several figures on one page: no id twice


def test_every_finding_is_there_with_its_rule_link_and_line(example, example_page):
    _, report, text = example
    found = [d for r in report.lint.results for d in r.diagnostics]
    assert found  # the example has warnings (LIS321, LIS324, LIS607)
    plain = example_page.words()
    for d in found:
        assert f'href="{DOCS}#{d.code.lower()}"' in text
        assert " ".join(d.message.split()) in plain
        assert f"{d.path}:{d.line}:{d.column}" in plain
    # the excerpt marks the line a finding points at
    first = next(d for d in found if d.path.endswith("achsmds1.lis"))
    line = (EXAMPLE / "listen" / "achsmds1.lis").read_text(encoding="latin-1").splitlines()[first.line - 1]
    assert re.search(
        rf'<span class="hit"> *{first.line} │ {re.escape(html.escape(line.rstrip()))}</span>', text
    )


def test_the_counts_are_those_of_lint(example, example_page):
    request, _, _ = example
    outcome = run_lint(LintRequest([str(request.target), str(request.program)], machine=str(request.target)))
    warnings = sum(1 for r in outcome.results for d in r.diagnostics if d.severity.value == "warning")
    assert f"{warnings} warnings" in example_page.words()


def test_the_assumed_geometry_is_marked_and_only_where_assumed(example):
    _, _, given = example
    assumed = as_html(
        build_report(ReportRequest(EXAMPLE / "listen" / "hochlauf.lis", program=EXAMPLE / "rfp.nc"))
    )
    # machine.toml gives X its cam: with it, X's cam is not marked; without it, it is
    x_given = given[given.index('data-axis="X"') : given.index('data-axis="Y"')]
    x_assumed = assumed[assumed.index('data-axis="X"') : assumed.index('data-axis="Y"')]
    assert "<td>reference cam</td><td>-20, -2</td><td>given</td>" in x_given
    assert re.search(
        r'<tr class="assumed"><td>reference cam</td><td>[^<]*</td><td><span class="badge assumed">', x_assumed
    )
    assert "Assumed geometry:" in x_assumed and "Assumed geometry:" not in x_given
    assert "ASSUMED, not given" in x_assumed  # the figure says so too


def test_the_same_input_gives_the_same_bytes(example):
    request, _, text = example
    assert as_html(build_report(request)) == text


def test_a_single_axis_list_with_its_backup(tmp_path):
    source = FIXTURES / "lists" / "achsmds1.lis"
    current = tmp_path / "achsmds1.lis"
    text = source.read_bytes()
    current.write_bytes(text.replace(b"Ende", b"getriebe[0].vb_reflow 1234\nEnde", 1))
    report = build_report(ReportRequest(current, against=source))
    page = as_html(report)
    parse_strictly(page)
    assert_self_contained(page)
    assert report.list_diff is not None and "comparison" in Page(page).ids()
    assert "<td>getriebe[0].vb_reflow</td>" in page[page.index('id="comparison"') :]


def test_a_machine_against_its_backup(tmp_path):
    now, backup = tmp_path / "mill", tmp_path / "mill_backup"
    shutil.copytree(FIXTURES / "machine_diff" / "mill", now)
    shutil.copytree(FIXTURES / "machine_diff" / "mill_backup", backup)
    first = now / "listen" / "achsmds1.lis"
    first.write_bytes(first.read_bytes().replace(b"Ende", b"getriebe[0].vb_reflow 4321\nEnde", 1))
    report = build_report(ReportRequest(now, against=backup))
    assert report.machine_diff is not None and report.machine_diff["differ"]
    page = as_html(report)
    parse_strictly(page)
    comparison = page[page.index('id="comparison"') :]
    assert "<td>getriebe[0].vb_reflow</td>" in comparison and "<td>4321</td>" in comparison


HOSTILE_NAME = '<i>&amp;"x.lis'  # a start-up list entry holds no space
HOSTILE_VALUE = '"<img src=x onerror=alert(1)>"'


def test_what_comes_from_the_files_is_escaped(tmp_path):
    """A list named like markup, with markup in a value and a comment, shows as text."""
    machine = tmp_path / "m"
    shutil.copytree(EXAMPLE / "listen", machine / "listen")
    hostile = machine / "listen" / HOSTILE_NAME
    (machine / "listen" / "achsmds1.lis").rename(hostile)
    startup = machine / "listen" / "hochlauf.lis"
    startup.write_text(
        startup.read_text(encoding="latin-1").replace("achsmds1.lis", HOSTILE_NAME), encoding="latin-1"
    )
    data = hostile.read_bytes().replace(
        b"Ende", f"kopf.log_achs_name {HOSTILE_VALUE}\nkenngr.bogus <b>x</b>\nEnde".encode(), 1
    )
    hostile.write_bytes(data)
    report = build_report(ReportRequest(startup))
    page = as_html(report)
    parse_strictly(page)
    assert_self_contained(page)
    assert "<i>" not in page and "<img" not in page and "<b>x" not in page
    assert "&lt;i&gt;&amp;amp;&quot;x.lis" in page
    words = Page(page).words()
    assert HOSTILE_NAME in words  # shown as written
    markdown = as_markdown(report)
    rendered = render_markdown(markdown)
    assert "<i>" not in rendered and "<b>" not in rendered


def test_the_report_never_overwrites_an_input(tmp_path):
    machine = tmp_path / "m"
    shutil.copytree(EXAMPLE, machine)
    for victim in ("listen/achsmds2.lis", "rfp.nc", "machine.toml", "listen/hochlauf.lis"):
        before = (machine / victim).read_bytes()
        done = run_cli(
            "report",
            str(machine / "listen" / "hochlauf.lis"),
            "--program",
            str(machine / "rfp.nc"),
            "--scenario",
            str(machine / "machine.toml"),
            "-o",
            str(machine / victim),
        )
        assert done.returncode == 2 and "this run reads" in done.stderr, done.stderr
        assert (machine / victim).read_bytes() == before


def test_the_command_writes_the_file_and_fails_cleanly(tmp_path):
    target = tmp_path / "report.html"
    done = run_cli("report", str(EXAMPLE / "listen" / "hochlauf.lis"), "-o", str(target))
    assert done.returncode == 0, done.stderr
    assert target.read_text(encoding="utf-8").startswith("<!DOCTYPE html>")
    missing = run_cli("report", str(tmp_path / "nope" / "hochlauf.lis"), "-o", str(target))
    assert missing.returncode == 2 and "Traceback" not in missing.stderr and "nope" in missing.stderr
    program = run_cli("report", str(FIXTURES / "multi_rule.lis"), "--program", "rfp.nc", "-o", str(target))
    assert program.returncode == 2 and "--program goes with a start-up list" in program.stderr
    # A folder of two machine variants: the report asks which, in its own words (not the diff's "compare").
    two = tmp_path / "two"
    two.mkdir()
    for name in ("hochlauf_coe.lis", "hochlauf_soe.lis"):
        shutil.copy(EXAMPLE / "listen" / "hochlauf.lis", two / name)
    variants = run_cli("report", str(two), "-o", str(target))
    assert variants.returncode == 2 and variants.stderr.count("\n") == 1
    assert (
        "holds 2 start-up lists (hochlauf_coe.lis, hochlauf_soe.lis): name the one meant" in variants.stderr
    )
    (tmp_path / "empty").mkdir()
    empty = run_cli("report", str(tmp_path / "empty"), "-o", str(target))
    assert "no start-up list" in empty.stderr and "compare" not in empty.stderr


# --- Markdown -------------------------------------------------------------------------------------


def render_markdown(text: str) -> str:
    """CommonMark with GitHub's tables; raw HTML in the source would show as an html token."""
    from markdown_it import MarkdownIt

    parser = MarkdownIt("commonmark").enable("table")
    tokens = parser.parse(text)
    flat = [t for token in tokens for t in [token, *(token.children or [])]]
    assert not [t for t in flat if t.type in ("html_inline", "html_block")], "raw HTML in the Markdown"
    return parser.render(text)


def test_markdown_of_lint_is_a_table_of_the_worst_findings():
    done = run_cli("lint", str(FIXTURES / "multi_rule.lis"), "--format", "markdown")
    assert done.returncode == 1
    rendered = render_markdown(done.stdout)
    assert "<table>" in rendered and f'href="{DOCS}#lis203"' in rendered
    assert "2 errors, 2 warnings, 2 info" in rendered
    assert "<code>" not in rendered  # backticks of the messages are text, not code spans
    assert "`DRIVE_CONROLLED`" in rendered


def test_markdown_of_explain_and_report():
    for args in (
        ("explain", str(EXAMPLE / "listen" / "achsmds1.lis")),
        ("explain", str(EXAMPLE / "listen" / "hochlauf.lis"), "--program", str(EXAMPLE / "rfp.nc")),
        ("explain", "vb_reflow"),
        (
            "report",
            str(EXAMPLE / "listen" / "hochlauf.lis"),
            "--program",
            str(EXAMPLE / "rfp.nc"),
            "--scenario",
            str(EXAMPLE / "machine.toml"),
        ),
    ):
        done = run_cli(*args, "--format", "markdown")
        assert done.returncode == 0, done.stderr
        rendered = render_markdown(done.stdout)
        assert rendered.startswith("<h2>")
    assert "done in 29.21 s" in rendered and "<table>" in rendered
