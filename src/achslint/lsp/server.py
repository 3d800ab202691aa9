"""`achslint server`: the language server (stdio), on pygls 2.

The handlers only translate between the protocol and `session` / `features`; no finding,
card or fix is computed here. Three promises shape this module:

- Every message is answered. Our own reader (`protocol.FrameReader`) takes the byte stream
  and skips what is not a message; `dispatch` answers malformed requests with the JSON-RPC
  error they call for (ParseError, InvalidRequest, InvalidParams, ServerNotInitialized, and
  InvalidRequest after `shutdown`) before pygls sees them. Every handler is guarded.
- The message loop never waits for a lint. Lints, fix-all and formatting run on one worker
  thread (`worker.Worker`), which alone touches the `Session`; hover, completion, definition,
  outline and inlay hints answer from the last analysis of the document. A lint whose text
  was edited again before it finished is not published (the newer one follows): it stops at
  its next pause point. The loop goes first: while it has a message to handle (or bytes of one
  wait unread), and for a moment after each answer, the worker waits at its pause points
  (`worker.Gate`). Formatting does not wait for the lint either: each
  document's `fmt.LiveFormat`, made on the worker with its first diagnostics, is brought up to
  date on the loop with the lines edited since the last request (a millisecond for one line of a
  50,000-line list).
- Nothing hostile fills the log: problems are one line each, without tracebacks.
"""

from __future__ import annotations

import asyncio
import contextlib
import functools
import gc
import itertools
import json
import logging
import os
import stat
import sys
import threading
import traceback
from collections.abc import Awaitable, Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, BinaryIO, TypeVar

from lsprotocol import types as lsp
from pygls.io_ import StdoutWriter
from pygls.lsp.server import LanguageServer
from pygls.protocol import LanguageServerProtocol, default_converter
from pygls.protocol.json_rpc import JsonRPCNotification, JsonRPCRequestMessage
from pygls.uris import to_fs_path

from .. import __version__
from ..core.files import is_xml
from ..core.pause import pause
from . import features
from .documents import Document
from .outline import Outline
from .protocol import FrameReader, Skipped
from .session import ClientSettings, Session, Snapshot
from .worker import Gate, Latest, Superseded, WatchedSelector, Worker

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from ..fmt import LiveFormat
    from ..linting.config import FmtOptions
    from ..machine.startup import StartupEntry
    from ..rules.context import Context
    from ..syntax.parser import ListFile

log = logging.getLogger("achslint.lsp")
_T = TypeVar("_T")

# Lists up to this long are formatted on the loop even when every line is formatted again (an edit that changes
# fmt's decisions about the whole file: tens of milliseconds); longer ones on the worker then.
LOOP_FORMAT_LINES = 10_000
FIRST_ANALYSIS_WAIT = 30.0  # seconds a request waits for a document's first lint before answering without it
DRAIN_WAIT = 5.0  # seconds the server waits for running requests when the client's input ends
IDLE_COLLECTION = 2.0  # seconds without a message before the server collects garbage (see run())
COLLECT_AFTER_LINTS = 200  # ... or after this many lints without such a pause
PIPE_SIZE = 1 << 20  # bytes the pipe to the client holds, where the system allows it (`wide_pipe`)
SHOWN_PROBLEMS = 5  # problems of the editor's settings named in the one message that tells them
IN_FLIGHT = 64  # messages read but not yet handled; the reader waits beyond that (a flood cannot fill memory)
_DOCUMENT_SYNC = (lsp.TEXT_DOCUMENT_DID_OPEN, lsp.TEXT_DOCUMENT_DID_CHANGE, lsp.TEXT_DOCUMENT_DID_CLOSE)


def describe(exc: BaseException) -> str:
    """An exception in one line: type, message (shortened) and where it was raised."""
    text = " ".join(str(exc).split())
    text = text if len(text) <= 200 else text[:200] + "..."
    frames = traceback.extract_tb(exc.__traceback__)
    where = f" ({Path(frames[-1].filename).name}:{frames[-1].lineno})" if frames else ""
    return f"{type(exc).__name__}: {text}{where}"


@dataclass(frozen=True)
class RawResult:
    """A request's result written as JSON already (a large outline): sent as it is, not serialised again."""

    json: str


@dataclass
class Analysis:
    """A document's text as it was linted, and what the lint found."""

    generation: int  # which edit of the document this is (newer edits have larger numbers)
    document: Document  # a copy: positions in the findings are positions in this text
    snapshot: Snapshot
    found: list[Diagnostic]
    outline: RawResult | None = None  # its outline, once made (on the worker, or by the first request)


@dataclass(frozen=True)
class _Unreadable:
    """A message body that is not JSON."""

    reason: str


class _Protocol(LanguageServerProtocol):
    def _handle_cancel_notification(self, msg_id: Any) -> None:
        # A request answered already (or unknown) is no news: the protocol lets the client cancel one whose answer
        # is on its way, and editors do while typing; pygls logs a warning line for each.
        if msg_id in self._request_futures:
            super()._handle_cancel_notification(msg_id)

    def _send_response(
        self, msg_id: Any, result: Any | None = None, error: lsp.ResponseError | None = None
    ) -> None:
        assert isinstance(self._server, AchslintServer)
        if error is None and isinstance(result, RawResult):
            self._result_types.pop(msg_id, None)
            body = f'{{"jsonrpc": "2.0", "id": {json.dumps(msg_id)}, "result": {result.json}}}'
            self._server._send(body.encode("utf-8"))
        else:
            super()._send_response(msg_id, result, error)
        self._server._gate.answered()


