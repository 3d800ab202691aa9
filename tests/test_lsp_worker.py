"""The language server's worker gives way to the message loop and drops a lint whose text changed: at its
pause points (before each rule, `engine.pause_between_rules`; at the start of each job) it waits while the
loop has work (`worker.Gate`), and inside `superseded_when` a pause point ends the job (`Superseded`)."""

from __future__ import annotations

import asyncio
import io
import os
import threading
import time
from pathlib import Path

import pytest

from achslint.api import lint_text
from achslint.linting import engine
from achslint.lsp import worker as worker_module
from achslint.lsp.worker import Gate, Superseded, WatchedSelector, Worker

LIST = "kopf.achs_nr 1\nkenngr.antr_typ 1\nEnde\n"


@pytest.fixture
def gate(monkeypatch) -> Gate:
    monkeypatch.setattr(worker_module, "PAUSE_LIMIT", 5.0)  # long enough to see a pause, short enough to end
    return Gate()


def test_rules_pause_only_on_a_thread_that_asked_for_it():
    calls = []
    engine.pause_between_rules(lambda: calls.append(1))
    try:
        first = lint_text(LIST, filename="achsmds1.lis")
    finally:
        engine.pause_between_rules(None)
    assert len(calls) >= 10  # once per rule
    calls.clear()
    assert lint_text(LIST, filename="achsmds1.lis") == first  # the same findings, and no pause without a hook
    assert calls == []
    elsewhere: list[int] = []
    thread = threading.Thread(target=lambda: (engine.pause(), elsewhere.append(1)))
    thread.start()
    thread.join()
    assert elsewhere == [1]


def test_a_job_waits_while_the_loop_is_busy(gate: Gate):
    work = Worker(gate=gate)
    try:
        gate.loop(True)
        started = time.perf_counter()
        future = work.submit(lambda: (engine.pause(), time.perf_counter())[1])
        time.sleep(0.1)
        assert not future.done()  # held at the start of the job
        gate.loop(False)
        assert future.result(timeout=5) - started >= 0.1
        gate.read()  # a message read and not yet taken: the loop has work too
        ran = []
        future = work.submit(lambda: ran.append(1))
        time.sleep(0.1)
        assert ran == []
        gate.taken()
        gate.loop(False)
        future.result(timeout=5)
        assert ran == [1]
    finally:
        work.stop()


def test_a_paused_rule_loop_goes_on_when_the_loop_is_quiet(gate: Gate):
    work = Worker(gate=gate)
    try:
        reached = threading.Event()

        def job() -> list:
            reached.set()
            return lint_text(LIST, filename="achsmds1.lis")

        future = work.submit(job)
        assert reached.wait(5)
        gate.loop(True)  # between rules now (or done already)
        time.sleep(0.1)
        gate.loop(False)
        assert future.result(timeout=5) == lint_text(LIST, filename="achsmds1.lis")
    finally:
        work.stop()


def test_a_superseded_job_ends_at_its_next_pause_point():
    work = Worker(gate=Gate())
    stale = threading.Event()
    rounds = []
    try:

        def job() -> None:
            with work.superseded_when(stale.is_set):
                while True:
                    engine.pause()
                    rounds.append(1)
                    if len(rounds) == 3:
                        stale.set()

        with pytest.raises(Superseded):
            work.submit(job).result(timeout=5)
        assert len(rounds) == 3
        assert work.submit(lambda: (engine.pause(), "no longer superseded")[1]).result(timeout=5)
    finally:
        work.stop()


def test_the_watched_selector_tells_when_the_loop_waits():
    gate = Gate()
    seen = {}

    async def main() -> None:
        seen["running"] = gate.busy
        thread = threading.Thread(target=lambda: (time.sleep(0.05), seen.setdefault("waiting", gate.busy)))
        thread.start()
        await asyncio.sleep(0.2)
        seen["after"] = gate.busy
        thread.join()

    loop = asyncio.SelectorEventLoop(WatchedSelector(gate))
    try:
        loop.run_until_complete(main())
    finally:
        loop.close()
    assert seen == {"running": True, "waiting": False, "after": True}


def test_the_warm_up_after_the_first_lint_reads_and_writes_every_sample(monkeypatch):
    """The warm-up lets the converters make their code for the requests and answers the editor sends most:
    a sample they cannot read would warm nothing (the warm-up itself never fails the server)."""
    from achslint.lsp import server

    failed: list[BaseException] = []

    class Loud:
        def __init__(self, *kinds: type[BaseException]) -> None:
            pass

        def __enter__(self) -> None:
            return None

        def __exit__(self, kind, error, trace) -> bool:
            if error is not None:
                failed.append(error)
            return True

    monkeypatch.setattr(server.contextlib, "suppress", Loud)
    server.create()._warm_up(None)
    # with the first analysis of a list: one of its hover cards is made too
    from achslint.lsp.documents import Document
    from achslint.lsp.session import Session

    session, document = Session(), Document("untitled:warm", None, LIST, 1)
    session.open(document)
    snapshot, found, _ = session.diagnostics(document.uri)
    assert snapshot is not None
    cards: list[str] = []
    hover_text = server.features.hover_text
    monkeypatch.setattr(server.features, "hover_text", lambda *args: cards.append(hover_text(*args)))
    server.create()._warm_up(server.Analysis(1, document, snapshot, found))
    assert failed == []
    assert len(cards) == 1 and "P-AXIS-00016" in cards[0]  # kopf.achs_nr, the first line


