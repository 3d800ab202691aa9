"""Machines, NC programs and XML never crash and say what they did (issue 22, items 7, 10 and 11).

Each test builds its hostile input in `tmp_path` and runs it the way a user would: through the command line
in this process (`achslint.cli.main`) or through the function the command calls. Every test failed before
the change it guards.
"""

from __future__ import annotations

import io
import sys
import time
from pathlib import Path
from typing import Any

import pytest

from achslint.cli import main
from achslint.core.decode import UnreadableInput
from achslint.machine.build import build_machine
from achslint.machine.model import HomingBlock, MoveBlock, Program
from achslint.machine.program import read_program
from achslint.machine.run import MachineRun, run_machine
from achslint.machine.scenario import read_machine_scenario
from achslint.syntax.xmlinput import extract, source_text

from .conftest import ROOT

EXAMPLE = ROOT / "docs" / "dry-run" / "machine"  # the README's example machine (six axes)


@pytest.fixture
def run(capsys, monkeypatch):
    """The command line in this process: (exit code, stdout, stderr)."""

    def invoke(*args: str | Path):
        monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(b"")))
        code = main([str(a) for a in args])
        out, err = capsys.readouterr()
        return code, out, err

    return invoke


# -- XML in an encoding expat cannot use, or with a lone surrogate (item 10) ---------------------------

# A list with a finding of its own (LIS005): it must still be reported beside a refused XML file.
DUPLICATE = b"kopf.achs_nr 1\nkopf.achs_nr 2\nEnde\n"


def _axis_xml(encoding: str) -> bytes:
    return (
        f'<?xml version="1.0" encoding="{encoding}"?>\n'
        "<TcSmProject><IsgAxisDef><AchsMds><![CDATA[kopf.achs_nr 7\nEnde\n]]></AchsMds></IsgAxisDef>"
        "</TcSmProject>\n"
    ).encode("ascii")


UNUSABLE_ENCODINGS = ["Shift_JIS", "GB2312", "EUC-KR", "Big5", "UTF-7", "IDNA", "punycode", "utf-32"]


@pytest.mark.parametrize("encoding", UNUSABLE_ENCODINGS)
def test_xml_in_an_encoding_expat_cannot_use_is_refused_alone(run, tmp_path, encoding):
    (tmp_path / "achsmds1.lis").write_bytes(DUPLICATE)
    (tmp_path / "axis.xml").write_bytes(_axis_xml(encoding))
    code, out, err = run("lint", tmp_path)
    assert "internal error" not in err and "Traceback" not in err
    [line] = [line for line in err.splitlines() if "axis.xml" in line]
    assert f"declares the encoding `{encoding}`" in line and "save it as UTF-8" in line
    assert code == 2
    assert "achsmds1.lis:2:1: LIS005" in out  # the list beside it is still linted


@pytest.mark.parametrize("encoding", UNUSABLE_ENCODINGS)
def test_the_list_beside_an_unusable_xml_is_linted_with_its_folder(run, tmp_path, encoding):
    # Named alone, the list is checked against its folder, which reads the XML file for LIS501-LIS503.
    (tmp_path / "achsmds1.lis").write_bytes(DUPLICATE)
    (tmp_path / "axis.xml").write_bytes(_axis_xml(encoding))
    code, out, err = run("lint", tmp_path / "achsmds1.lis")
    assert "internal error" not in err and "Traceback" not in err
    assert code == 0 and "achsmds1.lis:2:1: LIS005" in out  # a warning: the run passes


def test_an_own_handler_error_is_not_blamed_on_the_encoding(monkeypatch):
    # The encoding refusal covers what expat raises before the first element, not a fault of ours later.
    from achslint.syntax import xmlinput

    def broken(self, *args):
        raise ValueError("a bug")

    monkeypatch.setattr(xmlinput._Collector, "characters", broken)
    with pytest.raises(ValueError, match="a bug"):
        extract(_axis_xml("cp1252"), "axis.xml")


