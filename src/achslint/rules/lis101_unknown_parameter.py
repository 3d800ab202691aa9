"""
What
----
A parameter name the catalogue does not know. The message names the closest
known parameter: a typo (`kenngr.ref_ricth`), a manual misprint
(`antr_simu.rpf_weg_bis_nip`), a member in the wrong group
(`kenngr.vb_reflow`), or an index where none belongs / a missing index.
When the intended name is unambiguous, a safe fix renames it.

Severity follows the `unknown-parameters` setting (warn, error or ignore).

In a list of another kind (a channel list, tool data, the start-up list ...)
the name is looked up in that kind's catalogue, and an unknown name is only an
`info`: those catalogues are built from reference tables that hold part of the
vendor's parameters (params-chan.tsv has 560 of the roughly 1,009 channel
parameters), so a name missing from them may well be a real parameter. The
message says the catalogue was not complete enough to judge it, and names a
parameter only when the written name is very close to one (a typo of a known
name, or an index missing or too many); the rename is offered as an unsafe
fix, never applied by `--fix` alone. `unknown-parameters = "ignore"` silences
these too. When the list's content clearly is of another kind than the start-up
entry that names it says (an axis list named by `sda_mds[i]`: LIS523 on that
entry), a name of that other kind is told as such instead.

A name that is not an axis parameter but one of another kind of list
(`wz[1].laenge` of a tool data list, `dynamic_weighting[0].path_limit` of a
channel list) is told as such, with no rename: a list whose content is too
short to show its kind (one or two lines) is read as an axis list, and renaming
its names to the nearest axis parameter would rewrite a correct list. The
start-up list entry that names it (`werkz_data[i]`, `sda_mds[i]` ...) makes it
the kind it is; a list of another kind named by `achs_mds[i]` gets the same
message.

Why
---
The CNC reports an unknown name while reading the list and ignores the line,
so the value you wrote never takes effect, and the parameter you meant keeps
its default.

Example
-------
```
kenngr.ref_ricth                1
antr_simu.rpf_weg_bis_nip       200
```

Use instead
-----------
```
kenngr.ref_richt                1
antr.simu.rpf_weg_bis_nip       200
```

Reference
---------
Parameter catalogue (P-AXIS ids and paths); documented inconsistencies A.1–A.9.
Other kinds: their catalogues (`catalogue.kinds`, from params-chan.tsv,
params-stup.tsv, params-tool.tsv ... with P-CHAN, P-STUP, P-TOOL ... ids).
"""

from __future__ import annotations

import difflib
from collections.abc import Iterator
from typing import TYPE_CHECKING

from ..catalogue import fill_indices
from ..catalogue.kinds import BY_ID, ENTRY_KINDS, Kind, content_kind, path_index
from ..core.closest import ratio_bound
from ..core.diagnostics import Diagnostic, Severity
from ..syntax import parser as syntax
from ._common import replace_path_fix

if TYPE_CHECKING:
    from ..axis.analysis import Setting
    from .context import Context

CODE = "LIS101"
NAME = "unknown-parameter"
FIX = "sometimes"
SUMMARY = "Unknown parameter name"
INFO_WHEN_UNCHECKED = True  # a name another kind's partial catalogue lacks is not judged: info


def _with_indices(pattern: str, indices: tuple[int, ...]) -> tuple[str, bool]:
    """Fill the written indices into a suggested pattern; False when they do not fit."""
    count = pattern.count("[i]")
    if count == len(indices):
        return fill_indices(pattern, indices), True
    return fill_indices(pattern, (0,) * count), False


def _clear_winner(pattern: str, candidates: list[str]) -> bool:
    """The best candidate is close (ratio >= 0.85) and clearly ahead of the next one (by 0.05 or more).

    The exact ratios (difflib's, slow) are worked out only when the fast upper bound cannot decide: a bound
    below 0.85 rules the best one out, and a runner-up bounded 0.05 below the best one is behind enough."""
    if ratio_bound(pattern, candidates[0]) < 0.85:
        return False
    ratio = difflib.SequenceMatcher(None, pattern, candidates[0]).ratio()
    if ratio < 0.85:
        return False
    if len(candidates) < 2 or ratio - ratio_bound(pattern, candidates[1]) >= 0.05:
        return True
    return ratio - difflib.SequenceMatcher(None, pattern, candidates[1]).ratio() >= 0.05


def _diagnose(ctx: Context, setting: Setting) -> tuple[str, str | None, str | None]:
    """(message, suggestion, fix applicability or None) for an unknown path."""
    path = setting.line.path or ""
    cat = ctx.catalogue
    pattern, indices = syntax.path_pattern(path)
    if setting.misspelt and setting.resolution is not None:
        target = setting.resolution.canonical
        return (
            f"unknown parameter `{path}` (a spelling found in manuals); the CNC name is `{target}`",
            target,
            "safe",
        )
    elsewhere = _other_kinds(path, pattern)
    if elsewhere:
        return elsewhere, None, None
    shape = cat.by_unindexed.get(pattern.replace("[i]", ""))
    if shape and len(shape) == 1:
        right = shape[0].path
        count = right.count("[i]")
        if count == 0:
            return f"`{shape[0].path}` is not an array; remove the index from `{path}`", right, "safe"
        suggestion, _ = _with_indices(right, indices)
        return (
            f"`{path}` needs {count} index{'es' if count > 1 else ''}: write `{suggestion}` "
            f"(indices are zero-based)",
            suggestion,
            None,
        )
    candidates = cat.suggest(path)
    if not candidates:
        return f"unknown parameter `{path}`; check the spelling against `achslint explain`", None, None
    best, fits = _with_indices(candidates[0], indices)
    unambiguous = fits and (candidates[0] == pattern.lower() or _clear_winner(pattern, candidates))
    message = f"unknown parameter `{path}`; did you mean `{best}`?"
    if len(candidates) > 1 and not unambiguous:
        others = ", ".join(f"`{_with_indices(c, indices)[0]}`" for c in candidates[1:])
        message += f" (other candidates: {others})"
    return message, best, "safe" if unambiguous else None


