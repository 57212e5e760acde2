"""A withdrawal word that is also the office's own verb: "scrap my old tyre would you" where
the office scraps tyres asks for the service, not to drop what was asked. It is the service
when the words after it name the thing that operation works on ("my old tyre"); "scrap that",
"scrap it, never mind", "scrap the ruler" (a thing it never works on) still withdraw. A name
of the office's that begins with the word ("scrap cage open today?") is that name, never a
withdrawal."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.asking_forms import asking_forms
from assistantx.agents.symbolic.reading.lexicon import Lexicon, key_of


def service_asked(lex: Lexicon, head: tuple[str, ...], rest: list[str]) -> bool:
    """Whether ``head`` (a withdrawal head, "scrap") followed by ``rest`` is no withdrawal:
    an office operation of that verb on the thing it works on, or a name of the office's
    that begins with it."""
    if len(head) != 1 or not rest:
        return False
    whole = lex.scan(lex.tokens(" ".join([*head, *rest])))
    if any(m.kind in ("facility", "place", "item") and m.start == 0 for m in whole):
        return True  # "scrap cage open today?": the office's name begins with the word
    if head[0] not in lex.operation_words:
        return False
    inputs = {
        op.input
        for op in lex.office.operations
        if op.input is not None and any(head[0] in asking_forms(key_of(verb)) for verb in op.verbs)
    }
    if not inputs:
        return False
    mentions = lex.scan(lex.tokens(" ".join(rest)))
    return any(m.kind == "item" and inputs.intersection(m.ids) for m in mentions)
