"""The rules' shared walks and the parse by line take shortcuts; each test here works the answer out the long
way and compares.

A rule context lists the known settings once (`Context.known`) and the ones with value facts once
(`Context.with_facts`), so that the value rules no longer walk every setting of a list each; LIS204 looks up
the assignments of `kenngr.achs_mode` by their path. The tests state which settings each must hold and
check the shortcut against a walk of every setting, on every distinct fixture list and on generated lists.
The parse by line splits a text at LF or CRLF, or with `str.splitlines`, where it can instead of by the
pattern of line breaks: the lines and breaks must be the pattern's.
"""

from __future__ import annotations

import itertools
import random
import re
from dataclasses import fields
from operator import attrgetter

import pytest

from achslint.catalogue import catalogue, fill_indices
from achslint.linting.linter import FileSettings, lint_file
from achslint.rules.context import Context
from achslint.syntax import parser as syntax
from achslint.syntax.parser import parse_text

from .conftest import FIXTURES
from .fixture_lists import distinct_lists

LISTS = distinct_lists()


def _contexts() -> list[tuple[str, Context]]:
    found = []
    for path in LISTS:
        result = lint_file(path.read_bytes(), path.name, FileSettings(keep_context=True))
        if result.context is not None:
            found.append((str(path.relative_to(FIXTURES)), result.context))
    return found


@pytest.fixture(scope="module")
def contexts() -> list[tuple[str, Context]]:
    return _contexts()


_ODD_VALUES = ("abc", "1.5", "-1", "99999999999999999999", "P-AXIS-00008.0", "P-AXIS-99999.0", "x" * 40, "")


def _generated(seed: int, lines: int = 600) -> Context:
    """An axis list of random catalogue parameters: most written with their default, some with a value of
    the wrong kind or size, an index beyond the array, an old name or a misspelt one."""
    rng = random.Random(seed)
    parameters = catalogue().parameters
    out = []
    for _ in range(lines):
        parameter = rng.choice(parameters)
        indices = [rng.choice((low, high, high + 1)) for low, high in parameter.index_bounds]
        path = fill_indices(parameter.path, tuple(indices))
        if parameter.aliases and rng.random() < 0.5:
            path = parameter.aliases[0].path
        elif rng.random() < 0.02:
            path = path.replace("_", "", 1)
        value = rng.choice(_ODD_VALUES) if rng.random() < 0.2 else str(parameter.default or 0)
        out.append(f"{path} {value}")
    out.append("Ende")
    name = f"achsmds{seed}.lis"
    return Context(name, parse_text("\n".join(out) + "\n", name))


def _known_the_long_way(ctx: Context) -> list[tuple[object, object, str]]:
    """Every setting of a catalogue parameter written with a name the CNC reads (no misspelling)."""
    known = []
    for setting in ctx.analysis.settings:
        resolution = setting.resolution
        if resolution is None or resolution.misspelt:
            continue
        assert setting.canonical == resolution.canonical
        known.append((setting, resolution.parameter, resolution.canonical))
    return known


def _same(got: list[tuple[object, ...]], wanted: list[tuple[object, ...]]) -> bool:
    """The same settings (by identity), parameters and paths, in the same order."""
    return len(got) == len(wanted) and all(
        all(a is b or a == b for a, b in zip(g, w, strict=True)) for g, w in zip(got, wanted, strict=True)
    )


def test_the_sweep_sees_lists_with_facts_and_old_names(contexts: list[tuple[str, Context]]) -> None:
    """The comparisons below are about something: the fixtures hold lists with facts of several kinds."""
    kinds = {
        type(fact).__name__
        for _, ctx in contexts
        for setting, _ in ctx.with_facts
        for fact in setting.problems
    }
    assert len(contexts) > 250
    assert {
        "OutOfRange",
        "UnknownSymbol",
        "NotBoolean",
        "IndexOutOfBounds",
        "TooLong",
        "BadReference",
    } <= kinds
    assert any(ctx.kind.id != "axis" for _, ctx in contexts)  # lists of other kinds are compared too


def test_known_settings_are_every_resolved_setting(contexts: list[tuple[str, Context]]) -> None:
    for name, ctx in contexts:
        assert _same(ctx.known, _known_the_long_way(ctx)), name  # type: ignore[arg-type]


def test_settings_with_facts_are_every_known_setting_with_a_fact(contexts: list[tuple[str, Context]]) -> None:
    for name, ctx in contexts:
        wanted = [
            (setting, parameter) for setting, parameter, _ in _known_the_long_way(ctx) if setting.problems
        ]
        assert _same(ctx.with_facts, wanted), name  # type: ignore[arg-type]
        # a fact is only ever recorded for a known setting: none is left out by the shortcut
        assert sum(1 for s in ctx.analysis.settings if s.problems) == len(ctx.with_facts), name


