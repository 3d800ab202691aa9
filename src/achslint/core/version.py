"""The package's version, as pyproject.toml gives it: `achslint --version`, SARIF's tool record and the
language server report it; `achslint.__version__` is this one."""

__version__ = "0.1.0"