def _other_kinds(path: str, pattern: str) -> str | None:
    """For a name an axis list does not know: what it is when it is a parameter of another kind of list (that
    kind, its id, the start-up entry naming such a list), else None."""
    owners = path_index().get(pattern, ())
    if not owners:
        return None
    described = []
    for kind_id in owners:
        kind = BY_ID[kind_id]
        cat = kind.catalogue()
        parameter = cat.by_pattern.get(pattern) if cat is not None else None
        entries = [f"`{key}`" for key, named in ENTRY_KINDS.items() if named.table == kind.table]
        what = f"of a {kind.name}" + (f" ({parameter.id})" if parameter is not None else "")
        described.append(what + (f", named by the start-up entry {' or '.join(entries)}" if entries else ""))
    return (
        f"`{path}` is no axis-list parameter: it is a parameter {'; or '.join(described)}. An axis list "
        "cannot set it (the CNC ignores the line); if this file is such a list, it belongs in that start-up "
        "entry"
    )


def _diagnose_other_kind(ctx: Context, setting: Setting) -> tuple[str, str | None, str | None]:
    """(message, suggestion, fix applicability or None) for a name a partial kind catalogue lacks: a
    suggestion only for a missing or extra index or a clear, close winner, and never a safe rename."""
    path = setting.line.path or ""
    cat = ctx.catalogue
    pattern, indices = syntax.path_pattern(path)
    unknown = (
        f"unknown parameter `{path}` in this {ctx.kind_name}: not in achslint's catalogue of this kind, "
        f"which holds {len(cat.by_pattern)} of the vendor's {ctx.kind.prefix} parameters, so it is not checked"
    )
    shape = cat.by_unindexed.get(pattern.replace("[i]", ""))
    if shape and len(shape) == 1:
        right = shape[0].path
        count = right.count("[i]")
        if count == 0:
            return f"{unknown}; did you mean `{right}` (it is no array)?", right, "unsafe"
        suggestion, _ = _with_indices(right, indices)
        return f"{unknown}; did you mean `{suggestion}` (indices are zero-based)?", suggestion, None
    candidates = cat.suggest(path)
    if candidates:
        best, fits = _with_indices(candidates[0], indices)
        if fits and (candidates[0] == pattern.lower() or _clear_winner(pattern, candidates)):
            return f"{unknown}; did you mean `{best}`?", best, "unsafe"
    return unknown, None, None


def _of_content_kind(ctx: Context, setting: Setting, shown: Kind, parameter: str) -> str:
    """The message for a name of the kind the list's content shows, in a list read as another kind."""
    return (
        f"`{setting.line.path}` is a parameter of {shown.a_name} ({parameter}), not of a "
        f"{ctx.kind_name}, and this file's content is {shown.a_name}: it is read as a {ctx.kind_name} "
        f"because the start-up entry naming it says so (LIS523 there), where its lines set nothing"
    )


def check(ctx: Context) -> Iterator[Diagnostic]:
    mode = ctx.options.unknown_parameters
    if mode == "ignore":
        return
    severity = Severity.ERROR if mode == "error" else Severity.WARNING
    if not ctx.axis_list:
        yield from _check_other_kind(ctx)
        return
    for setting in ctx.settings:
        if setting.canonical is not None or syntax.is_misspelt_end(setting.line):  # known (Setting.known)
            continue
        message, suggestion, applicability = _diagnose(ctx, setting)
        line = setting.line
        start, end = ctx.path_span(line)
        fix = replace_path_fix(line, suggestion, applicability) if suggestion and applicability else None
        yield ctx.report(CODE, line, message, column=start, end_column=end, severity=severity, fix=fix)


def _check_other_kind(ctx: Context) -> Iterator[Diagnostic]:
    # A list whose content clearly is of another kind than the start-up entry names (LIS523 there): its names
    # are told as that kind's, not as names a partial catalogue may lack.
    shown = content_kind(ctx.file)
    other = shown.catalogue() if shown is not None and shown.prefix != ctx.kind.prefix else None
    for setting in ctx.settings:
        if setting.canonical is not None or syntax.is_misspelt_end(setting.line):  # known (Setting.known)
            continue
        parameter = other.resolve(setting.line.path or "") if other is not None else None
        if shown is not None and parameter is not None:
            message, suggestion, applicability = (
                _of_content_kind(ctx, setting, shown, parameter.parameter.id),
                None,
                None,
            )
        else:
            message, suggestion, applicability = _diagnose_other_kind(ctx, setting)
        line = setting.line
        start, end = ctx.path_span(line)
        fix = replace_path_fix(line, suggestion, applicability) if suggestion and applicability else None
        yield ctx.report(CODE, line, message, column=start, end_column=end, severity=Severity.INFO, fix=fix)
