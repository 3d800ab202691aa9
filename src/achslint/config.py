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
from dataclasses import dataclass, field, fields, replace
from functools import lru_cache
from pathlib import Path, PurePosixPath
from typing import Any, Literal

from .tomlfile import read_toml

CONFIG_NAMES = (".achslint.toml", "achslint.toml", "pyproject.toml")


class ConfigError(Exception):
    """A configuration file that cannot be used (exit code 2)."""


def parse_codes(values: list[str]) -> list[str]:
    """Rule codes and prefixes (each value may hold several, comma-separated), upper-cased.

    Raises `ValueError` for one that picks no rule (`LIS9999`, `LIS6`), naming the closest codes: a
    selection that checks nothing must never pass silently.
    """
    from .rules import selector_problem

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


@dataclass(frozen=True)
class Settings:
    """The keys of an achslint configuration (see README, Configuration); file keys use dashes."""

    select: list[str] | None = None
    extend_select: list[str] = field(default_factory=list)
    ignore: list[str] = field(default_factory=list)
    per_file_ignores: dict[str, list[str]] = field(default_factory=dict)
    severity: dict[str, str] = field(default_factory=dict)
    fail_on: str = "error"
    include: list[str] = field(default_factory=lambda: ["achsmds*.lis"])
    exclude: list[str] = field(default_factory=list)
    unknown_parameters: str = "warn"
    cycle_time_us: int = 1000
    repeatability_tolerance_um: float = 20.0
    scenario: dict[str, Any] = field(default_factory=dict)  # scenario defaults for dry-run
    cnc_root: str | None = None  # the CNC working directory start-up entries are resolved against
    docs_url: str | None = None  # where rule documentation links point (json url, SARIF helpUri)

    def as_file_keys(self) -> dict[str, Any]:
        """The settings as a configuration file spells them."""
        return {f.name.replace("_", "-"): getattr(self, f.name) for f in fields(self)}


@lru_cache(maxsize=1)
def _file_model():
    """The pydantic model that validates a configuration file (built only when a file is read)."""
    from pydantic import BaseModel, ConfigDict, Field, field_validator

    severity_name = Literal["error", "warning", "info"]
    default = Settings()  # the defaults live in one place: the dataclass above

    class SettingsFile(BaseModel):
        model_config = ConfigDict(extra="forbid", populate_by_name=True)

        select: list[str] | None = None
        extend_select: list[str] = Field(default_factory=list, alias="extend-select")
        ignore: list[str] = Field(default_factory=list)
        per_file_ignores: dict[str, list[str]] = Field(default_factory=dict, alias="per-file-ignores")
        severity: dict[str, severity_name] = Field(default_factory=dict)
        fail_on: severity_name = Field(default.fail_on, alias="fail-on")
        include: list[str] = Field(default_factory=lambda: list(default.include))
        exclude: list[str] = Field(default_factory=list)
        unknown_parameters: Literal["warn", "error", "ignore"] = Field(
            default.unknown_parameters, alias="unknown-parameters"
        )
        cycle_time_us: int = Field(default.cycle_time_us, alias="cycle-time-us", gt=0)
        repeatability_tolerance_um: float = Field(
            default.repeatability_tolerance_um, alias="repeatability-tolerance-um", ge=0
        )
        scenario: dict[str, Any] = Field(default_factory=dict)
        cnc_root: str | None = Field(None, alias="cnc-root", min_length=1)
        docs_url: str | None = Field(None, alias="docs-url", pattern=r"^https?://\S+$")

        @field_validator("select", "extend_select", "ignore")
        @classmethod
        def _check_codes(cls, value):
            return None if value is None else parse_codes(value)

        @field_validator("per_file_ignores")
        @classmethod
        def _check_per_file(cls, value):
            return {pattern: parse_codes(codes) for pattern, codes in value.items()}

        @field_validator("severity")
        @classmethod
        def _check_severity_codes(cls, value):
            from .rules import known_codes

            codes = parse_codes(list(value))
            partial = [code for code in codes if code not in known_codes()]
            if partial:  # an override is looked up by the full code, so a prefix would change nothing
                raise ValueError(f"severity overrides take full rule codes, not the prefix {partial[0]!r}")
            return dict(zip(codes, value.values(), strict=False))

    return SettingsFile


@dataclass(frozen=True)
class ResolvedConfig:
    """Settings plus the file they came from (None: built-in defaults)."""

    settings: Settings
    path: Path | None = None

    @property
    def root(self) -> Path:
        return self.path.parent if self.path else Path.cwd()

    def relative(self, target: Path) -> str:
        try:
            return PurePosixPath(
                Path(os.path.realpath(target)).relative_to(os.path.realpath(self.root))
            ).as_posix()
        except (ValueError, OSError):
            return PurePosixPath(Path(target)).as_posix()

    def cnc_root(self) -> Path | None:
        """The `cnc-root` setting as a folder (relative to the configuration file's folder), or None."""
        if self.settings.cnc_root is None:
            return None
        return Path(os.path.abspath(self.root / Path(self.settings.cnc_root).expanduser()))

    def ignored_for(self, target: Path) -> list[str]:
        """Codes ignored for one file by `per-file-ignores`."""
        codes: list[str] = []
        for pattern, ignored in self.settings.per_file_ignores.items():
            if matches_glob(self.relative(target), pattern):
                codes.extend(ignored)
        return codes


