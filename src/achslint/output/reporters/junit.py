"""JUnit XML: one test suite per file, one test case per diagnostic (Jenkins, GitLab, Azure).

A diagnostic fails its test case only at or above the file's `fail-on` severity, the same rule as the
exit code: advice below it is kept as the test case's `system-out`, so a run that exits 0 is not marked
unstable by Jenkins.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Sequence
from typing import TYPE_CHECKING, TextIO

from ...core.diagnostics import Severity
from ...core.display import printable

if TYPE_CHECKING:
    from .base import LintResult


def document(results: Sequence[LintResult]) -> ET.Element:
    root = ET.Element("testsuites", name="achslint")
    total = failures = errors = 0
    for result in results:
        name = printable(result.name)  # XML 1.0 has no way to hold most control characters
        suite = ET.SubElement(root, "testsuite", name=name)
        cases = 0
        if result.error:
            case = ET.SubElement(suite, "testcase", classname=name, name="read")
            error = printable(result.error)
            ET.SubElement(case, "error", message=error).text = error
            cases, failed = 1, 1
        elif not result.diagnostics:
            ET.SubElement(suite, "testcase", classname=name, name="achslint")
            cases, failed = 1, 0
        else:
            failed = 0
            threshold = Severity(result.fail_on).rank
            for d in result.diagnostics:
                case = ET.SubElement(
                    suite, "testcase", classname=name, name=f"{d.code} line {d.line}:{d.column}"
                )
                message = printable(d.message)
                text = f"{printable(d.path)}:{d.line}:{d.column}: {d.code} [{d.severity.value}] {message}"
                if d.severity.rank >= threshold:
                    failure = ET.SubElement(
                        case, "failure", message=message, type=f"{d.code} ({d.severity.value})"
                    )
                    failure.text = text
                    failed += 1
                else:
                    ET.SubElement(case, "system-out").text = text
                cases += 1
        suite.set("tests", str(cases))
        suite.set("failures", str(failed if not result.error else 0))
        suite.set("errors", "1" if result.error else "0")
        total += cases
        if result.error:
            errors += 1  # the suite counts it as an error, so the totals do too (not as a failure)
        else:
            failures += failed
    root.set("tests", str(total))
    root.set("failures", str(failures))
    root.set("errors", str(errors))
    return root


def report(results: Sequence[LintResult], stream: TextIO, **_options: object) -> None:
    root = document(results)
    ET.indent(root)
    stream.write('<?xml version="1.0" encoding="UTF-8"?>\n')
    stream.write(ET.tostring(root, encoding="unicode"))
    stream.write("\n")
