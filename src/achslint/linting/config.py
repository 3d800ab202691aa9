"""Configuration files: `[tool.achslint]` in pyproject.toml, achslint.toml or .achslint.toml.

The configuration that applies to a list is the nearest one found walking up
from the list's folder (`.achslint.toml` before `achslint.toml` before a
pyproject.toml that has a `[tool.achslint]` table); `--config FILE` replaces
the search. Keys are validated with pydantic: an unknown key or a bad value is
a configuration error (exit code 2) naming the file and the key.
"""

from __future__ import annotations

import fnmatch
import os
from dataclasses import MISSING, asdict, dataclass, field, fields, is_dataclass, replace
from functools import lru_cache
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING, Any, Literal

from ..homing.bounds import CYCLE_MS, CYCLE_TIME_US
from ..rules.codes import known_codes, selector_problem
from ..rules.options import DEFAULT_OPTIONS
from ..rules.options import UnknownParameters as UnknownParameters  # the command line's choices too

if TYPE_CHECKING:
    from pydantic import ValidationError

CONFIG_NAMES = (".achslint.toml", "achslint.toml", "pyproject.toml")


class ConfigError(Exception):
    """A configuration file that cannot be used (exit code 2)."""


def parse_codes(values: list[str]) -> list[str]:
    """Rule codes and prefixes (each value may hold several, comma-separated), upper-cased.

    Raises `ValueError` for one that picks no rule (`LIS9999`, `LIS6`), naming the closest codes: a
    selection that checks nothing must never pass silently.
    """
    cleaned = []
    for value in values:
        for part in str(value).split(","):
            if not part.strip():
                continue
            problem = selector_problem(part)
            if problem is not None:
                raise ValueError(problem)
            cleaned.append(part.strip().upper())
    return cleaned


# Bounds of the numbers a configuration file may set: the same as the command-line options' (an absurd
# value is a configuration error, never gigabytes of padding or a MemoryError).
MAX_COLUMN = 400  # [fmt] value-column / comment-column: wider than any real list, small enough to pad
# cycle-time-us: bounds.CYCLE_TIME_US, the CNC's cycle (the dry run's scenario has the same bounds); the file
# may write it in ms as `cycle-time-ms` (the unit of --cycle-time-ms), read into it by `_cycle_time_in_ms`
MAX_TOLERANCE_UM = 1_000_000.0  # repeatability tolerance on linear axes: up to 1 m
MAX_TOLERANCE_DEG = 360.0  # and on rotary axes: up to one turn

LEFT: Literal["left"] = "left"
RIGHT: Literal["right"] = "right"
KEEP: Literal["keep"] = "keep"
AlignValues = Literal["left", "right", "keep"]
ALIGN_VALUES: tuple[AlignValues, ...] = (LEFT, RIGHT, KEEP)


@dataclass(frozen=True)
class FmtOptions:
    """Layout choices that replace what fmt would detect in a file.

    Columns count from 1, as editors show them. `align_values` `"keep"` keeps
    the file's own alignment; `"left"`/`"right"` put every value in one column
    of that kind: `value_column`, else the one most values already use, else the
    canonical one. `value_column` is where values start (left-aligned; also when
    it is given with `"keep"`) or the column of their last character
    (right-aligned). `comment_column` is where a comment after a value starts.
    """

    value_column: int | None = None
    comment_column: int | None = None
    align_values: AlignValues = KEEP

    def __post_init__(self) -> None:
        for name in ("value_column", "comment_column"):
            column = getattr(self, name)
            if column is not None and (type(column) is not int or not 1 <= column <= MAX_COLUMN):
                raise ValueError(
                    f"{name.replace('_', '-')} must be a column number from 1 to {MAX_COLUMN}, not {column!r}"
                )
        if self.align_values not in ALIGN_VALUES:
            choices = ", ".join(f'"{choice}"' for choice in ALIGN_VALUES)
            raise ValueError(f"align-values must be one of {choices}, not {self.align_values!r}")


SeverityName = Literal["error", "warning", "info"]

# How a command-line value combines with the configuration's (Settings field metadata "cli").
REPLACE, EXTEND = "replace", "extend"


