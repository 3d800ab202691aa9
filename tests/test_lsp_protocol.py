"""The language server answers every message and never waits for a lint (issue 22, items 8 and 9).

The wire is tested as editors use it: bytes in, bytes out. One test starts `achslint server` as a
process; the others run a server in this process on pipes (or on a byte string), which lets them
make a lint slow on purpose and look at what the server answers meanwhile.
"""

from __future__ import annotations

import gc
import io
import json
import logging
import os
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any, BinaryIO

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

pytest.importorskip("pygls.lsp.server", reason="the lsp extra is not installed")

from achslint.lsp import features
from achslint.lsp.protocol import MAX_CONTENT_LENGTH, MAX_LINE, FrameReader, Skipped
from achslint.lsp.server import AchslintServer, create

from .conftest import examples

LIST = "kopf.achs_nr                 1\nkenngr.ref_ricth             1\nEnde\n"


def frame(message: dict[str, Any] | bytes, header: bytes = b"Content-Length: %d\r\n\r\n") -> bytes:
    body = message if isinstance(message, bytes) else json.dumps(message).encode("utf-8")
    return header % len(body) + body


def request(number: int | str, method: str, params: object = None) -> dict[str, Any]:
    message: dict[str, Any] = {"jsonrpc": "2.0", "id": number, "method": method}
    if params is not None:
        message["params"] = params
    return message


def notification(method: str, params: object) -> dict[str, Any]:
    return {"jsonrpc": "2.0", "method": method, "params": params}


def hover(number: int | str, uri: str, line: int, character: int) -> dict[str, Any]:
    where = {"textDocument": {"uri": uri}, "position": {"line": line, "character": character}}
    return request(number, "textDocument/hover", where)


def opened(uri: str, text: str, version: int = 1) -> dict[str, Any]:
    item = {"uri": uri, "languageId": "achsmds", "version": version, "text": text}
    return notification("textDocument/didOpen", {"textDocument": item})


def changed(uri: str, text: str, version: int) -> dict[str, Any]:
    document = {"uri": uri, "version": version}
    return notification(
        "textDocument/didChange", {"textDocument": document, "contentChanges": [{"text": text}]}
    )


INITIALIZE = request(1, "initialize", {"capabilities": {}, "initializationOptions": {"debounceMs": 0}})


def messages_in(data: bytes) -> Iterator[dict[str, Any]]:
    """The messages of a server's output (which the server frames correctly)."""
    reader = FrameReader(io.BytesIO(data))
    while (body := reader.next()) is not None:
        assert isinstance(body, bytes), body
        yield json.loads(body)


class Wire:
    """A client's end of the byte streams to a server: send frames, collect every message that comes back."""

    def __init__(self, to_server: BinaryIO, from_server: BinaryIO) -> None:
        self._out = to_server
        self.received: list[dict[str, Any]] = []
        self._arrived = threading.Condition()
        self._reader = threading.Thread(target=self._read, args=(from_server,), daemon=True)
        self._reader.start()

    def _read(self, stream: BinaryIO) -> None:
        reader = FrameReader(stream)
        while (body := reader.next()) is not None:
            if isinstance(body, bytes):
                with self._arrived:
                    self.received.append(json.loads(body))
                    self._arrived.notify_all()

    def send(self, *data: dict[str, Any] | bytes) -> None:
        self._out.write(b"".join(d if isinstance(d, bytes) else frame(d) for d in data))
        self._out.flush()

    def wait(self, check: Callable[[dict[str, Any]], bool], timeout: float = 20.0) -> dict[str, Any]:
        with self._arrived:
            found: list[dict[str, Any]] = []

            def seen() -> bool:
                found[:] = [m for m in self.received if check(m)]
                return bool(found)

            assert self._arrived.wait_for(seen, timeout), f"no such message in {self.received}"
            return found[0]

    def answer(self, number: int | str, timeout: float = 20.0) -> dict[str, Any]:
        return self.wait(lambda m: m.get("id") == number and "method" not in m, timeout)

    def diagnostics(self, uri: str, version: int, timeout: float = 20.0) -> dict[str, Any]:
        def published(m: dict[str, Any]) -> bool:
            params = m.get("params") or {}
            return (
                m.get("method") == "textDocument/publishDiagnostics"
                and params.get("uri") == uri
                and (params.get("version") == version)
            )

        return self.wait(published, timeout)


