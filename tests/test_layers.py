"""The import graph of `src/achslint` runs one way (issue 23, STYLE.md "The house, drawn").

Every module has a layer; a module imports only from its own layer or the layers below it, and no chain of
imports leads back to where it started. Imports inside functions and under `TYPE_CHECKING` count as much as
the ones at the top of a module: hiding an import in a function defers it, it does not remove the arrow.
`ALLOWED` lists arrows that may offend for now; it is empty (issue 23 is done when it is) and stays so.

Also here: linting a list does not load the heavy optional libraries, and each homing strategy's published
`example` selects that strategy.
"""

from __future__ import annotations

import ast
import json
import subprocess
import sys
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cache
from itertools import takewhile
from pathlib import Path

import pytest

from achslint.axis.resolved import resolve_bytes
from achslint.homing.base import StrategyDef
from achslint.homing.registry import classify, strategies

from .conftest import FIXTURES, ROOT, run_cli, source_tree

PACKAGE = ROOT / "src" / "achslint"

# The layers, bottom first, after the target layout of issue 23 (STYLE.md, "The house, drawn") for today's flat
# modules. A few stages have an order inside them too: what a registry lists sits below the registry. A name
# ending in `.*` puts every module of that package (its `__init__` too, unless named on its own) there.
LAYERS: tuple[tuple[str, tuple[str, ...]], ...] = (
    # reading and writing files, text, what a finding is, how values are shown
    ("core", ("core.*",)),
    ("syntax", ("syntax.*",)),
    ("catalogue", ("catalogue.*",)),
    # a reader of lists inside XML: ISG XML names parameters by id, which the catalogue turns into paths
    ("syntax: xml", ("syntax.xmlinput",)),
    # one axis's typed values, the CNC's corrections, and the resolved axis that applies them
    ("axis", ("axis.facts", "axis.analysis", "axis.drives", "axis.corrections", "axis.source", "axis")),
    ("axis: resolved", ("axis.resolved",)),
    # homing: the axis's values in mm and s, the geometry a simulation assumes, the motion, the strategy (its
    # data names the sequence that simulates it), the sequences, the strategies, the registry that picks one
    ("homing: setup", ("homing.setup",)),
    ("homing: scenario input", ("homing.bounds", "homing.scenario_input")),
    ("homing: scenario", ("homing.scenario",)),
    ("homing: motion", ("homing.motion",)),
    ("homing: strategy", ("homing.base", "homing.parameters")),
    ("homing: sequences", ("homing.sequences.*",)),
    ("homing: strategies", ("homing.strategies.*",)),
    ("homing: registry", ("homing.registry", "homing")),
    (
        "machine",
        (
            "machine.model",
            "machine.startup",
            "machine.identity",
            "machine.channel",
            "machine.program",
            "machine.resolved",
            "machine.build",
            "machine",
        ),
    ),
    ("rules: codes and options", ("rules.codes", "rules.options")),
    ("rules: what a rule sees", ("rules.context", "rules.programcontext")),
    ("rules", ("rules.*",)),
    ("rules: registry", ("rules",)),
    ("lint", ("linting.*",)),
    # products built on the stages below: the model, explanations, machine runs, diff, layout, rule docs
    ("model base", ("model.base",)),
    ("model fields", ("model.generated", "model.generated_channel", "model.generated_startup")),
    (
        "products",
        (
            "model",
            "explanation",
            "dryrun",
            "machine.run",
            "machine.scenario",
            "machine.explain",
            "listdiff",
            "machinediff",
            "fmt",
            "docs",
            "report",
        ),
    ),
    # every format of every command: the screen they write to, the formats, lint's registry of them
    ("output: screen", ("output",)),
    (
        "output: formats",
        (
            "output.reporters.*",
            "output.figuredata",
            "output.figures",
            "output.svgplot",
            "output.plot",
            "output.explain",
            "output.dryrun",
            "output.machine",
            "output.diff",
            "output.fmt",
            "output.config",
            "output.markdown",
            "output.report",
        ),
    ),
    ("output: registry", ("output.reporters",)),
    ("output: lint's report around its format", ("output.lint",)),
    ("output: the registry's first name", ("reporters",)),
    # the public API (the package re-exports it) and the editor
    ("api", ("achslint", "api", "lsp.*")),
    ("cli", ("cli", "__main__")),
)
LAYER_OF = {module: number for number, (_, names) in enumerate(LAYERS) for module in names}

# Offending arrows allowed for now, "importer -> imported" (each would close a cycle or point up the layers).
# Empty: a new arrow that offends is moved, split or passed in, not listed here.
ALLOWED: frozenset[str] = frozenset()