def _key(default: Any = None, *, factory: Any = None, cli: str = REPLACE, **check: Any) -> Any:
    """A settings field: its default, how the command line combines with it, and the checks pydantic makes
    on the configuration file's value (`gt`, `ge`, `min_length`, `pattern`, `codes`)."""
    metadata = {"cli": cli, "check": check}
    if factory is not None:
        return field(default_factory=factory, metadata=metadata)
    return field(default=default, metadata=metadata)


@dataclass(frozen=True)
class MachineTable:
    """A `[[machine]]` table: lists that form one machine although no start-up list names them (a repository
    of axis lists without its start-up list). `lists` are glob patterns relative to the configuration file's
    folder (`listen/*.lis`, `**/achsmds*.lis`)."""

    lists: list[str] = _key(factory=list, min_length=1)
    name: str | None = _key(None, min_length=1)  # how messages name it (default: its number in the file)

    def __post_init__(self) -> None:
        if not self.lists:  # a table that names no list declares nothing: a mistake, never a machine
            raise ValueError(
                'a [[machine]] table needs `lists`, the patterns of its lists (lists = ["listen/achsmds*.lis"])'
            )
        for pattern in self.lists:
            if not pattern.strip() or PurePosixPath(pattern).is_absolute() or Path(pattern).is_absolute():
                raise ValueError(f"lists: {pattern!r} is not a pattern relative to the configuration file")
            if ".." in PurePosixPath(pattern.replace("\\", "/")).parts:
                raise ValueError(f"lists: {pattern!r} leads out of the configuration file's folder (`..`)")


@dataclass(frozen=True)
class Settings:
    """Every achslint setting, once: the configuration file's schema (keys spelled with dashes), its
    defaults, what rules read (`ctx.options`) and what the command line may override (`Overrides`)."""

    # another configuration file this one builds on (relative to this file, inside its repository)
    extend: str | None = _key(None, min_length=1)
    select: list[str] | None = _key(None, codes="list")
    extend_select: list[str] = _key(factory=list, cli=EXTEND, codes="list")
    ignore: list[str] = _key(factory=list, cli=EXTEND, codes="list")
    fixable: list[str] | None = _key(None, codes="list")  # the codes --fix may fix (default: every code)
    unfixable: list[str] = _key(factory=list, cli=EXTEND, codes="list")  # and those it must leave alone
    per_file_ignores: dict[str, list[str]] = _key(factory=dict, codes="values")
    severity: dict[str, SeverityName] = _key(factory=dict, codes="keys")
    fail_on: SeverityName = _key("error")
    include: list[str] = _key(factory=lambda: ["achsmds*.lis"])
    exclude: list[str] = _key(factory=list, cli=EXTEND)  # the command line extends it (--extend-exclude)
    # the keys rules read (rules.options.RuleOptions), with the rules' defaults
    unknown_parameters: UnknownParameters = _key(DEFAULT_OPTIONS.unknown_parameters)
    cycle_time_us: int = _key(DEFAULT_OPTIONS.cycle_time_us, ge=CYCLE_TIME_US[0], le=CYCLE_TIME_US[1])
    repeatability_tolerance_um: float = _key(  # linear axes (LIS403)
        DEFAULT_OPTIONS.repeatability_tolerance_um, ge=0, le=MAX_TOLERANCE_UM
    )
    repeatability_tolerance_deg: float = _key(  # rotary axes (LIS403)
        DEFAULT_OPTIONS.repeatability_tolerance_deg, ge=0, le=MAX_TOLERANCE_DEG
    )
    scenario: dict[str, Any] = _key(factory=dict)  # scenario defaults for dry-run
    cnc_root: str | None = _key(
        None, min_length=1
    )  # the CNC working directory start-up entries resolve against
    docs_url: str | None = _key(None, pattern=r"^https?://\S+$")  # rule documentation links (json, SARIF)
    # NC homing programs (relative to the configuration file's folder) that a lint of the machine's
    # start-up list also checks against that machine (LIS6xx), as `lint rfp.nc --machine hochlauf.lis` does
    homing_programs: list[str] = _key(factory=list)
    fmt: FmtOptions = _key(factory=FmtOptions)  # the [fmt] table: the layout `achslint fmt` keeps or imposes
    # [[machine]] tables: lists compared with each other although no start-up list names them
    machine: list[MachineTable] = _key(factory=list)

    def as_file_keys(self) -> dict[str, Any]:
        """The settings as a configuration file spells them."""
        return {file_key(f.name): _as_file_value(getattr(self, f.name)) for f in fields(self)}


