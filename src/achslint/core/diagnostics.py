"""The diagnostic model shared by rules, the engine and every reporter, and the `noqa` directive that
suppresses diagnostics (read by `linting.suppression`, judged by LIS009)."""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum

# Where the rule documentation (docs/rules.md, generated from the rule modules) is published; one anchor
# per rule. `docs-url` in the configuration or --docs-url replaces it (an internal mirror, a fork).
DOCS_URL = "https://achslint.readthedocs.io/en/latest/rules.html"


class Severity(str, Enum):
    """A finding's severity; a string (`severity == "warning"`), printed as its value (`str`, f-strings)."""

    ERROR = "error"
    WARNING = "warning"
    INFO = "info"

    def __str__(self) -> str:
        return self.value

    def __format__(self, spec: str) -> str:
        return format(self.value, spec)

    @property
    def rank(self) -> int:
        return {"error": 3, "warning": 2, "info": 1}[self.value]


@dataclass(frozen=True, slots=True)
class Edit:
    """Replace the text between two 1-based positions (end exclusive) by `content`."""

    line: int
    column: int
    end_line: int
    end_column: int
    content: str


@dataclass(frozen=True, slots=True)
class Fix:
    applicability: str  # "safe" or "unsafe"
    description: str
    edits: tuple[Edit, ...] = ()
    remove_bom: bool = False


@dataclass(frozen=True, slots=True)
class Related:
    path: str
    line: int
    column: int
    parameter: str | None = None
    message: str = ""


@dataclass(slots=True)
class Diagnostic:
    path: str
    line: int
    column: int
    end_line: int
    end_column: int
    code: str
    severity: Severity
    message: str
    parameter: str | None = None
    p_axis: str | None = None
    related: tuple[Related, ...] = ()  # a tuple: millions of diagnostics share the empty one
    fix: Fix | None = None

    def __post_init__(self) -> None:
        # Every producer (rules, machine checks, XML) gets the same treatment of huge quoted text.
        self.message = clip_quotes(self.message)

    @property
    def url(self) -> str:
        return rule_url(self.code)

    def sort_key(self) -> tuple[str, int, int, str]:
        return (self.path, self.line, self.column, self.code)


@dataclass
class Directive:
    """One `noqa` comment: where it is written (line, first and past-last column), the codes it names and,
    once the engine has applied it, the codes it suppressed."""

    line: int
    column: int
    end_column: int
    codes: list[str] | None  # None: every code
    file_level: bool = False
    used: set[str] = field(default_factory=set)

    def covers(self, code: str) -> bool:
        return self.codes is None or code in self.codes


_CLIP = 60  # quoted text longer than twice this is shortened in messages


def clip_quotes(message: str) -> str:
    """Shorten very long quoted text (`...`) in a message: a 1 MB line is named, not repeated."""
    if len(message) < 2 * _CLIP:
        return message
    parts = message.split("`")
    if len(parts) % 2 == 0:
        return message  # an unpaired backtick: leave the message as written
    out = [parts[0]]
    for index in range(1, len(parts), 2):
        quoted, after = parts[index], parts[index + 1]
        if len(quoted) > 2 * _CLIP:
            out.append(f"`{quoted[:_CLIP]}…{quoted[-12:]}` ({len(quoted):,} characters){after}")
        else:
            out.append(f"`{quoted}`{after}")
    return "".join(out)


def rule_url(code: str, base: str | None = None) -> str:
    """The absolute address of a rule's documentation: the docs page and the rule's anchor."""
    return f"{(base or DOCS_URL).split('#', 1)[0]}#{code.lower()}"