class InProcess(Wire):
    """A server of this process, on two pipes (so a test can reach into its session)."""

    def __init__(self) -> None:
        self.server: AchslintServer = create()
        into_read, into_write = os.pipe()
        out_read, out_write = os.pipe()
        self._server_in = os.fdopen(into_read, "rb")
        self._server_out = os.fdopen(out_write, "wb")
        self.code: int | None = None
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()
        super().__init__(os.fdopen(into_write, "wb"), os.fdopen(out_read, "rb"))

    def _serve(self) -> None:
        self.code = self.server.serve(self._server_in, self._server_out)
        self._server_out.close()

    def close(self) -> None:
        self.send(request("bye", "shutdown"))
        self.answer("bye")
        self.send(notification("exit", None))
        self._thread.join(10)
        self._out.close()
        self._server_in.close()


@pytest.fixture
def inprocess() -> Iterator[InProcess]:
    wire = InProcess()
    wire.send(INITIALIZE, notification("initialized", {}))
    wire.answer(1)
    yield wire
    wire.close()
    assert wire.code == 0


# -- the reader ------------------------------------------------------------------------------------------


def read_all(data: bytes, limit: int = MAX_CONTENT_LENGTH) -> list[bytes | Skipped]:
    reader = FrameReader(io.BytesIO(data), limit)
    out: list[bytes | Skipped] = []
    while (item := reader.next()) is not None:
        out.append(item)
    return out


BODY = b'{"jsonrpc":"2.0","method":"initialized","params":{}}'


@pytest.mark.parametrize(
    "header",
    [
        b"Content-Length: %d\r\n\r\n",
        b"content-length:%d\r\n\r\n",
        b"CONTENT-LENGTH :  %d \t\r\n\r\n",
        b"Content-Length: %d\r\nContent-Type: application/vscode-jsonrpc; charset=utf-8\r\n\r\n",
        b"Content-Type: application/vscode-jsonrpc; charset=utf8\r\nContent-Length: %d\r\n\r\n",
        b"Content-Length: %d\n\n",  # LF alone
        b"\r\n\r\nContent-Length: %d\r\n\r\n",  # blank lines between messages
    ],
)
def test_headers_the_base_protocol_allows_are_read(header: bytes) -> None:
    assert read_all(frame(BODY, header) + frame(BODY)) == [BODY, BODY]


@pytest.mark.parametrize(
    ("bad", "why"),
    [
        (b"Content-Type: text/plain\r\n\r\n", "no Content-Length"),
        (b"Content-Length: twelve\r\n\r\n", "Content-Length 'twelve', not a number"),
        (b"Content-Length: -5\r\n\r\n", "Content-Length '-5', not a number"),
        (b"Content-Length: \r\n\r\n", "Content-Length '', not a number"),
        (b"Content-Length: \xd9\xa3\r\n\r\n", "not a number"),  # an Arabic-Indic digit is no ASCII digit
    ],
)
def test_a_malformed_header_block_is_skipped_and_told(bad: bytes, why: str) -> None:
    found = read_all(bad + frame(BODY))
    assert found[1:] == [BODY]
    assert isinstance(found[0], Skipped) and why in found[0].reason and not found[0].refused


def test_noise_is_skipped_up_to_the_next_header_even_mid_line() -> None:
    # The rest of a body whose Content-Length was too small runs into the next header on the same line.
    stream = b'Content-Length: 4\r\n\r\n{"a": 1}' + frame(BODY) + b"tail without a break"
    found = read_all(stream)
    assert found[0] == b'{"a"' and found[2] == BODY
    assert isinstance(found[1], Skipped) and "skipped 4 bytes" in found[1].reason
    assert isinstance(found[3], Skipped) and "skipped 20 bytes" in found[3].reason  # told at the end


def test_an_oversize_length_is_refused_without_reading_it() -> None:
    huge = b"Content-Length: %d\r\n\r\n" % (MAX_CONTENT_LENGTH + 1)
    found = read_all(huge + frame(BODY))
    assert found[1:] == [BODY]
    assert isinstance(found[0], Skipped) and found[0].refused and "64 MB" in found[0].reason
    small = read_all(frame(BODY) + frame(BODY, b"Content-Length: %d\r\n\r\n"), limit=len(BODY) - 1)
    # Refused bodies are not read as messages; what follows the second one is noise to the end.
    assert [item.refused for item in small if isinstance(item, Skipped)] == [True, True, False]
    assert len(small) == 3 and "over the 51 bytes limit" in str(small[0])


