"""No module names an operation, product or facility of the default office (issue 16).

The office file declares them and ``task_schema`` holds the task contract; every other
module must get them from the office. The test reads every module's string literals (not
its docstrings or comments, which may use the default office for examples) and fails on any
that names one. Two words are exempt because they are the task schema's own kinds and lock
purposes as well as operation ids of the default office: "print", "copy" and "heat" (see
``task_schema.SHAPE_KIND``). ``nav/office_map_gen.py`` draws the default office's floor plan
and is exempt as a whole.
"""

from __future__ import annotations

import ast
import functools
import re
from pathlib import Path

import pytest
import yaml

from assistantx.core import task_kinds

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src" / "assistantx"
ALLOWED_MODULES = {"core/office.py", "core/task_schema.py", "nav/office_map_gen.py"}
SCHEMA_WORDS = {"print", "copy", "heat"}


def _default_office_words() -> set[str]:
    office = yaml.safe_load((ROOT / "dataset" / "office.yaml").read_text(encoding="utf-8"))
    words: set[str] = set()
    for op in office["operations"]:
        words.add(op["id"])
        if op.get("product"):
            words.add(op["product"])
    products = {t["id"]: t for t in office["item_types"] if t.get("kind") == "product"}
    for t in products.values():
        words |= {t["id"], t["name"]}
    for f in office["facilities"]:
        words |= {f["id"], f["name"], f["id"].replace("_", " ")}
    return words - SCHEMA_WORDS


WORDS = sorted(_default_office_words())
PATTERN = re.compile(r"\b(" + "|".join(re.escape(w) for w in WORDS) + r")\b")


def _strings(tree: ast.AST) -> list[tuple[int, str]]:
    """String constants that are not docstrings, with their line numbers (one walk)."""
    docstrings: set[int] = set()
    constants: list[ast.Constant] = []
    for node in _walked(tree):
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            constants.append(node)
        elif (
            isinstance(node, ast.Module | ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef)
            and node.body
            and isinstance(node.body[0], ast.Expr)
            and isinstance(node.body[0].value, ast.Constant)
        ):
            docstrings.add(id(node.body[0].value))
    return [(node.lineno, node.value) for node in constants if id(node) not in docstrings]


def test_the_word_list_is_the_default_office() -> None:
    assert {"printer", "coffee_machine", "vend", "snack", "printout", "fridge"} <= set(WORDS)


def _modules(exempt: set[str]) -> list[str]:
    """Every module of the package, as a path under ``src/assistantx``, less ``exempt``."""
    return sorted(rel for p in SRC.rglob("*.py") if (rel := str(p.relative_to(SRC))) not in exempt)


@functools.cache
def _walked(tree: ast.AST) -> tuple[ast.AST, ...]:
    """Every node of a tree, walked once for both scans (a walk of the whole package is about
    as long as its parse); a tree is cached by its identity, as ``_tree`` keeps it alive."""
    return tuple(ast.walk(tree))


@functools.cache
def _tree(module: str) -> ast.Module:
    """The module's syntax tree, parsed once for both scans (parsing the package's 1.7 MB of
    source is about 2 CPU-s; the two scans share one xdist worker, below, to share it)."""
    return ast.parse((SRC / module).read_text(encoding="utf-8"))


# Both whole-package scans on one worker, so the second reuses the first's parsed trees.
_ONE_PARSE = pytest.mark.shares_worker("source_scan")


def _office_words_in(tree: ast.AST) -> list[str]:
    return [
        f"line {line}: {match.group(0)!r} in {text[:60]!r}"
        for line, text in _strings(tree)
        for match in [PATTERN.search(text)]
        if match is not None
    ]


@_ONE_PARSE
def test_no_module_names_a_default_office_word() -> None:
    # One scan of every module (a test per module made 190 tests of this one check); the
    # message names every offending module, not only the first.
    found = {
        module: hits
        for module in _modules(ALLOWED_MODULES)
        if (hits := _office_words_in(_tree(module)))
    }
    assert not found, found


def test_the_word_check_sees_a_word() -> None:
    assert _office_words_in(ast.parse('"""The printer."""\nPLACE = "printer"\n')) == [
        "line 2: 'printer' in 'printer'"
    ]


# --- task kinds: listed by the task schema only -----------------------------------------------

TASK_KINDS = {k.id for k in task_kinds.kinds()} | set(task_kinds.part_kinds())
# Lock purposes share some words with task kinds, but they are the lock's wire protocol (what
# a code opens the locker for), not a reading of a request.
KIND_LIST_EXEMPT = {"core/ports/lock.py", "adapters/lock/protocol/controller.py"}
LOCK_ONLY_PURPOSES = {"deposit", "collect"}


def _listed_kinds(tree: ast.AST) -> list[tuple[int, list[str]]]:
    """Literal collections (tuples, lists, sets, dict keys, ``Literal[...]``) that name three
    or more task kinds: a module listing the kinds itself."""
    found: list[tuple[int, list[str]]] = []
    for node in _walked(tree):
        elements: list[ast.expr | None]
        if isinstance(node, ast.Tuple | ast.List | ast.Set):
            elements = list(node.elts)
        elif isinstance(node, ast.Dict):
            elements = list(node.keys)
        else:
            continue
        kinds = [
            e.value
            for e in elements
            if isinstance(e, ast.Constant) and isinstance(e.value, str) and e.value in TASK_KINDS
        ]
        purposes = [
            e for e in elements if isinstance(e, ast.Constant) and e.value in LOCK_ONLY_PURPOSES
        ]
        if len(set(kinds)) >= 3 and not purposes:  # a table of lock purposes is not one
            found.append((node.lineno, kinds))
    return found


@_ONE_PARSE
def test_no_module_lists_task_kinds() -> None:
    found = {
        module: listed
        for module in _modules({"core/task_schema.py"} | KIND_LIST_EXEMPT)
        if (listed := _listed_kinds(_tree(module)))
    }
    assert not found, found


def test_the_kind_check_sees_a_listing() -> None:
    tree = ast.parse('KINDS = ("print", "copy", "sign")\nX = Literal["transfer", "seal", "heat"]')
    assert [line for line, _ in _listed_kinds(tree)] == [1, 2]
