"""Linting: the one rule loop for every scope (`engine`), one list (`linter`), NC programs (`program`), the
settings (`config`), `noqa` (`suppression`) and `lint --fix` (`fixer`).

Named `linting`, not `lint`: `achslint.lint` is the library function the package exports.
"""
