"""Generate realistic axis lists from the catalogue (valid names, typed default values)."""

from __future__ import annotations

import itertools
import random

from achslint.catalogue import BOOL, INTEGER, REAL, STRING, SYMBOL, catalogue, fill_indices


def _value(parameter) -> str:
    default = parameter.typed_default
    kind = parameter.kind
    if kind == BOOL:
        return "1" if default else "0"
    if kind == SYMBOL:
        return default or parameter.symbols[0]
    if kind == STRING:
        return default or "NAME"
    if kind == REAL:
        return repr(float(default or 0.0))
    if kind == INTEGER:
        if isinstance(default, int):
            return str(default)
        return str((parameter.symbol_codes and next(iter(parameter.symbol_codes.values()))) or 0)
    return "0"


def all_paths() -> list[tuple[str, object]]:
    """Every concrete path the catalogue allows (2534), with its parameter."""
    result = []
    for parameter in catalogue().parameters:
        if parameter.id == "P-AXIS-00015":
            continue
        for indices in itertools.product(*(range(low, high + 1) for low, high in parameter.index_bounds)):
            result.append((fill_indices(parameter.path, indices), parameter))
    return result


def axis_list(lines: int, seed: int = 1) -> str:
    """About `lines` assignment lines, column-aligned with `( P-AXIS-…` comments, ending with Ende.

    Up to 2534 lines every path is distinct; longer lists repeat the set (as a
    list concatenated from several exports would), which the duplicate rule reports.
    """
    rng = random.Random(seed)
    paths = all_paths()
    rng.shuffle(paths)
    out = [
        "# generated benchmark list",
        "kopf.achs_nr                                          1        ( P-AXIS-00016",
    ]
    position = 0
    while len(out) < lines:
        path, parameter = paths[position % len(paths)]
        position += 1
        if parameter.id == "P-AXIS-00016":
            continue
        out.append(
            f"{path:<46}{_value(parameter):>16}        ( {parameter.id} : {_ascii(parameter.summary[:40])}"
        )
    out.append("Ende")
    return "\r\n".join(out) + "\r\n"


def _ascii(text: str) -> str:
    return text.encode("ascii", "replace").decode("ascii")
