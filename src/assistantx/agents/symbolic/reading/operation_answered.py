"""The answer to "Which do you mean: print or large-format plot?", the question the operation
chooser asks where the words said do not settle which of the office's services is meant (a
verb of one and a facility or size of another): the one service the answer names, by a word
of its verbs in any form ("print it", "plot"), its name said whole ("large-format plot") or
the name of a facility that offers it ("the plotter"). The request is then read again with
that service chosen, never with both ("... A1 if poss. large-format plot" read as a print and
a plot)."""

from __future__ import annotations

import re

from assistantx.core import language
from assistantx.core.office import Office, Operation

WHICH_OF = "Which do you mean: "
_LISTED = re.compile(r",\s*|\s+or\s+")


def operation_answered(office: Office, question: str, answer: str) -> str | None:
    """The id of the one operation listed in ``question`` that ``answer`` names, or None
    (another question, or an answer naming none or several)."""
    if not question.startswith(WHICH_OF):
        return None
    names = [n.strip() for n in _LISTED.split(question[len(WHICH_OF) :].rstrip("?"))]
    by_name = {op.name: op for op in office.operations}
    if len(names) < 2 or not all(n in by_name for n in names):
        return None  # not a question about the office's services
    said = set(_words(answer))
    found = [by_name[n] for n in names if _names(office, by_name[n], said)]
    return found[0].id if len(found) == 1 else None


def _names(office: Office, op: Operation, said: set[str]) -> bool:
    verbs = {f for v in op.verbs for w in _words(v)[:1] for f in language.verb_forms(w)}
    if said & (verbs | {w for v in op.verbs for w in _words(v)[:1]}):
        return True  # "print it", "plot"
    if set(_words(op.name)) <= said:
        return True  # "the large-format plot"
    facilities = (n for f in office.offering(op.id) for n in (f.name, *f.synonyms))
    return any(set(_words(n)) <= said for n in facilities)  # "the plotter"


def _words(text: str) -> list[str]:
    return language.fold(text).replace("-", " ").split()