class Endless(io.RawIOBase):
    """A stream of `count` bytes of noise without a line break, then one message; counts what was read."""

    def __init__(self, count: int) -> None:
        self.left, self.tail = count, frame(BODY)

    def readable(self) -> bool:
        return True

    def readinto(self, buffer: Any) -> int:
        if self.left > 0:
            size = min(len(buffer), self.left)
            buffer[:size] = b"x" * size
            self.left -= size
            return size
        size = min(len(buffer), len(self.tail))
        buffer[:size], self.tail = self.tail[:size], self.tail[size:]
        return size


def test_a_line_without_end_does_not_fill_memory() -> None:
    reader = FrameReader(io.BufferedReader(Endless(20 * 1024 * 1024)))
    first = reader.next()
    assert isinstance(first, Skipped) and "20971520 bytes" in first.reason
    assert reader.next() == BODY and reader.next() is None
    assert len(reader._buffer) <= MAX_LINE


def test_the_end_of_the_stream_inside_a_body_ends_the_reading() -> None:
    found = read_all(frame(BODY) + b"Content-Length: 100\r\n\r\n{}")
    assert found[0] == BODY and isinstance(found[1], Skipped) and len(found) == 2


class Chunks:
    """A raw stream that gives one chunk per read (as a pipe gives what one write put in it)."""

    def __init__(self, *chunks: bytes) -> None:
        self._chunks = list(chunks)

    def read(self, size: int = -1) -> bytes:
        return self._chunks.pop(0) if self._chunks else b""


def test_the_reader_tells_before_each_read_that_what_it_gave_is_all_there_is() -> None:
    half = len(frame(BODY)) // 2
    events: list[object] = []
    reader = FrameReader(
        Chunks(frame(BODY) + frame(BODY), frame(BODY)[:half], frame(BODY)[half:]),  # type: ignore[arg-type]
        waiting=lambda: events.append("wait"),
    )
    while (item := reader.next()) is not None:
        events.append(item)
    # two messages of one read, told together; a message split over two reads, told once it is whole
    assert events == ["wait", BODY, BODY, "wait", "wait", BODY, "wait"]


# -- the server on the wire ------------------------------------------------------------------------------