@dataclass(frozen=True)
class Arrow:
    importer: str
    imported: str
    line: int  # the first import of `imported` in the importer's file
    eager: bool  # one of those imports runs when the importer loads (module level, not under TYPE_CHECKING)

    def __str__(self) -> str:
        return f"{self.importer} -> {self.imported}"


def module_name(path: Path, package: Path) -> str:
    """`src/achslint/homing/registry.py` -> `homing.registry`; the package's own `__init__` is `achslint`."""
    parts = list(path.relative_to(package).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts) or "achslint"


@cache
def modules(package: Path = PACKAGE) -> dict[str, Path]:
    return {module_name(path, package): path for path in sorted(package.rglob("*.py"))}


def _inside(name: str) -> str | None:
    """`achslint.homing.setup` -> `homing.setup`; None for a module outside the package."""
    if name == "achslint":
        return name
    return name.removeprefix("achslint.") if name.startswith("achslint.") else None


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


class _Imports(ast.NodeVisitor):
    """The achslint modules one file imports: `import`, `from ... import` (relative or absolute) and
    `importlib.import_module(f"{__package__}.pkg.{name}")`, each marked eager or deferred."""

    def __init__(self, importer: str, path: Path, source: str, known: dict[str, Path]) -> None:
        self.importer = importer
        self.known = known
        parts = [] if importer == "achslint" else importer.split(".")
        self.package = parts if path.name == "__init__.py" else parts[:-1]  # where `from .` starts
        tree = source_tree(path, source)
        # Import statements sit among statements; only a file that calls import_module needs its expressions
        # walked, and only there are its strings (the registry's module names) of interest.
        self.dynamic = "import_module" in source
        self.constants = (
            {n.value for n in ast.walk(tree) if isinstance(n, ast.Constant) and isinstance(n.value, str)}
            if self.dynamic
            else set()
        )
        self.deferred = 0  # > 0 inside a function or an `if TYPE_CHECKING:` block
        self.found: list[tuple[str, int, bool]] = []
        self.visit(tree)

    def generic_visit(self, node: ast.AST) -> None:
        if self.dynamic:
            super().generic_visit(node)
            return
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.stmt, ast.excepthandler, ast.match_case)):
                self.visit(child)

    def _add(self, imported: str, line: int) -> None:
        if imported != self.importer:
            self.found.append((imported, line, self.deferred == 0))

    def _defer(self, node: ast.AST) -> None:
        self.deferred += 1
        self.generic_visit(node)
        self.deferred -= 1

    visit_FunctionDef = visit_AsyncFunctionDef = visit_Lambda = _defer

    def visit_If(self, node: ast.If) -> None:
        if not _is_type_checking(node.test):
            self.generic_visit(node)
            return
        self.deferred += 1
        for statement in node.body:
            self.visit(statement)
        self.deferred -= 1
        for statement in node.orelse:
            self.visit(statement)

    def visit_Import(self, node: ast.Import) -> None:
        for alias in node.names:
            name = _inside(alias.name)
            if name is not None:
                self._add(name, node.lineno)

    def visit_ImportFrom(self, node: ast.ImportFrom) -> None:
        if node.level:
            parts = self.package[: len(self.package) - (node.level - 1)]
            base = ".".join([*parts, *(node.module.split(".") if node.module else [])]) or "achslint"
        else:
            found = _inside(node.module or "")
            if found is None:
                return
            base = found
        for alias in node.names:
            submodule = alias.name if base == "achslint" else f"{base}.{alias.name}"
            self._add(submodule if submodule in self.known else base, node.lineno)

    def visit_Call(self, node: ast.Call) -> None:
        """A registry's `import_module(f"{__name__}.{name}")`: the package's modules that the file names in a
        string (its tuple or table of module names), or every module of the package if it names none."""
        self.generic_visit(node)
        if not (isinstance(node.func, ast.Attribute) and node.func.attr == "import_module"):
            return
        if not node.args or not isinstance(node.args[0], ast.JoinedStr):
            return
        pieces = node.args[0].values
        head = pieces[0] if pieces else None
        if not (isinstance(head, ast.FormattedValue) and isinstance(head.value, ast.Name)):
            return
        if head.value.id == "__name__":
            anchor = [] if self.importer == "achslint" else self.importer.split(".")
        elif head.value.id == "__package__":
            anchor = self.package
        else:
            return
        fixed = takewhile(lambda piece: isinstance(piece, ast.Constant), pieces[1:])
        middle = "".join(str(piece.value) for piece in fixed if isinstance(piece, ast.Constant))
        package = ".".join([*anchor, *filter(None, middle.split("."))])
        members = [m for m in self.known if m.startswith(f"{package}.")]
        named = [m for m in members if m.rsplit(".", 1)[-1] in self.constants]
        for member in named or members:
            self._add(member, node.lineno)


