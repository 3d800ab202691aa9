#!/usr/bin/env python
"""The language server's budgets (`benchmarks/run` runs this as its `lsp` part).

    python benchmarks/lsp.py [--quick]

- diagnostics after a one-character edit of a 2,000-line list: the server's own work for the
  edit (apply the change, parse the edited line, lint, machine rules, LSP conversion), median,
  against Lark's bare parse of the same text (tree only, our grammar);
- hover on a parameter and completion of a path and of a symbol on that list, median, the
  answer serialised as the server sends it;
- the server process's resident memory after opening 100 typical lists (250 lines, in ten
  folders of ten axes) over stdio, once every list's diagnostics arrived;
- for information, the same edit end to end through a real server process (stdio, JSON-RPC,
  debounce 0): from sending the change to receiving its diagnostics;
- formatting and fix-all edits of a list of n and 2n bytes (1 MB at full size; the line diff that
  turns the result into edits, in-process): doubling the list at most 2.6 times the time;
- LIS101 on a list of 1,000 distinct unknown names (the closest-name search), in-process;
- a hover sent while that list is linted again, over stdio: answered from the last analysis;
- a 50,000-line list in a fresh server process: a hover while it is linted again, the server's
  resident memory, and the size of its diagnostics message (capped at 1,000 findings);
- as a client sees them (issue 28): a server process with the editor's default settings and a
  client's capabilities, a 2,000-line list typed into (bursts of keystrokes 40 ms apart): from the
  last keystroke to its diagnostics, and hover, completion, formatting and outline asked right after
  a keystroke (worst case, not median); then a 50,000-line list: how long each of those requests
  waits while the list is linted again (the first round of them right after the list was opened, when
  the server makes its outline and formatting once: shown apart as well).
"""

from __future__ import annotations

import argparse
import gc
import json
import os
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from generate import axis_list

BUDGET_DIAGNOSTICS_MS = 50
BUDGET_ANSWER_MS = 20
BUDGET_MEMORY_MB = 300
BUDGET_DOUBLING = 2.6  # time(2n) / time(n); 2 is linear, 4 would be quadratic
BUDGET_UNKNOWN_S = 0.5  # LIS101 on 1,000 distinct unknown names
BUDGET_HOVER_WHILE_LINT_MS = 50
BUDGET_LARGE_MEMORY_MB = 300  # a server with a 50,000-line list open
BUDGET_DIAGNOSTICS_BYTES = 1_000_000  # one publishDiagnostics message
# As a client sees them (issue 28), a 2,000-line list: worst case of each, milliseconds
BUDGET_CLIENT_MS = {"diagnostics": 50, "hover": 5, "completion": 20, "formatting": 50, "outline": 20}
BUDGET_LARGE_WAIT_MS = 50  # a 50,000-line list: no request waits longer
KEYSTROKE_GAP = 0.04  # seconds between two keystrokes of a burst (a fast typist)
CLIENT_CAPABILITIES = {  # what an editor announces (Neovim 0.11's, abridged)
    "general": {"positionEncodings": ["utf-16"]},
    "textDocument": {
        "synchronization": {"didSave": True, "dynamicRegistration": False},
        "hover": {"contentFormat": ["markdown", "plaintext"]},
        "completion": {
            "completionItem": {"snippetSupport": True, "documentationFormat": ["markdown", "plaintext"]},
            "completionList": {"itemDefaults": ["editRange", "insertTextFormat", "insertTextMode", "data"]},
        },
        "documentSymbol": {"hierarchicalDocumentSymbolSupport": True},
        "publishDiagnostics": {"relatedInformation": True, "versionSupport": True},
    },
}


def verdict(ok: bool) -> str:
    return "ok" if ok else "OVER BUDGET"


def median_ms(samples: list[float]) -> float:
    return statistics.median(samples) * 1000


def bare_parse_ms(text: str, runs: int) -> float:
    from lark import Lark

    from achslint.syntax.parser import _grammar_text

    bare = Lark(_grammar_text(), parser="lalr", lexer="contextual", maybe_placeholders=False)
    samples = []
    for _ in range(runs):
        start = time.perf_counter()
        bare.parse(text)
        samples.append(time.perf_counter() - start)
    return median_ms(samples)


