"""The engine sequences a homing strategy runs, one module per kind; each `run(simulator, trace, start,
cam_shift)` drives the axis through `homing.motion` and returns the trace. A strategy in `homing/strategies/`
names its sequence in `simulate`."""
