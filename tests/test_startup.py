"""Start-up lists as the CNC reads them: entries resolved against the CNC's working directory."""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import pytest

from achslint.linting.config import forget_cached

from .conftest import FIXTURES
from .test_strictness import run_in

SDK = FIXTURES / "machines" / "sdk"  # listen/hochlauf.lis names ./listen/achsmds1.lis, as in the vendor SDK


def linted(result, cwd: Path) -> tuple[set[str], list[str]]:
    """(the axis lists linted, the LIS504 messages) of a JSON run."""
    document = json.loads(result.stdout)
    names = {Path(d["path"]).name for d in document["diagnostics"]}
    lis504 = [d["message"] for d in document["diagnostics"] if d["code"] == "LIS504"]
    return names, lis504


@pytest.fixture
def machine(tmp_path) -> Path:
    copy = tmp_path / "machine"
    shutil.copytree(SDK, copy)
    (tmp_path / "elsewhere").mkdir()
    return copy


@pytest.mark.parametrize(
    "where,argument",
    [
        ("listen", "hochlauf.lis"),  # the start-up list's own folder: the reported bug
        (".", "listen/hochlauf.lis"),  # its parent, the CNC's working directory
        ("../elsewhere", None),  # anywhere else, by absolute path
    ],
)
def test_entries_resolve_from_any_working_directory(machine, where, argument):
    cwd = (machine / where).resolve()
    target = argument or str(machine / "listen" / "hochlauf.lis")
    result = run_in(cwd, "lint", target, "--format", "json")
    assert result.returncode == 0, result.stderr.decode()
    names, lis504 = linted(result, cwd)
    assert lis504 == []
    assert {"achsmds2.lis", "achsmds3.lis"} <= names  # their info findings show they were linted


def test_a_missing_entry_says_where_it_looked(machine):
    (machine / "listen" / "achsmds3.lis").unlink()
    result = run_in(machine / "listen", "lint", "hochlauf.lis", "--format", "json")
    assert result.returncode == 1
    _, lis504 = linted(result, machine)
    assert len(lis504) == 1
    assert f"looked for `{(machine / 'listen' / 'achsmds3.lis').resolve()}" in lis504[0].replace(
        str(machine), str(machine.resolve())
    )
    assert "CNC root" in lis504[0]


def test_cnc_root_option_and_setting(machine, tmp_path):
    wrong = tmp_path / "elsewhere"
    result = run_in(machine, "lint", "listen/hochlauf.lis", "--format", "json", "--cnc-root", str(wrong))
    _, lis504 = linted(result, machine)
    assert len(lis504) == 4 and all(
        f"looked for `{wrong}/listen/" in m and "given by --cnc-root" in m for m in lis504
    )
    (machine / ".git").mkdir()  # the repository the configuration belongs to: cnc-root may point up to it
    (machine / "listen" / ".achslint.toml").write_text('cnc-root = "../.."\n')  # relative to the config file
    forget_cached()  # the first run saw no configuration in listen/
    result = run_in(
        tmp_path / "elsewhere", "lint", str(machine / "listen" / "hochlauf.lis"), "--format", "json"
    )
    assert result.returncode == 2 and b"key `cnc-root`: '../..' lies outside" in result.stderr
    (machine / "listen" / ".achslint.toml").write_text('cnc-root = ".."\n')
    forget_cached()
    result = run_in(
        tmp_path / "elsewhere", "lint", str(machine / "listen" / "hochlauf.lis"), "--format", "json"
    )
    assert result.returncode == 0, result.stderr
    names, lis504 = linted(result, machine)
    assert lis504 == [] and "achsmds3.lis" in names
    assert run_in(machine, "lint", "listen/hochlauf.lis", "--cnc-root", "nowhere").returncode == 2


