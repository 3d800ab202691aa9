"""A warm `achslint` command for tests that start it many times as a command of its own: the shell steps of
action.yml and the GitLab job (tests/test_ci_templates.py, two or three `achslint lint` each), and the runs
that must not hang on a FIFO (tests/test_reliability_reach.py: a hang stays in a child, which is ended).

A cold `achslint` process spends most of its ~0.2 s of CPU starting Python and importing achslint; the lint of
the fixture machine is a small part. Here one server process imports achslint and lints once (so the grammar,
the catalogue and the rules are loaded), then forks a child for each call: the `achslint` the scripts find
on PATH is a small client (plain Python, no imports beyond the standard library) that hands the server its
standard input, output and error, arguments, working directory and environment, and exits with the code the
child's `achslint.cli.main` returned. The scripts see a command that behaves as the installed one does
(its own streams, redirections, environment and exit code); the real entry point's own start is tested by
tests/test_entry_point.py, and the `slow` tests run the CI templates against a real install.
"""

from __future__ import annotations

import contextlib
import json
import os
import signal
import socket
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

CLIENT = """#!{python} -IS
import json, os, socket, sys
connection = socket.socket(socket.AF_UNIX)
connection.connect({socket!r})
socket.send_fds(connection, [b"-"], [0, 1, 2])
request = {{"argv": sys.argv[1:], "cwd": os.getcwd(), "env": dict(os.environ)}}
connection.sendall(json.dumps(request).encode())
connection.shutdown(socket.SHUT_WR)
answer = b""
while chunk := connection.recv(64):
    answer += chunk
if not answer:
    sys.stderr.write("achslint (tests/warm_cli.py): the server gave no exit code\\n")
sys.exit(int(answer) if answer else 70)
"""


CALL_LIMIT = 120  # seconds a call may take: then SIGALRM ends it, and its client exits 70


@contextlib.contextmanager
def warm_achslint(folder: Path) -> Iterator[Path]:
    """Start the server; yields a folder holding the `achslint` client, to be put first on PATH."""
    folder.mkdir(parents=True, exist_ok=True)
    address = folder / "achslint.sock"
    assert len(os.fsencode(address)) < 100, f"too long for a socket's address: {address}"
    server = subprocess.Popen(
        [sys.executable, __file__, str(address)], stdout=subprocess.PIPE, stderr=subprocess.PIPE
    )
    try:
        assert server.stdout is not None
        ready = server.stdout.readline()
        assert ready == b"ready\n", (ready, server.stderr.read() if server.stderr else b"")
        client = folder / "bin" / "achslint"
        client.parent.mkdir()
        client.write_text(CLIENT.format(python=sys.executable, socket=str(address)), encoding="utf-8")
        client.chmod(0o755)
        yield client.parent
    finally:
        server.terminate()
        server.communicate(timeout=30)


def _serve(address: str) -> None:
    import tempfile

    from achslint.cli import main

    fixture = Path(__file__).resolve().parents[1] / "fixtures" / "machines" / "sdk"
    with tempfile.TemporaryFile("w+") as sink, contextlib.redirect_stdout(sink):
        main(["lint", str(fixture), "--format", "concise", "--exit-zero"])  # loads what a lint needs
    signal.signal(signal.SIGCHLD, signal.SIG_IGN)  # the children are reaped without waiting for them
    listener = socket.socket(socket.AF_UNIX)
    listener.bind(address)
    listener.listen(16)
    sys.stdout.write("ready\n")
    sys.stdout.flush()
    while True:
        connection, _ = listener.accept()
        if os.fork() == 0:
            listener.close()
            _child(connection)
        connection.close()


def _child(connection: socket.socket) -> None:
    """Run one call: the client's streams as ours, its arguments, folder and environment; its exit code back."""
    code = 70
    try:
        _, streams, _, _ = socket.recv_fds(connection, 1, 3)
        request = b""
        while chunk := connection.recv(1 << 16):
            request += chunk
        call = json.loads(request)
        for number, stream in enumerate(streams):
            os.dup2(stream, number)
            os.close(stream)
        os.chdir(call["cwd"])
        os.environ.clear()
        os.environ.update(call["env"])
        signal.signal(signal.SIGCHLD, signal.SIG_DFL)
        signal.alarm(CALL_LIMIT)  # a call that hangs (the bug a test looks for) ends rather than stays behind
        from achslint.cli import main

        code = main(call["argv"])
    finally:
        with contextlib.suppress(Exception):
            sys.stdout.flush()
            sys.stderr.flush()
        with contextlib.suppress(OSError):
            connection.sendall(str(code).encode())
        _save_coverage()
        os._exit(0)


def _save_coverage() -> None:
    """Under `coverage run` (which measures the server as a child process), the call's measurements too: a
    forked child writes a data file of its own (coverage starts one when the process id changed)."""
    coverage = sys.modules.get("coverage")
    current = coverage.Coverage.current() if coverage is not None else None
    if current is not None:
        with contextlib.suppress(Exception):
            current.stop()
            current.save()


if __name__ == "__main__":
    del sys.path[0]  # tests/: its modules are no one's imports here
    _serve(sys.argv[1])