class AchslintServer(LanguageServer):
    def __init__(self) -> None:
        super().__init__(
            "achslint",
            __version__,
            text_document_sync_kind=lsp.TextDocumentSyncKind.Incremental,
            protocol_cls=_Protocol,
        )
        # pygls keeps its own copy of every document for features we do not use: the editor's text
        # lives once, in `documents`.
        for method in _DOCUMENT_SYNC:
            self.protocol.fm.builtin_features.pop(method, None)
        self.session = Session()  # used on the worker thread only
        self.documents: dict[str, Document] = {}  # the editor's documents, as they are now
        self.generations: dict[str, int] = {}
        self.analyses: dict[str, Analysis] = {}  # the last analysis of each document
        self._edits = itertools.count(1)
        self._timers: dict[str, asyncio.TimerHandle] = {}
        self._waiting: dict[str, list[tuple[int, asyncio.Future[Analysis | None]]]] = {}
        self._to_lint: Latest[tuple[Document, int]] = Latest()
        # fix-all edits and the fixes --fix refuses (`Session.fix_all`), by generation
        self._fixes: dict[str, tuple[int, list[lsp.TextEdit], set[tuple[str, int, int]]]] = {}
        self.formats: dict[str, tuple[int, RawResult]] = {}  # formatting edits by generation
        self._outlines: dict[str, Outline] = {}  # each document's outline, line by line (on the worker)
        # each document's formatting, brought up to date with each request (`format_here`); on the loop, but
        # for the moments the worker works one out (`format_on_worker`)
        self._live: dict[str, LiveFormat] = {}
        # formattings the worker made after a document's first lint, until the loop or a formatting job takes one
        self._made: dict[str, LiveFormat] = {}
        self._formats_made: set[str] = set()  # the documents whose formatting the worker made (on the worker)
        # what the worker is making now for a document's first analysis ("outline", "format"): requests wait
        # for it rather than make it again on the loop or queue a job after the next lint
        self._coming: dict[tuple[str, str], asyncio.Future[None]] = {}
        self._converter = default_converter()  # type: ignore[no-untyped-call]  # the one pygls uses
        self._loop: asyncio.AbstractEventLoop | None = None
        self._worker: Worker | None = None
        self._gate = Gate()  # whether the loop has work: the worker gives way meanwhile
        self._slots = threading.Semaphore(IN_FLIGHT)
        self._done: asyncio.Future[int] | None = None
        self._drain = False  # at the end of the input, answer the requests still running before stopping
        self.initialized = False
        self.stopping = False  # `shutdown` received
        # Seconds without a message after which the garbage collector runs (None: it runs on its own, as
        # in tests). `run()` turns its full collections off: one takes a third of a second with a large
        # list open and would stop the loop in the middle of typing.
        self.collect_when_idle: float | None = None
        self._collector: asyncio.TimerHandle | None = None
        self._uncollected = 0  # lints since the last full collection
        self._warm = False  # the modules the answers import on first use are imported (`_warm_up`)

    # -- client capabilities -------------------------------------------------------------------
    def _text_capabilities(self) -> lsp.TextDocumentClientCapabilities | None:
        try:
            return self.client_capabilities.text_document
        except AttributeError:  # no client capabilities yet (before initialize)
            return None

    def _completion_capabilities(self) -> lsp.CompletionClientCapabilities | None:
        text = self._text_capabilities()
        return text.completion if text is not None else None

    @property
    def markdown(self) -> bool:
        text = self._text_capabilities()
        hover = text.hover if text is not None else None
        formats = hover.content_format if hover is not None else None
        return not formats or lsp.MarkupKind.Markdown in formats

    @property
    def markdown_in_completion(self) -> bool:
        """Whether completion documentation may be Markdown (completionItem.documentationFormat)."""
        completion = self._completion_capabilities()
        item = completion.completion_item if completion is not None else None
        formats = item.documentation_format if item is not None else None
        return not formats or lsp.MarkupKind.Markdown in formats

    @property
    def snippets(self) -> bool:
        completion = self._completion_capabilities()
        item = completion.completion_item if completion is not None else None
        return item is not None and bool(item.snippet_support)

    @property
    def edit_range_default(self) -> bool:
        completion = self._completion_capabilities()
        completion_list = completion.completion_list if completion is not None else None
        defaults = completion_list.item_defaults if completion_list is not None else None
        return defaults is not None and "editRange" in defaults

    @property
    def encoding(self) -> str:
        encoding = self.workspace.position_encoding
        names: dict[str, str] = {
            lsp.PositionEncodingKind.Utf8: "utf-8",
            lsp.PositionEncodingKind.Utf32: "utf-32",
        }
        return names.get(encoding or "", "utf-16")

    # -- serving ---------------------------------------------------------------------------------
    def serve(self, stdin: BinaryIO, stdout: BinaryIO) -> int:
        """Answer the messages of `stdin` on `stdout` until `exit` or the end of the input; the exit code
        (0 after shutdown and exit or at the end of the input, 1 for an exit without shutdown)."""
        self.protocol.set_writer(StdoutWriter(stdout))
        # asyncio.run with a selector that tells the gate when the loop waits (Python 3.10 has no Runner)
        loop = asyncio.SelectorEventLoop(WatchedSelector(self._gate))
        asyncio.set_event_loop(loop)
        try:
            return loop.run_until_complete(self._serve(stdin))
        finally:
            pending = asyncio.all_tasks(loop)
            for task in pending:
                task.cancel()
            loop.run_until_complete(asyncio.gather(*pending, return_exceptions=True))
            loop.run_until_complete(loop.shutdown_asyncgens())
            asyncio.set_event_loop(None)
            loop.close()

    async def _serve(self, stdin: BinaryIO) -> int:
        self._loop = asyncio.get_running_loop()
        self._done = self._loop.create_future()
        self._worker = Worker(gate=self._gate)
        self._gate.watch(stdin)
        threading.Thread(target=self._read, args=(stdin,), name="achslint-reader", daemon=True).start()
        try:
            code = await self._done
            if self._drain:  # the input ended: answer what was asked before it
                pending = asyncio.all_tasks() - {asyncio.current_task()}
                if pending:
                    await asyncio.wait(pending, timeout=DRAIN_WAIT)
                for _ in range(3):  # the answers are sent by callbacks of the finished tasks
                    await asyncio.sleep(0)
            return code
        finally:
            for timer in self._timers.values():
                timer.cancel()
            if self._collector is not None:
                self._collector.cancel()
            self._worker.stop()

    def _finish(self, code: int, drain: bool = False) -> None:
        if self._done is not None and not self._done.done():
            self._drain = drain
            self._done.set_result(code)

    def _read(self, stdin: BinaryIO) -> None:
        """The reader thread: frames from the stream, parsed, handed to the loop together once the stream has no
        more for now.

        Handing each message over at once woke the loop for an edit while the request sent right behind it
        (a hover after a keystroke, the same read) was still to be parsed: the reader then waited for the
        processor behind the loop and the lint that the edit started, milliseconds on a busy machine."""
        loop = self._loop
        assert loop is not None
        batch: list[object] = []

        def hand_over() -> None:
            if batch:
                loop.call_soon_threadsafe(self._receive_all, batch.copy())
                batch.clear()

        reader = FrameReader(stdin, waiting=hand_over)
        try:
            while True:
                frame = reader.next()
                if frame is None:
                    break
                self._gate.read()
                item: object
                if isinstance(frame, Skipped):
                    item = frame
                else:
                    try:
                        item = json.loads(frame)
                    except (ValueError, RecursionError) as exc:
                        item = _Unreadable(describe(exc))
                if not self._slots.acquire(blocking=False):  # the loop is behind: it has these first
                    hand_over()
                    self._slots.acquire()
                batch.append(item)
        except (OSError, ValueError) as exc:  # the stream broke (or was closed)
            log.warning("achslint: stopped reading the client: %s", describe(exc))
        except RuntimeError:  # the loop has closed: the server stopped
            return
        finally:
            self._gate.watch(None)  # (at the end, the input stays readable: it no longer means work)
        with contextlib.suppress(RuntimeError):  # the loop has closed meanwhile
            hand_over()
            loop.call_soon_threadsafe(self._finish, 0, True)

    def _idle_later(self) -> None:
        """(Re)start the wait for a quiet moment to collect garbage in."""
        if self.collect_when_idle is None or self._loop is None:
            return
        if self._collector is not None:
            self._collector.cancel()
        self._collector = self._loop.call_later(self.collect_when_idle, self._collect)

    def _collect(self) -> None:
        self._collector = None
        if self._worker is not None and not self._worker.idle:
            self._idle_later()  # a lint is running: not a quiet moment yet
            return
        self._uncollected = 0
        gc.collect()

    def _receive_all(self, items: list[object]) -> None:
        for item in items:
            try:
                self._receive(item)
            except Exception as exc:  # (the next messages are handled all the same)
                log.error("achslint: cannot handle a message: %s", describe(exc))

    def _receive(self, item: object) -> None:
        self._slots.release()
        self._gate.taken()
        self._idle_later()
        try:
            if isinstance(item, Skipped):
                log.warning("achslint: %s", item.reason)
                if item.refused:
                    self.window_show_message(
                        lsp.ShowMessageParams(lsp.MessageType.Warning, f"achslint: {item.reason}")
                    )
            elif isinstance(item, _Unreadable):
                log.warning("achslint: a message is not JSON: %s", item.reason)
                self._reply_error(None, lsp.ErrorCodes.ParseError, f"the message is not JSON: {item.reason}")
            else:
                self.dispatch(item)
        except OSError as exc:  # the client is gone (broken pipe)
            log.warning("achslint: cannot write to the client: %s", describe(exc))
            self._finish(1)

    def _send(self, body: bytes) -> None:
        """Write one message (its JSON) to the client, framed; on the loop, like everything pygls sends."""
        writer = self.protocol.writer
        if writer is not None:
            writer.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)

    def _reply_error(self, msg_id: int | str | None, code: int, message: str) -> None:
        error = {"jsonrpc": "2.0", "id": msg_id, "error": {"code": int(code), "message": message}}
        self._send(json.dumps(error).encode("utf-8"))

    def dispatch(self, raw: object) -> None:
        """Check one message and hand it to pygls, or answer it with the error it calls for."""
        if not isinstance(raw, dict):
            kind = "a batch" if isinstance(raw, list) else f"a JSON {type(raw).__name__}"
            log.warning("achslint: ignored %s where a message object belongs", kind)
            self._reply_error(None, lsp.ErrorCodes.InvalidRequest, f"{kind} is not a JSON-RPC message")
            return
        method, msg_id = raw.get("method"), raw.get("id")
        has_id = "id" in raw
        good_id = isinstance(msg_id, (int, str)) and not isinstance(msg_id, bool)
        answer_to = msg_id if good_id else None
        if (
            raw.get("jsonrpc") != "2.0"
            or (has_id and not good_id)
            or not isinstance(method, (str, type(None)))
        ):
            log.warning("achslint: ignored a message that is not JSON-RPC 2.0")
            self._reply_error(answer_to, lsp.ErrorCodes.InvalidRequest, "not a JSON-RPC 2.0 message")
            return
        if method is None:
            if not has_id:
                self._reply_error(None, lsp.ErrorCodes.InvalidRequest, "a message needs a method or an id")
            elif _is_response(raw):
                self._handle(raw, None)  # the client's answer to a request of ours
            else:  # a response is not answered: told in the log only
                log.warning("achslint: ignored a response without a result or a well-formed error")
            return
        request = has_id
        if method == lsp.EXIT:
            self._finish(0 if self.stopping else 1)
            return
        refusal = self._refusal(method)
        if refusal is not None:
            code, why = refusal
            if request:
                self._reply_error(answer_to, code, why)
            return
        if self._handle(raw, method) and request:
            if method == lsp.INITIALIZE:
                self.initialized = True
            elif method == lsp.SHUTDOWN:
                self.stopping = True
                for timer in self._timers.values():
                    timer.cancel()
                self._timers.clear()

    def _refusal(self, method: str) -> tuple[int, str] | None:
        """Why a message cannot be handled now (error code and words), or None."""
        if self.stopping:
            return lsp.ErrorCodes.InvalidRequest, f"{method}: the server is shutting down"
        if method == lsp.INITIALIZE and self.initialized:
            return lsp.ErrorCodes.InvalidRequest, "the server is already initialized"
        if method != lsp.INITIALIZE and not self.initialized:
            return lsp.ErrorCodes.ServerNotInitialized, f"{method}: the server is not initialized yet"
        return None

    def _handle(self, raw: dict[str, Any], method: str | None) -> bool:
        """Structure the message as lsprotocol types and let pygls route it; False when its params do not
        fit (a request gets InvalidParams)."""
        msg_id = raw.get("id")
        try:
            if method is None:
                message = self.protocol.structure_message(raw)
            else:
                known = self.protocol.get_message_type(method)
                if known is None:  # a method lsprotocol does not know: pygls answers MethodNotFound
                    raw = {"params": None, **raw}
                fallback = JsonRPCRequestMessage if "id" in raw else JsonRPCNotification
                message = self._converter.structure(raw, known or fallback)
        except Exception as exc:
            why = _invalid(exc)
            log.warning("achslint: ignored %s: invalid params: %s", method or "a response", why)
            if method is not None and "id" in raw:
                self._reply_error(msg_id, lsp.ErrorCodes.InvalidParams, f"invalid params for {method}: {why}")
            return False
        try:
            self.protocol.handle_message(message)
        except OSError:
            raise
        except Exception as exc:
            log.error("achslint: %s failed: %s", method, describe(exc))
            if method is not None and "id" in raw:
                self._reply_error(msg_id, lsp.ErrorCodes.InternalError, f"{method} failed: {describe(exc)}")
            return False
        return True

    # -- the worker ------------------------------------------------------------------------------
    def run_on_worker(self, job: Callable[[], _T]) -> Awaitable[_T]:
        """Run `job` on the worker thread (after the work queued before it); awaitable on the loop."""
        assert self._worker is not None
        return asyncio.wrap_future(self._worker.submit(job))

    def on_worker(self, job: Callable[[], object]) -> None:
        """Queue `job` on the worker without waiting for it."""
        if self._worker is not None:
            self._worker.submit(job)

    # -- diagnostics -----------------------------------------------------------------------------
    def edited(self, uri: str) -> None:
        """The document's text changed: it needs a new analysis."""
        self.generations[uri] = next(self._edits)

    def schedule(self, uri: str, delay_ms: int | None = None) -> None:
        """Lint the document's newest text: at once by default (the worker takes it as soon as the lint before
        it is done; a text edited again meanwhile is replaced, not linted), after the editor's `debounceMs`
        when it set one (restarted by every edit)."""
        delay = self.session.settings.debounce_ms if delay_ms is None else delay_ms
        timer = self._timers.pop(uri, None)
        if timer is not None:
            timer.cancel()
        if delay <= 0 or self._loop is None:
            self.lint(uri)
            return
        self._timers[uri] = self._loop.call_later(delay / 1000, self.lint, uri)

    def lint(self, uri: str) -> None:
        """Queue a lint of the document's current text (replacing one not started yet)."""
        timer = self._timers.pop(uri, None)
        if timer is not None:
            timer.cancel()
        document = self.documents.get(uri)
        if document is None or self._worker is None or self.stopping:
            return
        if self._to_lint.put(uri, (document.copy(), self.generations[uri])):
            self._worker.submit(functools.partial(self._lint_now, uri))

    def lint_all(self) -> None:
        """Lint every open document again (settings or files changed): fix-all edits computed under the
        old ones no longer hold."""
        self._fixes.clear()
        self.formats.clear()  # a configuration's [fmt] may have changed
        for uri in list(self.documents):
            self.lint(uri)

    def _lint_now(self, uri: str) -> None:
        """On the worker: lint the newest text asked for, then hand the result to the loop."""
        taken = self._to_lint.take(uri)
        if taken is None:
            return  # closed meanwhile
        document, generation = taken
        analysis: Analysis | None = None
        peers: list[str] = []
        worker = self._worker
        assert worker is not None
        try:  # whatever fails, the loop hears back: requests waiting for this analysis must not hang
            self.session.open(document)
            # Edited again (and linted before): the newer text is linted next, this lint stops where it is.
            with worker.superseded_when(lambda: uri in self.analyses and self._to_lint.waiting(uri)):
                snapshot, found, peers = self.session.diagnostics(uri)
            if snapshot is not None:
                analysis = Analysis(generation, document, snapshot, found)
            if self._to_lint.waiting(uri):  # a newer text is queued: its lint publishes, not this one
                self._hand_over(uri, generation, analysis, None, [])
                return
            pause()  # (the loop first, again: the findings are converted and written out next)
            diagnostics = features.publishable(document, snapshot, found)
        except Superseded:
            self._hand_over(uri, generation, None, None, [])
            return
        except Exception as exc:
            log.error("achslint: cannot lint %s: %s", uri, describe(exc))
            diagnostics = [
                lsp.Diagnostic(
                    lsp.Range(lsp.Position(0, 0), lsp.Position(0, 1)),
                    f"achslint could not check this document: internal error {describe(exc)}",
                    lsp.DiagnosticSeverity.Error,
                    source="achslint",
                )
            ]
        # Written out here, not on the loop: a thousand findings take tens of milliseconds to serialise (one by
        # one, giving way to the loop now and then).
        params = self._converter.unstructure(
            lsp.PublishDiagnosticsParams(uri=uri, diagnostics=[], version=document.version)
        )
        for number, diagnostic in enumerate(diagnostics):
            if not number % 64:
                pause()
            params["diagnostics"].append(self._converter.unstructure(diagnostic))
        message = {"jsonrpc": "2.0", "method": lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS, "params": params}
        # The outline, which the editor asks for after each edit: made before the loop has the analysis, so it
        # answers at once (2 ms for a 2,000-line list, the lines an edit did not touch are kept); the first of
        # a document (all its lines: 12 ms there, 250 ms for 50,000 lines) after its diagnostics are out.
        first = uri not in self._outlines
        if analysis is not None and not first:
            analysis.outline = self._outline(uri, analysis)
        if analysis is not None and analysis.snapshot.file is not None:
            features.paths_for_completion(analysis.snapshot.file)  # what completion ranks by, likewise
        body = json.dumps(self._converter.unstructure(message)).encode("utf-8")
        make_outline = analysis is not None and first and analysis.snapshot.file is not None
        make_format = analysis is not None and uri not in self._formats_made and not is_xml(document.name)
        # Requests that come meanwhile wait for them: told before the diagnostics go out.
        for what, making in (("outline", make_outline), ("format", make_format)):
            if making:
                self._coming_soon(what, uri)
        if make_format:
            self._make_format(uri, document)
        self._hand_over(uri, generation, analysis, body, peers)
        if not self._warm:  # (first: a request may come while the outline is made)
            self._warm = True
            self._warm_up(analysis)
        if make_outline and analysis is not None:
            outline = None
            try:
                outline = self._outline(uri, analysis)
            finally:  # (whatever happens, a request waiting for it is answered)
                self._arrived("outline", uri, lambda: self._outlined(analysis, outline))

    def _make_format(self, uri: str, document: Document) -> None:
        """On the worker, after a document's first lint: its formatting, made once and then brought up to date
        on the loop with each request (a few milliseconds for a one-line edit of 50,000 lines); made on
        request, it would wait for the lint (or, on the loop, hold up other answers). Made before the first
        diagnostics go out (a tenth of a second for 50,000 lines, the lines parsed already), not after them
        with the outline: the editor asks for formatting right after the diagnostics, and would wait for
        both."""
        self._formats_made.add(uri)
        try:
            live = self._made[uri] = self._new_format(document)
            live.update(document.body_lines)
        except Exception as exc:  # (the diagnostics go out all the same; a request makes it on the worker)
            self._made.pop(uri, None)
            log.error("achslint: cannot format %s: %s", uri, describe(exc))
        finally:
            self._arrived("format", uri, lambda: self._formatted_ready(uri))

    def _outline(self, uri: str, analysis: Analysis) -> RawResult | None:
        """On the worker: the analysis's outline as JSON (`outline.Outline` rewrites only the lines changed
        since the last one: 2 ms for a 2,000-line list, a few tens for 50,000 lines)."""
        file = analysis.snapshot.file
        if file is None or is_xml(analysis.document.name):
            return None
        return RawResult(self._outlines.setdefault(uri, Outline()).json(analysis.document, file))

    def _outlined(self, analysis: Analysis, outline: RawResult | None) -> None:
        if analysis.outline is None:
            analysis.outline = outline

    def _coming_soon(self, what: str, uri: str) -> None:
        """On the worker: the document's `what` is made next; requests for it wait (`until_made`)."""
        if self._loop is not None:
            self._loop.call_soon_threadsafe(self._expect, (what, uri))

    def _arrived(self, what: str, uri: str, keep: Callable[[], None]) -> None:
        """On the worker: the document's `what` is made; on the loop, `keep` keeps it, and the requests that
        waited for it go on."""

        def arrived() -> None:
            keep()
            coming = self._coming.pop((what, uri), None)
            if coming is not None and not coming.done():
                coming.set_result(None)

        if self._loop is not None:
            self._loop.call_soon_threadsafe(arrived)

    def _expect(self, key: tuple[str, str]) -> None:
        if key[1] in self.documents and self._loop is not None and key not in self._coming:
            self._coming[key] = self._loop.create_future()

    async def until_made(self, what: str, uri: str) -> bool:
        """Wait until the worker has made the document's `what`, if it is making it now; whether it was."""
        coming = self._coming.get((what, uri))
        if coming is None:
            return False
        with contextlib.suppress(asyncio.TimeoutError):  # (not TimeoutError before Python 3.11)
            await asyncio.wait_for(asyncio.shield(coming), FIRST_ANALYSIS_WAIT)
        return True

    # -- formatting --------------------------------------------------------------------------------
    def _new_format(self, document: Document, options: FmtOptions | None = None) -> LiveFormat:
        """A document's formatting (`fmt.LiveFormat`), with `[fmt]` of its configuration (as `achslint fmt`
        formats), parsing lines with the document's cache (the lines its lints parsed)."""
        from ..fmt import LiveFormat

        if options is None:
            options = self.session.config_for(document)[0].settings.fmt
        return LiveFormat(options, document.cache.line)

    def _formatted_ready(self, uri: str, live: LiveFormat | None = None) -> None:
        """On the loop: a formatting the worker worked out is kept (unless a newer one is kept already): the
        one given, or the one it made after a document's first lint (if no formatting job took it first)."""
        if live is None:
            live = self._made.pop(uri, None)
        if live is not None and uri in self.documents:
            self._live.setdefault(uri, live)

    def format_here(self, document: Document, options: FmtOptions) -> LiveFormat | None:
        """On the loop: the document's formatting, brought up to date with the edits since its last use when
        they leave fmt's decisions about the whole file standing or the list is short (`LOOP_FORMAT_LINES`);
        None when the worker is to work it out."""
        uri = document.uri
        short = document.line_count <= LOOP_FORMAT_LINES
        live = self._live.get(uri)
        if live is None or live.options != options:
            if not short:
                return None
            live = self._live[uri] = self._new_format(document, options)
        return live if live.update(document.body_lines, full=short) else None

    async def format_on_worker(self, document: Document, options: FmtOptions) -> tuple[Document, LiveFormat]:
        """The document's formatting worked out on the worker (after the work queued before), with the text it
        is of; kept for the next requests."""
        uri = document.uri
        kept = self._live.pop(uri, None)  # the worker's alone until it is done
        copy = document.copy()

        def job() -> LiveFormat:
            made = self._made.pop(
                uri, None
            )  # the one made after the first lint, if the loop has not taken it
            live = next((one for one in (kept, made) if one is not None and one.options == options), None)
            live = live or self._new_format(copy, options)
            live.update(copy.body_lines)
            return live

        live = await self.run_on_worker(job)
        self._formatted_ready(uri, live)
        return copy, live

    def _warm_up(self, analysis: Analysis | None) -> None:
        """After the first diagnostics, on the worker: import what the answers import on first use, fill the
        caches a hover card reads (one card of the list), and let the converters make their code for the
        requests and answers (cattrs writes it on first use): the first hover would otherwise take the loop 5
        to 15 ms longer than the next."""
        from .. import explanation, fmt  # noqa: F401
        from ..homing import registry  # noqa: F401

        file = analysis.snapshot.file if analysis is not None else None
        if analysis is not None and file is not None and not is_xml(analysis.document.name):
            kind = features.document_kind(analysis.snapshot)
            line = next((line for line in file.lines if line.path and line.path_ok), None)
            if line is not None:
                with contextlib.suppress(Exception):  # only a head start
                    features.hover_text(analysis.snapshot.context, file, line.number, 1, self.markdown, kind)

        span = {"start": {"line": 0, "character": 0}, "end": {"line": 0, "character": 1}}
        where = lsp.Range(lsp.Position(0, 0), lsp.Position(0, 1))
        params = {
            "textDocument": {"uri": "file:///warm-up/achsmds1.lis", "version": 1},
            "contentChanges": [{"range": span, "text": "1"}],
            "position": span["start"],
            "range": span,
            "options": {"tabSize": 4, "insertSpaces": True},
            "context": {"diagnostics": [], "triggerKind": 1},  # (completion and code action contexts)
        }
        edit = lsp.TextEdit(where, "")
        answers: dict[str, object] = {
            lsp.TEXT_DOCUMENT_HOVER: lsp.Hover(lsp.MarkupContent(lsp.MarkupKind.Markdown, "")),
            lsp.TEXT_DOCUMENT_COMPLETION: lsp.CompletionList(
                True,
                [lsp.CompletionItem("x", kind=lsp.CompletionItemKind.Field, filter_text="x", text_edit=edit)],
                item_defaults=lsp.CompletionItemDefaults(edit_range=where),
            ),
            lsp.TEXT_DOCUMENT_FORMATTING: [edit],
            lsp.TEXT_DOCUMENT_RANGE_FORMATTING: [edit],
            lsp.TEXT_DOCUMENT_DEFINITION: [lsp.Location("file:///warm-up/achsmds1.lis", where)],
            lsp.TEXT_DOCUMENT_CODE_ACTION: [
                lsp.CodeAction(
                    "x",
                    kind=lsp.CodeActionKind.QuickFix,
                    diagnostics=[lsp.Diagnostic(where, "x")],
                    edit=lsp.WorkspaceEdit(changes={"file:///warm-up/achsmds1.lis": [edit]}),
                )
            ],
            lsp.TEXT_DOCUMENT_INLAY_HINT: [lsp.InlayHint(lsp.Position(0, 0), "x")],
            lsp.TEXT_DOCUMENT_DOCUMENT_SYMBOL: [],
            lsp.TEXT_DOCUMENT_DID_CHANGE: None,  # a notification: structured only
        }
        protocol = self.protocol
        for method, answer in answers.items():
            asked, answered = protocol.get_message_type(method), protocol.get_result_type(method)
            with contextlib.suppress(Exception):  # only a head start: whatever fails is made on first use
                if asked is not None:
                    message = {"jsonrpc": "2.0", "method": method, "params": params}
                    self._converter.structure(message if answered is None else {"id": 0, **message}, asked)
                if answered is not None:
                    protocol._converter.unstructure(answered(id=0, result=answer))

    def _hand_over(
        self, uri: str, generation: int, analysis: Analysis | None, published: bytes | None, peers: list[str]
    ) -> None:
        if self._loop is not None:
            self._loop.call_soon_threadsafe(self._linted, uri, generation, analysis, published, peers)

    def _linted(
        self, uri: str, generation: int, analysis: Analysis | None, published: bytes | None, peers: list[str]
    ) -> None:
        """On the loop: keep the analysis, publish it unless the text changed meanwhile."""
        self._uncollected += 1
        if self.collect_when_idle is not None and self._uncollected >= COLLECT_AFTER_LINTS:
            self._uncollected = 0
            gc.collect()  # never quiet for long: collect now and then anyway
        else:
            self._idle_later()
        if uri not in self.documents:
            return
        last = self.analyses.get(uri)
        if analysis is not None and (last is None or analysis.generation >= last.generation):
            self.analyses[uri] = analysis
            self.documents[uri].adopt_lines(analysis.document)
        self._wake(uri, generation)
        if published is None or generation != self.generations.get(uri) or self.stopping:
            return  # stale: the lint of the newer text follows
        self._send(published)
        for peer in peers:  # other open lists of the machine whose machine findings changed with this one
            self.lint(peer)

    def _wake(self, uri: str, generation: int | None) -> None:
        """Answer the requests that waited for an analysis of this generation (all of them when None)."""
        waiting = self._waiting.pop(uri, [])
        still = []
        for wanted, future in waiting:
            if generation is None or wanted <= generation:
                if not future.done():
                    future.set_result(self.analyses.get(uri))
            else:
                still.append((wanted, future))
        if still:
            self._waiting[uri] = still

    async def analysis(self, uri: str, current: bool = False) -> Analysis | None:
        """The document's last analysis (waiting for the first one); with `current`, one of its text as it
        is now (linted at once if need be: fixes and formatting must not act on an older text)."""
        if uri not in self.documents or self._loop is None:
            return None
        wanted = self.generations[uri] if current else 0
        found = self.analyses.get(uri)
        if found is not None and found.generation >= wanted:
            return found
        if current:
            self.lint(uri)
        future: asyncio.Future[Analysis | None] = self._loop.create_future()
        self._waiting.setdefault(uri, []).append((wanted, future))
        try:
            return await asyncio.wait_for(future, FIRST_ANALYSIS_WAIT)
        except asyncio.TimeoutError:  # (not TimeoutError before Python 3.11)
            return None

    async def fix_all_edits(self, analysis: Analysis) -> tuple[list[lsp.TextEdit], set[tuple[str, int, int]]]:
        """The edits of every safe fix in the analysed text, and the findings whose fix the lint calls safe
        but `--fix` refuses (computed once per text, on the worker)."""
        uri = analysis.document.uri
        cached = self._fixes.get(uri)
        if cached is not None and cached[0] == analysis.generation:
            return cached[1], cached[2]
        document, session = analysis.document, self.session

        def edits() -> tuple[list[lsp.TextEdit], set[tuple[str, int, int]]]:
            fixed, refused = session.fix_all(document)
            return (features.diff_edits(document, fixed) if fixed is not None else [], set(refused))

        found, refused = await self.run_on_worker(edits)
        if uri in self.documents:
            self._fixes[uri] = (analysis.generation, found, refused)
        return found, refused

    def close(self, uri: str) -> Document | None:
        document = self.documents.pop(uri, None)
        timer = self._timers.pop(uri, None)
        if timer is not None:
            timer.cancel()
        self._to_lint.drop(uri)
        self.generations.pop(uri, None)
        self.analyses.pop(uri, None)
        self._fixes.pop(uri, None)
        self.formats.pop(uri, None)
        self._live.pop(uri, None)
        self._made.pop(uri, None)
        for what in ("outline", "format"):
            coming = self._coming.pop((what, uri), None)
            if coming is not None and not coming.done():
                coming.set_result(None)
        self._wake(uri, None)
        session, outlines = self.session, self._outlines

        def closed() -> None:
            session.close(uri)
            outlines.pop(uri, None)
            self._formats_made.discard(uri)
            self._made.pop(uri, None)

        self.on_worker(closed)
        return document

    def forget_disk(self) -> None:
        """Files or configurations changed on disk: the worker reads them again (before its next lint)."""
        session = self.session
        self.on_worker(session.forget_disk)


