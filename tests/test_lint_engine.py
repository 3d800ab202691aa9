"""The one lint engine (`lintengine.run`): every rule scope selected, suppressed, overridden and sorted alike.

Lists and NC programs share one `noqa` model, so a directive that suppresses nothing is LIS009 in both;
the machine-level rules get the severities of the configuration wherever they run.
"""

from __future__ import annotations

import ast
import json
from pathlib import Path

from achslint.core.diagnostics import Diagnostic, Severity
from achslint.linting.config import Settings
from achslint.linting.engine import Policy, enabled_checks, enabled_codes, run
from achslint.linting.linter import FileSettings, lint_file
from achslint.linting.suppression import Suppressions
from achslint.machine.resolved import Machine
from achslint.rules import Scope, registry
from achslint.syntax.parser import parse_text

from .conftest import FIXTURES, ROOT, run_cli
from .source_nodes import nodes

PORTAL = FIXTURES / "machines" / "portal" / "listen" / "hochlauf.lis"

# A homing program for the portal machine: Z moves before its G74 on lines 2 to 4, X on line 6 (LIS606).
PROGRAM = (
    "; achslint: noqa: LIS604\n"  # 1: no axis here is DISABLED and homed: suppresses nothing
    "N10 G01 G90 Z200 F500 (noqa: LIS606)\n"  # 2: suppresses the LIS606 of this line
    "N20 G01 G90 Z210 F500 ; lift first, noqa: LIS602\n"  # 3: LIS606 here, no LIS602: suppresses nothing
    "N30 G01 G90 Z220 F500 (noqa: LIS6O6)\n"  # 4: a letter O: no rule code
    "N40 G74 Z1\n"
    "N50 G00 X10 (noqa)\n"  # 6: X is not homed yet, so the bare noqa suppresses LIS606
    "N60 G74 X1 Y1\n"
    "N70 G01 Z100 (noqa)\n"  # 8: Z is homed now: a bare noqa that suppresses nothing
    "N80 M30\n"
)


def lint_program(tmp_path: Path, *extra: str, config: str | None = None) -> list[dict[str, object]]:
    program = tmp_path / "rfp.nc"
    program.write_text(PROGRAM, encoding="utf-8")
    if config is not None:
        (tmp_path / "achslint.toml").write_text(config, encoding="utf-8")
    result = run_cli(
        "lint", str(program), "--machine", str(PORTAL), "--format", "json", "--exit-zero", *extra
    )
    assert result.returncode == 0, result.stderr.decode()
    return list(json.loads(result.stdout)["diagnostics"])


def test_unused_noqa_in_a_program_is_lis009(tmp_path: Path) -> None:
    found = lint_program(tmp_path)
    assert [(d["line"], d["column"], d["code"], d["severity"]) for d in found] == [
        (1, 1, "LIS009", "warning"),
        (3, 13, "LIS606", "warning"),
        (3, 37, "LIS009", "warning"),
        (4, 13, "LIS606", "warning"),
        (4, 24, "LIS009", "warning"),
        (8, 15, "LIS009", "warning"),
    ]
    messages = {d["line"]: d["message"] for d in found if d["code"] == "LIS009"}
    assert messages[1] == "`noqa` for LIS604 suppresses nothing in this file; remove it"
    assert messages[3] == "`noqa` for LIS602 suppresses nothing on this line; remove it"
    assert messages[4].startswith(
        "`noqa` names the unknown code `LIS6O6`, which suppresses nothing; did you mean LIS606?"
    )
    assert messages[8] == "this `noqa` suppresses no diagnostic; remove it"


def test_a_noqa_for_an_unselected_rule_in_a_program_is_not_unused(tmp_path: Path) -> None:
    # Only LIS009 and LIS606 run: the directives for LIS604 and LIS602 name rules that are off.
    found = lint_program(tmp_path, "--select", "LIS009,LIS606")
    assert [(d["line"], d["code"]) for d in found] == [
        (3, "LIS606"),
        (4, "LIS606"),
        (4, "LIS009"),
        (8, "LIS009"),
    ]


def test_severity_overrides_reach_lis009_in_a_program(tmp_path: Path) -> None:
    found = lint_program(tmp_path, config='[severity]\nLIS009 = "error"\nLIS606 = "info"\n')
    assert {(d["code"], d["severity"]) for d in found} == {("LIS009", "error"), ("LIS606", "info")}


def _axes_xml(*numbers: int) -> bytes:
    axes = "".join(
        f"<IsgAxisDef><AchsMds><![CDATA[kopf.achs_nr {n}\nkopf.log_achs_name A{i}\nEnde\n]]></AchsMds></IsgAxisDef>\n"
        for i, n in enumerate(numbers)
    )
    return f"<TcSmProject>\n{axes}</TcSmProject>\n".encode()


def test_machine_findings_of_an_xml_project_get_the_configured_severity() -> None:
    # Two axes of one TwinCAT project share kopf.achs_nr 1: LIS501, a warning unless configured otherwise.
    data = _axes_xml(1, 1)
    plain = [
        d for d in lint_file(data, "project.tsproj.xml", FileSettings()).diagnostics if d.code == "LIS501"
    ]
    assert [d.severity for d in plain] == [Severity.WARNING]
    settings = FileSettings(Settings(severity={"LIS501": "error"}))
    found = [d for d in lint_file(data, "project.tsproj.xml", settings).diagnostics if d.code == "LIS501"]
    assert [(d.line, d.severity) for d in found] == [(plain[0].line, Severity.ERROR)]


