#!/usr/bin/env python
"""Issue 24's budget: building and linting a whole machine costs at most 1.5x linting its axis lists alone.

    python benchmarks/machine.py [--axes 32] [--channels 4] [--repeat 7]

Generates a machine like the SDK's `listen/` folder — a start-up list naming 32 axis lists, a default axis
list, 4 channel lists and a default channel list, tool data, zero offsets, external variables, manual mode
and the real-time configuration — and times, with the real CLI in a fresh process each time:

- `achslint lint listen/hochlauf.lis` (the machine: discovery, every list by its kind, the machine rules);
- `achslint lint axes/` (the same 32 axis lists copied to a folder with nothing else: no machine).

Prints the medians and their ratio against the budget; exits 1 when the budget is missed. The machine is
our own generated data (numbers, names), not a vendor's.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BUDGET = 1.5


def axis_list(number: int) -> str:
    name = f"A{number}"
    return "\n".join(
        [
            f"# Axis {name}",
            f"kopf.achs_nr                                    {number}",
            f"kopf.log_achs_name                              {name}",
            "kenngr.achs_typ                                 1",
            "kenngr.antr_typ                                 1",
            "lr_hw[0].cam_direct_access                      0",
            "getriebe[0].a_ref                               1000",
            "getriebe[0].vb_refmax                           30000",
            "getriebe[0].vb_reflow                           5000",
            "getriebe[0].dynamik.vb_max                      200000",
            *(f"getriebe[{gear}].dynamik.a_max                  5000" for gear in range(4)),
            "kenngr.swe_pos                                  1000000",
            "kenngr.swe_neg                                  -1000000",
            "Ende",
            "",
        ]
    )


def channel_list(channel: int, axes: list[int]) -> str:
    lines = [f"# Channel {channel}", f"gruppe[0].achs_anzahl                           {len(axes)}"]
    for index, number in enumerate(axes):
        lines += [
            f"gruppe[0].achse[{index}].bezeichnung                  A{number}",
            f"gruppe[0].achse[{index}].log_achs_nr                  {number}",
        ]
    return "\n".join([*lines, "Ende", ""])


def build(root: Path, axes: int, channels: int) -> tuple[Path, Path]:
    listen = root / "machine" / "listen"
    listen.mkdir(parents=True)
    alone = root / "axes"
    alone.mkdir()
    entries = [
        "kanal_anzahl                                     " + str(channels),
        f"zahl_mds                                         {axes}",
        "default_achs_mds                                 ./listen/default_mds.lis",
        "default_sda_mds                                  ./listen/default_sda.lis",
    ]
    for number in range(1, axes + 1):
        (listen / f"achsmds{number}.lis").write_text(axis_list(number), encoding="latin-1")
        shutil.copy(listen / f"achsmds{number}.lis", alone / f"achsmds{number}.lis")
        entries.append(
            f"achs_mds[{number - 1}]                                  ./listen/achsmds{number}.lis"
        )
    per_channel = axes // channels
    for channel in range(channels):
        numbers = list(range(channel * per_channel + 1, (channel + 1) * per_channel + 1))
        (listen / f"sda_mds{channel + 1}.lis").write_text(
            channel_list(channel + 1, numbers), encoding="latin-1"
        )
        entries.append(
            f"sda_mds[{channel}]                                   ./listen/sda_mds{channel + 1}.lis"
        )
    (listen / "default_mds.lis").write_text("getriebe[0].dynamik.vb_max  300000\nEnde\n", encoding="latin-1")
    (listen / "default_sda.lis").write_text("gruppe[0].achs_anzahl  0\nEnde\n", encoding="latin-1")
    others = {
        "werkz_data[0]": ("tool.lis", "wz[0].ident.radius  5000\nEnde\n"),
        "nullp_data[0]": ("zero.lis", "# zero offsets\nEnde\n"),
        "ve_var[0]": ("extvar.lis", "# external variables\nEnde\n"),
        "hand_mds": ("hand.lis", "# manual mode\nEnde\n"),
        "rtconf_lis": ("rtconf.lis", "# real-time configuration\nEnde\n"),
    }
    for key, (name, text) in others.items():
        (listen / name).write_text(text, encoding="latin-1")
        entries.append(f"{key:<49}./listen/{name}")
    startup = listen / "hochlauf.lis"
    startup.write_text("\n".join(["# Generated machine", *entries, "Ende", ""]), encoding="latin-1")
    return startup, alone


def timed(args: list[str], repeat: int) -> float:
    runs = []
    env = {**os.environ, "NO_COLOR": "1"}
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "achslint", *args], capture_output=True, env=env, check=False)
        runs.append(time.perf_counter() - start)
    return statistics.median(runs)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--axes", type=int, default=32)
    parser.add_argument("--channels", type=int, default=4)
    parser.add_argument("--repeat", type=int, default=7)
    options = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        startup, alone = build(Path(folder), options.axes, options.channels)
        whole = timed(["lint", str(startup), "--exit-zero", "--jobs", "1"], options.repeat)
        lists = timed(["lint", str(alone), "--exit-zero", "--jobs", "1"], options.repeat)
    ratio = whole / lists
    verdict = "met" if ratio <= BUDGET else "MISSED"
    print(
        f"machine of {options.axes} axes, {options.channels} channels, all list kinds: {whole * 1000:.0f} ms"
    )
    print(f"its {options.axes} axis lists alone:                         {lists * 1000:.0f} ms")
    print(f"ratio {ratio:.2f} x (budget <= {BUDGET} x) -> {verdict}")
    return 0 if ratio <= BUDGET else 1


if __name__ == "__main__":
    sys.exit(main())
