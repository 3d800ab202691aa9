#!/usr/bin/env python
"""Instructions of a cold `achslint lint` against the import floor, counted by valgrind (issue 23).

    python benchmarks/coldcount.py             # floor, imports of the CLI, whole lint
    python benchmarks/coldcount.py --lint-only # the lint alone (what to compare between two edits)
    python benchmarks/coldcount.py --breakdown # and what the budget leaves: Lark's parse, module imports

The wall-clock budget (`benchmarks/run --only cold`: fastest of 21 runs, 1.3 x `python -c "import lark,
typer"`) is noisy on a shared machine; the instruction count of the same two commands is not, and tracks
it closely (a run's time is almost all interpreter work). Each command runs once first so that byte code,
the grammar cache and the dataclass code cache are written, as they are on a user's machine.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import sys
import tempfile
from importlib.machinery import SourceFileLoader
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from generate import axis_list

# benchmarks/run (a script without .py) holds the budget and the child processes' command and environment.
_run = SourceFileLoader("run", str(HERE / "run")).load_module()
BUDGET_COLD_RATIO, achslint_command, child_env = _run.BUDGET_COLD_RATIO, _run.achslint_command, _run.child_env


def instructions(command: list[str]) -> int:
    """Instructions the command executes (valgrind's callgrind, user space, the whole process)."""
    subprocess.run(
        command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=child_env(), check=False
    )
    done = subprocess.run(
        ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", *command],
        capture_output=True,
        text=True,
        env=child_env(),
        check=False,
    )
    found = re.search(r"Collected : (\d+)", done.stderr)
    if not found:
        raise SystemExit(f"valgrind gave no count for {command}:\n{done.stderr[-2000:]}")
    return int(found.group(1))


def main() -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--lint-only", action="store_true", help="count only the lint")
    parser.add_argument(
        "--breakdown",
        action="store_true",
        help="also count Lark's own parse of the list and the import machinery of as many empty modules as a lint loads",
    )
    parser.add_argument(
        "--list", type=Path, help="the list to lint (default: a generated 250-line axis list)"
    )
    options = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        typical = options.list or Path(folder) / "achsmds1.lis"
        if options.list is None:
            typical.write_bytes(axis_list(250).encode("latin-1"))
        lint = instructions([*achslint_command(), "lint", str(typical)])
        print(f"achslint lint (250-line list)      {lint / 1e6:8.1f} M instructions")
        if options.lint_only:
            return 0
        imports = instructions([sys.executable, "-c", "import achslint.cli"])
        floor = instructions([sys.executable, "-c", "import lark, typer"])
        print(f"import achslint.cli                {imports / 1e6:8.1f} M")
        print(f"floor: import lark, typer          {floor / 1e6:8.1f} M")
        print(
            f"ratio {lint / floor:.2f} x floor (budget <= {BUDGET_COLD_RATIO} x: {BUDGET_COLD_RATIO * floor / 1e6:.0f} M)"
        )
        if options.breakdown:
            breakdown(Path(folder), typical, floor)
    return 0


_LARK = """
import sys
from lark import Lark
grammar = open(sys.argv[3], encoding="utf-8").read()
parser = Lark(grammar, parser="lalr", lexer="contextual", maybe_placeholders=False, cache=sys.argv[1])
if len(sys.argv) > 4:
    parser.parse(open(sys.argv[2], encoding="latin-1").read())
"""

_MODULES = """
import sys
from achslint.cli import run
sys.argv = ["achslint", "lint", sys.argv[1]]
try:
    run()
except SystemExit:
    pass
print(sum(name == "achslint" or name.startswith("achslint.") for name in sys.modules), file=sys.stderr)
"""


def breakdown(folder: Path, typical: Path, floor: int) -> None:
    """What the budget's allowance over the floor must pay for before any of our code runs: Lark's own
    parse of the list (a bare tree, the grammar loaded from Lark's cache) and the import machinery of as
    many modules as a lint loads (counted on empty modules: finding, reading and running a module that
    holds one assignment)."""
    allowance = (BUDGET_COLD_RATIO - 1) * floor
    cache = str(folder / "grammar.lark-cache")
    # The grammar as this Python reads it (3.10 has no possessive repeats), written where no achslint import
    # is needed to read it.
    from achslint.syntax.parser import _grammar_text

    grammar = folder / "achsmds.lark"
    grammar.write_text(_grammar_text(), encoding="utf-8")
    lark = [sys.executable, "-c", _LARK, cache, str(typical), str(grammar)]
    build = instructions(lark)
    parse = instructions([*lark, "parse"]) - build
    lark_alone = instructions([sys.executable, "-c", "import lark"])
    loaded = subprocess.run(
        [sys.executable, "-c", _MODULES, str(typical)],
        capture_output=True,
        text=True,
        env=child_env(),
        check=True,
    )
    count = int(loaded.stderr.strip().splitlines()[-1])
    package = folder / "emptymods"
    package.mkdir()
    (package / "__init__.py").write_text("")
    for number in range(count):
        (package / f"m{number}.py").write_text(f"X = {number}\n")
    importing = f"import sys; sys.path.insert(0, {str(folder)!r}); [__import__(f'emptymods.m{{n}}') for n in range({count})]"
    empty = instructions([sys.executable, "-c", importing]) - instructions([sys.executable, "-c", "pass"])
    print(f"allowance over the floor ({BUDGET_COLD_RATIO} x)  {allowance / 1e6:8.1f} M")
    print(f"  Lark: load the analysed grammar  {(build - lark_alone) / 1e6:8.1f} M")
    print(f"  Lark: bare parse of the list     {parse / 1e6:8.1f} M")
    print(f"  import machinery, {count} empty modules (as many as a lint loads)  {empty / 1e6:8.1f} M")
    left = allowance - (build - lark_alone) - parse - empty
    print(f"  left for everything else         {left / 1e6:8.1f} M")


if __name__ == "__main__":
    sys.exit(main())