def create() -> AchslintServer:
    """A language server with every feature registered (one per process; tests make several)."""
    ls = AchslintServer()
    for method, options, handler in _FEATURES:
        ls.feature(method, options)(handler)
    return ls


_FEATURES: list[tuple[str, object, Callable[..., Any]]] = []
_Handler = TypeVar("_Handler", bound=Callable[..., Any])


def feature(method: str, options: object = None) -> Callable[[_Handler], _Handler]:
    def register(handler: _Handler) -> _Handler:
        _FEATURES.append((method, options, handler))
        return handler

    return register


def guarded(default: Callable[[], object] | None = None) -> Callable[[_Handler], _Handler]:
    """Answer `default()` (or None) instead of failing when a handler meets something unexpected (one line
    on stderr)."""

    def fallback(handler: Callable[..., Any], exc: Exception) -> object:
        log.error("achslint: %s failed: %s", handler.__name__, describe(exc))
        return default() if default is not None else None

    def wrap(handler: _Handler) -> _Handler:
        if asyncio.iscoroutinefunction(handler):

            @functools.wraps(handler)
            async def run_async(ls: AchslintServer, params: object) -> object:
                try:
                    return await handler(ls, params)
                except Exception as exc:
                    return fallback(handler, exc)

            return run_async  # type: ignore[return-value]

        @functools.wraps(handler)
        def run(ls: AchslintServer, params: object) -> object:
            try:
                return handler(ls, params)
            except Exception as exc:
                return fallback(handler, exc)

        return run  # type: ignore[return-value]

    return wrap