@pytest.mark.parametrize(
    "data",
    [
        # UTF-8 bytes of a high surrogate, in the list text
        b"<AchsMds>kopf.log_achs_name X\xed\xa0\x80\nEnde\n</AchsMds>",
        # a character reference to one
        b"<AchsMds>kopf.log_achs_name X&#xD800;\nEnde\n</AchsMds>",
        # a lone low surrogate in UTF-16, in an ISG attribute
        b"\xff\xfe"
        + '<AX_MDS><P-AXIS-00297 Value="X'.encode("utf-16-le")
        + b"\x00\xdc"
        + '"/></AX_MDS>'.encode("utf-16-le"),
    ],
    ids=["utf-8 bytes", "character reference", "utf-16 attribute"],
)
def test_xml_with_a_lone_surrogate_is_a_refusal_naming_the_file(data):
    with pytest.raises(UnreadableInput, match=r"^axis\.xml is not well-formed XML: .*\(line 1\)$"):
        extract(data, "axis.xml")


@pytest.mark.parametrize(
    ("encoding", "body"),
    [("UTF-7", "+2AA-"), ("unicode_escape", "\\ud800"), ("IDNA", "a.xn--a")],
)
def test_source_text_never_holds_a_lone_surrogate(encoding, body):
    # The code frames of a file come from here: UTF-7 `+2AA-` and the escape `\ud800` decode to a lone
    # U+D800, which no output can show; IDNA fails on `xn--a` with a bare UnicodeError.
    data = f'<?xml version="1.0" encoding="{encoding}"?>\n<a>{body}</a>\n'.encode("ascii")
    text = source_text(data)
    assert not any(0xD800 <= ord(c) <= 0xDFFF for c in text)
    assert text.splitlines()[1] == f"<a>{body}</a>"


def test_a_skipped_xml_in_an_unusable_encoding_gets_its_note(run, tmp_path):
    # An XML file without a list is only named in a note; working out its root element must not
    # decode it with a codec that fails.
    (tmp_path / "achsmds1.lis").write_bytes(DUPLICATE)
    (tmp_path / "tools.xml").write_bytes(b'<?xml version="1.0" encoding="IDNA"?>\n<Tools>.xn--a</Tools>\n')
    code, out, err = run("lint", tmp_path)
    assert "internal error" not in err and "Traceback" not in err
    assert "skipped, an XML file without a list (<Tools>)" in err
    assert code == 0 and "achsmds1.lis:2:1: LIS005" in out


# -- linear time: the NC program reader and the timeline plot (item 7) --------------------------------

# Each line took the reader tens of seconds before (quadratic); now a fraction of a second. The bound is
# loose on purpose: the benchmark (benchmarks/run --only robustness) measures the doubling.
LOOSE_SECONDS = 5.0  # half of the fastest case before the fix (10 s), twenty times the time after it


def _read_timed(data: bytes) -> tuple[Program, float]:
    start = time.perf_counter()
    program = read_program(data, "rfp.nc")
    return program, time.perf_counter() - start


def test_a_long_number_followed_by_many_words_is_read_in_linear_time():
    # `X` with 20,000 digits, then 10,000 words without a blank: every word used to search to the line's end
    # for an extended name's `=` (14 s).
    program, seconds = _read_timed(b"G74 X" + b"1" * 20_000 + b"Y1" * 10_000 + b"\n")
    assert seconds < LOOSE_SECONDS
    [problem] = program.problems
    assert (problem.at.column, problem.at.end_column) == (5, 20_006)
    assert problem.message == (
        "`X1111111111111111111… (20,001 characters)`: the number is too large to use, so the block cannot be read"
    )


def test_a_long_run_of_axis_words_is_read_in_linear_time():
    program, seconds = _read_timed(b"G74 " + b"Z1" * 25_000 + b"\n")  # 10 s before
    assert seconds < LOOSE_SECONDS
    [block] = program.blocks
    assert isinstance(block, HomingBlock) and len(block.words) == 25_000
    assert block.words[-1].at.column == 4 + 2 * 24_999 + 1


def test_many_program_ends_in_one_block_are_read_in_linear_time():
    program, seconds = _read_timed(b"G01 X1 F100 " + b"M30 " * 8_000 + b"\n")  # 10 s before
    assert seconds < LOOSE_SECONDS
    [block] = program.blocks
    assert isinstance(block, MoveBlock) and program.end is not None and program.end.column == 13


