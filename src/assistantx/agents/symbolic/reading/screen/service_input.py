"""Which of several things stated before a service asked on "it" the service works on: "my
contract's got coffee on it, could you photocopy it" states a contract and a coffee, but only
the contract is what photocopying takes, so "it" is the contract. Read from the office's own
operations (their verbs and inputs), never from the sentence."""

from __future__ import annotations

import functools
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language
from assistantx.core.office import Office


@functools.cache
def _inputs_by_form(office: Office) -> dict[str, frozenset[str]]:
    """Each form of an operation's verb → the item types the operations it asks for take."""
    out: dict[str, set[str]] = {}
    for op in office.operations:
        if op.input is None:
            continue
        for verb in op.verbs:
            for form in language.verb_forms(verb):
                if " " not in form:
                    out.setdefault(form, set()).add(op.input)
    return {form: frozenset(types) for form, types in out.items()}


def worked_on(terms: Terms, text: str, stated: Sequence[str]) -> str | None:
    """The one entry of ``stated`` ("type|whose") whose thing every service asked in ``text``
    takes as its input; None where no service is asked, or none or several stated things fit."""
    forms = _inputs_by_form(terms.office)
    asked = [forms[t.word] for t in terms.lex.tokens(text) if t.word in forms]
    if not asked:
        return None
    fits = [s for s in stated if all(s.partition("|")[0] in types for types in asked)]
    if len({s.partition("|")[0] for s in fits}) != 1:
        return None
    return fits[-1]
