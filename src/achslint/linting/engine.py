"""The lint engine: the one loop every rule runs in, whatever it looks at.

A rule takes part in one or more scopes (`rules.Scope`); `run` takes the subject of one scope through
the whole pipeline:

    the scope's enabled rules -> `noqa` suppressions -> AFTER rules (LIS009) -> severity overrides
        -> fixes of codes that are not fixable dropped -> sorted

    scope     subject                                      caller
    LIST      (Context,)                                   linter: one list (its kind's rules)
    MACHINE   (Machine,)                                   machines (a run's machines), linter (XML projects)
    PROGRAM   (Program, ChannelView)                       programlint: a homing program on its machine
    AFTER     (path, directives, enabled)                  run itself, after LIST or PROGRAM

Which rules run and how severe their findings are is a `Policy`: select / extend-select / ignore and the
severity table of the configuration that applies to the file. The machine step checks lists that may each
have their own configuration; there a function gives the policy of the file a finding is in.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass
from functools import cached_property, lru_cache

from ..core.diagnostics import Diagnostic, Severity
from ..core.pause import hook as pause_hook
from ..core.pause import pause as pause  # re-exported: the pause points of a thread (engine.pause)
from ..core.pause import set_hook
from ..rules import Check, Scope, codes, known_codes, matches, rule
from ..rules.codes import applies_to
from .suppression import Suppressions

ALL = ("ALL",)


@dataclass(frozen=True)
class Policy:
    """Which rules are enabled (ruff-style select / extend-select / ignore, by code or prefix) and the
    severity each code's findings get instead of the rule's own (`[severity]` of the configuration)."""

    select: tuple[str, ...] | None = None  # None or empty: every rule
    extend_select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()
    severity: tuple[tuple[str, Severity], ...] = ()
    fixable: tuple[str, ...] | None = None  # the codes whose findings keep their fix (None: every code)
    unfixable: tuple[str, ...] = ()

    @classmethod
    def of(
        cls,
        select: Iterable[str] | None = None,
        extend_select: Iterable[str] = (),
        ignore: Iterable[str] = (),
        severity: Mapping[str, str] | None = None,
        fixable: Iterable[str] | None = None,
        unfixable: Iterable[str] = (),
    ) -> Policy:
        return cls(
            tuple(select) if select is not None else None,
            tuple(extend_select),
            tuple(ignore),
            tuple((code, Severity(name)) for code, name in sorted((severity or {}).items())),
            tuple(fixable) if fixable is not None else None,
            tuple(unfixable),
        )

    def may_fix(self, code: str) -> bool:
        """Whether findings of `code` keep their fix (`fixable` / `unfixable`, by code or prefix)."""
        chosen = ALL if self.fixable is None else self.fixable  # `fixable = []`: nothing is fixed
        return matches(code, chosen) and not matches(code, self.unfixable)

    def enabled(self, code: str) -> bool:
        chosen = self.select or ALL
        if not (matches(code, chosen) or matches(code, self.extend_select)):
            return False
        return not matches(code, self.ignore)

    @cached_property
    def overrides(self) -> dict[str, Severity]:
        return dict(self.severity)


# The policy of the file a finding is in (the machine step: each list has its own configuration).
PolicyOf = Callable[[str], Policy]


def pause_between_rules(pause: Callable[[], None] | None) -> None:
    """Call `pause` before each rule `run` runs on this thread, and at the other pause points
    (`core.pause`: the parse, the axis analysis) (None: never). The language server's worker gives way to
    the editor's requests there and stops a lint whose text changed meanwhile (by raising); the command
    line sets none."""
    set_hook(pause)


def run(
    scope: Scope,
    subject: tuple[object, ...],
    policy: Policy | PolicyOf,
    *,
    suppressions: Suppressions | None = None,
    whole_axis: bool = True,
    kind: str = "axis",
) -> list[Diagnostic]:
    """The findings of every enabled rule of `scope` on `subject`, sorted.

    `suppressions`: the `noqa` directives of the list or program the subject was read from; they drop what
    they cover, then the AFTER rules judge them. `whole_axis=False` for a default list, which alone is no
    axis: the rules that judge parameters together (`Rule.needs_whole_axis`) do not run on it. `kind`: the
    list kind (`catalogue.kinds` id) of a LIST subject; only the rules that apply to it run (`Rule.kinds`).
    """
    fixed = policy if isinstance(policy, Policy) else None
    policy_of = _always(policy) if isinstance(policy, Policy) else policy
    found: list[Diagnostic] = []
    hook: Callable[[], None] | None = pause_hook()
    for code, check in enabled_checks(scope, fixed, whole_axis, kind):
        findings = check(*subject)
        if hook is not None:
            hook()
            findings = _pausing(findings, hook)
        if fixed is not None:
            found.extend(findings)
        else:  # every rule of the scope ran: a finding stays when the policy of its file enables the rule
            found.extend(d for d in findings if policy_of(d.path).enabled(code))
    if suppressions is not None:
        found = suppressions.apply(found)
        own = policy_of(suppressions.path)
        enabled = enabled_codes(own, whole_axis, kind).__contains__
        for _, check in enabled_checks(Scope.AFTER, own, whole_axis, kind):
            found.extend(check(suppressions.path, suppressions.directives, enabled))
    for diagnostic in found:
        chosen = fixed or policy_of(diagnostic.path)
        override = chosen.overrides.get(diagnostic.code)
        if override is not None:
            diagnostic.severity = override
        if diagnostic.fix is not None and not chosen.may_fix(diagnostic.code):
            diagnostic.fix = None  # `unfixable`: --fix, the editor and the counts leave it alone
    found.sort(key=Diagnostic.sort_key)
    return found


def _pausing(findings: Iterable[Diagnostic], hook: Callable[[], None]) -> Iterator[Diagnostic]:
    """The findings of a rule, with a pause after each (a rule yields them as it goes)."""
    for finding in findings:
        yield finding
        hook()


def _always(policy: Policy) -> PolicyOf:
    return lambda _path: policy


@lru_cache(maxsize=256)
def enabled_checks(
    scope: Scope, policy: Policy | None, whole_axis: bool = True, kind: str = "axis"
) -> tuple[tuple[str, Check], ...]:
    """(code, check) of the rules that look at `scope` and that `policy` enables (None: every rule), in
    code order; for a list (LIST, AFTER) only the rules that apply to its `kind`."""
    per_list = scope in (Scope.LIST, Scope.AFTER)
    chosen = []
    for code in known_codes():  # by the code table: only the rules that run are imported (`rules.rule`)
        if scope not in codes.scopes(code) or (policy is not None and not policy.enabled(code)):
            continue
        if per_list and not applies_to(codes.kinds(code), kind):
            continue
        found = rule(code)
        check = found.checker(scope)
        if check is not None and (whole_axis or not found.needs_whole_axis):
            chosen.append((code, check))
    return tuple(chosen)


@lru_cache(maxsize=256)
def enabled_codes(policy: Policy, whole_axis: bool = True, kind: str = "axis") -> frozenset[str]:
    """The codes of every rule `policy` enables for a list of `kind` (for AFTER rules: a `noqa` for a rule
    that is not enabled, or does not look at this kind of list, is not unused)."""
    return frozenset(
        code
        for code in known_codes()
        if policy.enabled(code)
        and (Scope.LIST not in codes.scopes(code) or applies_to(codes.kinds(code), kind))
        and (whole_axis or not rule(code).needs_whole_axis)
    )