def test_policy_selects_like_ruff() -> None:
    policy = Policy.of(select=["LIS3"], extend_select=["LIS009"], ignore=["LIS30"])
    assert [policy.enabled(code) for code in ("LIS302", "LIS310", "LIS009", "LIS101")] == [
        False,
        True,
        True,
        False,
    ]
    assert Policy().enabled("LIS606") and not Policy.of(ignore=["ALL"]).enabled("LIS606")


def test_every_rule_has_a_check_for_each_of_its_scopes() -> None:
    for code, rule in registry().items():
        if rule.produced_by == "dry-run":
            assert rule.scopes == (), code  # the dry-run reports it, no lint scope runs it
            continue
        assert rule.scopes, f"{code} has no check, check_machine, check_program or check_after"
        for scope in rule.scopes:
            assert callable(rule.checker(scope)) and getattr(rule.module, scope.value) is rule.checker(scope)
    assert registry()["LIS316"].scopes == (Scope.LIST, Scope.MACHINE)
    assert [code for code, _ in enabled_checks(Scope.AFTER, Policy())] == ["LIS009"]
    assert {code[:4] for code, _ in enabled_checks(Scope.PROGRAM, Policy())} == {"LIS6"}


def test_a_default_list_runs_no_rule_that_judges_a_whole_axis() -> None:
    whole = {code for code, _ in enabled_checks(Scope.LIST, Policy())}
    alone = {code for code, _ in enabled_checks(Scope.LIST, Policy(), whole_axis=False)}
    assert alone < whole and whole - alone == {c for c in whole if registry()[c].needs_whole_axis}
    # (the kind rules of other lists, LIS7xx, do not look at axis lists at all)
    assert enabled_codes(Policy(), whole_axis=False) == {
        code
        for code, rule in registry().items()
        if not rule.needs_whole_axis and (Scope.LIST not in rule.scopes or rule.applies_to("axis"))
    }


def test_run_applies_noqa_then_judges_it_then_overrides_and_sorts() -> None:
    from achslint.rules.context import Context

    text = (
        "kenngr.ref_ricth 1   # noqa: LIS101\n"  # an unknown name, suppressed
        "kopf.achs_nr 1   # noqa: LIS302\n"  # suppresses nothing
        "kopf.achs_nr 2\n"  # LIS005: the first line set it already
        "Ende\n"
    )
    file = parse_text(text, "a.lis")
    found = run(
        Scope.LIST,
        (Context("a.lis", file),),
        Policy.of(severity={"LIS009": "info"}),
        suppressions=Suppressions.of_list(file, "a.lis"),
    )
    assert [(d.line, d.code, d.severity) for d in found] == [
        (2, "LIS009", Severity.INFO),
        (3, "LIS005", registry()["LIS005"].severity),
    ]


def test_machine_findings_take_the_policy_of_their_own_file() -> None:
    # Two lists with kopf.achs_nr 1: LIS501 is reported on the second, with the policy of that file.
    members = []
    for name, axis in (("a.lis", "X"), ("b.lis", "Y")):
        summary = lint_file(f"kopf.achs_nr 1\nkopf.log_achs_name {axis}\nEnde\n".encode(), name).summary
        assert summary is not None
        members.append((name, summary))
    policies = {"a.lis": Policy.of(ignore=["LIS501"]), "b.lis": Policy.of(severity={"LIS501": "error"})}

    def repeated() -> list[tuple[str, str, Severity]]:
        found = run(Scope.MACHINE, (Machine("a folder", members=members),), lambda path: policies[path])
        return [(d.path, d.code, d.severity) for d in found]

    assert repeated() == [("b.lis", "LIS501", Severity.ERROR)]
    policies["b.lis"] = Policy.of(ignore=["LIS5"])
    assert repeated() == []


def test_only_the_engine_calls_rule_checks() -> None:
    """No module outside the engine runs rules itself: `Rule.checker` is read in linting/engine.py only."""
    callers = []
    for path in sorted((ROOT / "src" / "achslint").rglob("*.py")):
        if any(isinstance(n, ast.Attribute) and n.attr == "checker" for n in nodes(path)):
            callers.append(path.relative_to(ROOT / "src" / "achslint").as_posix())
    assert callers == ["linting/engine.py"]


def _diagnostic(line: int, code: str) -> Diagnostic:
    return Diagnostic("p.nc", line, 1, line, 2, code, Severity.ERROR, "")


def test_program_directives_apply_like_list_directives() -> None:
    lines = ["(achslint: noqa: LIS605)", "N10 G01 Z1 (noqa: LIS606, LIS607)", "N20 G74 Z1 ; noqa", "N30 M30"]
    suppressions = Suppressions.of_program(lines, "p.nc")
    assert [(d.line, d.column, d.end_column, d.codes, d.file_level) for d in suppressions.directives] == [
        (1, 1, 25, ["LIS605"], True),
        (2, 13, 33, ["LIS606", "LIS607"], False),
        (3, 14, 18, None, False),
    ]
    kept = suppressions.apply(
        [
            _diagnostic(2, "LIS606"),
            _diagnostic(2, "LIS602"),
            _diagnostic(3, "LIS601"),
            _diagnostic(4, "LIS605"),
        ]
    )
    assert [(d.line, d.code) for d in kept] == [(2, "LIS602")]
    assert [d.used for d in suppressions.directives] == [{"LIS605"}, {"LIS606"}, {"LIS601"}]