def _as_file_value(value: Any) -> Any:
    """A setting as the file spells it: a table's keys with dashes."""
    if is_dataclass(value) and not isinstance(value, type):
        return {file_key(name): item for name, item in asdict(value).items()}
    if isinstance(value, list):
        return [_as_file_value(item) for item in value]
    return value


def file_key(name: str) -> str:
    """The configuration-file spelling of a settings field (`fail_on` -> `fail-on`)."""
    return name.replace("_", "-")


def _check_codes(value: Any, how: str) -> Any:
    """The one validation of rule codes in a configuration file (the command line uses `parse_codes` too)."""
    if value is None:
        return None
    if how == "list":
        return parse_codes(value)
    if how == "values":
        return {pattern: parse_codes(codes) for pattern, codes in value.items()}
    codes = parse_codes(list(value))
    partial = [code for code in codes if code not in known_codes()]
    if partial:  # an override is looked up by the full code, so a prefix would change nothing
        raise ValueError(f"severity overrides take full rule codes, not the prefix {partial[0]!r}")
    return dict(zip(codes, value.values(), strict=True))


@lru_cache(maxsize=1)
def _file_model() -> Any:
    """The pydantic model of a configuration file, derived from `Settings` (built only when a file is
    read: importing pydantic costs more than linting a small list)."""
    from pydantic import ConfigDict, create_model

    return create_model(
        "SettingsFile", __config__=ConfigDict(extra="forbid", populate_by_name=True), **_definitions(Settings)
    )


def _table_model(table: type) -> Any:
    """A table of the configuration file (`[fmt]`) read into its dataclass: keys with dashes, no unknown
    keys, and the dataclass's own checks (its `ValueError`s become configuration errors)."""
    from typing import Annotated

    from pydantic import AfterValidator, ConfigDict, create_model

    names = [item.name for item in fields(table)]
    model = create_model(
        "table",  # pydantic names it in "should be a valid dictionary or instance of table"
        __config__=ConfigDict(extra="forbid", populate_by_name=True),
        **_definitions(table),
    )
    return Annotated[
        model, AfterValidator(lambda read: table(**{name: getattr(read, name) for name in names}))
    ]


def _definitions(settings: type) -> dict[str, Any]:
    """The pydantic field of every field of a settings dataclass: its type, the file's spelling (dashes),
    its default and the checks of its metadata (`_key`); a dataclass-typed field is a table of its own."""
    from typing import Annotated, get_args, get_origin, get_type_hints

    from pydantic import AfterValidator, Field

    hints = get_type_hints(settings)
    definitions: dict[str, Any] = {}
    for item in fields(settings):
        check = dict(item.metadata.get("check", {}))
        codes = check.pop("codes", None)
        kind: Any = hints[item.name]
        if codes:
            kind = Annotated[kind, AfterValidator(lambda value, how=codes: _check_codes(value, how))]
        if isinstance(kind, type) and is_dataclass(kind):
            kind = _table_model(kind)
        elif get_origin(kind) is list and is_dataclass(get_args(kind)[0]):  # an array of tables
            kind = list[_table_model(get_args(kind)[0])]  # type: ignore[misc]
        default: dict[str, Any] = (
            {"default_factory": item.default_factory}
            if item.default_factory is not MISSING
            else {"default": item.default}
        )
        definitions[item.name] = (kind, Field(alias=file_key(item.name), **default, **check))
    return definitions