def in_process(runs: int) -> bool:
    from lsprotocol import converters

    from achslint.lsp import features
    from achslint.lsp.documents import Document
    from achslint.lsp.session import Session

    converter = converters.get_converter()

    def sent(answer) -> str:  # what the server puts on the wire
        return json.dumps(converter.unstructure(answer))

    folder = Path(tempfile.mkdtemp(prefix="achslint-lsp-bench-"))
    path = folder / "achsmds1.lis"
    text = axis_list(2000)
    path.write_text(text, encoding="utf-8")
    session = Session(folder)
    document = Document(path.as_uri(), path, text, 1)
    session.open(document)
    snapshot, found, _ = session.diagnostics(document.uri)  # the first lint (not timed)
    features.publishable(document, snapshot, found)
    lines = document.lines
    target = next(i for i, line in enumerate(lines) if line.split()[1:2] and line.split()[1].isdigit())
    column = len(lines[target]) - 1

    edit_samples = []
    for run in range(runs):
        start = time.perf_counter()
        digit = str(run % 10)
        document.apply((target, column), (target, column + 1), digit)  # one character
        snapshot, found, _ = session.diagnostics(document.uri)
        sent(features.publishable(document, snapshot, found))
        edit_samples.append(time.perf_counter() - start)
    edit = median_ms(edit_samples)
    bare = bare_parse_ms(document.text, max(5, runs // 4))
    ok_edit = edit <= BUDGET_DIAGNOSTICS_MS
    print(f"language server, a {len(lines) - 1:,}-line list ({len(found)} findings)")
    print(
        f"  diagnostics after a one-character edit   {edit:7.1f} ms median "
        f"(budget <= {BUDGET_DIAGNOSTICS_MS} ms)  -> {verdict(ok_edit)}"
    )
    print(
        f"  Lark bare parse of the whole text         {bare:7.1f} ms  (edit / bare parse = {edit / bare:.2f})"
    )

    snapshot = session.snapshot(document.uri)
    symbol_line = next(i for i, line in enumerate(lines) if line.startswith("kenngr.homing.homing_type"))
    path_line = target  # a numeric parameter with a unit

    def hover():
        from lsprotocol import types as lsp

        text_ = features.hover_text(snapshot.context, snapshot.file, path_line + 1, 3)
        assert text_ and "In this list" in text_, text_
        return sent(lsp.Hover(lsp.MarkupContent(lsp.MarkupKind.Markdown, text_ or "")))

    typing = Document(
        document.uri + "-typing",
        None,
        "\n".join("getriebe[0].vb_re" if i == path_line else line for i, line in enumerate(lines)),
        1,
    )
    session.open(typing)
    typing_snapshot = session.snapshot(typing.uri)

    def completed(line: int, column: int, wanted: str, where=document, current=snapshot) -> str:
        answer = features.complete(where, current, line + 1, column)
        assert any(item.label == wanted for item in answer.items), wanted
        return sent(answer)

    def complete_path():  # the line's path cut after `vb_re`, as if being typed
        return completed(
            path_line, len("getriebe[0].vb_re") + 1, "getriebe[0].vb_reflow", typing, typing_snapshot
        )

    def complete_top():
        return completed(path_line, 1, "kenngr.homing.homing_type")

    value_start = lines[symbol_line].index(lines[symbol_line].split()[1]) + 1  # nothing typed: every symbol

    def complete_symbol():
        return completed(symbol_line, value_start, "CNC_CONTROLLED")

    ok = ok_edit
    for label, call in (
        ("hover on a parameter (card, value, effect)", hover),
        ("completion of getriebe[0].vb_re", complete_path),
        ("completion at a line start (all paths)", complete_top),
        ("completion of a symbol value", complete_symbol),
    ):
        call()
        samples = []
        for _ in range(runs):
            start = time.perf_counter()
            call()
            samples.append(time.perf_counter() - start)
        took = median_ms(samples)
        ok = ok and took <= BUDGET_ANSWER_MS
        print(
            f"  {label:<44} {took:6.2f} ms (budget <= {BUDGET_ANSWER_MS} ms)  -> {verdict(took <= BUDGET_ANSWER_MS)}"
        )
    return ok


class Client:
    """A minimal LSP client over a server process's stdio."""

    def __init__(self, command: list[str]):
        self.process = subprocess.Popen(
            command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL
        )
        self.published: dict[str, tuple[float, int | None]] = {}
        self.sizes: dict[str, int] = {}  # bytes of the last diagnostics message per document
        self.responses: dict[int, dict] = {}
        self.lock = threading.Condition()
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()
        self.next_id = 0

    def _read(self) -> None:
        stream = self.process.stdout
        while True:
            length = None
            while True:
                header = stream.readline()
                if not header:
                    return
                if header in (b"\r\n", b"\n"):
                    break
                if header.lower().startswith(b"content-length:"):
                    length = int(header.split(b":")[1])
            body = stream.read(length)
            message = json.loads(body)
            with self.lock:
                if message.get("method") == "textDocument/publishDiagnostics":
                    params = message["params"]
                    self.published[params["uri"]] = (time.perf_counter(), params.get("version"))
                    self.sizes[params["uri"]] = len(body)
                elif "id" in message and "method" not in message:
                    self.responses[message["id"]] = message
                self.lock.notify_all()

    def send(self, message: dict) -> None:
        body = json.dumps({"jsonrpc": "2.0", **message}).encode("utf-8")
        self.process.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.process.stdin.flush()

    def request(self, method: str, params: dict) -> dict:
        self.next_id += 1
        number = self.next_id
        self.send({"id": number, "method": method, "params": params})
        with self.lock:
            self.lock.wait_for(lambda: number in self.responses, timeout=120)
            return self.responses.pop(number)

    def wait(self, check, timeout: float = 300) -> None:
        with self.lock:
            if not self.lock.wait_for(check, timeout=timeout):
                raise SystemExit("the server did not answer in time")

    def rss_mb(self) -> float:
        for line in Path(f"/proc/{self.process.pid}/status").read_text().splitlines():
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
        return float("nan")

    def close(self) -> None:
        try:
            self.request("shutdown", None)
            self.send({"method": "exit"})
            self.process.wait(timeout=10)
        except Exception:
            self.process.kill()


def server_process(lists: int, runs: int) -> bool:
    folder = Path(tempfile.mkdtemp(prefix="achslint-lsp-memory-"))
    client = Client([sys.executable, "-m", "achslint", "server"])
    client.request(
        "initialize",
        {
            "processId": os.getpid(),
            "rootUri": folder.as_uri(),
            "capabilities": {},
            "initializationOptions": {"debounceMs": 0},
        },
    )
    client.send({"method": "initialized", "params": {}})
    uris = []
    for number in range(lists):
        machine = folder / f"machine{number // 10}"
        machine.mkdir(exist_ok=True)
        path = machine / f"achsmds{number % 10 + 1}.lis"
        text = axis_list(250, seed=number + 1)
        path.write_text(text, encoding="utf-8")
        uris.append(path.as_uri())
        client.send(
            {
                "method": "textDocument/didOpen",
                "params": {
                    "textDocument": {
                        "uri": path.as_uri(),
                        "languageId": "achsmds",
                        "version": 1,
                        "text": text,
                    }
                },
            }
        )
    started = time.perf_counter()
    client.wait(lambda: all(uri in client.published for uri in uris))
    opened = time.perf_counter() - started
    time.sleep(0.5)
    rss = client.rss_mb()
    ok = rss <= BUDGET_MEMORY_MB
    print(f"language server process, {lists} lists of 250 lines open ({lists // 10} machines of 10 axes)")
    print(f"  resident memory   {rss:7.1f} MB (budget <= {BUDGET_MEMORY_MB} MB)  -> {verdict(ok)}")
    print(f"  all diagnostics published {opened:5.2f} s after the last didOpen was sent")

    big = folder / "big" / "achsmds1.lis"
    big.parent.mkdir()
    text = axis_list(2000)
    big.write_text(text, encoding="utf-8")
    uri = big.as_uri()
    client.send(
        {
            "method": "textDocument/didOpen",
            "params": {"textDocument": {"uri": uri, "languageId": "achsmds", "version": 1, "text": text}},
        }
    )
    client.wait(lambda: uri in client.published)
    lines = text.splitlines()
    target = next(i for i, line in enumerate(lines) if line.split()[1:2] and line.split()[1].isdigit())
    column = len(lines[target]) - 1
    samples = []
    for run in range(runs):
        version = run + 2
        sent = time.perf_counter()
        client.send(
            {
                "method": "textDocument/didChange",
                "params": {
                    "textDocument": {"uri": uri, "version": version},
                    "contentChanges": [
                        {
                            "range": {
                                "start": {"line": target, "character": column},
                                "end": {"line": target, "character": column + 1},
                            },
                            "text": str(run % 10),
                        }
                    ],
                },
            }
        )
        client.wait(lambda version=version: client.published.get(uri, (0, None))[1] == version)
        samples.append(client.published[uri][0] - sent)
    print(
        f"  end to end (stdio, 2,000-line list, debounce 0): change -> diagnostics  {median_ms(samples):6.1f} ms median "
        "(information)"
    )
    client.close()
    return ok


def unknown_list(count: int, round_: int = 0) -> str:
    """`count` distinct unknown names: catalogue names with one letter changed and a number added (another
    number each round, so a new lint searches again instead of finding its earlier answers)."""
    import random

    from achslint.catalogue import catalogue

    rng = random.Random(7)
    names = list(catalogue()._candidates)
    lines = ["kopf.achs_nr 1"]
    for number in range(count):
        name = rng.choice(names).replace("[i]", "[0]")
        at = rng.randrange(len(name))
        lines.append(
            f"{name[:at]}{rng.choice('abcdefghijklmnopqrstuvwxyz')}{name[at + 1 :]}_{round_}_{number} 1"
        )
    return "\n".join([*lines, "Ende", ""])


def doubling(label: str, small: float, large: float) -> float:
    ratio = large / max(small, 1e-4)
    print(f"  {label:<44} {small * 1000:8.1f} ms -> {large * 1000:8.1f} ms  ({ratio:4.2f} x)")
    return ratio if large > 0.005 else 0.0  # below 5 ms the ratio is noise


def edits_linear(size: int) -> bool:
    """Formatting and fix-all edits (the server's own work for them) at n and 2n bytes, in-process, with the
    server's garbage collector settings; CPU time of this process (the ratio is about how the work grows,
    and other programs on a shared machine do not count in it)."""
    from achslint.lsp import features
    from achslint.lsp.documents import Document
    from achslint.lsp.server import quiet_collector
    from achslint.lsp.session import Session

    quiet_collector()

    def real_list(n: int) -> str:  # generated lists, comments out of their column: every line formatted
        return axis_list(n // 90).replace("        ( ", "  ( ")

    def repeated(n: int) -> str:  # two lines over and over, spaced two ways: half of them formatted
        return "kopf.achs_nr    1\nkopf.achs_nr 1\n" * (n // 32) + "Ende\n"

    def misspelt_end(text: str) -> str:  # one safe fix (LIS004) at the end of a long list
        return text[: text.rindex("Ende")] + "End\n"

    session = Session()

    def timed(text: str, fix: bool) -> float:
        samples: list[float] = []
        while len(samples) < 3 and sum(samples) < 2.0:  # slow cases: fewer repetitions
            document = Document("file:///bench/achsmds1.lis", None, text, 1)
            start = time.process_time()
            if fix:
                fixed = session.fixed_text(document)
                assert fixed is not None
                edits = features.diff_edits(document, fixed)
            else:
                edits = features.format_document(document)
            samples.append(time.process_time() - start)
            assert edits
        return statistics.median(samples)

    print(f"formatting and fix-all edits at n = {size:,} bytes and 2n (in-process, CPU time)")
    timed(real_list(size // 8), False)  # imports and caches: not part of the first figure
    worst = 0.0
    for label, make, fix in (
        ("format: generated list, comments moved", real_list, False),
        ("format: two lines repeated", repeated, False),
        ("fix all: generated list ending in End", lambda n: misspelt_end(real_list(n)), True),
        ("fix all: two lines repeated, then End", lambda n: misspelt_end(repeated(n)), True),
    ):
        worst = max(worst, doubling(label, timed(make(size), fix), timed(make(2 * size), fix)))
    ok = worst <= BUDGET_DOUBLING
    print(f"  worst doubling {worst:.2f} x (linear is 2, budget <= {BUDGET_DOUBLING})  -> {verdict(ok)}")
    return ok


def unknown_names() -> bool:
    """LIS101 on 1,000 distinct unknown names (the closest-name search), in-process, searched afresh each run."""
    from achslint.catalogue import catalogue
    from achslint.linting.linter import lint_file

    data = unknown_list(1000).encode("ascii")
    samples = []
    for _ in range(3):
        catalogue()._suggestions.clear()
        start = time.perf_counter()
        result = lint_file(data, "achsmds1.lis")
        samples.append(time.perf_counter() - start)
    took = statistics.median(samples)
    found = sum(1 for d in result.diagnostics if d.code == "LIS101")
    ok = took <= BUDGET_UNKNOWN_S
    print(f"LIS101, a list of 1,000 distinct unknown names ({found} findings), in-process")
    print(f"  lint            {took:7.3f} s median (budget <= {BUDGET_UNKNOWN_S} s)  -> {verdict(ok)}")
    return ok


def _open(client: Client, uri: str, text: str) -> None:
    item = {"uri": uri, "languageId": "achsmds", "version": 1, "text": text}
    client.send({"method": "textDocument/didOpen", "params": {"textDocument": item}})
    client.wait(lambda: uri in client.published)


def _started(folder: Path) -> Client:
    client = Client([sys.executable, "-m", "achslint", "server"])
    client.request(
        "initialize",
        {
            "processId": os.getpid(),
            "rootUri": folder.as_uri(),
            "capabilities": {},
            "initializationOptions": {"debounceMs": 0},
        },
    )
    client.send({"method": "initialized", "params": {}})
    return client


def hover_while_linting(
    client: Client, uri: str, changes: list[dict], line: int = 0
) -> tuple[list[float], list[float], int]:
    """Make each change in turn and hover while the document is linted: the hover times, the lint times
    (change -> diagnostics) and how many hovers were answered before the lint ended."""
    hovers, lints, overlapped = [], [], 0
    where = {"textDocument": {"uri": uri}, "position": {"line": line, "character": 2}}  # on kopf.achs_nr
    for version, change in enumerate(changes, 2):
        sent = time.perf_counter()
        client.send(
            {
                "method": "textDocument/didChange",
                "params": {
                    "textDocument": {"uri": uri, "version": version},
                    "contentChanges": [change],
                },
            }
        )
        time.sleep(0.02)  # the worker has taken the lint
        asked = time.perf_counter()
        answer = client.request("textDocument/hover", where)
        answered = time.perf_counter()
        assert "kopf.achs_nr" in json.dumps(answer.get("result")), answer
        with client.lock:
            done = client.published.get(uri, (0.0, None))
        overlapped += done[1] != version or done[0] > answered
        hovers.append(answered - asked)
        client.wait(lambda version=version: client.published.get(uri, (0, None))[1] == version)
        lints.append(client.published[uri][0] - sent)
    return hovers, lints, overlapped


def busy_server(runs: int) -> bool:
    """Hovers while a slow lint runs, memory and diagnostics size with a 50,000-line list (fresh processes)."""
    folder = Path(tempfile.mkdtemp(prefix="achslint-lsp-busy-"))
    ok = True

    client = _started(folder)
    uri = (folder / "unknown" / "achsmds1.lis").as_uri()
    _open(client, uri, unknown_list(1000))
    renamed = [{"text": unknown_list(1000, r + 1)} for r in range(runs)]  # all names new: searched again
    hovers, lints, overlapped = hover_while_linting(client, uri, renamed)
    client.close()
    hover = median_ms(hovers)
    good = hover <= BUDGET_HOVER_WHILE_LINT_MS
    ok = ok and good
    print("language server process, busy")
    print(
        f"  hover while 1,000 unknown names are linted  {hover:6.1f} ms median, worst {max(hovers) * 1000:.1f} ms "
        f"(budget <= {BUDGET_HOVER_WHILE_LINT_MS} ms)  -> {verdict(good)}"
    )
    print(
        f"    (lint {median_ms(lints):.0f} ms median; {overlapped} of {len(hovers)} hovers answered before it ended)"
    )

    client = _started(folder)
    uri = (folder / "large" / "achsmds1.lis").as_uri()
    text = axis_list(50_000)
    started = time.perf_counter()
    _open(client, uri, text)
    first = time.perf_counter() - started
    column = text.splitlines()[1].index("1 ")  # the axis number, typed over (the editor sends the edit)
    typed = [
        {
            "range": {"start": {"line": 1, "character": column}, "end": {"line": 1, "character": column + 1}},
            "text": str(n % 9 + 1),
        }
        for n in range(1, max(3, runs // 5) + 1)
    ]
    hovers, lints, overlapped = hover_while_linting(client, uri, typed, line=1)
    rss = client.rss_mb()
    size = client.sizes[uri]
    client.close()
    hover = median_ms(hovers)
    good_hover = hover <= BUDGET_HOVER_WHILE_LINT_MS
    good_memory = rss <= BUDGET_LARGE_MEMORY_MB
    good_size = size <= BUDGET_DIAGNOSTICS_BYTES
    ok = ok and good_hover and good_memory and good_size
    print(
        f"  a 50,000-line list: first diagnostics after {first:.1f} s, a new lint takes {median_ms(lints) / 1000:.1f} s"
    )
    print(
        f"  hover while it is linted                    {hover:6.1f} ms median, worst {max(hovers) * 1000:.1f} ms "
        f"(budget <= {BUDGET_HOVER_WHILE_LINT_MS} ms)  -> {verdict(good_hover)}"
    )
    print(
        f"  resident memory   {rss:7.1f} MB (budget <= {BUDGET_LARGE_MEMORY_MB} MB)  -> {verdict(good_memory)}"
    )
    print(
        f"  diagnostics message {size / 1e6:5.2f} MB (budget <= {BUDGET_DIAGNOSTICS_BYTES / 1e6:.0f} MB)  "
        f"-> {verdict(good_size)}"
    )
    return ok


def _typed(uri: str, version: int, line: int, character: int, text: str, length: int = 0) -> dict:
    end = {"line": line, "character": character + length}
    change = {"range": {"start": {"line": line, "character": character}, "end": end}, "text": text}
    return {
        "method": "textDocument/didChange",
        "params": {"textDocument": {"uri": uri, "version": version}, "contentChanges": [change]},
    }


def _client_requests(uri: str, path_line: int, value_line: int) -> dict[str, tuple[str, dict]]:
    document = {"uri": uri}
    return {
        "hover": (
            "textDocument/hover",
            {"textDocument": document, "position": {"line": path_line, "character": 3}},
        ),
        "completion": (
            "textDocument/completion",
            {
                "textDocument": document,
                "position": {"line": value_line, "character": len("getriebe[0].vb_re")},
            },
        ),
        "formatting": (
            "textDocument/formatting",
            {"textDocument": document, "options": {"tabSize": 4, "insertSpaces": True}},
        ),
        "outline": ("textDocument/documentSymbol", {"textDocument": document}),
    }


def as_a_client_sees_it(bursts: int) -> bool:
    """The budgets of issue 28, timed at the client's end of a server process started as an editor starts
    it (no settings: the defaults), with a client's capabilities. This client's own garbage collector is
    off meanwhile: reading a 460 KB outline, it stopped the client for 30 ms now and then, a pause of this
    Python client that an editor does not have. For the same reason each answer is freed before the next
    request is timed: assigning the hover's answer freed the outline read before it, 1.3-1.6 ms of this
    client's time inside the hover's."""
    gc.disable()
    try:
        return _as_a_client_sees_it(bursts)
    finally:
        gc.enable()


def _as_a_client_sees_it(bursts: int) -> bool:
    folder = Path(tempfile.mkdtemp(prefix="achslint-lsp-client-"))
    client = Client([sys.executable, "-m", "achslint", "server"])
    client.request(
        "initialize",
        {"processId": os.getpid(), "rootUri": folder.as_uri(), "capabilities": CLIENT_CAPABILITIES},
    )
    client.send({"method": "initialized", "params": {}})
    path = folder / "achsmds1.lis"
    text = axis_list(2000)
    lines = text.splitlines()
    value_line = len(lines)  # a line typed at the end, before Ende: `getriebe[0].vb_re`
    lines.insert(len(lines) - 1, "getriebe[0].vb_re")
    text = "\n".join(lines) + "\n"
    path.write_text(text, encoding="utf-8")
    uri = path.as_uri()
    _open(client, uri, text)
    value_line = lines.index("getriebe[0].vb_re")
    path_line = next(i for i, line in enumerate(lines) if line.split()[1:2] and line.split()[1].isdigit())
    column = len(lines[path_line]) - 1
    requests = _client_requests(uri, path_line, value_line)
    taken: dict[str, list[float]] = {name: [] for name in ["diagnostics", *requests]}
    version = 1
    for burst in range(bursts):
        for key in range(6):  # a burst of keystrokes on a value: one digit typed over
            version += 1
            client.send(_typed(uri, version, path_line, column, str((burst + key) % 10), 1))
            last = time.perf_counter()
            time.sleep(KEYSTROKE_GAP)
        client.wait(lambda version=version: client.published.get(uri, (0, None))[1] == version)
        taken["diagnostics"].append(client.published[uri][0] - last)
        for name, (method, params) in requests.items():  # each asked right after a keystroke
            version += 1
            client.send(_typed(uri, version, path_line, column, str(burst % 10), 1))
            asked = time.perf_counter()
            answer = client.request(method, params)
            taken[name].append(time.perf_counter() - asked)
            assert "error" not in answer, answer
            if name == "completion":
                items = answer["result"]["items"] if isinstance(answer["result"], dict) else answer["result"]
                assert any(item["label"] == "getriebe[0].vb_reflow" for item in items), items[:3]
            del answer  # freed here, not in the next request's timing (see the docstring)
            client.wait(lambda version=version: client.published.get(uri, (0, None))[1] == version)
    client.close()
    ok = True
    load = ", ".join(f"{value:.2f}" for value in os.getloadavg())
    print(
        f"as a client sees them: a server process with the default settings, a 2,000-line list (load {load})"
    )
    for name, samples in taken.items():
        worst = max(samples) * 1000
        budget = BUDGET_CLIENT_MS[name]
        good = worst <= budget
        ok = ok and good
        label = (
            "last keystroke -> diagnostics" if name == "diagnostics" else f"{name} right after a keystroke"
        )
        print(
            f"  {label:<40} {worst:6.1f} ms worst, {median_ms(samples):6.1f} ms median "
            f"(budget <= {budget} ms)  -> {verdict(good)}"
        )

    client = Client([sys.executable, "-m", "achslint", "server"])
    client.request(
        "initialize",
        {"processId": os.getpid(), "rootUri": folder.as_uri(), "capabilities": CLIENT_CAPABILITIES},
    )
    client.send({"method": "initialized", "params": {}})
    large = folder / "large" / "achsmds1.lis"
    large.parent.mkdir()
    lines = axis_list(50_000).splitlines()
    lines.insert(len(lines) - 1, "getriebe[0].vb_re")
    text = "\n".join(lines) + "\n"
    large.write_text(text, encoding="utf-8")
    uri = large.as_uri()
    _open(client, uri, text)
    value_line = lines.index("getriebe[0].vb_re")
    column = lines[1].index("1 ")
    waits: dict[str, list[float]] = {name: [] for name in requests}
    version = 1
    for run in range(max(2, bursts // 2)):
        for name, (method, params) in _client_requests(uri, 1, value_line).items():
            version += 1
            client.send(_typed(uri, version, 1, column, str(run % 9 + 1), 1))
            time.sleep(0.05)  # the lint of the edit has begun
            asked = time.perf_counter()
            answer = client.request(method, params)
            waits[name].append(time.perf_counter() - asked)
            assert "error" not in answer, answer
            del answer
        client.wait(lambda version=version: client.published.get(uri, (0, None))[1] == version)
    client.close()
    worst_name, worst = max(
        ((name, max(samples)) for name, samples in waits.items()), key=lambda pair: pair[1]
    )
    good = worst * 1000 <= BUDGET_LARGE_WAIT_MS
    ok = ok and good
    print(
        "  a 50,000-line list, each request while it is linted again (the first: right after it was opened):"
    )
    for name, samples in waits.items():
        print(
            f"    {name:<12} {max(samples) * 1000:7.1f} ms worst, {median_ms(samples):7.1f} ms median, "
            f"{samples[0] * 1000:7.1f} ms first, {max(samples[1:]) * 1000:7.1f} ms worst after it"
        )
    print(
        f"  longest wait {worst * 1000:.1f} ms ({worst_name}; budget <= {BUDGET_LARGE_WAIT_MS} ms)  -> {verdict(good)}"
    )
    return ok


def main() -> int:
    parser = argparse.ArgumentParser(description="Measure the language server against its budgets.")
    parser.add_argument("--quick", action="store_true", help="fewer repetitions")
    parser.add_argument("--client", action="store_true", help="only the budgets as a client sees them")
    args = parser.parse_args()
    try:
        import pygls.lsp.server  # noqa: F401
    except ImportError:
        print("language server: SKIPPED (pip install 'achslint[lsp]' to measure it)")
        return 0
    runs = 15 if args.quick else 41
    if args.client:
        return 0 if as_a_client_sees_it(4 if args.quick else 10) else 1
    ok = in_process(runs)
    print()
    ok = server_process(100, runs) and ok
    print()
    ok = edits_linear(1 << 18 if args.quick else 1 << 20) and ok
    print()
    ok = unknown_names() and ok
    print()
    ok = busy_server(5 if args.quick else 15) and ok
    print()
    ok = as_a_client_sees_it(4 if args.quick else 10) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
