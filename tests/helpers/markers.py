"""What a `-m` marker expression selects, asked before collection."""

from __future__ import annotations

import functools
import itertools
import re

from _pytest.mark.expression import Expression


def _carries(present: set[str], name: str, /, **_kwargs: object) -> bool:
    return name in present


def never_selects(markexpr: str, marker: str) -> bool:
    """Whether `-m markexpr` deselects every test carrying ``marker``, whatever other markers
    that test has (each other name in the expression is tried both ways)."""
    if not markexpr:
        return False
    expression = Expression.compile(markexpr)
    names = sorted(set(re.findall(r"[A-Za-z_][\w.]*", markexpr)) - {"and", "or", "not", marker})
    for values in itertools.product((False, True), repeat=len(names)):
        present = {marker, *(n for n, v in zip(names, values, strict=True) if v)}
        if expression.evaluate(functools.partial(_carries, present)):
            return False
    return True