@dataclass(frozen=True)
class ResolvedConfig:
    """Settings plus the file they came from (None: built-in defaults), and the files it extends (`extend`,
    nearest first)."""

    settings: Settings
    path: Path | None = None
    extends: tuple[Path, ...] = ()

    @property
    def root(self) -> Path:
        return self.path.parent if self.path else Path.cwd()

    def relative(self, target: Path) -> str:
        """`target` relative to the configuration's folder, by the name it is found under: a link is
        matched where it lies, not where it leads (as git and ruff match), so `backup/achsmds1.lis ->
        ../listen/achsmds1.lis` is `backup/achsmds1.lis`. A path that reaches the folder through a link
        above it (a linked working folder) is taken from the last folder on its way that is the
        configuration's folder; a path outside it stays as it is given."""
        from ..core.files import real_path

        absolute = Path(os.path.abspath(target))
        root = Path(os.path.abspath(self.root))
        if absolute.is_relative_to(root):
            return PurePosixPath(absolute.relative_to(root)).as_posix()
        try:
            real_root = real_path(root)
            for folder in absolute.parents:
                if real_path(folder) == real_root:
                    return PurePosixPath(absolute.relative_to(folder)).as_posix()
        except (OSError, ValueError):
            pass
        return PurePosixPath(Path(target)).as_posix()

    def cnc_root(self) -> Path | None:
        """The `cnc-root` setting as a folder (relative to the configuration file's folder), or None."""
        if self.settings.cnc_root is None:
            return None
        if self.path is None:  # pragma: no cover - the built-in defaults set no cnc-root
            return Path(os.path.abspath(Path(self.settings.cnc_root).expanduser()))
        return named_path(self.path, self.settings.cnc_root)

    def declared_machines(self) -> list[tuple[str, list[Path]]]:
        """The `[[machine]]` tables as (key, the files their patterns find), files in a stable order."""
        if self.path is None:
            return []
        found = []
        for number, table in enumerate(self.settings.machine, start=1):
            files: dict[str, Path] = {}
            for pattern in table.lists:
                for path in sorted(self.root.glob(pattern)):
                    if path.is_file() and path != self.path:
                        files.setdefault(os.path.realpath(path), path)
            found.append((f"{self.path}#{table.name or number}", list(files.values())))
        return found

    def ignored_for(self, target: Path) -> list[str]:
        """Codes ignored for one file by `per-file-ignores`."""
        codes: list[str] = []
        for pattern, ignored in self.settings.per_file_ignores.items():
            if matches_glob(self.relative(target), pattern):
                codes.extend(ignored)
        return codes


def matches_glob(relative: str, pattern: str) -> bool:
    """Glob match on the path relative to the config folder (`*` crosses `/`), as `.gitignore` and ruff
    match: a pattern without `/` matches the file's name or the name of a folder on its way (`archive`,
    `*.lis`); a pattern with one is anchored at the configuration's folder and matches the file or a folder
    on its way (`legacy/old`, `./archive/`, `**/archive` which takes `archive` at the top too)."""
    if fnmatch.fnmatch(relative, pattern):
        return True
    parts = relative.split("/")
    if "/" not in pattern:
        return any(fnmatch.fnmatch(part, pattern) for part in parts)
    anchored = pattern.rstrip("/")
    while anchored.startswith("./"):
        anchored = anchored[2:]
    if not anchored:
        return False
    forms = [anchored, anchored[3:]] if anchored.startswith("**/") else [anchored]
    leading = ["/".join(parts[:end]) for end in range(1, len(parts) + 1)]  # the folders on the way, the file
    return any(fnmatch.fnmatch(prefix, form) for form in forms if form for prefix in leading)


def _model_of(annotation: Any) -> Any:
    """The model of a table from its field's annotation (unwrapping `Annotated[...]` and `list[...]`)."""
    from typing import get_args

    while not hasattr(annotation, "model_fields") and get_args(annotation):
        annotation = get_args(annotation)[0]
    return annotation


def _format_error(path: Path, error: ValidationError, model: Any) -> str:
    problems = []
    for item in error.errors():
        key = ".".join(str(part) for part in item["loc"]) or "(top level)"
        if item["type"] == "extra_forbidden":
            table = model
            for part in item["loc"][:-1]:  # an unknown key inside a table: that table's keys
                if isinstance(part, int):  # the n-th table of an array of tables ([[machine]])
                    continue
                table = _model_of(
                    next(f.annotation for n, f in table.model_fields.items() if part in (n, f.alias))
                )
            allowed = ", ".join(sorted(f.alias or name for name, f in table.model_fields.items()))
            problems.append(f"unknown key `{key}` (known keys: {allowed})")
        else:
            problems.append(f"key `{key}`: {item['msg']}")
    return f"configuration error in {path}: " + "; ".join(problems)


def load_file(path: Path) -> ResolvedConfig:
    """Read one configuration file (pyproject.toml: its [tool.achslint] table), and the files it extends."""
    data, extends = _extended(path, ())
    return ResolvedConfig(_validated(path, data), path, extends)


