"""Lint time of one typical list and of a large list, cold (CLI) and warm (library).

    python benchmarks/lint_speed.py [--runs N]

Prints medians; machines here are noisy, so compare within one run.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from generate import axis_list  # noqa: E402

from achslint.linter import check_bytes  # noqa: E402


def median_wall(command: list[str], runs: int) -> float:
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def warm(data: bytes, runs: int) -> float:
    check_bytes(data, "warmup.lis")
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        check_bytes(data, "bench.lis")
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--large", type=int, default=100_000, help="lines in the large list")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        typical = Path(tmp) / "achsmds1.lis"
        typical.write_bytes(axis_list(250).encode("latin-1"))
        large = Path(tmp) / "achsmds_large.lis"
        large_text = axis_list(args.large, seed=2)
        large.write_bytes(large_text.encode("latin-1"))
        floor = median_wall([sys.executable, "-c", "import lark, pydantic, typer"], args.runs)
        cold = median_wall([sys.executable, "-m", "achslint", "lint", str(typical), "--format", "concise"], args.runs)
        cold_large = median_wall([sys.executable, "-m", "achslint", "lint", str(large), "--format", "concise"], 3)
        warm_typical = warm(typical.read_bytes(), args.runs * 3)
        warm_large = warm(large.read_bytes(), 3)
        lines = large_text.count("\n")
    print(f"import floor (python -c 'import lark, pydantic, typer'): {floor * 1000:7.1f} ms")
    print(f"cold CLI, typical list (250 lines):                    {cold * 1000:7.1f} ms  ({cold / floor:.2f} x floor)")
    print(f"warm library, typical list:                            {warm_typical * 1000:7.1f} ms")
    print(f"cold CLI, large list ({lines} lines):                {cold_large:7.2f} s")
    print(f"warm library, large list:                              {warm_large:7.2f} s  ({lines / warm_large:,.0f} lines/s)")


if __name__ == "__main__":
    main()
