"""The library API: paths are paths, text has its own functions, models round-trip."""

from __future__ import annotations

import ast
import json
import re
import shutil
from pathlib import Path

import pytest

import achslint
from achslint.fmt import canonical_text

from .conftest import FIXTURES, ROOT, run_cli, source_tree

LIST = FIXTURES / "lists" / "achsmds1.lis"


def test_a_missing_path_raises_file_not_found(tmp_path):
    with pytest.raises(FileNotFoundError):
        achslint.lint("nope.lis")
    with pytest.raises(FileNotFoundError):
        achslint.load(tmp_path / "nope.lis")


def test_paths_and_text_give_the_same_findings():
    by_path = [(d.line, d.code) for d in achslint.lint(str(LIST))]
    text = LIST.read_bytes().decode("latin-1")
    assert [(d.line, d.code) for d in achslint.lint_text(text, filename="achsmds1.lis")] == by_path


def test_loads_dumps_round_trip():
    model = achslint.load(LIST)
    text = achslint.dumps(model)
    assert achslint.loads(text) == achslint.loads(achslint.dumps(achslint.loads(text)))
    assert achslint.loads(text).model_dump() == model.model_dump()
    assert achslint.format_text(text) == canonical_text(text) == text  # dumps writes the canonical layout


def test_explain_dry_run_and_format_text():
    report = achslint.explain(LIST)
    assert (
        report["strategy"]["id"] and achslint.explain(LIST) == report
    )  # still the function after the first call
    run = achslint.dry_run(LIST, {"start_position": 50.0})
    assert run.trace.outcome in ("homed", "failed", "skipped") or run.trace.outcome
    assert achslint.format_text("kopf.achs_nr 1   \nEnde\n") == "kopf.achs_nr  1\nEnde\n"


def test_the_package_is_typed():
    assert (Path(achslint.__file__).parent / "py.typed").is_file()


# --- issue 27 item 6: what a Python user expects -----------------------------------------------------------

SDK = FIXTURES / "machines" / "sdk"


def cli_findings(*paths: str | Path) -> list[tuple[str, int, str]]:
    result = run_cli("lint", *map(str, paths), "--format", "json", "--exit-zero")
    assert result.returncode == 0, result.stderr
    return [(d["path"], d["line"], d["code"]) for d in json.loads(result.stdout)["diagnostics"]]


def found(diagnostics) -> list[tuple[str, int, str]]:
    return [(d.path, d.line, d.code) for d in diagnostics]


@pytest.mark.parametrize("target", [SDK, SDK / "listen", SDK / "listen" / "hochlauf.lis"], ids=str)
def test_lint_of_a_folder_or_a_start_up_list_is_the_machine(target):
    """The command line lints a folder or a start-up list as a machine; so does `lint` (it raised
    FileNotFoundError for a folder, and checked a start-up list as one list)."""
    expected = cli_findings(target)
    assert {code for _, _, code in expected} == {"LIS102", "LIS401"}  # the machine's axis lists
    assert found(achslint.lint(target)) == found(achslint.lint(str(target))) == expected
    assert found(achslint.lint_paths([target])) == expected
    assert found(achslint.lint(target, ignore=["LIS4"])) == [f for f in expected if f[2] != "LIS401"]


def test_a_start_up_list_named_otherwise_is_told_by_its_content(tmp_path):
    machine = tmp_path / "sdk"
    shutil.copytree(SDK, machine)
    (machine / "listen" / "hochlauf.lis").rename(machine / "listen" / "maschine.lis")
    assert found(achslint.lint(machine / "listen" / "maschine.lis")) == cli_findings(
        machine / "listen" / "maschine.lis"
    )
    assert {d.code for d in achslint.lint(machine / "listen" / "maschine.lis")} == {"LIS102", "LIS401"}


def test_lint_paths_failures(tmp_path):
    with pytest.raises(FileNotFoundError):
        achslint.lint_paths([tmp_path / "nope"])
    (tmp_path / "achsmds1.lis").write_bytes("kopf.achs_nr 1\nEnde\n".encode("utf-16"))
    with pytest.raises(achslint.LintFailed, match="UTF-16") as failed:
        achslint.lint_paths([tmp_path])
    assert len(failed.value.errors) == 1 and "achsmds1.lis" in failed.value.errors[0]
    (tmp_path / "achsmds1.lis").unlink()
    (tmp_path / "achslint.toml").write_text("fail-on = 3\n")
    (tmp_path / "achsmds2.lis").write_text("kopf.achs_nr 2\nEnde\n")
    with pytest.raises(achslint.ConfigError, match=r"achslint\.toml"):
        achslint.lint_paths([tmp_path])


@pytest.mark.parametrize(
    ("function", "takes"),
    [(achslint.loads, "load()"), (achslint.lint_text, "lint()"), (achslint.format_text, "decode")],
)
def test_text_functions_refuse_bytes_with_a_type_error(function, takes):
    with pytest.raises(TypeError, match=takes):
        function(LIST.read_bytes())
    with pytest.raises(TypeError):
        achslint.loads(LIST.read_text(encoding="latin-1"), defaults=b"Ende\n")


def test_loads_of_dumps_is_the_model():
    for path in (LIST, SDK / "listen" / "achsmds3.lis", FIXTURES / "rules" / "LIS203" / "bad.lis"):
        model = achslint.load(path)
        again = achslint.loads(achslint.dumps(model))
        assert again == model, path
        assert again.source_of("kopf.achs_nr") != model.source_of("kopf.achs_nr")  # read from elsewhere
    text = achslint.dumps(achslint.load(LIST))
    changed = re.sub(r"(?m)^(getriebe\[0\]\.vb_reflow\s+)\d+", r"\g<1>12345", text)
    assert changed != text and achslint.loads(changed) != achslint.load(LIST)
    assert achslint.load(LIST) != text  # a model is not its text