def _is_response(raw: dict[str, Any]) -> bool:
    """A JSON-RPC response: a result, or an error with a number and words (what pygls can read)."""
    if "error" not in raw:
        return "result" in raw
    error = raw["error"]
    return (
        isinstance(error, dict)
        and isinstance(error.get("code"), int)
        and not isinstance(error.get("code"), bool)
        and isinstance(error.get("message"), str)
    )


def _invalid(exc: Exception) -> str:
    """What is wrong with a message's params, in one line."""
    from cattrs import transform_error
    from cattrs.errors import ClassValidationError

    if isinstance(exc, ClassValidationError):
        return "; ".join(transform_error(exc)[:3])
    return describe(exc)


def _take_settings(ls: AchslintServer, raw: object) -> None:
    """Use the editor's settings; codes that pick no rule are told to the user (and not used)."""
    ls.session.settings = ClientSettings.from_dict(raw)
    ls.session.settings_changed()
    problems = ls.session.settings.problems
    if problems:  # one message, however many codes are wrong (each its own pop-up would bury the editor)
        shown = problems[:SHOWN_PROBLEMS]
        more = len(problems) - len(shown)
        text = "; ".join(shown) + (f"; and {more} more" if more else "")
        ls.window_show_message(lsp.ShowMessageParams(lsp.MessageType.Warning, text))


