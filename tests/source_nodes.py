"""Every node of a Python file's syntax tree, walked once per test process: several tests look through all
of src/achslint for one kind of node (test_lint_engine.py, test_strategy_once.py, test_engine_facts.py), and
`ast.walk` over every module takes about 0.15 s each time."""

from __future__ import annotations

import ast
import functools
from pathlib import Path

from .conftest import source_tree


@functools.cache
def _walked(tree: ast.AST) -> tuple[ast.AST, ...]:
    return tuple(ast.walk(tree))


def nodes(path: Path) -> tuple[ast.AST, ...]:
    """The nodes of the file's tree (`conftest.source_tree`) in `ast.walk` order. Read them, never change
    them: the trees are shared."""
    return _walked(source_tree(path))
