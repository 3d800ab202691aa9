"""Review of the safety promises: writes only where the user said, reads only inside the project, never
lose what the user wrote, never hang. Each test is a way one of them was broken."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from achslint.core import codecache
from achslint.core.files import write_output

FIXTURE = Path(__file__).resolve().parents[1] / "fixtures" / "lists" / "achsmds1.lis"
needs_fifo = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs are POSIX")


def _achslint(
    *args: str, cwd: Path, env: dict[str, str] | None = None, timeout: float = 60
) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "achslint", *args],
        cwd=cwd,
        env={**os.environ, **(env or {})},
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        timeout=timeout,
    )


# -- -o through a folder that does not exist ----------------------------------------------------------------


def _python(script: str, cache: Path, timeout: float) -> subprocess.CompletedProcess[str]:
    """`script` in a fresh interpreter whose per-user cache folder lies in `cache`."""
    return subprocess.run(
        [sys.executable, "-c", script],
        env={**os.environ, "XDG_CACHE_HOME": str(cache)},
        capture_output=True,
        text=True,
        timeout=timeout,
    )


def test_output_through_a_missing_folder_is_not_written_over_the_file_the_letters_reach(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """`missing/../x` names no file for the system (the walk stops at `missing`), but resolving it by the
    letters gives `x`: the write went there, over a file `same_file` had not recognised."""
    kept = tmp_path / "achsmds1.lis"
    kept.write_bytes(b"kopf.achs_nr 1\nEnde\n")
    monkeypatch.chdir(tmp_path)
    with pytest.raises(FileNotFoundError):
        write_output(Path("missing/../achsmds1.lis"), b"report\n")
    assert kept.read_bytes() == b"kopf.achs_nr 1\nEnde\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["achsmds1.lis"]


def test_output_to_a_new_file_in_an_existing_folder_still_works(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "sub").mkdir()
    write_output(Path("report.txt"), b"one\n")
    write_output(Path("sub/../sub/report.txt"), b"two\n")
    assert (tmp_path / "report.txt").read_bytes() == b"one\n"
    assert (tmp_path / "sub" / "report.txt").read_bytes() == b"two\n"


@pytest.mark.slow
def test_lint_output_file_through_a_missing_folder_keeps_the_input(tmp_path: Path) -> None:
    shutil.copy(FIXTURE, tmp_path / "achsmds1.lis")
    before = (tmp_path / "achsmds1.lis").read_bytes()
    done = _achslint("lint", ".", "-o", "./missing/../achsmds1.lis", cwd=tmp_path)
    assert done.returncode == 2, done.stderr
    assert "missing/../achsmds1.lis" in done.stderr and "Traceback" not in done.stderr
    assert (tmp_path / "achsmds1.lis").read_bytes() == before


# -- caches -------------------------------------------------------------------------------------------------


@needs_fifo
@pytest.mark.slow
def test_a_fifo_in_place_of_the_code_cache_does_not_hang_a_run(tmp_path: Path) -> None:
    """The code cache was opened with a blocking `open`: a FIFO with no writer at its name stopped every run."""
    cache = tmp_path / "cache"
    script = (
        "import sys\n"
        "from achslint.core import codecache\n"
        "folder = codecache.private_folder()\n"
        "import os; os.mkfifo(codecache.cache_path(folder))\n"
        "c = codecache.CodeCache(codecache.cache_path(folder))\n"
        "print(len(c.stored))\n"
    )
    done = _python(script, cache, timeout=20)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "0"


def test_a_link_from_the_code_cache_to_a_device_reads_nothing(tmp_path: Path) -> None:
    if not Path("/dev/zero").exists():
        pytest.skip("no /dev/zero")
    target = tmp_path / "dataclass-code.marshal"
    target.symlink_to("/dev/zero")
    assert codecache.CodeCache(str(target)).stored == {}


def test_a_hostile_code_cache_only_means_compiling_again(tmp_path: Path) -> None:
    """Not code for a text, a key of another type, nested too deep, truncated: none of them is run."""
    import marshal

    path = tmp_path / "cache.marshal"
    source = "def f(x):\n return x + 1\n"
    for content in (
        marshal.dumps({source: b"not marshal"}),
        marshal.dumps({source: marshal.dumps(42)}),
        marshal.dumps({source: marshal.dumps(compile("y = 1", "<x>", "exec"))})[:-3],
        marshal.dumps([source]),
        b"\xff" * 100,
    ):
        path.write_bytes(content)
        cache = codecache.CodeCache(str(path))
        namespace: dict[str, object] = {}
        cache.exec(source, namespace)
        assert namespace["f"](1) == 2  # type: ignore[operator]


def test_a_relative_xdg_cache_home_puts_no_grammar_cache_in_the_working_directory(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from achslint.syntax import parser

    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("XDG_CACHE_HOME", "relative-cache")
    where = parser._cache_file("grammar text")
    assert not (where and os.path.abspath(str(where)).startswith(str(tmp_path)))
    assert not (tmp_path / "relative-cache").exists()


def test_the_language_server_writes_no_rule_documentation_into_the_working_directory(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from achslint.lsp import features

    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("XDG_CACHE_HOME", "relative-cache")
    monkeypatch.setattr(features, "__file__", str(tmp_path / "a" / "b" / "c" / "features.py"))
    features.rules_document.cache_clear()
    try:
        features.rules_document()
    finally:
        features.rules_document.cache_clear()
    assert not (tmp_path / "relative-cache").exists()


@needs_fifo
@pytest.mark.slow
def test_a_fifo_in_place_of_the_grammar_cache_does_not_hang_a_run(tmp_path: Path) -> None:
    cache = tmp_path / "cache"
    script = (
        "import os\n"
        "from achslint.syntax import parser\n"
        "where = parser._cache_file(parser._grammar_text())\n"
        "os.mkfifo(where)\n"
        "parser.parser()\n"
        "print('parsed')\n"
    )
    done = _python(script, cache, timeout=8)
    assert done.stdout.strip() == "parsed", done.stderr


# -- lint --watch -----------------------------------------------------------------------------------------------


@pytest.mark.slow
def test_watch_is_not_woken_by_the_report_it_writes(tmp_path: Path) -> None:
    shutil.copy(FIXTURE, tmp_path / "achsmds1.lis")
    process = subprocess.Popen(
        [sys.executable, "-m", "achslint", "lint", ".", "--watch", "-o", "report.txt"],
        cwd=tmp_path,
        env={**os.environ, "ACHSLINT_WATCH_INTERVAL": "0.1"},
        stdin=subprocess.DEVNULL,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        _, errors = process.communicate(timeout=6)
    except subprocess.TimeoutExpired:
        process.terminate()
        _, errors = process.communicate(timeout=20)
    assert errors.count("watching for changes") == 1, errors[-500:]
