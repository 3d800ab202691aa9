"""A machine: its start-up list (`startup`), channel lists (`channel`), homing programs (`program`), the
value objects they become (`model`) and how they are put together (`build`).

Above the rules in this package sit the machine dry-run (`run`, `scenario`) and its explanation (`explain`);
the layering test knows the order.
"""