def _table(path: Path) -> dict[str, Any]:
    """The achslint keys of one configuration file, spelled with dashes."""
    from ..core.tomlfile import read_toml

    data = read_toml(path, "configuration", ConfigError)
    if path.name == "pyproject.toml":
        tool = data.get("tool", {})
        data = tool.get("achslint", {}) if isinstance(tool, dict) else {}
        if not isinstance(data, dict):
            raise ConfigError(
                f"configuration error in {path}: `tool.achslint` must be a table ([tool.achslint]), "
                f"not {type(data).__name__}"
            )
    known = {item.name for item in fields(Settings)}
    keys = {file_key(key) if key in known else key: value for key, value in data.items()}
    _fmt_columns(path, keys.get("fmt"))
    return _cycle_time_in_ms(path, keys)


def _fmt_columns(path: Path, table: object) -> None:
    """The [fmt] table's columns are whole numbers as written: `true` and `"30"` are refused here (the
    settings' validation would take them for 1 and 30)."""
    if not isinstance(table, dict):
        return
    for key in ("value-column", "comment-column"):
        value = table.get(key)
        if value is not None and type(value) is not int:
            raise ConfigError(
                f"configuration error in {path}: key `fmt.{key}`: {value!r} is not a column number; write a "
                f"whole number from 1 to {MAX_COLUMN} (value-column = 40)"
            )


def _cycle_time_in_ms(path: Path, keys: dict[str, Any]) -> dict[str, Any]:
    """`cycle-time-ms` (ms, as `--cycle-time-ms` and the scenario's `cycle_time_ms` take it) read as the
    setting it is, `cycle-time-us`; both in one file is an error naming the file."""
    if "cycle-time-ms" not in keys:
        return keys
    if "cycle-time-us" in keys:
        raise ConfigError(
            f"configuration error in {path}: keys `cycle-time-ms` and `cycle-time-us` both set the cycle time; "
            "keep one (cycle-time-ms)"
        )
    value = keys.pop("cycle-time-ms")
    low, high = CYCLE_MS
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not low <= value <= high:
        raise ConfigError(
            f"configuration error in {path}: key `cycle-time-ms`: {value!r} is not a cycle time in ms from "
            f"{low:g} to {high:g}"
        )
    keys["cycle-time-us"] = round(value * 1000)
    return keys


def _validated(path: Path, data: dict[str, Any]) -> Settings:
    """The settings of a configuration's keys; a configuration error names `path` and the key."""
    from pydantic import ValidationError

    model = _file_model()
    try:
        validated = model.model_validate(data)
    except ValidationError as exc:
        raise ConfigError(_format_error(path, exc, model)) from None
    settings = Settings(**{item.name: getattr(validated, item.name) for item in fields(Settings)})
    _check_contained(path, settings)
    return settings


# Keys whose paths are relative to the file that names them: taken from a file `extend` names, they are
# moved to stay relative to the file that extends it. Patterns (include, exclude, per-file-ignores,
# [[machine]] lists) are matched below the folder of the configuration that applies, wherever written.
_PATH_KEYS = ("cnc-root", "homing-programs")


def _extended(path: Path, chain: tuple[Path, ...]) -> tuple[dict[str, Any], tuple[Path, ...]]:
    """A configuration's keys over those of the files it extends (`extend`, followed as far as it goes),
    and those files, nearest first. The file's own keys win; a list the command line extends (`ignore`,
    `extend-select`, `exclude`, `unfixable`) adds to the base's, and a table (`severity`,
    `per-file-ignores`, `[fmt]` ...) is merged key by key. Each file is checked on its own first, so an
    error names the file it is in."""
    data = _table(path)
    _validated(path, data)
    base_name = data.get("extend")
    if base_name is None:
        return data, ()
    base = named_path(path, base_name)
    if any(os.path.realpath(base) == os.path.realpath(seen) for seen in (*chain, path)):
        cycle = " -> ".join(str(p) for p in (*chain, path, base))
        raise ConfigError(
            f"configuration error in {path}: key `extend`: {base_name!r} extends in a circle ({cycle})"
        )
    from ..core.files import MISSING, not_a_list_file

    problem = not_a_list_file(base, what="a configuration")
    if problem is not None:
        said = "does not exist" if problem in MISSING else f"is {problem}"
        raise ConfigError(f"configuration error in {path}: key `extend`: {base_name!r} ({base}) {said}")
    if base.name == "pyproject.toml" and not _has_table(base):
        raise ConfigError(
            f"configuration error in {path}: key `extend`: {base_name!r} ({base}) has no [tool.achslint] "
            "table to build on; add one, or name another configuration file"
        )
    below, extends = _extended(base, (*chain, path))
    for key in _PATH_KEYS:
        if key in below:
            below[key] = _moved(below[key], base, path)
    merged = dict(below)
    modes = {file_key(item.name): item.metadata["cli"] for item in fields(Settings)}
    for key, value in data.items():
        if modes.get(key) == EXTEND and isinstance(value, list) and isinstance(below.get(key), list):
            merged[key] = [*below[key], *value]
        elif isinstance(value, dict) and isinstance(below.get(key), dict):
            merged[key] = {**below[key], **value}
        else:
            merged[key] = value
    return merged, (base, *extends)