@pytest.mark.parametrize("seed", range(4))
def test_generated_lists_agree(seed: int) -> None:
    ctx = _generated(seed)
    known = _known_the_long_way(ctx)
    assert len(known) > 400 and len(ctx.with_facts) > 50
    assert _same(ctx.known, known)  # type: ignore[arg-type]
    assert _same(ctx.with_facts, [(s, p) for s, p, _ in known if s.problems])  # type: ignore[arg-type]


def test_achs_mode_assignments_are_found_by_their_path(contexts: list[tuple[str, Context]]) -> None:
    """LIS204 reads the assignments of its parameter from the groups by path: the same ones, in order."""
    seen = 0
    for name, ctx in contexts:
        if not ctx.axis_list:
            continue
        wanted = [s for s, parameter, _ in ctx.known if parameter.id == "P-AXIS-00015"]
        got = ctx.analysis.by_canonical().get(ctx.catalogue.by_id["P-AXIS-00015"].path, [])
        assert [id(s) for s in got] == [id(s) for s in wanted], name
        seen += bool(wanted)
    assert seen > 10


def test_achs_mode_set_twice_is_judged_twice() -> None:
    """Each assignment of `kenngr.achs_mode` is judged, the first one too (LIS204 and LIS005 both report)."""
    from achslint import api

    text = "kenngr.achs_mode 0x5\nkenngr.achs_typ 1\nkenngr.achs_mode 0x7\nEnde\n"
    found = [d for d in api.lint_text(text, filename="achsmds1.lis") if d.code == "LIS204"]
    assert [d.line for d in found] == [1, 3]


# -- the parse by line: splitting a text into its lines ----------------------------------------------------


def _lines_by_the_pattern(text: str) -> tuple[list[str], list[str]]:
    """The lines and their breaks as the parser numbers them: only CR, LF and CRLF end a line, and a text
    ending with a break (or an empty one) has an empty last line."""
    raw = re.findall(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+", text)
    if not raw or raw[-1].endswith(("\n", "\r")):
        raw.append("")
    bodies = [line.rstrip("\r\n") for line in raw]
    return bodies, [line[len(body) :] for line, body in zip(raw, bodies, strict=True)]


def _split(text: str) -> tuple[list[str], list[str]]:
    bodies, breaks = syntax._bodies(text)
    if isinstance(breaks, str):  # one break after every line but the last
        breaks = [breaks] * (len(bodies) - 1) + [""]
    return bodies, breaks


@pytest.mark.parametrize("alphabet", ["a\r\n", "\r\n\x0b", "a\r\n\u2028", "\r\n\x85\x1c"])
def test_every_short_text_splits_into_the_parsers_lines(alphabet: str) -> None:
    """Every text of up to six characters of CR, LF and a letter or a character `str.splitlines` breaks at."""
    for length in range(7):
        for letters in itertools.product(alphabet, repeat=length):
            text = "".join(letters)
            assert _split(text) == _lines_by_the_pattern(text), repr(text)


@pytest.mark.parametrize("newline", ["\n", "\r\n", "\r"])
def test_a_list_with_one_kind_of_break_splits_at_it(newline: str) -> None:
    text = newline.join(["kopf.achs_nr 1", "", "  # note", "Ende", ""])
    bodies, breaks = syntax._bodies(text)
    assert (bodies, breaks) == (["kopf.achs_nr 1", "", "  # note", "Ende", ""], newline)
    assert _split(text) == _lines_by_the_pattern(text)


def test_the_kept_fields_are_those_of_a_line_before_its_break_and_number() -> None:
    names = [f.name for f in fields(syntax.Line)]
    assert names[-2:] == ["newline", "number"]  # a parse appends the two to the kept fields
    assert len(syntax._Head.__args__) == len(names) - 2
    line = syntax.parse_text("kopf.achs_nr 1\r\nEnde").lines[0]
    assert (*syntax._LineParses._head(line), line.newline, line.number) == attrgetter(*names)(line)


# -- the default list underneath: analysed once per context ------------------------------------------------


def test_the_default_list_is_analysed_once_for_the_axis_and_the_rules(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    from achslint.rules import context

    calls: list[str] = []
    analyse = context.analyse

    def counting(file: syntax.ListFile, cat: object = None) -> object:
        calls.append(file.name)
        return analyse(file, cat)  # type: ignore[arg-type]

    monkeypatch.setattr(context, "analyse", counting)
    defaults = parse_text("getriebe[0].vb_reflow 1000\nkenngr.ref_richt 1\nEnde\n", "default_mds.lis")
    ctx = Context("achsmds1.lis", parse_text("kopf.achs_nr 1\nEnde\n", "achsmds1.lis"), default_file=defaults)
    assert ctx.values.number("getriebe[0].vb_reflow") == 1000  # the default list's value, under the list's
    assert [s.canonical for s in ctx.default_settings] == ["getriebe[0].vb_reflow", "kenngr.ref_richt"]
    assert ctx.values.origin("getriebe[0].vb_reflow").setting is ctx.default_settings[0]  # the one analysis
    assert calls == ["achsmds1.lis", "default_mds.lis"]
    assert Context("achsmds1.lis", parse_text("Ende\n", "achsmds1.lis")).default_settings == []