@pytest.mark.slow  # runs a real process (the slow tier: .ci/run, `pytest -m slow`)
def test_every_message_is_answered_over_stdio(tmp_path: Path) -> None:
    """`achslint server` as a process: malformed headers, an oversize length, invalid params, a request
    before initialize and after shutdown: each gets its answer (or a log line), and a hover still works."""
    uri = (tmp_path / "achsmds1.lis").as_uri()
    process = subprocess.Popen(
        [sys.executable, "-m", "achslint", "server"],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    assert process.stdin is not None and process.stdout is not None
    wire = Wire(process.stdin, process.stdout)
    try:
        wire.send(
            frame(hover("early", uri, 0, 0)),
            frame(
                INITIALIZE,
                b"content-length:%d\r\nContent-Type: application/vscode-jsonrpc; charset=utf-8\r\n\r\n",
            ),
            frame(notification("initialized", {}), b"CONTENT-LENGTH :  %d  \n\n"),
            b"Content-Type: text/plain\r\n\r\n",  # no Content-Length
            b"Content-Length: twelve\r\n\r\n",
            b"Content-Length: %d\r\n\r\n" % (10 * MAX_CONTENT_LENGTH),
            b"noise that is no header\r\n",
            frame(b"{not json"),
            frame(b"[1, 2]"),
            frame(b'{"jsonrpc": "2.0", "id": [1], "method": "shutdown"}'),
            frame(hover(2, uri, -1, 0)),
            frame(hover(3, uri, 2**40, 0)),
            frame(request(4, "textDocument/hover", {})),
            frame(request(5, "textDocument/definition", {"textDocument": {"uri": 7}, "position": "here"})),
            frame(request(6, "no/such/method")),
            frame(opened(uri, LIST)),
            frame(hover(7, uri, 0, 2)),
        )
        assert wire.answer("early")["error"]["code"] == -32002  # ServerNotInitialized
        assert "capabilities" in wire.answer(1)["result"]
        shown = wire.wait(lambda m: m.get("method") == "window/showMessage")
        assert "refused a message of" in shown["params"]["message"]
        for number in (2, 3, 4, 5):
            assert wire.answer(number)["error"]["code"] == -32602  # InvalidParams
        assert wire.answer(6)["error"]["code"] == -32601  # MethodNotFound
        answer = wire.answer(7)["result"]
        assert "kopf.achs_nr" in answer["contents"]["value"]
        # Without a usable id: ParseError for the broken JSON, InvalidRequest for the batch and the list id.
        errors = [m["error"]["code"] for m in wire.received if m.get("id") is None and "error" in m]
        assert errors == [-32700, -32600, -32600]

        wire.send(request(8, "shutdown"), hover(9, uri, 0, 2), notification("exit", None))
        assert wire.answer(8)["result"] is None
        assert wire.answer(9)["error"]["code"] == -32600  # InvalidRequest after shutdown
        assert process.wait(20) == 0
    finally:
        if process.poll() is None:
            process.kill()
        process.wait()
    assert process.stderr is not None
    log = process.stderr.read().decode("utf-8", "replace")
    assert "Traceback" not in log
    assert "skipped 2 header blocks with no Content-Length; refused a message of 671088640 bytes" in log
    assert "not an LSP header" in log


def slow_lint(server: AchslintServer) -> tuple[threading.Event, threading.Event]:
    """Make the server's next lints run until released, busy (holding the interpreter as a real lint does)."""
    started, release = threading.Event(), threading.Event()
    session = server.session
    lint = session.diagnostics

    def slow(uri: str) -> Any:
        started.set()
        while not release.is_set():
            sum(range(2000))
        return lint(uri)

    session.diagnostics = slow  # type: ignore[method-assign]
    return started, release


def test_a_hover_is_answered_while_a_slow_lint_runs(inprocess: InProcess, tmp_path: Path) -> None:
    uri = (tmp_path / "achsmds1.lis").as_uri()
    inprocess.send(opened(uri, LIST))
    inprocess.diagnostics(uri, 1)
    started, release = slow_lint(inprocess.server)
    inprocess.send(changed(uri, LIST.replace("1\n", "2\n", 1), 2))
    assert started.wait(10)
    sent = time.perf_counter()
    inprocess.send(hover(10, uri, 0, 2))
    answer = inprocess.answer(10)
    took = time.perf_counter() - sent
    assert not any(m.get("params", {}).get("version") == 2 for m in inprocess.received)  # still linting
    release.set()
    assert "kopf.achs_nr" in answer["result"]["contents"]["value"]  # from the analysis of version 1
    assert took < 5.0  # loose: the lint never ends on its own; benchmarks/lsp.py measures the real figure
    inprocess.diagnostics(uri, 2)


def test_the_messages_of_one_read_reach_the_loop_together(inprocess: InProcess, tmp_path: Path) -> None:
    """An edit and the request sent right behind it are handed over in one go: woken for the edit alone, the
    loop took the processor from the reader before it had parsed the request."""
    server = inprocess.server
    batches: list[list[str]] = []
    receive_all = server._receive_all

    def counted(items: list[object]) -> None:
        batches.append([item.get("method", "") for item in items if isinstance(item, dict)])
        receive_all(items)

    server._receive_all = counted  # type: ignore[method-assign]
    uri = (tmp_path / "achsmds1.lis").as_uri()
    inprocess.send(opened(uri, LIST))
    inprocess.diagnostics(uri, 1)
    inprocess.send(changed(uri, LIST.replace("1\n", "2\n", 1), 2), hover(12, uri, 0, 2))  # one write
    assert "kopf.achs_nr" in inprocess.answer(12)["result"]["contents"]["value"]
    assert batches == [["textDocument/didOpen"], ["textDocument/didChange", "textDocument/hover"]]


def test_each_answer_gives_the_editor_a_turn_to_read_it(
    inprocess: InProcess, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from achslint.lsp import worker

    monkeypatch.setattr(worker, "ANSWER_TURN", 0.25)
    uri = (tmp_path / "achsmds1.lis").as_uri()
    inprocess.send(opened(uri, LIST))
    inprocess.diagnostics(uri, 1)
    gate = inprocess.server._gate

    def idle_after() -> float:
        """Seconds until the gate is idle (the turns of the answers before end), at most 5."""
        started = time.monotonic()
        while gate.busy and time.monotonic() - started < 5:
            time.sleep(0.005)
        assert not gate.busy
        return time.monotonic() - started

    idle_after()
    inprocess.send(hover(13, uri, 0, 2))
    inprocess.answer(13)
    answered = time.monotonic()
    time.sleep(0.03)  # the loop waits for messages again, nothing is unread: the editor's turn
    assert gate.busy
    idle_after()
    assert time.monotonic() - answered >= 0.2  # the whole turn, not the loop's own idling


def test_a_lint_of_an_older_text_is_not_published(inprocess: InProcess, tmp_path: Path) -> None:
    uri = (tmp_path / "achsmds1.lis").as_uri()
    inprocess.send(opened(uri, LIST))
    inprocess.diagnostics(uri, 1)
    started, release = slow_lint(inprocess.server)
    inprocess.send(changed(uri, LIST + "kenngr.other_typo 1\n", 2))
    assert started.wait(10)
    inprocess.send(changed(uri, "kopf.achs_nr 1\nEnde\n", 3), hover(11, uri, 0, 2))
    inprocess.answer(11)  # answered after the change to version 3 was taken (messages are handled in order)
    release.set()
    final = inprocess.diagnostics(uri, 3)
    assert final["params"]["diagnostics"] == []
    published = [
        m["params"]["version"] for m in inprocess.received if m.get("method", "").endswith("Diagnostics")
    ]
    assert published == [1, 3]  # version 2 was linted, but its findings were stale when they came


def test_garbage_is_collected_when_idle_not_during_a_lint(
    inprocess: InProcess, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    collections: list[float] = []
    monkeypatch.setattr(gc, "collect", lambda *_: collections.append(time.perf_counter()) or 0)
    inprocess.server.collect_when_idle = 0.05
    uri = (tmp_path / "achsmds1.lis").as_uri()
    started, release = slow_lint(inprocess.server)
    inprocess.send(opened(uri, LIST))
    assert started.wait(10)
    time.sleep(0.15)  # quiet on the wire (three times the idle wait), but the worker is busy
    assert collections == []
    release.set()
    published = inprocess.diagnostics(uri, 1)
    assert published["params"]["diagnostics"]
    deadline = time.perf_counter() + 10
    while not collections and time.perf_counter() < deadline:
        time.sleep(0.02)
    assert len(collections) == 1  # once the lint ended and nothing came for a while


def test_diagnostics_are_capped_with_a_summary(
    inprocess: InProcess, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # 1,000 in the server (benchmarks/lsp.py measures that message: under 1 MB); 20 here, the same code.
    monkeypatch.setattr(features, "MAX_DIAGNOSTICS", 20)
    names = "".join(f"kenngr.unknown_{n} 1\n" for n in range(30))
    text = "kopf.achs_nr 1\n" + names + "kenngr.ref_richt 7\nEnde\n"  # an error (LIS201) after 30 warnings
    uri = (tmp_path / "achsmds1.lis").as_uri()
    inprocess.send(opened(uri, text))
    found = inprocess.diagnostics(uri, 1)["params"]["diagnostics"]
    assert len(found) == 21
    summary = found[0]
    assert summary["severity"] == 3 and summary["message"].startswith("11 more findings are not shown")
    assert "achslint lint" in summary["message"]
    shown = found[1:]
    assert shown[-1]["code"] == "LIS201" and shown[-1]["severity"] == 1  # the error is kept, in its place
    lines = [d["range"]["start"]["line"] for d in shown]
    assert lines == sorted(lines)


# -- random bytes --------------------------------------------------------------------------------------

METHODS = [
    "initialize",
    "initialized",
    "shutdown",
    "textDocument/didOpen",
    "textDocument/didChange",
    "textDocument/didClose",
    "textDocument/didSave",
    "textDocument/hover",
    "textDocument/completion",
    "textDocument/definition",
    "textDocument/formatting",
    "textDocument/codeAction",
    "textDocument/documentSymbol",
    "workspace/didChangeConfiguration",
    "$/cancelRequest",
    "no/such",
]
JSON = st.recursive(
    st.none() | st.booleans() | st.integers(-(2**40), 2**40) | st.text(max_size=20),
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=8), inner, max_size=4),
    max_leaves=12,
)
POSITION = st.fixed_dictionaries({"line": st.integers(-3, 2**33), "character": st.integers(-3, 2**33)})
DOCUMENT = st.fixed_dictionaries({"uri": st.sampled_from(["file:///a/achsmds1.lis", "untitled:1", "x"])})
PARAMS = (
    JSON
    | st.fixed_dictionaries({"textDocument": DOCUMENT, "position": POSITION})
    | st.fixed_dictionaries(
        {
            "textDocument": st.fixed_dictionaries(
                {
                    "uri": st.just("file:///a/achsmds1.lis"),
                    "languageId": st.just("achsmds"),
                    "version": st.integers(-2, 5),
                    "text": st.text(max_size=60) | st.just(LIST),
                }
            )
        }
    )
    | st.fixed_dictionaries({"capabilities": st.just({}), "initializationOptions": JSON})
)
MESSAGE = st.fixed_dictionaries(
    {"method": st.sampled_from(METHODS) | st.text(max_size=10).filter(lambda m: m != "exit")},
    optional={
        "jsonrpc": st.sampled_from(["2.0", "2.0", "1.0"]) | JSON,
        "id": st.integers(-5, 2**40) | st.text(max_size=5) | JSON,
        "params": PARAMS,
    },
)
RESPONSE = st.fixed_dictionaries(
    {"jsonrpc": st.just("2.0"), "id": st.integers(0, 5) | st.text(max_size=3)},
    optional={"result": JSON, "error": JSON | st.fixed_dictionaries({"code": JSON, "message": JSON})},
)
HEADER = st.sampled_from(
    [
        b"Content-Length: %d\r\n\r\n",
        b"content-length:%d\n\n",
        b"Content-Type: x\r\nCONTENT-LENGTH : %d \r\n\r\n",
    ]
)
NOISE = st.binary(max_size=120).filter(lambda b: b"content-length" not in b.lower())
PIECE = st.one_of(
    st.builds(frame, st.binary(max_size=120), HEADER),  # a well-framed body that is anything
    st.builds(frame, MESSAGE, HEADER),  # a well-framed message that is nearly right
    st.builds(frame, RESPONSE, HEADER),  # as if the client answered a request of the server
    st.builds(
        lambda m: frame(json.dumps(m).encode("utf-8")[: len(json.dumps(m)) // 2]), MESSAGE
    ),  # cut short
    NOISE,
    st.lists(st.sampled_from([b"X: y", b"Content-Type: z", b"::", b"\x00\xff"]), min_size=1).map(
        lambda lines: b"\r\n".join(lines) + b"\r\n\r\n"
    ),  # a header block without a length
    st.integers(MAX_CONTENT_LENGTH + 1, 2**70).map(lambda n: b"Content-Length: %d\r\n\r\n" % n),
)


@settings(max_examples=examples(200, 12), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.booleans(), st.lists(PIECE, max_size=12))
def test_random_frames_never_make_the_server_deaf(initialized: bool, pieces: list[bytes]) -> None:
    """Whatever came before, a well-framed request is answered, and nothing logs a traceback."""
    if initialized:  # so that the messages after it reach the handlers
        pieces = [frame(INITIALIZE), *pieces]
    final = frame(
        request(
            "final",
            "textDocument/hover",
            {"textDocument": {"uri": "file:///z"}, "position": {"line": 0, "character": 0}},
        )
    )
    output = io.BytesIO()
    records: list[logging.LogRecord] = []
    collect = logging.Handler()
    collect.emit = records.append  # type: ignore[method-assign]
    watched = [logging.getLogger(name) for name in ("achslint", "pygls")]
    for logger in watched:
        logger.addHandler(collect)
    try:
        code = create().serve(io.BytesIO(b"".join(pieces) + b"\r\n" + final), output)
    finally:
        for logger in watched:
            logger.removeHandler(collect)
    assert code == 0
    answers = [m for m in messages_in(output.getvalue()) if m.get("id") == "final"]
    assert len(answers) == 1
    assert not [r for r in records if r.exc_info or "Traceback" in r.getMessage()]


def test_a_length_of_thousands_of_digits_is_refused_and_the_next_message_read():
    """Found by review: 4,301 digits made int() raise, and the server stopped reading its client."""
    frame = b"Content-Length: %d\r\n\r\n" % len(BODY) + BODY
    items = read_all(b"Content-Length: " + b"9" * 5000 + b"\r\n\r\n" + frame)
    assert items[-1] == BODY
    assert any(isinstance(item, Skipped) for item in items)