def test_cnc_root_extends_where_entries_may_be_read(tmp_path):
    """A start-up list kept apart from the lists: read only once the CNC root is named."""
    shutil.copytree(SDK / "listen", tmp_path / "listen")
    config = tmp_path / "config"
    config.mkdir()
    (tmp_path / "listen" / "hochlauf.lis").rename(config / "hochlauf.lis")
    result = run_in(tmp_path, "lint", "config/hochlauf.lis", "--format", "json")
    _, lis504 = linted(result, tmp_path)
    # the CNC root is the start-up list's folder (config/): the lists are not guessed from elsewhere
    assert len(lis504) == 4 and all("does not exist" in m and "/config/listen/" in m for m in lis504)
    result = run_in(tmp_path, "lint", "config/hochlauf.lis", "--format", "json", "--cnc-root", ".")
    names, lis504 = linted(result, tmp_path)
    assert lis504 == [] and "achsmds3.lis" in names


EXT_SCHEDULE = FIXTURES / "machines" / "extschedule"  # listen/ExtSchedule/hochlauf.lis names ./listen/*.lis


@pytest.mark.parametrize(
    "where,argument",
    [
        ("listen/ExtSchedule", "hochlauf.lis"),  # its own folder: entries are two folders up from here
        (".", "listen/ExtSchedule/hochlauf.lis"),  # the CNC's working directory
        ("..", None),  # elsewhere, by absolute path
    ],
)
def test_the_ext_schedule_variant_reads_the_lists_one_folder_up(tmp_path, where, argument):
    machine = tmp_path / "machine"
    shutil.copytree(EXT_SCHEDULE, machine)
    startup = machine / "listen" / "ExtSchedule" / "hochlauf.lis"
    result = run_in((machine / where).resolve(), "lint", argument or str(startup), "--format", "json")
    assert result.returncode == 0, result.stderr.decode()
    document = json.loads(result.stdout)
    assert [d["message"] for d in document["diagnostics"] if d["code"] == "LIS504"] == []
    # the start-up list itself (a list of its own kind), and achsmds1.lis, achsmds2.lis and the default list
    # default_mds.lis read through its entries
    assert document["summary"]["files"] == 4
    if where != "listen/ExtSchedule":
        return
    # Read and compared as one machine: a second axis 1 is found across the two lists.
    axis2 = machine / "listen" / "achsmds2.lis"
    axis2.write_text(
        axis2.read_text().replace("kopf.achs_nr                                    2", "kopf.achs_nr 1")
    )
    result = run_in((machine / where).resolve(), "lint", argument or str(startup), "--format", "json")
    assert "LIS501" in {d["code"] for d in json.loads(result.stdout)["diagnostics"]}


def test_entries_are_read_under_the_cnc_root_only(tmp_path):
    """The CNC root of `listen/ExtSchedule/hochlauf.lis` is the folder above `listen/`: an entry below it is
    read, whatever its name; one above it, or a symbolic link below it that leads out, is refused."""
    machine = tmp_path / "machine"
    shutil.copytree(EXT_SCHEDULE, machine)
    (machine / "listen" / "other").mkdir()
    (machine / "listen" / "other" / "achsmds9.lis").write_text("kopf.achs_nr 9\nEnde\n")
    (tmp_path / "outside.lis").write_text("kopf.achs_nr 8\nkopf.SECRET 1\nEnde\n")
    (machine / "listen" / "link.lis").symlink_to(tmp_path / "outside.lis")
    startup = machine / "listen" / "ExtSchedule" / "hochlauf.lis"
    text = re.sub(r"zahl_mds +2", "zahl_mds 5", startup.read_text())  # five entries the CNC reads
    startup.write_text(
        text.replace(
            "#\nEnde",
            "achs_mds[2] ./listen/other/achsmds9.lis\nachs_mds[3] ../outside.lis\n"
            "achs_mds[4] ./listen/link.lis\nEnde",
        )
    )
    result = run_in(machine, "lint", "listen/ExtSchedule/hochlauf.lis", "--format", "json")
    document = json.loads(result.stdout)
    refused = [d["message"] for d in document["diagnostics"] if d["code"] == "LIS504"]
    assert len(refused) == 2
    assert "`../outside.lis`" in refused[0] and "lies outside the CNC root" in refused[0]
    assert "`./listen/link.lis`" in refused[1] and "symbolic link that leads outside" in refused[1]
    # achsmds1, achsmds2, other/achsmds9, the default list, and the start-up list with its LIS504 findings
    assert document["summary"]["files"] == 5
    assert b"SECRET" not in result.stdout + result.stderr