def test_the_pipe_to_the_client_is_widened_where_the_system_allows(tmp_path):
    fcntl = pytest.importorskip("fcntl")
    if not hasattr(fcntl, "F_GETPIPE_SZ"):
        pytest.skip("the system cannot size a pipe")
    from achslint.lsp.server import PIPE_SIZE, wide_pipe

    read, write = os.pipe()
    try:
        before = fcntl.fcntl(write, fcntl.F_GETPIPE_SZ)
        wide_pipe(write)
        after = fcntl.fcntl(write, fcntl.F_GETPIPE_SZ)
        allowed = int(Path("/proc/sys/fs/pipe-max-size").read_text())
        assert after == max(before, min(PIPE_SIZE, allowed)) and after > before
    finally:
        os.close(read)
        os.close(write)
    with open(tmp_path / "out", "wb") as file:  # not a pipe: left alone, no error
        wide_pipe(file.fileno())


def test_a_loop_kept_busy_never_starves_a_job(monkeypatch):
    monkeypatch.setattr(worker_module, "PAUSE_LIMIT", 0.02)
    monkeypatch.setattr(worker_module, "JOB_PAUSES", 0.2)
    gate = Gate()
    work = Worker(gate=gate)
    try:
        gate.loop(True)  # and it stays busy
        started = time.perf_counter()

        def job() -> float:
            for _ in range(100):  # a hundred pause points: 2 s if each waited its limit
                engine.pause()
            return time.perf_counter() - started

        took = work.submit(job).result(timeout=10)
        assert 0.2 <= took < 1.0
    finally:
        gate.loop(False)
        work.stop()


def test_the_axis_analysis_gives_way_every_few_hundred_settings():
    # the one stretch of a lint without a rule boundary: on the worker it pauses every PAUSE_EVERY settings
    from achslint.axis.analysis import PAUSE_EVERY, analyse
    from achslint.syntax.parser import parse_text

    text = "".join(f"getriebe[0].vb_reflow  {n}\n" for n in range(4 * PAUSE_EVERY)) + "Ende\n"
    file = parse_text(text, "achsmds1.lis")
    calls: list[int] = []
    engine.pause_between_rules(lambda: calls.append(1))
    try:
        analyse(file)
    finally:
        engine.pause_between_rules(None)
    assert len(calls) == 8  # 4 in resolving the paths, 4 in checking the values
    analyse(file)
    assert len(calls) == 8  # no hook, no pause


def test_bytes_waiting_unread_in_the_input_hold_the_worker(gate: Gate):
    """The worker gives way as soon as the editor's bytes arrive, before the reader thread (which may wait for a
    processor meanwhile) has read them; not at the end of the input, nor once the gate stops watching."""
    read, write = os.pipe()
    stream = open(read, "rb", buffering=0)  # noqa: SIM115 - closed below
    work = Worker(gate=gate)
    try:
        gate.watch(stream)
        assert not gate.busy
        os.write(write, b"Content-Length: 2\r\n\r\n{}")
        time.sleep(2 * worker_module.UNREAD_LOOK)  # (the pause points look at the input that often)
        assert gate.busy
        future = work.submit(lambda: "ran")
        time.sleep(0.1)
        assert not future.done()
        assert stream.read(100)  # the reader takes them
        assert future.result(timeout=5) == "ran"
        assert not gate.busy
        os.write(write, b"more")
        gate.watch(None)
        assert not gate.busy
        gate.watch(stream)
        assert stream.read(100) == b"more"
        os.close(write)  # the end of the input: readable for ever, and no work of the loop's
        write = -1
        time.sleep(2 * worker_module.UNREAD_LOOK)
        assert not gate.busy
        gate.watch(io.BytesIO(b"not a file"))  # nothing to watch
        assert not gate.busy
    finally:
        work.stop()
        stream.close()
        if write >= 0:
            os.close(write)


def test_the_worker_waits_a_moment_after_an_answer(gate: Gate, monkeypatch):
    """The editor's turn to read an answer: the worker keeps off the processor meanwhile."""
    monkeypatch.setattr(worker_module, "ANSWER_TURN", 0.2)
    work = Worker(gate=gate)
    try:
        gate.answered()
        started = time.perf_counter()
        assert gate.busy
        waited = work.submit(lambda: time.perf_counter() - started).result(timeout=5)
        assert waited >= 0.15
        assert not gate.busy
        gate.loop(True)
        gate.answered()  # answered while the loop is busy: the turn follows when the loop gets idle
        future = work.submit(time.perf_counter)
        time.sleep(0.3)
        assert not future.done()
        idle = time.perf_counter()
        gate.loop(False)
        assert future.result(timeout=5) - idle < 0.15  # what was left of the turn, not a whole pause limit
    finally:
        work.stop()


def test_the_worker_thread_runs_as_batch_work_where_the_system_has_it():
    if not hasattr(os, "SCHED_BATCH"):
        pytest.skip("no SCHED_BATCH on this system")
    work = Worker()
    try:
        assert work.submit(lambda: os.sched_getscheduler(0)).result(timeout=5) == os.SCHED_BATCH
    finally:
        work.stop()
    assert os.sched_getscheduler(0) != os.SCHED_BATCH  # the thread that made the worker is left as it was


def test_stopping_ends_a_job_at_its_next_pause_point():
    """The server's exit: a lint held at its pause points (the loop is busy shutting down) ends there, instead of
    waiting out all its pauses (1 s) before the worker can be joined."""
    gate = Gate()  # (each pause waits PAUSE_LIMIT at most, as in the server)
    work = Worker(gate=gate)
    gate.loop(True)
    future = work.submit(lambda: [engine.pause() for _ in range(1000)])
    time.sleep(0.05)
    started = time.perf_counter()
    work.stop(timeout=5)
    assert time.perf_counter() - started < 0.5
    assert future.cancelled() or isinstance(future.exception(timeout=1), Superseded)
