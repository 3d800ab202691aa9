"""One classification (issue 23 item 5): `homing.registry.classify` decides the strategy for every product.

At power-up, `explain`, `lint` (what a rule sees), the machine's explanation and the single-axis dry-run name
the same strategy; for a G74 that names the axis, `explain`, the machine's explanation and the machine run name
the same one. The two differ only where the power-up strategy says so (an absolute encoder: no homing move
is needed, yet a G74 naming the axis runs its homing type, P-AXIS-00299 remark).
"""

from __future__ import annotations

import ast
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

import pytest

from achslint.axis.resolved import resolve_bytes
from achslint.dryrun import DryRunRefused, dry_run, prepare
from achslint.explanation import explain_list
from achslint.homing.registry import by_id, classify, strategies
from achslint.machine.build import build_machine
from achslint.machine.explain import explain_machine
from achslint.machine.model import ChannelView, MachineAxis
from achslint.machine.program import read_program
from achslint.machine.run import MachineRun, run_machine
from achslint.machine.scenario import MachineScenario
from achslint.rules.context import Context
from achslint.syntax.parser import parse_bytes

from .conftest import FIXTURES, run_cli
from .fixture_lists import distinct
from .source_nodes import nodes as source_nodes


@dataclass(frozen=True)
class Named:
    """The strategy ids each product reports for one axis."""

    explain: str
    lint: str
    machine_explain: str
    dry_run: str
    explain_g74: str
    machine_explain_g74: str
    machine_run: str


def _dry_run_strategy(data: bytes, name: str, defaults: bytes | None) -> str:
    try:
        return dry_run(data, name, defaults=defaults).trace.strategy.id
    except DryRunRefused:  # the CNC does not run this homing (LIS306, LIS319): what the dry-run prepared
        return prepare(data, name, defaults=defaults).strategy.id


def _machine_side(machine: ChannelView, program: bytes) -> tuple[dict, MachineRun]:
    """The machine's explanation and its run of `program` (a G74 block): the same for each of its axes, so
    worked out once per machine."""
    return explain_machine(machine), run_machine(machine, read_program(program, "rfp.nc"), MachineScenario())


def _named(axis: MachineAxis, machine_side: tuple[dict, MachineRun]) -> Named:
    """What every product names for `axis`; `machine_side` is `_machine_side` of its machine."""
    name = str(axis.list_path or "axis.lis")
    report = explain_list(axis.data, name, defaults=axis.defaults)
    default_file = parse_bytes(axis.defaults, "default list") if axis.defaults is not None else None
    context = Context(name, parse_bytes(axis.data, name), default_file=default_file)
    explained, run = machine_side
    row = next(r for r in explained["axes"] if r["name"] == axis.name)
    return Named(
        explain=report["strategy"]["id"],
        lint=context.strategy.id,
        machine_explain=row["strategy"]["id"],
        dry_run=_dry_run_strategy(axis.data, name, axis.defaults),
        explain_g74=report["commanded"]["id"],
        machine_explain_g74=row["commanded"]["id"],
        machine_run=run.axes[axis.name].strategy.id,
    )


def _check(named: Named) -> None:
    at_power_up = {named.explain, named.lint, named.machine_explain, named.dry_run}
    assert len(at_power_up) == 1, named
    assert len({named.explain_g74, named.machine_explain_g74, named.machine_run}) == 1, named
    # A G74 runs another strategy only where the power-up strategy leaves it to the homing type.
    assert named.explain_g74 == named.explain or by_id(named.explain).power_up_only, named


def _alone(path: Path) -> tuple[MachineAxis, ChannelView]:
    """A fixture list as the one axis X of a machine."""
    data = path.read_bytes()
    axis = MachineAxis("X", 1, path, data, None, resolve_bytes(data, str(path)))
    return axis, ChannelView(startup=None, axes={"X": axis})


LISTS = sorted(FIXTURES.glob("**/*.lis"))
STARTUPS = sorted(FIXTURES.glob("machines/*/listen/hochlauf.lis"))


def test_every_fixture_list_has_one_strategy_at_power_up_and_one_for_g74() -> None:
    assert len(LISTS) > 90
    seen: set[tuple[str, str]] = set()
    # What the products name depends on a list's bytes and file name (a default list by its name): a list
    # the fixtures hold more than once under one name (the axis lists machines share) is looked at once.
    for path in distinct(LISTS):
        axis, machine = _alone(path)
        named = _named(axis, _machine_side(machine, b"N10 G74 X1\nM30\n"))
        _check(named)
        seen.add((named.explain, named.machine_run))
    # The fixtures reach an absolute axis that a G74 still homes, and the ones whose G74 does what they say.
    assert ("absolute", "cam_zero_pulse") in seen
    assert {("disabled", "disabled"), ("ignore_abs_pos", "ignore_abs_pos")} <= seen


@pytest.mark.parametrize("startup", STARTUPS, ids=lambda path: path.parts[-3])
def test_every_axis_of_every_fixture_machine_has_one_strategy(startup: Path) -> None:
    machine = build_machine(startup)
    assert machine.axes
    program = ("N10 G74 " + " ".join(f"{name}1" for name in machine.axes) + "\nM30\n").encode()
    machine_side = _machine_side(machine, program)
    for axis in machine.axes.values():
        _check(_named(axis, machine_side))


ABSOLUTE = b"kenngr.antr_typ 1\nkenngr.abs_pos_gueltig 1\nkenngr.ref_ohne_rev 1\nEnde\n"


