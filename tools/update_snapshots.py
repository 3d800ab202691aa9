"""Write fixtures/rules/<CODE>/bad.snap: every finding of a rule on its bad fixture, in full.

Usage:
    python tools/update_snapshots.py            # rewrite every snapshot
    python tools/update_snapshots.py LIS203     # only these rules
    python tools/update_snapshots.py --check    # exit 1 when a snapshot is stale (what the test does)

A snapshot lists, per finding: where it starts and ends, code, severity, the message, its related
locations, and its fix as a diff of the fixture — so a change in any of them shows up in review.
Review the diff of the snapshot files before committing them.
"""

from __future__ import annotations

import argparse
import difflib
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

RULES = ROOT / "fixtures" / "rules"


def fixture(rule_dir: Path, kind: str) -> Path:
    """The `bad` or `good` fixture of a rule: a list (.lis), an XML file, a machine folder (LIS5xx), or an NC
    program (.nc, LIS6xx) checked against the machine whose start-up list the rule folder's `machine` file
    names."""
    for suffix in (".lis", ".xml", ".nc", ""):
        candidate = rule_dir / f"{kind}{suffix}"
        if candidate.exists():
            return candidate
    raise FileNotFoundError(f"{rule_dir} has no {kind}.lis, {kind}.xml, {kind}.nc or {kind}/")


def machine_of(path: Path) -> str | None:
    """For an NC program fixture: the start-up list named (relative to the rule folder) in `machine`."""
    if path.suffix != ".nc":
        return None
    return str(path.parent / (path.parent / "machine").read_text(encoding="utf-8").strip())


def selection(rule_dir: Path) -> list[str]:
    """The rule itself, plus the codes in `also_select` (LIS009 needs the rules its suppressions name)."""
    extra = rule_dir / "also_select"
    return [rule_dir.name, *(extra.read_text().split() if extra.exists() else [])]


def lint_fixture(path: Path, select: list[str] | None) -> list:
    """Every diagnostic of a fixture, linted as the CLI lints it: a machine folder through its start-up list
    when it has one."""
    from achslint.api import LintRequest, run_lint
    from achslint.linting.config import Overrides

    target = path
    if path.is_dir():
        startup = sorted(path.glob("hochlauf*.lis"))
        target = startup[0] if startup else path
    request = LintRequest([str(target)], Overrides(select=select), jobs=1, machine=machine_of(path))
    outcome = run_lint(request)
    assert not outcome.errors, outcome.errors
    return [d for result in outcome.results for d in result.diagnostics]


def findings(rule_dir: Path) -> list:
    """The diagnostics of the rule on its bad fixture."""
    found = [
        d for d in lint_fixture(fixture(rule_dir, "bad"), selection(rule_dir)) if d.code == rule_dir.name
    ]
    return sorted(found, key=lambda d: (d.path, d.line, d.column, d.message))


def _where(path: str, base: Path) -> str:
    try:
        return Path(path).resolve().relative_to(base.resolve()).as_posix()
    except ValueError:
        return Path(path).name


def _relative(message: str, base: Path) -> str:
    """The message with the fixture folder's own location left out, so snapshots do not depend on the clone."""
    for prefix in (str(base.resolve()), str(base), str(base.resolve().relative_to(ROOT))):
        message = message.replace(prefix + "/", "")
    for prefix in (str(base.resolve()), str(base)):  # the folder itself (a CNC root): `.`
        message = message.replace(prefix, ".")
    return message


def _fix_diff(diagnostic, base: Path) -> list[str]:
    from achslint.core.decode import decode
    from achslint.linting.fixer import apply_edits

    path = Path(diagnostic.path)
    source = decode(path.read_bytes())
    fixed, applied = apply_edits(source, [diagnostic.fix])
    if not applied:
        return ["    (the fix does not apply)"]
    if diagnostic.fix.remove_bom:
        return ["    (removes the byte-order mark)"]
    name = _where(diagnostic.path, base)
    diff = difflib.unified_diff(
        source.text.splitlines(), fixed.text.splitlines(), name, name, n=0, lineterm=""
    )
    return ["    " + line for line in list(diff)[2:]]


def dry_run_warnings(rule_dir: Path, kind: str = "bad") -> list[str]:
    """For a rule only the dry-run reports (LIS405): its warnings on `<kind>.lis` with `<kind>.toml`."""
    from achslint.dryrun import dry_run
    from achslint.homing.scenario import read_scenario

    data = (rule_dir / f"{kind}.lis").read_bytes()
    trace = dry_run(data, f"{kind}.lis", read_scenario(rule_dir / f"{kind}.toml")).trace
    return [w["message"] for w in trace.warnings if w["code"] == rule_dir.name]


def is_dry_run_rule(rule_dir: Path) -> bool:
    from achslint.rules import registry

    rule = registry().get(rule_dir.name)
    return rule is not None and rule.produced_by == "dry-run"


def render(rule_dir: Path) -> str:
    """The snapshot text of one rule."""
    if is_dry_run_rule(rule_dir):
        lines = [
            f"# {rule_dir.name}: dry-run of bad.lis with bad.toml; regenerate with "
            f"python tools/update_snapshots.py {rule_dir.name}"
        ]
        return (
            "\n".join(
                lines + [f"\ndry-run warning {rule_dir.name}\n  {m}" for m in dry_run_warnings(rule_dir)]
            )
            + "\n"
        )
    base = rule_dir / "bad" if (rule_dir / "bad").is_dir() else rule_dir
    out = [
        f"# {rule_dir.name} on its bad fixture; regenerate with python tools/update_snapshots.py {rule_dir.name}"
    ]
    for d in findings(rule_dir):
        out.append("")
        out.append(
            f"{_where(d.path, base)}:{d.line}:{d.column}-{d.end_line}:{d.end_column} {d.code} {d.severity.value}"
        )
        out.append(f"  {_relative(d.message, base)}")
        if d.parameter:
            out.append(f"  parameter: {d.parameter}" + (f" ({d.p_axis})" if d.p_axis else ""))
        for related in d.related:
            text = f" — {related.message}" if related.message else ""
            out.append(
                f"  related: {_where(related.path, base)}:{related.line}:{related.column}"
                f" {related.parameter or ''}{text}".rstrip()
            )
        if d.fix is not None:
            out.append(f"  fix ({d.fix.applicability}): {d.fix.description}")
            out.extend(_fix_diff(d, base))
    return "\n".join(out) + "\n"


def rule_dirs(codes: list[str] | None = None) -> list[Path]:
    dirs = sorted(p for p in RULES.iterdir() if p.is_dir())
    return [p for p in dirs if not codes or p.name in codes]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("codes", nargs="*", help="rule codes (default: all)")
    parser.add_argument("--check", action="store_true", help="change nothing; exit 1 if a snapshot is stale")
    args = parser.parse_args(argv)
    stale = []
    for rule_dir in rule_dirs(args.codes):
        text = render(rule_dir)
        target = rule_dir / "bad.snap"
        current = target.read_text(encoding="utf-8") if target.exists() else None
        if current == text:
            continue
        stale.append(rule_dir.name)
        if not args.check:
            target.write_text(text, encoding="utf-8")
    if stale:
        verb = "stale" if args.check else "updated"
        print(f"{verb}: {', '.join(stale)}", file=sys.stderr)
    return 1 if args.check and stale else 0


if __name__ == "__main__":
    sys.exit(main())
