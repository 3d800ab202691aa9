"""One module per homing strategy; `homing.registry.STRATEGY_MODULES` lists them in classification order."""
