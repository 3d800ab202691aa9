"""A review of the commands that write or suggest edits (`lint --fix`, `--add-noqa`, `fmt`, the editor's
quick fixes) and of `report`: each test holds one defect the review found, through the real CLI on files in
a temporary folder."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

# A machine whose default list sets the slow homing speed above the fast one the axis list sets (LIS302,
# an error only with the default list underneath) and whose axis list ends in `End` (LIS004, a safe fix).
STARTUP = b"zahl_mds 1\ndefault_achs_mds ./listen/default_mds.lis\nachs_mds[0]  ./listen/a1.lis\nEnde\n"
DEFAULTS = b"getriebe[0].vb_reflow 30000\nEnde\n"
AXIS = (
    b"kopf.achs_nr 1\nkopf.log_achs_name X\nkenngr.achs_typ 1\nkenngr.antr_typ 8\n"
    b"getriebe[0].vb_refmax 20000\nEnd\n"
)


def _machine(root: Path) -> Path:
    listen = root / "listen"
    listen.mkdir()
    (listen / "hochlauf.lis").write_bytes(STARTUP)
    (listen / "default_mds.lis").write_bytes(DEFAULTS)
    (listen / "a1.lis").write_bytes(AXIS)
    return listen


def _codes(done) -> list[tuple[str, int, str]]:
    return [(d["path"], d["line"], d["code"]) for d in json.loads(done.stdout)["diagnostics"]]


@pytest.mark.parametrize("how", [(), ("--diff",)])
def test_fix_reports_what_the_default_list_causes(cli, tmp_path, monkeypatch, how):
    """`lint --fix` linted (and checked the fixes of) each list without the default list under it: the
    LIS302 error the default list causes vanished from the run's findings and the run exited 0."""
    monkeypatch.chdir(tmp_path)
    _machine(tmp_path)
    plain = cli("lint", "listen/hochlauf.lis", "--format", "json")
    assert ("listen/a1.lis", 5, "LIS302") in _codes(plain) and plain.returncode == 1
    fixing = cli("lint", "listen/hochlauf.lis", "--fix", *how, "--format", "concise")
    findings = (fixing.stderr if how else fixing.stdout).decode()  # --diff puts the findings on stderr
    assert "listen/a1.lis:5:1: LIS302 [error]" in findings
    assert fixing.returncode == 1
    if not how:
        assert (tmp_path / "listen" / "a1.lis").read_bytes() == AXIS.replace(b"End\n", b"Ende\n")
        after = cli("lint", "listen/hochlauf.lis", "--format", "concise")
        assert after.stdout.decode().splitlines() == fixing.stdout.decode().splitlines()


def test_editor_fix_all_fixes_what_lint_fix_fixes_with_the_default_list(cli, tmp_path, monkeypatch):
    """The editor's "fix all" (`Session.fixed_text`) checked the fixes of a list without its default list
    and without the kind its start-up entry gives it: a symbol fix that keeps what the CNC does only with the
    default list's CANopen drive underneath (as `lint --fix` applies it) was not offered."""
    from achslint.lsp.documents import Document
    from achslint.lsp.session import Session

    monkeypatch.chdir(tmp_path)
    listen = _machine(tmp_path)
    (listen / "default_mds.lis").write_bytes(b"kenngr.antr_typ 8\nEnde\n")
    axis = b"kopf.achs_nr 1\nkopf.log_achs_name X\nkenngr.achs_typ 1\nkenngr.homing.homing_type DRIVE_CONROLLED\nEnde\n"
    (listen / "a1.lis").write_bytes(axis)
    session = Session(tmp_path)
    path = listen / "a1.lis"
    document = Document(path.as_uri(), path, axis.decode(), 1)
    session.open(document)
    fixed = session.fixed_text(document)
    assert cli("lint", "listen/hochlauf.lis", "--fix").returncode == 0
    assert path.read_bytes() == axis.replace(b"CONROLLED", b"CONTROLLED")
    assert fixed == path.read_text()


def test_plain_lint_counts_only_the_fixes_fix_applies(cli, tmp_path, monkeypatch):
    """A plain lint said "2 fixable with --fix" (and JSON called both fixes safe) for a list whose two fixes
    `--fix` then refuses as changing what the CNC does ("fixed 0 diagnostics")."""
    monkeypatch.chdir(tmp_path)
    text = (
        b"kopf.achs_nr 1\nkopf.log_achs_name X\nkenngr.achs_typ 1\nkenngr.antr_typ 4\n"
        b"kenngr.ref_ricth 1\nkenngr.homing.homing_type DRIVE_CONROLLED\nEnde\n"
    )
    (tmp_path / "a.lis").write_bytes(text)
    fixing = cli("lint", "a.lis", "--fix", "--format", "json")
    assert fixing.stderr.decode().strip() == "fixed 0 diagnostics"
    fixes = [d["fix"]["applicability"] for d in json.loads(fixing.stdout)["diagnostics"] if d["fix"]]
    assert fixes == ["unsafe", "unsafe"]
    plain = cli("lint", "a.lis", "--format", "json")
    assert [d["fix"] for d in json.loads(plain.stdout)["diagnostics"] if d["fix"]] == [
        d["fix"] for d in json.loads(fixing.stdout)["diagnostics"] if d["fix"]
    ]
    said = cli("lint", "a.lis").stdout.decode()
    assert "fixable with --fix\n" not in said.replace("--unsafe-fixes", "")
    assert said.rstrip().endswith("2 fixable with --fix --unsafe-fixes")