def _path(uri: str) -> Path | None:
    """The file a document's URI names on this system; None (the document is checked as an unsaved buffer)
    when it names none: another scheme, a NUL (file:///a%00b), or a path that is not absolute here. On POSIX a
    Windows drive (file:///C:/x) or a URI without its slashes (file:x) would be a path relative to the
    server's working folder, and a remote host (file://server/share) `//server/...`: files outside the
    workspace, read as the document's own."""
    if not uri.startswith("file:"):
        return None
    if os.name != "nt" and uri.startswith("file://"):
        host, _, rest = uri[len("file://") :].partition("/")
        if host.lower() == "localhost":  # file://localhost/p is file:///p (RFC 8089)
            uri = "file:///" + rest
        elif host:
            return None
    try:
        path = to_fs_path(uri)
    except Exception:
        return None
    if not path or "\0" in path or not Path(path).is_absolute():
        return None
    return Path(path)


@feature(lsp.INITIALIZE)
@guarded()
def initialize(ls: AchslintServer, params: lsp.InitializeParams) -> None:
    _take_settings(ls, params.initialization_options or {})
    folders = params.workspace_folders or []
    root = _path(folders[0].uri) if folders else (_path(params.root_uri) if params.root_uri else None)
    ls.session.root = root


@feature(lsp.TEXT_DOCUMENT_DID_OPEN)
@guarded()
def did_open(ls: AchslintServer, params: lsp.DidOpenTextDocumentParams) -> None:
    item = params.text_document
    if item.uri in ls.documents:
        ls.close(item.uri)  # opened again without a close: the new text counts
    ls.documents[item.uri] = Document(item.uri, _path(item.uri), item.text, item.version, ls.encoding)
    ls.edited(item.uri)
    ls.lint(item.uri)