def test_an_absolute_axis_needs_no_homing_at_power_up_but_a_g74_runs_its_homing_type() -> None:
    axis = resolve_bytes(ABSOLUTE, "abs.lis")
    assert classify(axis).id == "absolute"
    assert classify(axis, commanded=True).id == "one_phase_cam_zero_pulse"
    report = explain_list(ABSOLUTE, "abs.lis")
    assert report["strategy"]["id"] == "absolute" and report["phases"] == []
    commanded = report["commanded"]
    assert commanded["id"] == "one_phase_cam_zero_pulse"
    assert [phase["name"] for phase in commanded["phases"]] == ["to the reference cam", "on to the reference"]


def test_explain_text_names_what_a_g74_runs_on_an_absolute_axis(tmp_path: Path) -> None:
    axis_list = tmp_path / "abs.lis"
    axis_list.write_bytes(ABSOLUTE)
    done = run_cli("explain", str(axis_list), env={"COLUMNS": "200"})
    assert done.returncode == 0, done.stderr
    lines = done.stdout.decode().splitlines()
    assert lines[2].startswith("Homing: no homing move (absolute measuring system)")
    shown = lines.index(
        "A G74 that names the axis runs: one-phase homing on the cam and the zero pulse (type III)"
    )
    assert lines[shown + 2].startswith("  1. to the reference cam: move negative")
    assert lines[shown + 3].startswith("  2. on to the reference: move negative")


@pytest.mark.parametrize(
    "body",
    [
        "kenngr.abs_pos_gueltig 1\nkenngr.homing.homing_type DISABLED\n",
        "kenngr.abs_pos_gueltig 1\nkenngr.homing.homing_type IGNORE_ABS_POS\n",
        "kenngr.antr_typ 1\n",
    ],
)
def test_a_g74_runs_what_the_axis_does_at_power_up_unless_that_is_an_absolute_encoder(body: str) -> None:
    axis = resolve_bytes((body + "Ende\n").encode(), "a.lis")
    assert classify(axis, commanded=True).id == classify(axis).id


PACKAGE = Path(__file__).resolve().parents[1] / "src" / "achslint"


def _strategy_id_tests(nodes: Iterable[ast.AST], ids: set[str]) -> list[int]:
    """Lines that compare a strategy's `id`: `x.id == "fixed_stop"`, `x.id in ("disabled", ...)`,
    `x.id.startswith("spindle")`, or any `.id` compared with a registered strategy id."""

    def names_id(node: ast.AST) -> bool:
        return isinstance(node, ast.Attribute) and node.attr == "id"

    def strategy_ids(node: ast.AST) -> bool:
        constants = [
            n.value for n in ast.walk(node) if isinstance(n, ast.Constant) and isinstance(n.value, str)
        ]
        return bool(constants) and all(value in ids for value in constants)

    found = []
    for node in nodes:
        if isinstance(node, ast.Compare):
            operands = [node.left, *node.comparators]
            if any(names_id(o) for o in operands) and any(strategy_ids(o) for o in operands):
                found.append(node.lineno)
        elif (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and node.func.attr in ("startswith", "endswith")
            and names_id(node.func.value)
        ):
            found.append(node.lineno)
    return found


def test_nothing_outside_the_homing_package_dispatches_on_a_strategy_id() -> None:
    """STYLE.md: what a strategy decides is a field or method of the strategy, not a comparison of its id."""
    ids = {definition.id for definition in strategies()}
    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        if "homing" in path.relative_to(PACKAGE).parts:
            continue
        for line in _strategy_id_tests(source_nodes(path), ids):
            found.append(f"{path.relative_to(PACKAGE)}:{line}")
    assert not found, found


def test_the_id_walk_sees_equality_membership_and_prefix_tests() -> None:
    source = (
        'a = strategy.id == "fixed_stop"\n'
        'b = run.strategy.id in ("disabled", "absolute")\n'
        'c = ctx.strategy.id.startswith("spindle")\n'
        'd = parameter.id == "P-AXIS-00015"\n'  # a parameter id, not a strategy's
        'e = {"id": strategy.id}\n'  # reporting the id is fine
    )
    assert _strategy_id_tests(ast.walk(ast.parse(source)), {"fixed_stop", "disabled", "absolute"}) == [
        1,
        2,
        3,
    ]


def test_the_package_keeps_naming_the_registry_function_once_the_strategies_are_loaded() -> None:
    import achslint.homing
    from achslint.homing import registry

    classify(resolve_bytes(b"kenngr.antr_typ 1\nEnde\n", "x.lis"))  # loads every module of homing/strategies/
    assert achslint.homing.strategies is registry.strategies


def test_every_strategy_s_example_is_a_list_the_cnc_runs():
    """The examples `explain PARAM --format json` publishes are lists the CNC loads without an error: the
    fixed-stop one lacked its TORQUE_LIMIT drive ident (LIS328: the CNC stops the homing), the spindles'
    the MODULO bit (LIS327: the CNC corrects the mode)."""
    from achslint.core.diagnostics import Severity
    from achslint.homing import strategies
    from achslint.linting.linter import FileSettings, lint_file

    for definition in strategies():
        found = lint_file(
            (definition.example + "Ende\n").encode(), "achsmds1.lis", FileSettings(keep_source=False)
        )
        errors = [d.code for d in found.diagnostics if d.severity is Severity.ERROR]
        assert errors == [], (definition.id, errors)
