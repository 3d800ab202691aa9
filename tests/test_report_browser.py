"""The commissioning report in a real browser (issue 29): headless Chromium (Debian's `chromium` and
`chromium-driver`, driven by Selenium) opens the page from a file:// URL with the network switched off.

Checked: no console message at error level, no request for anything but the page itself, the summary table,
the timeline and every axis section laid out and visible, a screenshot of a plausible size, and printing to
PDF: in print media every axis (and the timeline, the findings, the sign-off) starts a page, and the PDF has
a page for each of them. `.ci/run` installs Chromium when it is missing (`pytest -m slow` runs this); the
test skips, saying why, only where the browser or its driver cannot be had."""

from __future__ import annotations

import base64
import json
import re
import shutil

import pytest

from .conftest import ROOT, run_cli

pytestmark = pytest.mark.slow

EXAMPLE = ROOT / "docs" / "dry-run" / "machine"


def _browser_or_skip():
    webdriver = pytest.importorskip("selenium.webdriver", reason="selenium is not installed (the test extra)")
    from selenium.webdriver.chrome.service import Service

    binary = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")
    driver = shutil.which("chromedriver")
    if binary is None or driver is None:
        pytest.skip("no Chromium or chromedriver on this machine (apt-get install chromium chromium-driver)")
    options = webdriver.ChromeOptions()
    options.binary_location = binary
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1280,1024"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    try:
        return webdriver.Chrome(service=Service(driver), options=options)
    except Exception as exc:  # the driver and the browser disagree, or the browser cannot start here
        pytest.skip(f"Chromium does not start: {str(exc).splitlines()[0]}")


@pytest.fixture(scope="module")
def page(tmp_path_factory: pytest.TempPathFactory):
    target = tmp_path_factory.mktemp("report") / "report.html"
    done = run_cli(
        "report",
        str(EXAMPLE / "listen" / "hochlauf.lis"),
        "--program",
        str(EXAMPLE / "rfp.nc"),
        "--scenario",
        str(EXAMPLE / "machine.toml"),
        "-o",
        str(target),
    )
    assert done.returncode == 0, done.stderr
    browser = _browser_or_skip()
    try:
        browser.execute_cdp_cmd("Network.enable", {})
        browser.execute_cdp_cmd(
            "Network.emulateNetworkConditions",
            {"offline": True, "latency": 0, "downloadThroughput": -1, "uploadThroughput": -1},
        )
        browser.get(target.as_uri())
        yield browser, target
    finally:
        browser.quit()


def test_the_page_renders_offline_without_errors_or_requests(page):
    browser, target = page
    assert browser.execute_script("return document.readyState") == "complete"
    errors = [entry for entry in browser.get_log("browser") if entry["level"] == "SEVERE"]
    assert errors == []
    requested = []
    failed = []
    for entry in browser.get_log("performance"):
        message = json.loads(entry["message"])["message"]
        if message["method"] == "Network.requestWillBeSent":
            requested.append(message["params"]["request"]["url"])
        elif message["method"] == "Network.loadingFailed":
            failed.append(message["params"])
    assert failed == []
    assert set(requested) <= {target.as_uri()}, requested


def test_the_summary_timeline_and_every_axis_are_visible(page, tmp_path):
    browser, _ = page
    from selenium.webdriver.common.by import By

    summary = browser.find_element(By.CSS_SELECTOR, "#summary table.axes")
    assert summary.is_displayed() and summary.size["height"] > 100
    rows = summary.find_elements(By.CSS_SELECTOR, "tbody tr")
    assert [row.find_element(By.TAG_NAME, "td").text for row in rows] == ["X", "Y", "Z", "A", "B", "S"]
    timeline = browser.find_element(By.CSS_SELECTOR, "#timeline svg")
    assert timeline.is_displayed() and timeline.size["width"] > 600 and timeline.size["height"] > 400
    axes = browser.find_elements(By.CSS_SELECTOR, "section.axis")
    assert [a.get_attribute("data-axis") for a in axes] == ["X", "Y", "Z", "A", "B", "S"]
    for axis in axes:
        browser.execute_script("arguments[0].scrollIntoView()", axis)
        assert axis.is_displayed()
        parameters = axis.find_element(By.CSS_SELECTOR, "table.parameters")
        assert parameters.is_displayed() and parameters.size["height"] > 50
        # the table fits the page: nothing hidden to the right
        assert parameters.size["width"] <= axis.size["width"] + 1
    browser.execute_script("window.scrollTo(0, 0)")
    shot = tmp_path / "report.png"
    assert browser.save_screenshot(str(shot))
    data = shot.read_bytes()
    width, height = int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and width >= 1000 and height >= 600
    assert len(data) > 50_000  # a page with tables and text, not a blank one


def test_printing_gives_a_page_per_axis(page, tmp_path):
    browser, _ = page
    browser.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": "print"})
    try:
        breaks = browser.execute_script(
            "return [...document.querySelectorAll('section')].map(s => "
            "[s.id, getComputedStyle(s).breakBefore])"
        )
    finally:
        browser.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": ""})
    starts = [name for name, rule in breaks if rule == "page"]
    assert starts == [
        "timeline",
        *(f"axis-{n}" for n in range(1, 7)),
        "findings",
        "sign-off",
    ], breaks
    printed = browser.execute_cdp_cmd("Page.printToPDF", {"printBackground": True, "preferCSSPageSize": True})
    pdf = base64.b64decode(printed["data"])
    target = tmp_path / "report.pdf"
    target.write_bytes(pdf)
    assert pdf.startswith(b"%PDF")
    pages = len(re.findall(rb"/Type\s*/Page(?!s)", pdf))
    assert pages >= len(starts) + 1, pages  # the summary, then at least one page per section that breaks