@cache
def arrows(package: Path = PACKAGE) -> tuple[Arrow, ...]:
    """Every import between the package's modules, wherever in the file it is written."""
    first: dict[tuple[str, str], int] = {}
    eager: set[tuple[str, str]] = set()
    known = modules(package)
    for importer, path in known.items():
        source = path.read_text(encoding="utf-8")
        for imported, line, runs_on_load in _Imports(importer, path, source, known).found:
            key = (importer, imported)
            first[key] = min(first.get(key, line), line)
            if runs_on_load:
                eager.add(key)
    return tuple(Arrow(a, b, line, (a, b) in eager) for (a, b), line in sorted(first.items()))


def layer_of(module: str) -> int | None:
    if module in LAYER_OF:
        return LAYER_OF[module]
    parts = module.split(".")
    for size in range(len(parts), 0, -1):
        layer = LAYER_OF.get(".".join(parts[:size]) + ".*")
        if layer is not None:
            return layer
    return None


def _graph(edges: Iterable[Arrow]) -> dict[str, set[str]]:
    graph: dict[str, set[str]] = {}
    for arrow in edges:
        graph.setdefault(arrow.importer, set()).add(arrow.imported)
    return graph


def components(edges: Iterable[Arrow]) -> list[set[str]]:
    """The strongly connected components of more than one module (Tarjan): the modules on a common cycle."""
    graph = _graph(edges)
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[set[str]] = []

    def visit(node: str) -> None:
        index[node] = low[node] = len(index)
        stack.append(node)
        for successor in sorted(graph.get(node, ())):
            if successor not in index:
                visit(successor)
                low[node] = min(low[node], low[successor])
            elif successor in stack:
                low[node] = min(low[node], index[successor])
        if low[node] == index[node]:
            component = set(stack[stack.index(node) :])
            del stack[stack.index(node) :]
            if len(component) > 1:
                found.append(component)

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return found


def path_back(arrow: Arrow, package: Path = PACKAGE) -> list[str] | None:
    """The shortest import chain from `arrow.imported` back to `arrow.importer`, if the arrow closes a cycle."""
    graph = _graph(arrows(package))
    came_from = {arrow.imported: arrow.imported}
    frontier = [arrow.imported]
    while frontier:
        following = []
        for node in frontier:
            for successor in sorted(graph.get(node, ())):
                if successor not in came_from:
                    came_from[successor] = node
                    following.append(successor)
        frontier = following
        if arrow.importer in came_from:
            chain = [arrow.importer]
            while chain[-1] != arrow.imported:
                chain.append(came_from[chain[-1]])
            return chain[::-1]
    return None


def _up(arrow: Arrow) -> bool:
    below, above = layer_of(arrow.importer), layer_of(arrow.imported)
    return below is not None and above is not None and above > below


def offending() -> dict[Arrow, str]:
    """The arrows that go up the layers, and the arrows that close a cycle within one layer, with why.

    Without the upward arrows a cycle can only run inside one layer. There, the imports deferred into a
    function or under TYPE_CHECKING are what close it (the module-level ones load in order); if the
    module-level imports of a layer still form a cycle of their own, those count as well."""
    found = {
        a: f"up from {LAYERS[layer_of(a.importer) or 0][0]} to {LAYERS[layer_of(a.imported) or 0][0]}"
        for a in arrows()
        if _up(a)
    }
    level = [a for a in arrows() if a not in found]
    for component in components(level):
        inside = [a for a in level if a.importer in component and a.imported in component]
        eager_cycles = components(a for a in inside if a.eager)
        for arrow in inside:
            if not arrow.eager or any({arrow.importer, arrow.imported} <= c for c in eager_cycles):
                layer = LAYERS[layer_of(arrow.importer) or 0][0]
                found[arrow] = f"closes a cycle in {layer}"
    return found


def _explained(arrow: Arrow, why: str) -> str:
    where = f"{modules()[arrow.importer].relative_to(ROOT)}:{arrow.line}"
    back = path_back(arrow)
    cycle = f"; back: {' -> '.join(back)}" if back else ""
    return f"  {arrow}  ({why}{cycle}; {where})"


def test_every_module_has_a_layer() -> None:
    missing = [name for name in modules() if layer_of(name) is None]
    assert not missing, (
        f"modules without a layer: {', '.join(missing)}; give each one in LAYERS of tests/test_layers.py "
        "(the layers are drawn in STYLE.md, 'The house, drawn')"
    )