@feature(lsp.TEXT_DOCUMENT_DID_CHANGE)
@guarded()
def did_change(ls: AchslintServer, params: lsp.DidChangeTextDocumentParams) -> None:
    document = ls.documents.get(params.text_document.uri)
    if document is None:
        return
    for change in params.content_changes:
        if isinstance(change, lsp.TextDocumentContentChangePartial):
            start, end = change.range.start, change.range.end
            document.apply((start.line, start.character), (end.line, end.character), change.text)
        else:
            document.apply(None, None, change.text)
    document.version = params.text_document.version
    ls.edited(document.uri)
    ls.schedule(document.uri)


@feature(lsp.TEXT_DOCUMENT_DID_SAVE)
@guarded()
def did_save(ls: AchslintServer, params: lsp.DidSaveTextDocumentParams) -> None:
    uri = params.text_document.uri
    if uri.endswith(".toml"):
        ls.forget_disk()
        ls.lint_all()
    elif uri in ls.documents:
        ls.forget_disk()  # the saved list is now what its neighbours see on disk
        ls.edited(uri)
        ls.schedule(uri, 0)


@feature(lsp.TEXT_DOCUMENT_DID_CLOSE)
@guarded()
def did_close(ls: AchslintServer, params: lsp.DidCloseTextDocumentParams) -> None:
    uri = params.text_document.uri
    document = ls.close(uri)
    ls.text_document_publish_diagnostics(lsp.PublishDiagnosticsParams(uri=uri, diagnostics=[]))
    if document is not None and document.path is not None:
        # Its neighbours now see the file on disk instead of the buffer.
        near = {document.path.parent, document.path.parent.parent}
        ls.forget_disk()
        for other in list(ls.documents.values()):
            if other.path is not None and other.path.parent in near:
                ls.lint(other.uri)


