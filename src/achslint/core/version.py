"""The package's version, written here and nowhere else: pyproject.toml reads it (hatch's version source),
`achslint --version`, SARIF's tool record and the language server report it, `achslint.__version__` is
this one, and CHANGELOG.md's newest release heading names it."""

__version__ = "0.1.0"
