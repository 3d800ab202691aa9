"""Simulated homings per second: `--sweep` over a three-phase axis with zero pulse.

    python benchmarks/dryrun_speed.py [--runs 10000]
"""

from __future__ import annotations

import argparse
import time

from achslint.dryrun import prepare, sweep
from achslint.scenario import ScenarioInput

AXIS = (b"kenngr.antr_typ 1\nkenngr.ref_richt 0\ngetriebe[0].vb_refmax 100000\ngetriebe[0].vb_reflow 10000\n"
        b"getriebe[0].a_ref 500\ngetriebe[0].pos_refpkt -9500000\nEnde\n")


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=10_000)
    args = parser.parse_args()
    simulator = prepare(AXIS, "bench.lis", ScenarioInput(cam=(-120.0, -100.0), cam_jitter=0.02,
                                                          limit_switches=(-130.0, 1000.0)))
    start = time.perf_counter()
    summary = sweep(simulator, args.runs)
    elapsed = time.perf_counter() - start
    print(f"{args.runs} simulated homings in {elapsed:.3f} s = {args.runs / elapsed:,.0f} per second "
          f"(outcomes {summary['outcomes']})")


if __name__ == "__main__":
    main()