def _moved(value: Any, source: Path, target: Path) -> Any:
    """A path (or list of paths) relative to configuration `source`, made relative to `target`'s folder."""
    if isinstance(value, list):
        return [_moved(item, source, target) for item in value]
    if not isinstance(value, str):
        return value  # a wrong type: the check of the merged keys names it
    where = named_path(source, value)
    return os.path.relpath(where, Path(os.path.abspath(target)).parent)


def named_path(config: Path, value: str) -> Path:
    """A path a configuration file names, relative to the file's folder (`~` is the home folder)."""
    return Path(os.path.normpath(Path(os.path.abspath(config)).parent / Path(value).expanduser()))


def repository_of(config: Path) -> Path:
    """The repository a configuration file belongs to: the git work tree that holds it (the nearest
    folder above it with a `.git`), else the configuration file's own folder."""
    folder = Path(os.path.abspath(config)).parent
    for candidate in (folder, *folder.parents):
        if os.path.lexists(candidate / ".git"):
            return candidate
    return folder


def _check_contained(path: Path, settings: Settings) -> None:
    """Paths a configuration names stay inside its repository: a pull request that changes the
    configuration must not make achslint read (and quote) files elsewhere on the machine that runs it.
    `homing-programs` must also name NC programs (`.nc`)."""
    from ..core.files import inside

    repository = repository_of(path)
    named = [("cnc-root", settings.cnc_root)] if settings.cnc_root is not None else []
    named += [("extend", settings.extend)] if settings.extend is not None else []
    named += [("homing-programs", program) for program in settings.homing_programs]
    for key, value in named:
        if "\x00" in value:
            raise ConfigError(
                f"configuration error in {path}: key `{key}`: a path cannot hold a NUL character (\\u0000)"
            )
        target = named_path(path, value)
        if not target.is_relative_to(repository):
            problem = f"lies outside {repository}"
        elif not inside(target, repository):  # links followed
            problem = f"leads outside {repository} through a symbolic link"
        else:
            problem = ""
        if problem:
            where = (
                "the git work tree"
                if os.path.lexists(repository / ".git")
                else "the configuration's folder (no git work tree holds it)"
            )
            raise ConfigError(
                f"configuration error in {path}: key `{key}`: {value!r} {problem}, {where}; "
                "name a folder or file inside it"
            )
        if key == "homing-programs" and not value.lower().endswith(PROGRAM_SUFFIXES):
            raise ConfigError(
                f"configuration error in {path}: key `homing-programs`: {value!r} is not an NC program "
                f"(a name ending in {', '.join(PROGRAM_SUFFIXES)})"
            )


PROGRAM_SUFFIXES = (".nc",)  # what the command line takes for an NC homing program (api.is_program)


def _has_table(pyproject: Path) -> bool:
    """Whether a pyproject.toml has a `[tool.achslint]` table (another project's `tool = 5` is not ours).

    A pyproject.toml that is not valid TOML is a configuration error: it may hold our table, and using
    the defaults instead would pass silently what the project meant to fail.

    The answer is kept for the file's content: a project's pyproject.toml without our table lies above
    every list of the project, and was parsed again for each run of a process (the language server, the
    tests), after `forget_cached`.
    """
    from ..core.files import SETTINGS_LIMIT, read_list

    try:
        content = read_list(pyproject, limit=SETTINGS_LIMIT)
    except OSError:
        return _table_in(pyproject)  # read_toml says why, or there is no file any more
    return _table_in_content(pyproject, content)


@lru_cache(maxsize=16)
def _table_in_content(pyproject: Path, content: bytes) -> bool:
    """`_table_in` for a file holding `content` (the key: an edit is a new content)."""
    return _table_in(pyproject)


