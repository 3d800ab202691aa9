"""The strategy registry: classification is the first match in this order, and
whether a parameter takes effect is a lookup in the matching strategy's data."""

from __future__ import annotations

import importlib
import re
from collections.abc import Iterator
from dataclasses import dataclass
from functools import lru_cache

from ..axis.resolved import ResolvedAxis
from ..catalogue import AXIS_TYPE_NAMES
from .base import HomingStrategy, StrategyDef
from .parameters import HOMING_PARAMETERS, SELECTORS
from .setup import HomingSetup

# Classification order: what G74 does with the axis at all, then who runs the sequence, then the sequence.
STRATEGY_MODULES = (
    "disabled",
    "ignore_abs_pos",
    "gantry_slave",
    "absolute",
    "drive_controlled",
    "fixed_stop",
    "compatibility_none",
    "simulation",
    "spindle_flying_cam",
    "spindle_flying_zero_pulse",
    "zero_pulse_only",
    "one_phase_cam_zero_pulse",
    "one_phase_cam",
    "cam_zero_pulse",
    "cam_only",
)


_LOADED: dict[str, StrategyDef] = {}


def _definitions() -> Iterator[StrategyDef]:
    """The strategies in classification order, each module imported when first reached: a lint classifies
    its axis after a few of them, and need not load the others with their sequences (cold start)."""
    for name in STRATEGY_MODULES:
        definition = _LOADED.get(name)
        if definition is None:
            module = importlib.import_module(f"{__package__}.strategies.{name}")
            definition = _LOADED.setdefault(name, module.STRATEGY)
        yield definition


@lru_cache(maxsize=1)
def strategies() -> tuple[StrategyDef, ...]:
    return tuple(_definitions())


def by_id(strategy_id: str) -> StrategyDef:
    for definition in _definitions():
        if definition.id == strategy_id:
            return definition
    raise KeyError(strategy_id)


def classify(axis: ResolvedAxis, gear: int = 0, *, commanded: bool = False) -> HomingStrategy:
    """The strategy of the axis (gear stage `gear` for speeds): the one place a strategy is chosen.

    By default what the axis does at power-up, as `lint`, `explain` and the single-axis dry-run report it;
    `commanded=True` gives what a G74 that names the axis runs. The two differ only for an axis whose strategy
    is `power_up_only` (an absolute encoder): its position is valid at power-up, yet a G74 naming it still runs
    its homing type (P-AXIS-00299 remark), i.e. the next strategy that matches."""
    for definition in _definitions():
        if commanded and definition.power_up_only:
            continue
        if definition.matches(axis):
            setup = HomingSetup(axis, gear)
            return HomingStrategy(
                definition,
                setup,
                definition.describe(axis),
                definition.phases(setup),
                definition.variants(setup),
            )
    raise AssertionError("the last strategy matches every axis")  # pragma: no cover


@dataclass(frozen=True)
class Effect:
    """Whether a parameter takes effect on this axis, why, and what decides it."""

    effective: bool
    reason: str
    cause: str  # "strategy", "axis type" or "drive type"


_GEAR = re.compile(r"getriebe\[\d+\]")


@lru_cache(maxsize=4096)
def generic(path: str) -> str:
    """`getriebe[2].vb_reflow` -> `getriebe[i].vb_reflow` (and the second cam input as the first)."""
    return _GEAR.sub("getriebe[i]", path).replace("lr_hw[1]", "lr_hw[0]")


def is_homing_parameter(path: str) -> bool:
    return generic(path) in _HOMING


_HOMING = frozenset(HOMING_PARAMETERS)


def effect(strategy: HomingStrategy, axis: ResolvedAxis, path: str) -> Effect:
    """Whether a parameter (canonical path) takes effect on the axis under its strategy, and why."""
    key = generic(path)
    if key in SELECTORS:
        return Effect(True, "selects the homing strategy", "strategy")
    parameter = axis.parameter(path)
    if parameter.axis_types and axis.axis_type not in parameter.axis_types:
        wanted = ", ".join(AXIS_TYPE_NAMES[a] for a in parameter.axis_types)
        return Effect(False, f"only for {wanted} axes ({parameter.id})", "axis type")
    if parameter.drive_group and axis.drive_type not in parameter.drive_group:
        names = axis.catalogue.drive_type_names
        wanted = ", ".join(names.get(code, str(code)) for code in parameter.drive_group)
        return Effect(False, f"only with drive type {wanted}", "drive type")
    use = strategy.definition.parameters.get(key)
    if use is not None:
        effective, reason = use.applies(axis)
        return Effect(effective, reason, "strategy")
    return Effect(False, strategy.definition.unused or f"not read by {strategy.title}", "strategy")


def homing_parameter_paths(gear: int = 0) -> list[str]:
    return [p.replace("[i]", f"[{gear}]") for p in HOMING_PARAMETERS]


def strategies_reading(path: str) -> list[StrategyDef]:
    """The registered strategies whose data lists a parameter (generic or canonical path)."""
    key = generic(path.replace("[i]", "[0]"))
    if key in SELECTORS:
        return list(strategies())
    return [d for d in strategies() if key in d.parameters]
