"""`files`: what achslint says about things that are not lists, and how a list is rewritten when the
usual way (a temporary file renamed over it) is not allowed. The permission cases are simulated so they
also run as root, where the kernel would allow everything."""

from __future__ import annotations

import os
import socket
import tempfile
from collections.abc import Callable
from pathlib import Path
from subprocess import CompletedProcess

import pytest

from achslint import files
from achslint.files import ChangedOnDisk, not_a_list_file, write_atomically

Cli = Callable[..., CompletedProcess]
MESSY = b"kopf.achs_nr 1\nkenngr.achs_typ     1\nEnde\n"
TIDY = b"kopf.achs_nr     1\nkenngr.achs_typ  1\nEnde\n"


def test_devices_sockets_and_impossible_names_are_not_lists(cli: Cli, tmp_path: Path) -> None:
    assert not_a_list_file(Path("/dev/null")) == "a device, not a regular file"
    assert not_a_list_file(tmp_path / "achs\x00mds.lis") == "a name the file system cannot hold"
    path = tmp_path / "achsmds1.lis"
    with socket.socket(socket.AF_UNIX) as server:
        server.bind(str(path))
        assert not_a_list_file(path) == "a socket, not a regular file"
        result = cli("lint", str(path))
    assert result.returncode == 2
    assert result.stderr.decode() == f"achslint: {path}: a socket, not a regular file\n"


def test_fmt_rewrites_in_place_when_the_folder_may_not_be_written(
    cli: Cli, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(MESSY)
    inode = path.stat().st_ino

    def no_new_files(*args: object, **kwargs: object) -> tuple[int, str]:
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(tempfile, "mkstemp", no_new_files)
    result = cli("fmt", str(path))
    assert result.returncode == 0, result.stderr
    assert path.read_bytes() == TIDY and path.stat().st_ino == inode


def test_fmt_rewrites_in_place_when_the_owner_cannot_be_kept(
    cli: Cli, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(MESSY)
    inode = path.stat().st_ino
    real_stat = os.stat

    def another_owner(target: object, *args: object, **kwargs: object) -> os.stat_result:
        """The list belongs to someone else (uid 4711); the temporary file would be ours."""
        info = real_stat(target, *args, **kwargs)  # type: ignore[arg-type]
        if Path(str(target)) != path:
            return info
        fields = list(info)
        fields[4] = 4711
        return os.stat_result(fields)

    def not_allowed(*args: object) -> None:
        raise PermissionError(1, "Operation not permitted")

    monkeypatch.setattr(files.os, "stat", another_owner)
    monkeypatch.setattr(files.os, "chown", not_allowed)
    result = cli("fmt", str(path))
    assert result.returncode == 0, result.stderr
    assert path.read_bytes() == TIDY and path.stat().st_ino == inode
    assert [p.name for p in tmp_path.iterdir()] == ["achsmds1.lis"]  # no temporary file left


def test_a_list_removed_while_it_is_written_is_not_written(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(MESSY)

    def removed_meanwhile(temporary: str, info: os.stat_result) -> bool:
        path.unlink()
        return True

    monkeypatch.setattr(files, "_keep_owner", removed_meanwhile)
    with pytest.raises(ChangedOnDisk, match="was removed while achslint was working on it; nothing written"):
        write_atomically(path, TIDY, expected=MESSY)
    assert list(tmp_path.iterdir()) == []  # neither the list nor a temporary file


def test_without_an_expected_content_the_list_is_simply_replaced(tmp_path: Path) -> None:
    path = tmp_path / "achsmds1.lis"
    path.write_bytes(b"anything\n")
    write_atomically(path, TIDY)
    assert path.read_bytes() == TIDY
