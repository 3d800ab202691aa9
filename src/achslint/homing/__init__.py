"""Homing: the strategy registry, the homing value object and the strategies' data.

    classify(axis, gear, commanded=False) -> HomingStrategy
                                          first registered strategy whose `matches` holds: at
                                          power-up, or (commanded) what a G74 naming the axis runs
    effect(strategy, axis, path) -> Effect whether a parameter takes effect, and why
    HomingSetup(axis, gear)               the axis's homing values in mm and seconds
    motion.Simulator(axis, strategy, scenario).run() -> Trace
                                          the analytic simulation: the strategy's sequence
                                          (sequences/) over the axis's motion; the trace's facts
                                          are worded by the rules they belong to

Rules, `explain` and `dry-run` all import from here; adding a strategy means one
module in `strategies/`, one line in `registry.STRATEGY_MODULES` and fixtures.
"""

# The subpackage `strategies` is loaded before the function of that name is bound here: loading it later (the
# registry imports its modules on first use) would make `achslint.homing.strategies` the package.
from . import strategies as _strategy_modules  # noqa: F401
from .base import NEGATIVE, POSITIVE, HomingStrategy, Phase, StrategyDef, Use
from .parameters import HOMING_PARAMETERS
from .registry import (
    STRATEGY_MODULES,
    Effect,
    by_id,
    classify,
    effect,
    generic,
    homing_parameter_paths,
    is_homing_parameter,
    strategies,
    strategies_reading,
)
from .setup import POSITION, VELOCITY, Acceleration, HomingSetup

__all__ = [
    "HOMING_PARAMETERS",
    "NEGATIVE",
    "POSITION",
    "POSITIVE",
    "STRATEGY_MODULES",
    "VELOCITY",
    "Acceleration",
    "Effect",
    "HomingSetup",
    "HomingStrategy",
    "Phase",
    "StrategyDef",
    "Use",
    "by_id",
    "classify",
    "effect",
    "generic",
    "homing_parameter_paths",
    "is_homing_parameter",
    "strategies",
    "strategies_reading",
]
