#!/usr/bin/env python
"""Instructions of a cold `achslint lint` against the import floor, counted by valgrind (issue 23).

    python benchmarks/coldcount.py             # floor, imports of the CLI, whole lint
    python benchmarks/coldcount.py --lint-only # the lint alone (what to compare between two edits)

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
    return 0


if __name__ == "__main__":
    sys.exit(main())
