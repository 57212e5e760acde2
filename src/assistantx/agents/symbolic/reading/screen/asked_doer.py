"""A colleague asked to run a facility they do not run: "could you get Zhang to make me a
copy", "ask Lee to print my file" where neither keeps the printer.

The work of a facility is done by the people who keep it (its guards); a request that names
someone else to do it cannot be done as said, and doing it by a guard instead would be a
choice the requester did not make. So it is asked: "Zhang Wei doesn't run the printer. Shall
I get it done at the printer instead?", a yes carrying out the request without the named
doer. Where the one named keeps a facility that runs the work, the request is read as usual.
"""

from __future__ import annotations

from assistantx.agents.symbolic.reading.asking_forms import asking_forms
from assistantx.agents.symbolic.reading.screen.english import split_words
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core.office import Office, Operation

# The verbs that ask a colleague to do something: "get Zhang to ...", "ask Lee to ...".
_ASKING = frozenset({"get", "ask", "have", "tell"})
# Verbs that ask for a thing to be made ("make me a copy"): the thing names the work.
_MAKING = frozenset({"make", "do", "produce"})


def asked_doer(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    words = piece.words
    for at, w in enumerate(words):
        if w not in _ASKING or at + 2 >= len(words):
            continue
        person = _one_person(terms, words[at + 1])
        if person is None or person == requester:
            continue
        rest = words[at + 2 :]
        if rest[0] != "to" and w != "have":
            continue
        op = _work_asked(terms.office, rest[1:] if rest[0] == "to" else rest)
        if op is None:
            continue
        runs = [f for f in terms.office.facilities if op.id in f.operations]
        if not runs or any(person in f.guards for f in runs):
            return None  # they keep a facility that runs it, or no facility does (declined)
        return _asked(terms, msg, piece, person, runs[0].name, words[at : at + 3])
    return None


def _one_person(terms: Terms, word: str) -> str | None:
    ids = terms.lex.people.get(word, set()) | terms.lex.name_words.get(word, set())
    return next(iter(ids)) if len(ids) == 1 else None


def _work_asked(office: Office, words: list[str]) -> Operation | None:
    """The operation the words after "to" ask for: by its verb ("copy my report"), or a
    making verb and the name of its product ("make me a copy")."""
    if not words:
        return None
    for op in office.operations:
        if not office.runnable(op.id):
            continue
        if _whole_verb_said(op, words):
            return op
        if words[0] in _MAKING and op.product is not None:
            product = office.item_type(op.product)
            # a one-word name only: the "copy" of "hard copy" is no printout asked for
            names = {
                w[0]
                for name in (product.name, *product.synonyms)
                if len(w := split_words(name)) == 1
            }
            names |= {n + "s" for n in names}
            if any(w in names for w in words[1:6]):
                return op
    return None


# the most words of an object between a verb and its particle ("send *the drive* off")
_OBJECT_WORDS = 4


def _whole_verb_said(op: Operation, words: list[str]) -> bool:
    """Whether the words say one of ``op``'s verbs whole: a one-word verb by its head, a verb
    with a particle ("send off") with the particle said within a short object after it ("get
    Ravi to send me his mix" asks no courier's "send off")."""
    for verb in op.verbs:
        head, *rest = split_words(verb)
        if words[0] not in asking_forms(head):
            continue
        if not rest or any(w == rest[0] for w in words[1 : 2 + _OBJECT_WORDS]):
            return True
    return False


def _asked(
    terms: Terms, msg: Message, piece: Piece, person: str, facility: str, said: list[str]
) -> Finding:
    name = terms.office.person(person).name
    # the request without the named doer: "could you get Zhang to make me a copy" → "could
    # you make me a copy"
    lowered = msg.text.lower()
    start = lowered.find(f"{said[0]} ")
    end = lowered.find(" to ", start) + len(" to ") if said[2] == "to" else -1
    if start < 0 or end < start:
        start = lowered.find(f"{said[0]} ")
        end = lowered.find(f" {said[1]} ", start) + len(f" {said[1]} ")
    offer = f"{msg.text[:start]}{msg.text[end:]}".strip()
    return Finding(
        "instead",
        piece,
        f"{name} asked to do work at the {facility}, which they do not run",
        message=(
            f"{name} doesn't run the {facility}, so I can't have them do it. Shall I get it "
            f"done at the {facility} instead?"
        ),
        offer=offer,
    )