def _table_in(pyproject: Path) -> bool:
    from ..core.tomlfile import read_toml

    try:
        data = read_toml(pyproject, "configuration", ConfigError)
    except ConfigError as exc:
        if not os.path.lexists(pyproject):  # gone since it was found: no configuration here any more
            return False
        if str(exc).startswith("cannot read"):
            # it may hold the project's [tool.achslint]: linting with the defaults instead would pass
            # silently what the project meant to fail (as for an unreadable achslint.toml)
            raise ConfigError(f"{exc}; make it readable, or give the configuration with --config") from None
        raise
    tool = data.get("tool", {})
    return isinstance(tool, dict) and "achslint" in tool


@lru_cache(maxsize=256)
def _config_in(folder: Path) -> Path | None:
    from ..core.files import SETTINGS_LIMIT, not_a_list_file

    for name in CONFIG_NAMES:
        candidate = folder / name
        try:
            exists = os.path.lexists(candidate)
        except (OSError, ValueError):  # a folder on the way we may not look into has no configuration for us
            continue
        if not exists:
            continue
        problem = not_a_list_file(candidate, limit=SETTINGS_LIMIT, what="a configuration")
        if problem is not None and problem != "permission denied":
            # a FIFO, a device or a dangling link where a configuration belongs: it may be meant to
            # apply, and skipping it silently would lint with other settings than the project's
            raise ConfigError(
                f"configuration error: {candidate} is {problem}; achslint does not read it "
                "(replace it with a regular file, or remove it)"
            )
        if problem is None and (name != "pyproject.toml" or _has_table(candidate)):
            return candidate
    return None


def discover(start: Path) -> ResolvedConfig:
    """The nearest configuration above `start` (a file or folder), or the defaults.

    Never fails on the path itself: a link loop, a name too long for the file system or a
    folder we may not read only stop the search where they are.
    """
    from ..core.files import real_path

    try:
        folder = real_path(start)  # resolved once per path while discovery holds the links
        is_folder = folder.is_dir()
    except (OSError, ValueError):
        folder, is_folder = Path(os.path.abspath(start)), False
    if not is_folder:
        folder = folder.parent
    return _nearest(folder)


@lru_cache(maxsize=256)
def _nearest(folder: Path) -> ResolvedConfig:
    """The configuration of the files of a folder (asked for each file of a folder lint)."""
    for candidate in (folder, *folder.parents):
        found = _config_in(candidate)
        if found is not None:
            return _load_cached(found)
    return ResolvedConfig(Settings())


@lru_cache(maxsize=64)
def _load_cached(path: Path) -> ResolvedConfig:
    return load_file(path)


class Overrides:
    """What the command line (or an editor) says about settings; an absent or None value means "use the
    configuration". Keys are `Settings` field names; a field marked `cli=EXTEND` adds to the configuration's
    list (`extend_exclude` adds to `exclude`)."""

    def __init__(self, **values: Any) -> None:
        # how each setting combines with the configuration (plain strings: an Overrides pickles)
        known = {f.name: str(f.metadata["cli"]) for f in fields(Settings)}
        self.values: dict[str, Any] = {}
        for name, value in values.items():
            target = "exclude" if name == "extend_exclude" else name
            if target not in known:
                raise TypeError(f"not a setting: {name}")
            if value is not None and value != []:
                self.values[target] = value
        self._modes = known

    def __getattr__(self, name: str) -> Any:
        """The overridden value of a setting, None when the command line leaves it to the configuration."""
        if name.startswith("_") or name == "values" or name not in self._modes:
            raise AttributeError(name)
        return self.values.get(name)

    def key(self) -> tuple[tuple[str, str], ...]:
        """A stable, hashable summary of what is overridden (equal overrides give equal keys)."""
        return tuple(sorted((name, repr(value)) for name, value in self.values.items()))

    def apply(self, settings: Settings) -> Settings:
        changes: dict[str, Any] = {}
        for name, value in self.values.items():
            if self._modes[name] == EXTEND:
                changes[name] = [*getattr(settings, name), *value]
            else:
                changes[name] = list(value) if isinstance(value, list) else value
        return replace(settings, **changes)


def forget_cached() -> None:
    """Forget which folders hold a configuration and what the files said (a file was created, edited or
    deleted: the language server calls this when the editor reports such a change)."""
    _config_in.cache_clear()
    _load_cached.cache_clear()
    _nearest.cache_clear()
