#!/usr/bin/env python
"""What telling a list's kind from its content costs, next to linting the same list.

    python benchmarks/kinds.py             # a 50,000-line axis list
    python benchmarks/kinds.py --lines N   # another size

A generated axis list in the vendor's layout (every line carries a `( P-AXIS-…` comment) is written once;
each run is a fresh Python process that reads it, lints it in-process and tells its kind (`kind_of`), in
either order. Told first, `kind_of` looks every distinct path up in the axis catalogue, whose cached
answers linting then reuses; told after linting (with its own caches emptied), it costs what it adds to a
lint, the figure the budget is about. Also printed: the warm `kind_of` (a second call). Run it with the Python of the environment achslint
is installed in.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from achslint.catalogue.kinds import KindGuess

BUDGET_SHARE = 0.02  # telling the kind may add at most 2 % to linting an axis list


def child(path: Path, order: str) -> None:
    """One run, in a fresh process: the figures as JSON on stdout. `first`: kind_of before linting (it
    then does the axis-catalogue lookups linting reuses); `after`: kind_of after linting, with its own
    caches emptied (what telling the kind adds to a lint)."""
    from achslint.api import lint
    from achslint.catalogue import catalogue
    from achslint.catalogue.kinds import _owners, kind_of, path_index
    from achslint.syntax.parser import parse_bytes

    def timed(action: Callable[[], object]) -> tuple[float, object]:
        start = time.perf_counter()
        result = action()
        return time.perf_counter() - start, result

    data = path.read_bytes()
    parsed = parse_bytes(data, path.name)
    catalogue()  # linting loads it too; not part of either figure
    if order == "first":
        cold, guess = timed(lambda: kind_of(parsed))
        linting, _ = timed(lambda: lint(data, name=path.name))
    else:
        linting, _ = timed(lambda: lint(data, name=path.name))
        path_index.cache_clear()
        _owners.clear()
        cold, guess = timed(lambda: kind_of(parsed))
    warm, _ = timed(lambda: kind_of(parsed))
    assert isinstance(guess, KindGuess)
    figures = {"cold": cold, "warm": warm, "lint": linting, "kind": guess.id, "read": guess.lines}
    print(
        json.dumps(figures | {"lines": len(parsed.lines), "paths": dict(guess.paths), "ids": dict(guess.ids)})
    )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--lines", type=int, default=50_000)
    parser.add_argument("--repeat", type=int, default=5, help="fresh processes to run")
    parser.add_argument("--child", type=Path, help=argparse.SUPPRESS)
    parser.add_argument("--order", choices=("first", "after"), default="after", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.child:
        child(args.child, args.order)
        return 0
    from generate import axis_list

    runs: dict[str, list[dict[str, Any]]] = {"first": [], "after": []}
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "achsmds1.lis"
        path.write_text(axis_list(args.lines), encoding="ascii", newline="")
        for _ in range(args.repeat):
            for order, figures in runs.items():
                command = [sys.executable, __file__, "--child", str(path), "--order", order]
                figures.append(
                    json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)
                )

    def median(order: str, key: str) -> float:
        return statistics.median(run[key] for run in runs[order])

    first = runs["first"][0]
    linting = statistics.median(run["lint"] for figures in runs.values() for run in figures)
    added = median("after", "cold")
    print(
        f"list: {first['lines']:,} lines, kind {first['kind']} (paths {first['paths']}, ids {first['ids']})"
    )
    print(
        f"lint (in-process): {linting * 1000:.0f} ms   (medians of {args.repeat} fresh processes per figure)"
    )
    print(f"kind_of reads the first {first['read']:,} lines:")
    print(
        f"  before linting, cold: {median('first', 'cold') * 1000:.1f} ms (axis-catalogue lookups linting reuses)"
    )
    print(f"  after linting, cold:  {added * 1000:.1f} ms (what it adds to a lint)")
    print(f"  warm:                 {median('after', 'warm') * 1000:.2f} ms")
    share = added / linting
    verdict = "ok" if share <= BUDGET_SHARE else "OVER BUDGET"
    print(f"added / lint: {share:.2%} (budget <= {BUDGET_SHARE:.0%}): {verdict}")
    return 0 if share <= BUDGET_SHARE else 1


if __name__ == "__main__":
    sys.exit(main())