def test_every_declared_layer_names_a_module() -> None:
    stale = [key for key in LAYER_OF if key.removesuffix(".*") not in modules()]
    assert not stale, f"LAYERS in tests/test_layers.py names modules that do not exist: {', '.join(stale)}"


def test_imports_go_down_the_layers_without_cycles() -> None:
    found = offending()
    new = {arrow: why for arrow, why in found.items() if str(arrow) not in ALLOWED}
    gone = sorted(ALLOWED - {str(arrow) for arrow in found})
    lines = []
    if new:
        lines.append(f"{len(new)} import(s) that go up the layers or close a cycle (tests/test_layers.py):")
        lines += [_explained(arrow, why) for arrow, why in sorted(new.items(), key=lambda item: str(item[0]))]
    if gone:
        lines.append("arrows in ALLOWED that no longer offend; delete them there:")
        lines += [f"  {arrow}" for arrow in gone]
    assert not lines, "\n".join(lines)


def test_the_walk_sees_deferred_type_checking_and_registry_imports(tmp_path: Path) -> None:
    package = tmp_path / "achslint"
    (package / "plugins").mkdir(parents=True)
    files = {
        "__init__.py": "from .api import run\n",
        "api.py": "def run():\n    from . import low\n    return low\n",
        "low.py": (
            "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from .api import run\n"
            "else:\n    import achslint.helpers\n"
        ),
        "helpers.py": "",
        "plugins/__init__.py": (
            "import importlib\nNAMES = ('first',)\n"
            "def load(name):\n    return importlib.import_module(f'{__name__}.{name}')\n"
        ),
        "plugins/first.py": "from .. import low\nfrom ..plugins import second\n",
        "plugins/second.py": "",
    }
    for name, text in files.items():
        (package / name).write_text(text, encoding="utf-8")
    found = {str(arrow): arrow.eager for arrow in arrows(package)}
    assert found == {
        "achslint -> api": True,
        "api -> low": False,  # inside a function
        "low -> api": False,  # under TYPE_CHECKING
        "low -> helpers": True,  # the else branch runs
        "plugins -> plugins.first": False,  # named in the registry's tuple; `second` is not
        "plugins.first -> low": True,
        "plugins.first -> plugins.second": True,
    }
    assert components(arrows(package)) == [{"api", "low"}]
    assert path_back(next(a for a in arrows(package) if str(a) == "api -> low"), package) == ["low", "api"]


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_linting_a_list_leaves_pydantic_matplotlib_and_pygls_unloaded(tmp_path: Path) -> None:
    """Start-up time: the CLI and the API lint lists of every kind (and explain a parameter of another kind)
    without the model, plotting or editor libraries."""
    probe = (
        "import json, sys\n"
        "import achslint\n"
        "from achslint.cli import main\n"
        "code = main(['lint', *sys.argv[1:]])\n"
        "found = achslint.lint(sys.argv[1])\n"
        "explained = main(['explain', 'P-CHAN-00036'])\n"
        "heavy = [name for name in ('pydantic', 'matplotlib', 'pygls') if name in sys.modules]\n"
        "print(json.dumps({'code': code, 'found': len(found), 'explained': explained, 'heavy': heavy}))\n"
    )
    kinds = FIXTURES / "kinds"
    lists = (
        str(FIXTURES / "multi_rule.lis"),
        str(FIXTURES / "lists" / "achsmds1.lis"),
        str(kinds / "sda_mds1.lis"),  # a channel list and a start-up list: the kinds with a typed model
        str(kinds / "basis.lis"),
    )
    done = subprocess.run(
        [sys.executable, "-c", probe, *lists], cwd=tmp_path, capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 0, done.stderr
    report = json.loads(done.stdout.splitlines()[-1])
    assert report["code"] == 1 and report["found"] > 0  # the lint ran and found what multi_rule.lis holds
    assert report["explained"] == 0 and report["heavy"] == []


@pytest.mark.parametrize("definition", strategies(), ids=lambda definition: definition.id)
def test_every_strategy_example_selects_that_strategy(definition: StrategyDef) -> None:
    axis = resolve_bytes(definition.example.encode(), f"the example of {definition.id}")
    assert classify(axis).id == definition.id, definition.example


def test_explain_publishes_each_strategy_with_an_example_that_selects_it() -> None:
    done = run_cli("explain", "kenngr.homing.homing_type", "--format", "json")
    assert done.returncode == 0, done.stderr
    published = json.loads(done.stdout)["strategies"]
    assert [entry["id"] for entry in published] == [d.id for d in strategies()]
    chosen = [classify(resolve_bytes(entry["example"].encode(), entry["id"])).id for entry in published]
    assert chosen == [entry["id"] for entry in published]