@feature(lsp.WORKSPACE_DID_CHANGE_CONFIGURATION)
@guarded()
def did_change_configuration(ls: AchslintServer, params: lsp.DidChangeConfigurationParams) -> None:
    hints = ls.session.settings.inlay_hints
    if isinstance(params.settings, dict) and params.settings:
        _take_settings(ls, params.settings)
    ls.forget_disk()
    ls.lint_all()
    if ls.session.settings.inlay_hints != hints and _inlay_refresh(ls):
        # the editor keeps the hints it has (none, or the old ones) until it is asked to fetch them again
        ls.workspace_inlay_hint_refresh(None)


def _inlay_refresh(ls: AchslintServer) -> bool:
    """Whether the client takes `workspace/inlayHint/refresh` (its workspace capability says so)."""
    try:
        hints = ls.client_capabilities.workspace.inlay_hint  # type: ignore[union-attr]
    except AttributeError:
        return False
    return bool(hints is not None and hints.refresh_support)


@feature(lsp.WORKSPACE_DID_CHANGE_WATCHED_FILES)
@guarded()
def did_change_watched_files(ls: AchslintServer, params: lsp.DidChangeWatchedFilesParams) -> None:
    ls.forget_disk()
    ls.lint_all()


# -- requests ---------------------------------------------------------------------------------------


def _xml_target(
    session: Session, document: Document, line: int, column: int
) -> tuple[Context | None, ListFile, int, int] | None:
    """The embedded list, its context and the list position under an XML position (TwinCAT CDATA, ISG XML).
    Lints the embedded list: runs on the worker."""
    from ..core.decode import UnreadableInput
    from ..linting.linter import lint_parsed
    from ..syntax.parser import parse_text
    from ..syntax.xmlinput import extract
    from .session import xml_bytes

    try:
        lists = extract(xml_bytes(document.text), document.name)
    except UnreadableInput:
        return None
    for embedded in lists:
        count = len(embedded.text.splitlines()) + 1
        for number in range(1, count + 1):
            xml_line, xml_column = embedded.position(number, 1)
            if xml_line != line:
                continue
            file = parse_text(embedded.text, document.name)
            config, _ = session.config_for(document)
            result = lint_parsed(
                file, document.name, session.file_settings(config, document.path, document.name)
            )
            list_column = 1 if embedded.line_map is not None else column - xml_column + 1
            return result.context, file, number, max(list_column, 1)
    return None


@feature(lsp.TEXT_DOCUMENT_HOVER)
@guarded()
async def hover(ls: AchslintServer, params: lsp.HoverParams) -> lsp.Hover | None:
    from ..syntax.parser import parse_text

    uri = params.text_document.uri
    analysis = await ls.analysis(uri)
    document = ls.documents.get(uri)
    if document is None or analysis is None:
        return None
    line, column = document.from_lsp(params.position.line, params.position.character)
    context: Context | None
    file: ListFile | None
    kind = features.document_kind(analysis.snapshot)
    if is_xml(document.name):
        copy, session = document.copy(), ls.session
        found = await ls.run_on_worker(lambda: _xml_target(session, copy, line, column))
        if found is None:
            return None
        context, file, line, column = found
    else:
        context, file = analysis.snapshot.context, analysis.snapshot.file
        if file is None and analysis.snapshot.startup:  # a start-up list is not parsed by its lint
            copy = document.copy()
            file = await ls.run_on_worker(lambda: parse_text(copy.text, copy.name))
    text = features.hover_text(context, file, line, column, ls.markdown, kind)
    if not text:
        return None
    markup = lsp.MarkupKind.Markdown if ls.markdown else lsp.MarkupKind.PlainText
    return lsp.Hover(lsp.MarkupContent(markup, text))


@feature(
    lsp.TEXT_DOCUMENT_COMPLETION,
    lsp.CompletionOptions(trigger_characters=[".", "[", " ", ":", ","], resolve_provider=True),
)
@guarded()
async def completion(ls: AchslintServer, params: lsp.CompletionParams) -> lsp.CompletionList | None:
    uri = params.text_document.uri
    analysis = await ls.analysis(uri)
    document = ls.documents.get(uri)
    if document is None or is_xml(document.name):
        return None
    line, column = document.from_lsp(params.position.line, params.position.character)
    snapshot = analysis.snapshot if analysis is not None else None
    return features.complete(document, snapshot, line, column, ls.snippets, ls.edit_range_default)


@feature(lsp.COMPLETION_ITEM_RESOLVE)
@guarded(default=None)
def completion_resolve(ls: AchslintServer, item: lsp.CompletionItem) -> lsp.CompletionItem:
    return features.resolve_item(item, ls.markdown_in_completion)


@feature(
    lsp.TEXT_DOCUMENT_CODE_ACTION,
    lsp.CodeActionOptions(
        code_action_kinds=[lsp.CodeActionKind.QuickFix, features.FIX_ALL, lsp.CodeActionKind.SourceFixAll]
    ),
)
@guarded(default=list)
async def code_action(ls: AchslintServer, params: lsp.CodeActionParams) -> list[lsp.CodeAction]:
    uri = params.text_document.uri
    analysis = await ls.analysis(uri, current=True)
    if analysis is None or analysis.generation != ls.generations.get(uri):
        return []  # no analysis of the text as it is now: an edit computed on another text could land anywhere
    snapshot, found = analysis.snapshot, analysis.found
    edits: list[lsp.TextEdit] = []
    refused: set[tuple[str, int, int]] = set()
    if snapshot.file is not None and any(d.fix is not None and d.fix.applicability == "safe" for d in found):
        edits, refused = await ls.fix_all_edits(analysis)
    return features.code_actions(
        analysis.document, snapshot, found, params.range, params.context.only, lambda: edits, refused
    )