def _example_run(moves: int) -> MachineRun:
    """The example machine homing Z, X and Y, then `moves` small moves of X and Z back and forth."""
    lines = "".join(f"N{i + 20} G01 G91 X{2 * (i % 2) - 1} Z{2 * (i % 2) - 1}\n" for i in range(moves))
    program = read_program(f"N10 G74 Z1 X2 Y2\nG01 G91 F30000\n{lines}M30\n".encode(), "rfp.nc")
    run = run_machine(
        build_machine(EXAMPLE / "listen" / "hochlauf.lis"),
        program,
        read_machine_scenario(EXAMPLE / "machine.toml"),
    )
    assert run.failure is None
    return run


def _artists(figure: Any) -> list[int]:
    """How many artists each panel has, block labels left aside (they are counted on their own)."""
    from matplotlib.text import Text

    return [sum(not isinstance(a, Text) for a in panel.get_children()) for panel in figure.axes]


def test_the_timeline_draws_each_kind_of_mark_once_however_many_blocks():
    # One artist per block and phase made matplotlib recompute its limits over all of them on each one:
    # 2,000 blocks took minutes. Each kind of mark is now one collection.
    pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    from achslint.output.figuredata import LABEL_GAP
    from achslint.output.figures import build_machine_figure

    short, long = _example_run(6), _example_run(30)
    figures = [build_machine_figure(short), build_machine_figure(long)]
    try:
        assert _artists(figures[0]) == _artists(figures[1])
        timeline = figures[1].axes[0]
        bars = sum(
            len(c.get_paths()) for c in timeline.collections if c.get_transform() == timeline.transData
        )
        assert bars == sum(len(axis.phases) for axis in long.axes.values())  # one bar per phase
        labels = [t for t in timeline.texts if t.get_text().startswith(" N")]
        assert 2 <= len(labels) <= 1 / LABEL_GAP + 1  # labels that would overlap are left out
        x_min, x_max = timeline.get_xlim()
        assert x_min < 0 < long.total_time < x_max  # limits set once, around the whole program
    finally:
        for figure in figures:
            plt.close(figure)


# -- honest output of the machine dry-run (item 11) -----------------------------------------------------


def test_a_tiny_feed_is_shown_as_written_in_text_and_json():
    from achslint.output import Screen
    from achslint.output.machine import RENDERERS, MachineDryRun, machine_json

    program = read_program(b"N10 G74 Z1\nN20 G01 G91 Z-1 F0.00001\nM30\n", "rfp.nc")
    run = run_machine(
        build_machine(EXAMPLE / "listen" / "hochlauf.lis"),
        program,
        read_machine_scenario(EXAMPLE / "machine.toml"),
    )
    assert machine_json(run)["blocks"][1]["text"] == "N20 G01 G91 Z-1 F0.00001"
    stream = io.StringIO()
    RENDERERS["text"](MachineDryRun(run), Screen(file=stream))
    text = stream.getvalue()
    assert "N20 G01 G91 Z-1 F0.00001" in text and "F0 " not in text
    # 1 mm at 0.00001 mm/min is 1.67e-07 mm/s, not a speed of 0
    [move] = [line for line in text.splitlines() if "F0.00001;" in line]
    assert "- 1.67e-07 mm/s" in move


# -- gantry couplings without a master (item 10) ---------------------------------------------------


def _machine(folder: Path, masters: dict[str, int | None]) -> Path:
    """A start-up list and one simulated axis per name (logical numbers 1, 2, … in order), each a gantry
    slave of the number given; the start-up list's path."""
    entries = []
    for number, (name, master) in enumerate(masters.items(), 1):
        coupling = f"kenngr.gantry_ax_nr {master}\n" if master else ""
        (folder / f"achsmds{number}.lis").write_text(
            f"kopf.achs_nr {number}\nkopf.log_achs_name {name}\n{coupling}Ende\n", encoding="ascii"
        )
        entries.append(f"achs_mds[{number - 1}] ./achsmds{number}.lis\n")
    startup = folder / "hochlauf.lis"
    startup.write_text(f"zahl_mds {len(entries)}\n{''.join(entries)}Ende\n", encoding="ascii")
    return startup


def _dry_run(run, folder: Path, startup: Path, program: str) -> tuple[int, str, str]:
    (folder / "rfp.nc").write_text(program, encoding="ascii")
    code, out, err = run("dry-run", startup, "--program", folder / "rfp.nc")
    assert "internal error" not in err and "Traceback" not in err
    return code, out, err


