"""A service's verb said of a thing the service cannot take: "shred my coffee" where the
shredder takes papers and the kitchen makes coffee. The only thing of the office in the
request is a product made from nothing (a drink a machine makes), so the request had been read
as making one, its verb dropped (a coffee made and handed over for "shred my coffee"). A
service's verb whose object is such a product, where no service of that verb takes or makes
it, is declined in one line: "I can't shred a coffee." Nothing is made.

Only the verb of one of the office's own services that takes a thing (its input) and makes
nothing of it ("shred", "laminate", "heat"; "print a visitor pass" makes one), said right
before its object (after "my", a colleague's or an article), and only a product the office
makes from nothing (a facility's product, or a service's with no input): "shred my printout"
(made from a file, a paper) and "brew me a tea" (its maker's own verb) read as before."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import DETERMINERS
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language
from assistantx.core.office import Office, Operation
from assistantx.core.wording import a_thing

# whose the object is, said between the verb and it ("shred *my* coffee", "*Wang's* coffee")
_OWNERS = frozenset({"self", "person"})


def wrong_input(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """The decline of a service's verb said of a thing made from nothing that no service of
    that verb takes ("shred my coffee"); None otherwise."""
    office = terms.office
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    for n, verb in enumerate(mentions):
        if verb.kind != "cue" or verb.end - verb.start != 1:
            continue
        said = tokens[verb.start].word
        ops = _taking(office, said)
        if not ops:
            continue
        k, at = n + 1, verb.end
        if k < len(mentions) and mentions[k].start == at and mentions[k].kind in _OWNERS:
            if not mentions[k].possessive:
                return None  # "shred me ...": whom for, read as before
            k, at = k + 1, mentions[k].end
        while at < len(tokens) and tokens[at].word in DETERMINERS:
            at += 1
        if k >= len(mentions) or mentions[k].start != at or mentions[k].kind != "item":
            continue
        thing = mentions[k]
        if len(thing.ids) != 1 or not _made_from_nothing(office, thing.ids[0]):
            continue
        item = thing.ids[0]
        if any(op.input == item or op.product == item for op in _of_verb(office, said)):
            continue  # "print a visitor pass" where a press prints them: its maker's verb
        name = office.item_type(item).name
        return Finding(
            "unsupported",
            piece,
            f"{said} asked of {name}, which it cannot take",
            message=f"I can't {said} {a_thing(name)}.",
        )
    return None


def _of_verb(office: Office, word: str) -> list[Operation]:
    """The office's services asked for by ``word`` (or its lemma): "shred", "shredding"."""
    forms = {word, *language.verb_lemmas(word)}
    return [op for op in office.operations if forms & {v.lower() for v in op.verbs if " " not in v}]


def _taking(office: Office, word: str) -> list[Operation]:
    """The services of ``word`` that take a thing and make nothing of it (shred, laminate,
    heat): a verb of a service that makes something ("print", "copy") may make another
    thing too ("print a visitor pass" where a press makes them)."""
    return [op for op in _of_verb(office, word) if op.input is not None and op.product is None]


def _made_from_nothing(office: Office, item: str) -> bool:
    """Whether the office makes ``item`` from nothing: the product of a service that takes
    no thing, or a facility's product no service makes from a thing (a drink, a snack)."""
    making = [op for op in office.operations if op.product == item]
    if any(op.input is not None for op in making):
        return False  # "a printout": made from a file, a paper a shredder may take
    return bool(making) or any(item in f.products for f in office.facilities)