def matches_glob(relative: str, pattern: str) -> bool:
    """Glob match on the path relative to the config folder; a pattern without `/` also matches any file name."""
    if fnmatch.fnmatch(relative, pattern):
        return True
    if "/" not in pattern:
        return fnmatch.fnmatch(relative.rsplit("/", 1)[-1], pattern)
    return fnmatch.fnmatch(relative, pattern.lstrip("./")) or fnmatch.fnmatch(
        relative, pattern.rstrip("/") + "/*"
    )


def _format_error(path: Path, error, model) -> str:
    problems = []
    for item in error.errors():
        key = ".".join(str(part) for part in item["loc"]) or "(top level)"
        if item["type"] == "extra_forbidden":
            allowed = ", ".join(sorted(f.alias or name for name, f in model.model_fields.items()))
            problems.append(f"unknown key `{key}` (known keys: {allowed})")
        else:
            problems.append(f"key `{key}`: {item['msg']}")
    return f"configuration error in {path}: " + "; ".join(problems)


def load_file(path: Path) -> ResolvedConfig:
    """Read one configuration file (pyproject.toml: its [tool.achslint] table)."""
    from pydantic import ValidationError

    data = read_toml(path, "configuration", ConfigError)
    if path.name == "pyproject.toml":
        tool = data.get("tool", {})
        data = tool.get("achslint", {}) if isinstance(tool, dict) else {}
        if not isinstance(data, dict):
            raise ConfigError(
                f"configuration error in {path}: `tool.achslint` must be a table ([tool.achslint]), "
                f"not {type(data).__name__}"
            )
    model = _file_model()
    try:
        validated = model.model_validate(data)
    except ValidationError as exc:
        raise ConfigError(_format_error(path, exc, model)) from None
    return ResolvedConfig(Settings(**validated.model_dump()), path)


def _has_table(pyproject: Path) -> bool:
    """Whether a pyproject.toml has a `[tool.achslint]` table (another project's `tool = 5` is not ours).

    A pyproject.toml that is not valid TOML is a configuration error: it may hold our table, and using
    the defaults instead would pass silently what the project meant to fail.
    """
    try:
        data = read_toml(pyproject, "configuration", ConfigError)
    except ConfigError as exc:
        if str(exc).startswith("cannot read"):
            return False
        raise
    tool = data.get("tool", {})
    return isinstance(tool, dict) and "achslint" in tool


@lru_cache(maxsize=256)
def _config_in(folder: Path) -> Path | None:
    for name in CONFIG_NAMES:
        candidate = folder / name
        try:
            found = candidate.is_file()
        except OSError:  # a folder on the way we may not look into has no configuration for us
            continue
        if found and (name != "pyproject.toml" or _has_table(candidate)):
            return candidate
    return None


def discover(start: Path) -> ResolvedConfig:
    """The nearest configuration above `start` (a file or folder), or the defaults.

    Never fails on the path itself: a link loop, a name too long for the file system or a
    folder we may not read only stop the search where they are.
    """
    try:
        folder = Path(os.path.realpath(start))
        is_folder = folder.is_dir()
    except (OSError, RuntimeError, ValueError):
        folder, is_folder = Path(os.path.abspath(start)), False
    if not is_folder:
        folder = folder.parent
    for candidate in (folder, *folder.parents):
        found = _config_in(candidate)
        if found is not None:
            return _load_cached(found)
    return ResolvedConfig(Settings())


@lru_cache(maxsize=64)
def _load_cached(path: Path) -> ResolvedConfig:
    return load_file(path)


@dataclass
class Overrides:
    """What the command line says; None means "use the configuration"."""

    select: list[str] | None = None
    extend_select: list[str] = field(default_factory=list)
    ignore: list[str] = field(default_factory=list)
    fail_on: str | None = None
    unknown_parameters: str | None = None
    cycle_time_us: int | None = None
    repeatability_tolerance_um: float | None = None
    include: list[str] | None = None
    extend_exclude: list[str] | None = None
    cnc_root: str | None = None  # a folder, already absolute (relative to the working directory when given)

    def apply(self, settings: Settings) -> Settings:
        changes: dict[str, Any] = {}
        if self.select is not None:
            changes["select"] = self.select
        if self.extend_select:
            changes["extend_select"] = [*settings.extend_select, *self.extend_select]
        if self.ignore:
            changes["ignore"] = [*settings.ignore, *self.ignore]
        for name in ("fail_on", "unknown_parameters", "cycle_time_us", "repeatability_tolerance_um"):
            value = getattr(self, name)
            if value is not None:
                changes[name] = value
        if self.include is not None:
            changes["include"] = list(self.include)
        if self.extend_exclude:
            changes["exclude"] = [*settings.exclude, *self.extend_exclude]
        if self.cnc_root is not None:
            changes["cnc_root"] = self.cnc_root
        return replace(settings, **changes)
