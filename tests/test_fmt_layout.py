"""`achslint fmt` keeps the layout a list already has and only evens out what breaks it."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from achslint.fmt import FmtOptions, canonical_text, changed_lines, detect_style, format_bytes, format_text
from achslint.syntax import parser as syntax

from .conftest import FIXTURES, examples
from .test_fmt import PIECES, tokens


def right(path: str, value: str, end: int, comment: str = "", at: int = 0) -> str:
    """`path` with `value` ending in column `end` and `comment` starting in column `at` (from 1)."""
    text = path + " " * (end - len(path) - len(value)) + value
    return text + " " * (at - 1 - len(text)) + comment if comment else text


def left(path: str, value: str, start: int, comment: str = "", at: int = 0) -> str:
    """`path` with `value` starting in column `start` and `comment` starting in column `at` (from 1)."""
    text = path.ljust(start - 1) + value
    return text + " " * (at - 1 - len(text)) + comment if comment else text


def style_of(text: str, options: FmtOptions | None = None) -> str:
    return detect_style(syntax.parse_text(text), options).describe()


# How many lines `fmt --check` would change in the published sample lists (dropped blank lines after
# `Ende` count). Before fmt kept layouts it changed 19, 5, 16, 29, 7, 19, 54 and 13 of them.
VENDOR = {
    "dynamic_axis_list_example_en_excerpt.lis": 0,
    "fixed_stop_drive_ident_example.lis": 0,
    # one blank between name and value throughout: no common column, so the canonical layout
    "homing_simulation_x_axis_excerpt.lis": 16,
    "isg_sdk_achsmds1_coe_minimal.lis": 0,
    # `0x400001` ends in column 55 where `X_Achse` starts in it; and a blank line after `Ende`
    "isg_sdk_achsmds1_minimal_template.lis": 2,
    "isg_sdk_achsmds1_soe_minimal.lis": 1,  # a blank line after `Ende`
    # two lines with trailing blanks and a blank line after `Ende`
    "isg_sdk_hochlauf.lis": 3,
    "sercos_over_ethercat_excerpt.lis": 0,
}


@pytest.mark.parametrize("name", sorted(VENDOR))
def test_vendor_lists_change_only_where_they_are_inconsistent(name):
    data = (FIXTURES / "vendor" / name).read_bytes()
    assert changed_lines(data) == VENDOR[name]
    formatted, changed = format_bytes(data)
    assert changed == bool(VENDOR[name])
    assert tokens(formatted) == tokens(data)


def test_vendor_layouts_are_recognised():
    def vendor(name: str) -> str:
        return style_of((FIXTURES / "vendor" / name).read_text(encoding="latin-1"))

    assert (
        vendor("isg_sdk_achsmds1_coe_minimal.lis") == "values end in column 55, comments in column 70, blanks"
    )
    assert (
        vendor("isg_sdk_achsmds1_soe_minimal.lis")
        == "values start in column 55, comments in column 70, blanks"
    )
    # The start-up list's first sections are right-aligned, the rest left-aligned: both are kept.
    assert vendor("isg_sdk_hochlauf.lis") == (
        "values start in column 55, a block where values end in column 111, comments kept, blanks"
    )
    assert vendor("homing_simulation_x_axis_excerpt.lis") == "no common value column: canonical layout"


def test_machine_fixture_lists_change_only_blank_only_lines():
    listen = FIXTURES / "machines" / "sdk" / "listen"
    counts = {path.name: changed_lines(path.read_bytes()) for path in sorted(listen.glob("*.lis"))}
    # achsmds1/2 hold lines with only a tab on them; those become empty lines.
    assert counts == {
        "achsmds1.lis": 4,
        "achsmds2.lis": 4,
        "achsmds3.lis": 0,
        "default_mds.lis": 0,
        "hochlauf.lis": 0,
    }


def test_right_aligned_values_stay_and_a_stray_line_joins_them():
    lines = [
        right("kopf.achs_nr", "1", 30, "( axis number", 36),
        right("kopf.log_achs_name", "X_Achse", 30, "( name", 36),
        "kenngr.achs_typ 1 ( type",
        right("getriebe[0].vb_reflow", "20000", 30, "( slow", 36),
        "Ende",
    ]
    text = "\n".join(lines) + "\n"
    assert style_of(text) == "values end in column 30, comments in column 36, blanks"
    expected = lines.copy()
    expected[2] = right("kenngr.achs_typ", "1", 30, "( type", 36)
    assert format_text(text) == "\n".join(expected) + "\n"


def test_left_aligned_values_and_a_comment_column():
    lines = [
        left("kopf.achs_nr", "1", 25, "( axis number", 40),
        left("kenngr.achs_typ", "1", 25, "( type", 40),
        left("getriebe[0].vb_reflow", "20000", 25, "( slow", 40),
        "kopf.log_achs_name    X  ( a comment out of line",
        "kenngr.homing.homing_type  CNC_CONTROLLED_WITH_A_LONG_NAME   ( past the column",
        "Ende",
    ]
    text = "\n".join(lines) + "\n"
    formatted = format_text(text).split("\n")
    assert formatted[:3] == lines[:3]  # lines in the layout are not touched
    assert formatted[3] == left("kopf.log_achs_name", "X", 25, "( a comment out of line", 40)
    # The name is too long for column 25: the value stays; the comment cannot reach column 40.
    assert formatted[4] == "kenngr.homing.homing_type  CNC_CONTROLLED_WITH_A_LONG_NAME ( past the column"


def test_a_block_in_another_alignment_is_kept():
    lines = [
        left("kanal_anzahl", "1", 30),
        left("konfiguration", "EIN_KANAL", 30),
        left("plc_mode", "0", 30),
        left("ext_var_max", "1000", 30),
        "",
        right("zahl_mds", "4", 52),
        right("default_achs_mds", "./listen/default_mds.lis", 52),
        right("achs_mds[0]", "./listen/achsmds1.lis", 52),
        "",
        "achs_kw_log_ax_nr[0]     1",
        "Ende",
    ]
    text = "\n".join(lines) + "\n"
    assert (
        style_of(text)
        == "values start in column 30, a block where values end in column 52, comments kept, blanks"
    )
    expected = [*lines[:9], left("achs_kw_log_ax_nr[0]", "1", 30), "Ende"]
    assert format_text(text) == "\n".join(expected) + "\n"


def test_tab_separated_lists_keep_their_tabs():
    text = (
        "kopf.achs_nr\t\t1\n"
        "kenngr.achs_typ\t\t1\n"
        "getriebe[0].vb_reflow\t20000\n"
        "kopf.mds_ident          1\n"  # in the column, but with blanks
        "kenngr.ref_richt 0\n"  # out of the column
        "Ende\n"
    )
    assert style_of(text) == "values start in column 25, comments kept, tabs"
    assert format_text(text) == (
        "kopf.achs_nr\t\t1\nkenngr.achs_typ\t\t1\ngetriebe[0].vb_reflow\t20000\n"
        "kopf.mds_ident\t\t1\nkenngr.ref_richt\t0\nEnde\n"
    )


def test_a_list_without_a_common_column_gets_the_canonical_layout():
    text = "a 1\nbbb 2\ncc   3 ( note\nEnde\n"
    assert style_of(text) == "no common value column: canonical layout"
    assert format_text(text) == "a    1\nbbb  2\ncc   3 ( note\nEnde\n"


def test_canonical_text_ignores_the_files_own_layout():
    text = right("kopf.achs_nr", "1", 30) + "\n" + right("kenngr.achs_typ", "1", 30) + "\nEnde\n"
    assert format_text(text) == text
    assert canonical_text(text) == "kopf.achs_nr     1\nkenngr.achs_typ  1\nEnde\n"


def test_options_fix_the_columns():
    text = "kopf.achs_nr  1 ( number\nkenngr.achs_typ  20 ( type\nEnde\n"
    assert format_text(text, options=FmtOptions(value_column=21, comment_column=31)) == (
        left("kopf.achs_nr", "1", 21, "( number", 31)
        + "\n"
        + left("kenngr.achs_typ", "20", 21, "( type", 31)
        + "\nEnde\n"
    )
    assert format_text(text, options=FmtOptions(value_column=25, align_values="right")) == (
        right("kopf.achs_nr", "1", 25)
        + " ( number\n"
        + right("kenngr.achs_typ", "20", 25)
        + " ( type\nEnde\n"
    )


def test_align_values_turns_a_right_aligned_list_left():
    names = ["kopf.achs_nr", "kopf.log_achs_name", "kenngr.achs_typ"]
    text = "\n".join(
        [right(names[0], "1", 30), right(names[1], "X_Achse", 30), right(names[2], "1", 30), "Ende\n"]
    )
    # Most values (one character wide) start in column 30 already: that becomes the column.
    assert format_text(text, options=FmtOptions(align_values="left")) == (
        "\n".join([left(names[0], "1", 30), left(names[1], "X_Achse", 30), left(names[2], "1", 30), "Ende\n"])
    )
    left_text = "kopf.achs_nr 1\nkopf.log_achs_name X_Achse\nEnde\n"
    assert format_text(left_text, options=FmtOptions(align_values="right")) == (
        right("kopf.achs_nr", "1", 27) + "\n" + right("kopf.log_achs_name", "X_Achse", 27) + "\nEnde\n"
    )


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"value_column": 0}, "value-column must be a column number from 1 to 400, not 0"),
        ({"comment_column": "40"}, "comment-column must be a column number from 1 to 400, not '40'"),
        ({"align_values": "center"}, 'align-values must be one of "left", "right", "keep", not \'center\''),
    ],
)
def test_bad_options_are_refused_with_a_message(options, message):
    with pytest.raises(ValueError, match="^" + message.replace("(", r"\(") + "$"):
        FmtOptions(**options)


# -- properties -----------------------------------------------------------------------------------------

NAMES = [
    "kopf.achs_nr",
    "getriebe[0].vb_reflow",
    "kenngr.homing.homing_type",
    "x.y",
    "antr.canopen.in[0].nc_ref",
]
VALUES = ["1", "20", "0x400001", "-1.5E-3", "X_Achse", '"a b"', "P-AXIS-00212.0", "DRIVE_STATUS"]
TRAILERS = ["", "( P-AXIS-00016 : number", "( c", "# note", "rest the CNC reads"]
OPTIONS = st.one_of(
    st.just(FmtOptions()),
    st.builds(
        FmtOptions,
        st.one_of(st.none(), st.integers(1, 70)),
        st.one_of(st.none(), st.integers(1, 90)),
        st.sampled_from(["left", "right", "keep"]),
    ),
)


@st.composite
def sections(draw: st.DrawFn) -> str:
    """Lists in sections, each aligned its own way, with some lines out of line (moved, indented, tabbed)."""
    out = []
    for _ in range(draw(st.integers(1, 3))):
        kind, column = draw(st.sampled_from(["left", "right"])), draw(st.integers(5, 50))
        comments, tabs = draw(st.integers(20, 80)), draw(st.booleans())
        for _ in range(draw(st.integers(1, 6))):
            name, value, trailer = (
                draw(st.sampled_from(NAMES)),
                draw(st.sampled_from(VALUES)),
                draw(st.sampled_from(TRAILERS)),
            )
            at = column if draw(st.integers(0, 4)) else draw(st.integers(1, 60))
            gap = max(1, (at if kind == "left" else at - len(value)) - len(name))
            text = name + ("\t" * max(1, gap // 8) if tabs and gap >= 8 else " " * gap) + value
            if trailer:
                text += " " * (max(1, comments - len(text)) if draw(st.integers(0, 3)) else 1) + trailer
            out.append(
                draw(st.sampled_from(["", "", "", " ", "\t"])) + text + draw(st.sampled_from(["", "", "  "]))
            )
        out.append(draw(st.sampled_from(["", "#", "# ----"])))
    return "\n".join([*out, "Ende"]) + "\n"


@settings(max_examples=examples(50), deadline=None)
@given(sections(), OPTIONS)
def test_formatting_keeps_the_detected_layout_and_is_idempotent(text, options):
    style = detect_style(syntax.parse_text(text), options)
    once = format_text(text, options=options)
    assert format_text(once, options=options) == once
    assert tokens(once.encode()) == tokens(text.encode())
    if style.values is not None:  # otherwise the canonical layout, a layout of its own
        assert detect_style(syntax.parse_text(once), options) == style


@settings(max_examples=examples(50), deadline=None)
@given(st.lists(PIECES, max_size=40).map("".join), OPTIONS)
def test_any_text_any_options_idempotent_and_whitespace_only(text, options):
    data = text.encode("latin-1")
    once, _ = format_bytes(data, options=options)
    assert tokens(once) == tokens(data)
    assert format_bytes(once, options=options) == (once, False)


@settings(max_examples=examples(50), deadline=None)
@given(
    st.lists(
        st.tuples(st.sampled_from(NAMES), st.sampled_from(VALUES), st.sampled_from(TRAILERS[:3])), min_size=2
    ),
    st.sampled_from(["left", "right"]),
    st.integers(0, 3),
)
def test_a_list_in_one_consistent_layout_is_left_alone(rows, kind, extra):
    column = max(len(name) for name, _, _ in rows) + 2 + extra
    if kind == "right":
        column += max(len(value) for _, value, _ in rows)
    comments = column + max(len(value) for _, value, _ in rows) + 3
    place = left if kind == "left" else right
    text = (
        "\n".join([place(name, value, column, trailer, comments) for name, value, trailer in rows] + ["Ende"])
        + "\n"
    )
    assert format_text(text) == text


# -- configuration --------------------------------------------------------------------------------------


def test_fmt_follows_the_fmt_table_of_the_nearest_configuration(cli, tmp_path):
    text = "kopf.achs_nr 1 ( number\nkenngr.achs_typ  20 ( type\nEnde\n"
    wanted = (
        right("kopf.achs_nr", "1", 25, "( number", 31)
        + "\n"
        + right("kenngr.achs_typ", "20", 25, "( type", 31)
    )
    (tmp_path / "a").mkdir()
    (tmp_path / "a" / ".achslint.toml").write_text(
        '[fmt]\nvalue-column = 25\ncomment-column = 31\nalign-values = "right"\n'
    )
    (tmp_path / "b").mkdir()
    (tmp_path / "b" / "pyproject.toml").write_text("[tool.achslint.fmt]\nvalue-column = 21\n")
    for folder in ("a", "b"):
        (tmp_path / folder / "achsmds1.lis").write_text(text)
    assert cli("fmt", str(tmp_path / "a"), str(tmp_path / "b")).returncode == 0
    assert (tmp_path / "a" / "achsmds1.lis").read_text() == wanted + "\nEnde\n"
    assert (tmp_path / "b" / "achsmds1.lis").read_text() == (
        left("kopf.achs_nr", "1", 21) + " ( number\n" + left("kenngr.achs_typ", "20", 21) + " ( type\nEnde\n"
    )


@pytest.mark.parametrize(
    ("table", "message"),
    [
        (
            "value-colum = 30",
            "unknown key `fmt.value-colum` (known keys: align-values, comment-column, value-column)",
        ),
        ("value-column = 0", "value-column must be a column number from 1 to 400, not 0"),
        ('align-values = "center"', "key `fmt.align-values`: Input should be 'left', 'right' or 'keep'"),
    ],
)
def test_a_bad_fmt_table_is_a_configuration_error(cli, tmp_path, table, message):
    (tmp_path / ".achslint.toml").write_text(f"[fmt]\n{table}\n")
    (tmp_path / "achsmds1.lis").write_text("kopf.achs_nr 1\nEnde\n")
    result = cli("fmt", "--check", str(tmp_path / "achsmds1.lis"))
    assert result.returncode == 2
    assert str(tmp_path / ".achslint.toml") in result.stderr.decode() and message in result.stderr.decode()
