"""`explain PARAM`, hover, completion, `fmt` and `--fix` for every list kind (issue 25 item 4).

A channel parameter's card comes from the channel catalogue (P-CHAN-00036, the `spindel[i].log_achs_nr`
of the manual's channel parameter list), a start-up parameter's from the start-up catalogue
(P-STUP-00167 `error_protocol_mode`, whose flags the SDK's start-up list OR-combines); the editor reads
the kind its lint decided (the start-up entry naming the list, else its content)."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from achslint.catalogue.kinds import AXIS, BY_ID, CHANNEL, CONTENT_KINDS, STARTUP, TOOLS
from achslint.core.decode import decode
from achslint.explanation import find_parameters, parameter_card, rules_checking
from achslint.fmt import format_bytes

from .conftest import FIXTURES, run_cli
from .test_kind_rules import GOOD_LISTS  # the good list of every kind, linted clean there

KINDS = FIXTURES / "kinds"


# -- explain PARAM ---------------------------------------------------------------------------------------


def test_a_channel_parameter_is_explained_by_id_and_by_path() -> None:
    for query in ("P-CHAN-00036", "p-chan-36", "spindel[0].log_achs_nr", "spindel[i].log_achs_nr"):
        found = find_parameters(query)
        assert [(hit.kind.id, hit.parameter.id) for hit in found] == [("channel", "P-CHAN-00036")], query
    card = parameter_card(found[0].parameter, found[0].kind)
    assert (card["kind"], card["list"], card["path"]) == ("channel", "channel list", "spindel[i].log_achs_nr")
    assert card["checked_range"] == {"min": 1, "max": 65535}  # "1... MAX(UNS16)"
    # no drive types, axis types or homing strategies: a channel list describes no axis
    assert card["drive_types"] is None and card["axis_types"] is None and card["strategies"] is None


def test_an_axis_parameter_still_wins_without_kind_and_kind_chooses_another() -> None:
    # `kopf.achs_nr` is P-AXIS-00016 of an axis list and P-COMP-00001 of an axis compensation list
    assert [(h.kind.id, h.parameter.id) for h in find_parameters("kopf.achs_nr")] == [
        ("axis", "P-AXIS-00016")
    ]
    compensation = BY_ID["compensation"]
    hits = find_parameters("kopf.achs_nr", compensation)
    assert [(h.kind.id, h.parameter.id) for h in hits] == [("compensation", "P-COMP-00001")]
    # the axis rules reading `kopf.achs_nr` (LIS501 ...) are no checks of the compensation parameter
    assert "LIS501" in rules_checking(find_parameters("kopf.achs_nr")[0].parameter, AXIS)
    assert rules_checking(hits[0].parameter, compensation) == ["LIS201", "LIS202"]
    # an id names its own kind: another kind asked for finds nothing
    assert find_parameters("P-CHAN-00036", TOOLS) == [] and find_parameters("P-AXIS-00218", CHANNEL) == []
    assert find_parameters("P-ZZZZ-00001") == [] and find_parameters("P-CHAN-99999") == []


def test_explain_cli_shows_the_card_of_any_kind() -> None:
    text = run_cli("explain", "error_protocol_mode")
    assert text.returncode == 0, text.stderr
    lines = text.stdout.decode().splitlines()
    assert lines[0] == "P-STUP-00167  error_protocol_mode"
    assert "  list             start-up list" in lines
    assert "  checked by       LIS201, LIS203" in lines
    card = json.loads(run_cli("explain", "kopf.achs_nr", "--kind", "compensation", "--format", "json").stdout)
    assert (card["p_axis"], card["kind"]) == ("P-COMP-00001", "compensation")
    axis = json.loads(run_cli("explain", "kopf.achs_nr", "--format", "json").stdout)
    assert (axis["p_axis"], axis["kind"], axis["list"]) == ("P-AXIS-00016", "axis", "axis list")


def test_explain_cli_failures_name_the_kind() -> None:
    unknown = run_cli("explain", "gruppe[0].achse[0].bezeichnug", "--kind", "channel")
    assert unknown.returncode == 2
    assert b"not a known parameter of a channel list; did you mean `gruppe[i].achse[i].bezeichnung`" in (
        unknown.stderr.replace(b"neither a file nor a known", b"not a known")
    )
    with_file = run_cli("explain", str(KINDS / "sda_mds1.lis"), "--kind", "channel")
    assert with_file.returncode == 2 and b"--kind goes with a parameter name" in with_file.stderr
    wrong = run_cli("explain", "vb_reflow", "--kind", "nonsense")
    assert wrong.returncode == 2


def test_a_name_several_other_kinds_share_asks_for_kind() -> None:
    axis = AXIS.catalogue()
    assert axis is not None
    owners: dict[str, set[str]] = {}
    for kind in CONTENT_KINDS:
        cat = kind.catalogue()
        if kind is AXIS or cat is None:
            continue
        for parameter in cat.parameters:
            if cat.find(parameter.member) is not None and axis.find(parameter.member) is None:
                owners.setdefault(parameter.member, set()).add(kind.id)
    # a member name two kinds other than axis lists know each by itself (and the axis catalogue does not)
    name = min(member for member, kinds in owners.items() if len(kinds) > 1)
    assert {hit.kind.id for hit in find_parameters(name)} == owners[name]
    result = run_cli("explain", name)
    assert result.returncode == 2 and b"choose one with --kind" in result.stderr
    chosen = sorted(owners[name])[0]
    assert run_cli("explain", name, "--kind", chosen).returncode == 0


# -- hover and completion --------------------------------------------------------------------------------

lsp_types = pytest.importorskip("lsprotocol.types", reason="the lsp extra is not installed")

from achslint.lsp import features  # noqa: E402
from achslint.lsp.documents import Document  # noqa: E402
from achslint.lsp.session import Session, Snapshot  # noqa: E402


def opened(session: Session, path: Path, text: str | None = None) -> tuple[Document, Snapshot]:
    if text is None:
        text = path.read_bytes().decode("latin-1")
    document = Document(path.as_uri(), path, text, 1)
    session.open(document)
    snapshot = session.snapshot(document.uri)
    assert snapshot is not None
    return document, snapshot


@pytest.fixture
def listen(tmp_path: Path) -> Path:
    folder = tmp_path / "listen"
    shutil.copytree(KINDS, folder)
    return folder


def test_hover_on_a_channel_parameter_shows_the_channel_card(tmp_path: Path, listen: Path) -> None:
    session = Session(tmp_path)
    document, snapshot = opened(session, listen / "sda_mds1.lis")
    assert features.document_kind(snapshot) is CHANNEL
    line = next(
        n for n, text in enumerate(document.text.splitlines(), 1) if text.startswith("spindel[0].log")
    )
    card = features.hover_text(snapshot.context, snapshot.file, line, 3, markdown=False)
    assert card is not None and card.startswith("P-CHAN-00036 spindel[i].log_achs_nr\n")
    assert "- list: channel list" in card and "In this list" not in card  # no resolved axis to show
    value = features.hover_text(snapshot.context, snapshot.file, line, 55, markdown=False)
    assert value == "3"
    # the axis catalogue knows no `grp_anzahl`: without the channel kind there would be no card at all
    first = features.hover_text(snapshot.context, snapshot.file, 3, 2, markdown=True)
    assert first is not None and first.startswith("**P-CHAN-00023** `grp_anzahl`")
    # what needs a resolved axis answers nothing for a channel list (and does not fail)
    assert (
        features.inlay_hints(
            document, snapshot, lsp_types.Range(lsp_types.Position(0, 0), lsp_types.Position(99, 0))
        )
        == []
    )


def test_hover_on_a_start_up_list_parameter_and_its_combined_flags(tmp_path: Path) -> None:
    session = Session(tmp_path)
    text = "error_protocol_mode  REPORT | REPORT_EXTENDED\nkanal_anzahl  1\nzahl_mds  1\nEnde\n"
    document, snapshot = opened(session, tmp_path / "basis.lis", text)  # a start-up list by its content
    assert features.document_kind(snapshot) is STARTUP
    file = snapshot.file if snapshot.file is not None else document.parse()
    card = features.hover_text(
        snapshot.context, file, 1, 3, markdown=False, kind=features.document_kind(snapshot)
    )
    assert card is not None and card.startswith("P-STUP-00167 error_protocol_mode\n")
    assert "- list: start-up list" in card
    # a start-up list named as one is read as its machine's definition (no Context): the kind still says
    named, named_snapshot = opened(session, tmp_path / "hochlauf.lis", text)
    assert named_snapshot.startup and features.document_kind(named_snapshot) is STARTUP
    card = features.hover_text(None, named.parse(), 2, 3, markdown=False, kind=STARTUP)
    assert card is not None and card.startswith("P-STUP-")


def test_completion_offers_the_paths_and_symbols_of_the_lists_kind(tmp_path: Path, listen: Path) -> None:
    session = Session(tmp_path)
    text = (
        (listen / "sda_mds1.lis").read_text(encoding="latin-1").replace("Ende", "gruppe[0].achse[1].\nEnde")
    )
    document, snapshot = opened(session, listen / "sda_mds1.lis", text)
    line = text.splitlines().index("gruppe[0].achse[1].") + 1
    found = features.complete(document, snapshot, line, len("gruppe[0].achse[1].") + 1)
    labels = {item.label for item in found.items}
    # the channel catalogue's paths, with the typed indices (the client filters the member typed after)
    assert {"gruppe[0].achse[1].bezeichnung", "gruppe[0].achse[1].log_achs_nr"} <= labels
    assert all(label.startswith("gruppe[0].achse[1].") for label in labels)
    item = next(i for i in found.items if i.label == "gruppe[0].achse[1].bezeichnung")
    assert item.data == {"kind": "channel"}
    card = features.resolve_item(item, markdown=False).documentation
    assert card is not None and card.value.startswith("P-CHAN-00006 gruppe[i].achse[i].bezeichnung\n")
    top = {item.label for item in features.complete(document, snapshot, line, 1).items}
    assert "grp_anzahl" in top and not any(label.startswith("kenngr.") for label in top)


def test_completion_in_a_start_up_list_offers_flags_after_a_bar(tmp_path: Path) -> None:
    session = Session(tmp_path)
    text = "error_protocol_mode  REPORT | REP\nerror_protocol_mode  \nkanal_anzahl 1\nEnde\n"
    document, snapshot = opened(session, tmp_path / "hochlauf.lis", text)
    after_bar = features.complete(document, snapshot, 1, len("error_protocol_mode  REPORT | REP") + 1)
    labels = [item.label for item in after_bar.items]
    # filtered by what is typed after the bar (REP), as every client needs it
    assert "REPORT_EXTENDED" in labels and all(label.startswith("REP") for label in labels)
    assert after_bar.items[0].text_edit.range.start.character == len("error_protocol_mode  REPORT | ")
    first = {
        item.label
        for item in features.complete(document, snapshot, 2, len("error_protocol_mode  ") + 1).items
    }
    assert "LOG" in first and not any(label.startswith("P-AXIS-") for label in first)  # no axis references
    paths = {item.label for item in features.complete(document, snapshot, 3, 1).items}
    assert {"zahl_mds", "kanal_anzahl", "error_protocol_mode"} <= paths


# -- fmt and --fix ---------------------------------------------------------------------------------------


@pytest.mark.parametrize("kind", sorted(GOOD_LISTS))
def test_fmt_formats_a_list_of_every_kind_without_touching_its_words(kind: str) -> None:
    data = (KINDS / GOOD_LISTS[kind]).read_bytes()
    messy = b"\n".join(b"  " + line.replace(b" ", b"\t", 1) + b"   " for line in data.splitlines()) + b"\n\n"
    formatted, changed = format_bytes(messy, GOOD_LISTS[kind])
    assert changed
    assert format_bytes(formatted, GOOD_LISTS[kind]) == (formatted, False)  # formatting twice changes nothing

    def words(raw: bytes) -> list[list[str]]:
        return [line.split() for line in decode(raw).text.splitlines() if line.strip()]

    assert words(formatted) == words(data)
    assert not any(line != line.rstrip() for line in decode(formatted).text.splitlines())


def test_fmt_and_fix_rewrite_the_start_up_list_and_the_lists_it_names(tmp_path: Path, listen: Path) -> None:
    startup, channel = listen / "hochlauf.lis", listen / "sda_mds1.lis"
    for path in (startup, channel):
        path.write_bytes(path.read_bytes().replace(b"\n", b"   \n"))
    check = run_cli("fmt", "--check", str(startup))
    assert check.returncode == 1
    assert "would reformat" in check.stdout.decode() + check.stderr.decode()
    said = check.stdout.decode() + check.stderr.decode()
    assert "hochlauf.lis" in said and "sda_mds1.lis" in said
    assert run_cli("fmt", str(startup)).returncode == 0
    assert b"   \n" not in startup.read_bytes() and b"   \n" not in channel.read_bytes()
    # --fix: the misspelt end marker of a channel list and of a tool data list the start-up list names
    tools = listen / "werkz_d1.lis"
    for path in (channel, tools):
        path.write_bytes(path.read_bytes().replace(b"Ende", b"End"))
    run_cli("lint", "--fix", str(startup))
    assert channel.read_bytes().rstrip().endswith(b"Ende") and tools.read_bytes().rstrip().endswith(b"Ende")