def test_severity_is_a_string():
    diagnostics = achslint.lint(FIXTURES / "rules" / "LIS203" / "bad.lis")
    error = next(d for d in diagnostics if d.code == "LIS203")
    assert error.severity == "error" and error.severity is achslint.Severity.ERROR
    assert isinstance(error.severity, str) and str(error.severity) == f"{error.severity}" == "error"
    assert json.dumps({"severity": error.severity}) == '{"severity": "error"}'
    assert achslint.Severity("warning") == "warning" != achslint.Severity.INFO


def test_the_exceptions_of_the_api_are_exported(tmp_path):
    with pytest.raises(achslint.UnreadableInput):
        achslint.lint("kopf.achs_nr 1\nEnde\n".encode("utf-16"))
    with pytest.raises(achslint.ScenarioError, match="bogus"):
        achslint.dry_run(LIST, {"bogus": 1})
    spindle = (
        b"kenngr.antr_typ 1\nkenngr.achs_typ 4\nkenngr.ref_ohne_rev 1\nkenngr.ref_ohne_nocken 0\n"
        b"kenngr.ref_richt 1\ngetriebe[0].vb_reflow 36000\nkenngr.vorz_richtung 1\nkenngr.beweg_richt 0\nEnde\n"
    )
    with pytest.raises(achslint.DryRunRefused, match="LIS319"):
        achslint.dry_run(spindle)
    with pytest.raises(achslint.OutputIsInput):
        achslint.api.run_lint(achslint.api.LintRequest(paths=[str(LIST)], output=str(LIST)))
    for name in achslint.__all__:
        value = getattr(achslint, name)
        if isinstance(value, type) and issubclass(value, BaseException):
            assert value.__module__.startswith("achslint."), name
    # the package stays light: these come with the first use of one of them
    assert "achslint.api" in __import__("sys").modules


def test_every_public_name_is_typed_for_the_checkers():
    """Every function of the API names its return type (never Any) and its parameters' types; the package's
    `__all__` is imported under TYPE_CHECKING, so that a type checker sees each re-exported name."""
    import achslint.api as api

    tree = source_tree(ROOT / "src" / "achslint" / "api.py")
    functions = {node.name: node for node in tree.body if isinstance(node, ast.FunctionDef)}
    public = [name for name in api.__all__ if name in functions]
    assert {"lint", "lint_paths", "load", "loads", "dumps", "explain", "dry_run", "format_text"} <= set(
        public
    )
    for name in public:
        node = functions[name]
        assert node.returns is not None and "Any" not in ast.unparse(node.returns), name
        arguments = [*node.args.args, *node.args.kwonlyargs]
        assert all(argument.annotation is not None for argument in arguments), name
    assert (
        ast.unparse(functions["load"].returns) == ast.unparse(functions["loads"].returns) == "AxisParameters"
    )
    assert isinstance(achslint.load(LIST), achslint.api.__dict__.get("AxisParameters") or object)
    package = source_tree(ROOT / "src" / "achslint" / "__init__.py")
    checked = next(node for node in package.body if isinstance(node, ast.If))
    typed = {alias.name for node in checked.body for alias in node.names}
    assert set(achslint.__all__) - {"__version__"} == typed


TWO_FINDINGS = "kenngr.swe_poss 1\nkenngr.swe_pos x\nEnde\n"  # LIS101 (unknown name), LIS201 (not a number)


@pytest.mark.parametrize(
    ("keyword", "value", "codes"),
    [
        ("select", "LIS201", ["LIS201"]),
        ("select", "LIS101,LIS201", ["LIS101", "LIS201"]),
        ("ignore", "LIS101", ["LIS201"]),
        ("ignore", ("LIS101",), ["LIS201"]),
    ],
)
def test_select_and_ignore_take_one_string_as_the_command_line_does(tmp_path, keyword, value, codes):
    """Found by review: a string was read letter by letter, so `ignore="LIS101"` ignored the prefix `L`,
    i.e. every rule (the call returned nothing), and `select="LIS201"` selected every rule."""
    assert sorted(d.code for d in achslint.lint_text(TWO_FINDINGS, **{keyword: value})) == codes
    assert sorted(d.code for d in achslint.lint(TWO_FINDINGS.encode(), **{keyword: value})) == codes
    (tmp_path / "achsmds1.lis").write_text(TWO_FINDINGS)
    assert sorted(d.code for d in achslint.lint_paths([tmp_path], **{keyword: value})) == codes


def test_a_code_that_picks_no_rule_is_a_value_error():
    with pytest.raises(ValueError, match=r"ignore: .*LIS9999"):
        achslint.lint_text(TWO_FINDINGS, ignore=["LIS9999"])
    with pytest.raises(ValueError, match="select"):
        achslint.lint(TWO_FINDINGS.encode(), select="LIS2O1")


def test_odd_arguments_are_type_errors_that_say_what_is_taken(tmp_path):
    """Found by review: lint_paths("listen") linted the paths `l`, `i`, `s` ... (FileNotFoundError for
    `l`), and dumps(None) raised AttributeError from inside the model code."""
    with pytest.raises(TypeError, match=r"list of paths.*lint_paths\(\[path\]\)"):
        achslint.lint_paths(str(tmp_path))
    with pytest.raises(TypeError, match="list of paths"):
        achslint.lint_paths(tmp_path)
    with pytest.raises(TypeError, match=r"dumps.*not NoneType"):
        achslint.dumps(None)