def test_a_gantry_axis_that_is_its_own_master_is_a_finding_and_not_simulated(run, tmp_path):
    startup = _machine(tmp_path, {"X": None, "Y": 2})
    code, out, _ = run("lint", startup)
    assert code == 1
    assert "achsmds2.lis:3:1: LIS507 [error] kenngr.gantry_ax_nr 2 is this axis's own kopf.achs_nr" in out
    code, out, _ = _dry_run(run, tmp_path, startup, "N10 G74 X1 Y1\nM30\n")  # KeyError before
    assert code == 1
    assert "FAILED at 0 s (line 1): Y is its own gantry master" in out and "(LIS507)" in out


@pytest.mark.parametrize("program", ["N10 G74 X1 Y1\nM30\n", "N10 G01 G91 Y5 F100\nM30\n"])
def test_two_axes_naming_each_other_as_master_are_findings_and_not_simulated(run, tmp_path, program):
    startup = _machine(tmp_path, {"X": 2, "Y": 1, "Z": None})
    code, out, _ = run("lint", startup)
    assert code == 1
    circles = [line for line in out.splitlines() if "LIS507" in line]
    assert [line.split(":", 1)[0] for line in circles] == [
        str(tmp_path / "achsmds1.lis"),
        str(tmp_path / "achsmds2.lis"),
    ]
    assert "in a circle (1 → 2 → 1)" in circles[0] and "in a circle (2 → 1 → 2)" in circles[1]
    code, out, _ = _dry_run(run, tmp_path, startup, program)
    assert code == 1
    assert "X → Y → X name each other as gantry master" in out or "Y → X → Y name each other" in out


def test_an_axis_beside_a_coupling_without_master_is_still_simulated(run, tmp_path):
    startup = _machine(tmp_path, {"X": 2, "Y": 1, "Z": None})
    code, out, _ = _dry_run(run, tmp_path, startup, "N10 G74 Z1\nM30\n")
    assert code == 0 and "Z (logical 3; simulated drive: single phase): homed" in out


@pytest.mark.parametrize("order", ["X1 Y1 Z1", "X1 Z1 Y1"])
def test_a_slave_of_a_slave_is_a_finding_and_not_simulated_in_any_order(run, tmp_path, order):
    startup = _machine(tmp_path, {"X": None, "Y": 1, "Z": 2})
    code, out, _ = run("lint", startup)
    assert code == 1
    [line] = [line for line in out.splitlines() if "LIS507" in line]
    assert line.startswith(f"{tmp_path / 'achsmds3.lis'}:3:1: LIS507 [error]")
    assert "axis 2 is itself the gantry slave of axis 1" in line
    code, out, _ = _dry_run(run, tmp_path, startup, f"N10 G74 {order}\nM30\n")  # KeyError for X1 Z1 Y1
    assert code == 1
    assert "Z follows the gantry master Y, which is itself the gantry slave of X" in out


def test_coupling_faults_are_found_in_linear_time_on_a_long_circle():
    from achslint.rules.lis507_gantry_master_chain import circle_words, coupling_faults

    # 20,000 axes, each the master of the one before, the first the master of the last; a slave of the
    # circle; an ordinary pair; an axis of its own.
    size = 20_000
    master_of = {n: n + 1 for n in range(1, size)} | {size: 1, 0: 5, -1: -2, -3: -3}
    start = time.perf_counter()
    faults = coupling_faults(master_of)
    assert time.perf_counter() - start < LOOSE_SECONDS
    assert faults[1].kind == "circle" and faults[1].axes(3) == (1, 2, 3) and len(faults[1].members) == size
    assert faults[size].axes(2) == (size, 1)
    assert (
        circle_words(faults[size - 1])
        == f"{size - 1} → {size} → 1 → 2 → 3 → 4 → … → {size - 1} (20,000 axes)"
    )
    assert (faults[0].kind, faults[0].members) == ("chain", (0, 5, 6))
    assert (faults[-3].kind, faults[-3].members) == ("itself", (-3,))
    assert -1 not in faults and len(faults) == size + 2


# -- start-up lists: channel lists that are not there, a list that names itself (item 11) -----------


def test_a_missing_channel_list_is_a_finding(run, tmp_path):
    startup = _machine(tmp_path, {"X": None})
    startup.write_text(startup.read_text().replace("Ende\n", "sda_mds[0] ./sda_mds1.lis\nEnde\n"))
    code, out, _ = run("lint", startup)  # before: all checks passed, only explain and dry-run knew
    assert code == 1
    assert f"{startup}:3:12: LIS504 [error] `sda_mds[0]` names `./sda_mds1.lis`, which does not exist" in out
    code, _, err = run("explain", startup)
    assert code == 2 and "the CNC does not start without it" in err