@pytest.mark.parametrize(
    ("line", "written"),
    [
        # text after a symbol that is no `(` comment: the CNC reads it with the value, so the codes go into
        # a `(` comment of their own, after it, and the text stays as it was
        (
            b"kenngr.homing_type   CNC_CONTROLLED  # old",
            b"kenngr.homing_type   CNC_CONTROLLED  # old  ( noqa: LIS007, LIS102",
        ),
        (b'kopf.log_achs_name  "X" trailing', b'kopf.log_achs_name  "X" trailing  ( noqa: LIS007'),
        # after a number everything is a comment: joined as before
        (b"getriebe[6].vb_refmax 20000 # wide", b"getriebe[6].vb_refmax 20000 # wide  noqa: LIS104"),
        (
            b"kenngr.homing_type   CNC_CONTROLLED  ( old",
            b"kenngr.homing_type   CNC_CONTROLLED  ( old  noqa: LIS102",
        ),
    ],
)
def test_add_noqa_after_text_that_is_no_comment_opens_a_comment(cli, tmp_path, monkeypatch, line, written):
    """`--add-noqa` appended `noqa: CODE` to the text after a symbol or string (LIS007: not a comment, the
    CNC reads it as part of the value), which lengthened what the CNC reads; the README promises "after
    text only `(`"."""
    monkeypatch.chdir(tmp_path)
    head = b"kopf.achs_nr 1\nkenngr.achs_typ 1\nkenngr.antr_typ 8\n"
    (tmp_path / "a.lis").write_bytes(head + line + b"\nEnde\n")
    (tmp_path / ".achslint.toml").write_text('ignore = ["LIS404"]\n')
    assert cli("lint", "a.lis", "--add-noqa").returncode == 0
    assert (tmp_path / "a.lis").read_bytes() == head + written + b"\nEnde\n"
    after = cli("lint", "a.lis", "--format", "concise")
    assert after.stdout.decode() == "All checks passed!\n"
    assert cli("lint", "a.lis", "--add-noqa").stderr.decode().startswith("added 0 noqa")


def test_editor_noqa_action_after_text_that_is_no_comment_opens_a_comment(tmp_path):
    """The editor's "Suppress … on this line (noqa)" appended `noqa: CODE` to the text after a symbol (no
    comment: the CNC reads it with the value), as `--add-noqa` did."""
    from achslint.core.diagnostics import Diagnostic, Severity
    from achslint.lsp import features
    from achslint.lsp.documents import Document
    from achslint.lsp.session import Session

    text = "kenngr.homing.homing_type  CNC_CONTROLLED  # old\nkenngr.achs_typ  1  # linear\nEnde\n"
    path = tmp_path / "achsmds1.lis"
    session = Session(tmp_path)
    document = Document(path.as_uri(), path, text, 1)
    session.open(document)
    file = document.parse()

    def finding(line: int) -> Diagnostic:
        return Diagnostic(document.name, line, 1, line, 2, "LIS007", Severity.WARNING, "text after")

    after_symbol = features.noqa_edit(document, file, finding(1))
    assert after_symbol is not None and after_symbol.new_text == "  ( noqa: LIS007"
    after_number = features.noqa_edit(document, file, finding(2))  # a comment there: joined
    assert after_number is not None and after_number.new_text == "  noqa: LIS007"


def test_add_noqa_on_a_list_it_may_not_write_does_not_blame_the_rules(cli, tmp_path, monkeypatch):
    """A read-only list keeps its findings because it was not written (said on standard error, exit 2), not
    because a noqa cannot suppress them, which the summary said."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "achsmds1.lis").write_bytes(b"kopf.achs_nr 1\nkenngr.ref_ricth 1\nEnde\n")
    (tmp_path / "achsmds1.lis").chmod(0o444)
    done = cli("lint", "--add-noqa", "achsmds1.lis")
    said = done.stderr.decode()
    assert done.returncode == 2
    assert "achsmds1.lis is read-only; not rewritten" in said
    assert said.rstrip().endswith("added 0 noqa directives; 1 list not read or not written (said above)")
    assert "cannot suppress" not in said