async def _formatting(ls: AchslintServer, uri: str) -> tuple[Document, LiveFormat] | None:
    """The formatting of the document's text as it is now (a list of any kind, not XML) and that text, without
    waiting for its lint: brought up to date on the loop (`AchslintServer.format_here`), else on the worker."""
    document = ls.documents.get(uri)
    if document is None or is_xml(document.name):
        return None
    # The configuration is read through caches that are safe to share with the worker (lru_cache).
    options = ls.session.config_for(document)[0].settings.fmt  # `[fmt]`: as `achslint fmt` formats
    live = ls.format_here(document, options)
    if live is None and await ls.until_made("format", uri):  # sooner than a job after the next lint
        document = ls.documents.get(uri)
        if document is None:
            return None
        live = ls.format_here(document, options)
    return (document, live) if live is not None else await ls.format_on_worker(document, options)


@feature(lsp.TEXT_DOCUMENT_FORMATTING)
@guarded(default=list)
async def formatting(
    ls: AchslintServer, params: lsp.DocumentFormattingParams
) -> list[lsp.TextEdit] | RawResult:
    uri = params.text_document.uri
    generation = ls.generations.get(uri)
    cached = ls.formats.get(uri)
    if cached is not None and cached[0] == generation:
        return cached[1]
    found = await _formatting(ls, uri)
    if found is None:
        return []
    edits = RawResult(features.format_edits_json(found[0], found[1].changes()))
    if generation is not None and uri in ls.documents:
        ls.formats[uri] = (generation, edits)
    return edits


@feature(lsp.TEXT_DOCUMENT_RANGE_FORMATTING)
@guarded(default=list)
async def range_formatting(
    ls: AchslintServer, params: lsp.DocumentRangeFormattingParams
) -> list[lsp.TextEdit]:
    found = await _formatting(ls, params.text_document.uri)
    return features.format_range(*found, params.range) if found is not None else []


async def _list_analysis(ls: AchslintServer, uri: str) -> Analysis | None:
    """The last analysis of an open axis list (not XML, not a start-up list)."""
    analysis = await ls.analysis(uri)
    if analysis is None or analysis.snapshot.file is None or is_xml(analysis.document.name):
        return None
    return analysis


@feature(lsp.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
@guarded(default=list)
async def document_symbol(
    ls: AchslintServer, params: lsp.DocumentSymbolParams
) -> list[lsp.DocumentSymbol] | RawResult:
    """`features.document_symbols`, written as JSON by `outline.Outline`: made on the worker with each
    analysis (`_lint_now`), here only when it is not made yet."""
    uri = params.text_document.uri
    analysis = await _list_analysis(ls, uri)
    if analysis is None or analysis.snapshot.file is None or uri not in ls.documents:
        return []
    if analysis.outline is None and await ls.until_made("outline", uri):
        analysis = ls.analyses.get(uri, analysis)  # (made for the analysis it waited for, or a newer one)
    if analysis.outline is None and analysis.snapshot.file is not None:
        analysis.outline = RawResult(Outline().json(analysis.document, analysis.snapshot.file))
    return analysis.outline or []


@feature(lsp.TEXT_DOCUMENT_DEFINITION)
@guarded(default=list)
async def definition(ls: AchslintServer, params: lsp.DefinitionParams) -> list[lsp.Location]:
    from ..syntax.parser import parse_text

    uri = params.text_document.uri
    analysis = await ls.analysis(uri)
    document = ls.documents.get(uri)
    if document is None or analysis is None or is_xml(document.name):
        return []
    line, column = document.from_lsp(params.position.line, params.position.character)
    snapshot = analysis.snapshot
    # A start-up list's lines as they are now (its lint may not parse them, or may be of an older text).
    if snapshot.startup and (snapshot.file is None or snapshot.text != document.text):
        copy = document.copy()
        parsed = await ls.run_on_worker(lambda: parse_text(copy.text, copy.name))
        snapshot = Snapshot(snapshot.version, copy.text, snapshot.result, parsed, startup=True)

    def entries() -> list[StartupEntry]:  # as `achslint lint` resolves them (the configured CNC root)
        return ls.session.startup_entries(document)

    return features.definition(document, snapshot, line, column, entries)


@feature(lsp.TEXT_DOCUMENT_INLAY_HINT)
@guarded(default=list)
async def inlay_hint(ls: AchslintServer, params: lsp.InlayHintParams) -> list[lsp.InlayHint]:
    if not ls.session.settings.inlay_hints:
        return []
    analysis = await ls.analysis(params.text_document.uri)
    if analysis is None or is_xml(analysis.document.name):
        return []
    return features.inlay_hints(analysis.document, analysis.snapshot, params.range)


class _OneLine(logging.Filter):
    """Every log record in one line: an exception is named with where it was raised, never a traceback
    (pygls logs some with theirs), and a message is cut at its first line break."""

    def filter(self, record: logging.LogRecord) -> bool:
        message = record.getMessage()
        if record.exc_info and record.exc_info[1] is not None:
            message = f"{message.splitlines()[0] if message else ''}: {describe(record.exc_info[1])}"
        first = message.splitlines()[0] if message else ""
        record.msg, record.args = first[:1000], None
        record.exc_info, record.exc_text, record.stack_info = None, None, None
        return True


def quiet_collector() -> None:
    """No automatic full garbage collections: the server runs them when it is idle. A lint makes no cyclic
    garbage, and the young generations are still collected as usual; a full collection with a large list
    open takes a third of a second, and during a lint several would stop the loop (and, over a growing
    heap, make linting a large list slower than linear)."""
    gc.set_threshold(700, 10, 1 << 30)


def wide_pipe(fd: int, size: int = PIPE_SIZE) -> None:
    """Let a pipe to the client hold `size` bytes (Linux; elsewhere, or when the system allows less, it stays
    as it is). An outline or the diagnostics of a long list are hundreds of kilobytes: through the usual
    64 KB the loop writes them in pieces, waiting for the client to read each one and then for the worker to
    hand the interpreter back."""
    try:
        import fcntl  # not on Windows
    except ImportError:
        return
    set_size = getattr(fcntl, "F_SETPIPE_SZ", None)
    if set_size is None:
        return
    with contextlib.suppress(OSError):
        if stat.S_ISFIFO(os.fstat(fd).st_mode):
            fcntl.fcntl(fd, set_size, size)


server = create()


def run() -> None:
    """Serve on standard input and output until the client says exit."""
    handler = logging.StreamHandler()
    handler.setFormatter(logging.Formatter("%(message)s"))
    handler.addFilter(_OneLine())
    logging.basicConfig(level=logging.WARNING, handlers=[handler])
    # The loop gets the interpreter back quickly where the worker has no pause point (0.2 ms rather than 1 ms:
    # a hover in the middle of a lint 3 -> 1.5 ms median)
    sys.setswitchinterval(0.0002)
    quiet_collector()
    wide_pipe(sys.stdout.fileno())
    server.collect_when_idle = IDLE_COLLECTION
    # The reader thread reads the descriptor itself: blocked in sys.stdin's buffer, it would hold that buffer's
    # lock when the interpreter exits, which aborts the process.
    stdin = open(sys.stdin.fileno(), "rb", buffering=0, closefd=False)  # noqa: SIM115 - open while serving
    sys.exit(server.serve(stdin, sys.stdout.buffer))