def test_a_channel_list_outside_the_cnc_root_is_a_finding(run, tmp_path):
    machine = tmp_path / "machine"
    machine.mkdir()
    (tmp_path / "default_sda.lis").write_text("gruppe[0].achse[0].bezeichnung X\nEnde\n")
    (machine / "default_sda.lis").symlink_to(tmp_path / "default_sda.lis")
    startup = _machine(machine, {"X": None})
    startup.write_text(startup.read_text().replace("Ende\n", "default_sda_mds ./default_sda.lis\nEnde\n"))
    code, out, _ = run("lint", startup)
    assert code == 0  # a warning: achslint does not read it, the CNC may
    assert "LIS504 [warning] `default_sda_mds` names `./default_sda.lis`, which achslint does not read" in out


def test_a_startup_list_that_names_only_itself_says_so(run, tmp_path):
    startup = tmp_path / "hochlauf.lis"
    startup.write_text("zahl_mds 1\nachs_mds[0] ./hochlauf.lis\nEnde\n")
    (tmp_path / "rfp.nc").write_text("N10 G74 X1\nM30\n")
    code, out, _ = run("lint", startup)
    assert code == 1
    assert (
        f"{startup}:2:13: LIS504 [error] `achs_mds[0]` names `./hochlauf.lis`, which is this start-up list "
        "itself, not an axis list" in out
    )
    # explain and dry-run took it for an axis list of defaults (an axis X_ACHSE); now they refuse
    for args in (("explain", startup), ("dry-run", startup, "--program", tmp_path / "rfp.nc")):
        code, out, err = run(*args)
        assert code == 2 and out == ""
        assert err.strip() == (
            f"achslint: {startup}:2: `achs_mds[0]` names this start-up list itself (`./hochlauf.lis`), not the "
            "axis list: name the axis list's file"
        )


# -- a channel list that gives one logical axis several names (item 11) -------------------------------


def test_a_logical_axis_with_two_names_in_the_channel_list_is_a_finding(run, tmp_path):
    startup = _machine(tmp_path, {"X": None, "Y": None})
    startup.write_text(startup.read_text().replace("Ende\n", "sda_mds[0] ./sda_mds1.lis\nEnde\n"))
    channel = tmp_path / "sda_mds1.lis"
    channel.write_text(
        "gruppe[0].achse[0].bezeichnung X\ngruppe[0].achse[0].log_achs_nr 1\n"
        "gruppe[0].achse[1].bezeichnung Y\ngruppe[0].achse[1].log_achs_nr 1\n"  # meant 2
        "gruppe[0].achse[2].bezeichnung C\ngruppe[0].achse[2].log_achs_nr 2\n"
        "spindel[0].bezeichnung S\nspindel[0].log_achs_nr 2\n"  # axis 2 as spindle S and axis C: LIS701's
        "Ende\n"
    )
    code, out, _ = run("lint", startup)
    assert code == 1  # LIS508 warns; LIS701: one number for a path axis and a spindle (an error, 20426)
    assert [line.split(" ")[1] for line in out.splitlines() if " LIS5" in line or " LIS7" in line] == [
        "LIS508",
        "LIS701",
    ]
    [line] = [line for line in out.splitlines() if "LIS508" in line]
    assert line == (
        f"{channel}:3:32: LIS508 [warning] gruppe[0].achse[1] names logical axis 1 `Y`, but gruppe[0].achse[0] "
        "already names it `X`: an axis has one name in a channel; give this slot the logical number of the "
        "axis it is meant for, or remove it"
    )
    # The dry-run simulated X and Y as two axes of one axis list; now Y is not a name of the machine.
    code, out, _ = _dry_run(run, tmp_path, startup, "N10 G74 X1 Y1\nM30\n")
    assert code == 1 and "G74 names Y, which is not an axis of the machine (its axes: C, S, X)" in out
    code, out, err = run("explain", startup)
    assert code == 0
    assert (
        f"{channel}:3: gruppe[0].achse[1] names logical axis 1 Y, which gruppe[0].achse[0] already names X"
        in (out + err)
    )
