"""A thing told to go into a vehicle or a home: "put Wang's stapler in my car", "leave the
scissors in Wang's van", "pop my book in the boot". Any verb ("put", "leave", "stick"), the
thing, then "in"/"into"/"to" a car, a van, someone's house: that is outside the office, where
the robot never goes, so the request is declined in words, with the reason (and, where the
thing is a colleague's, that it would need their yes anyway). It is never "Noted" (a placement
is a request, however its verb reads) and never read as a fetch for the requester.

Words that are part of the name of one of the office's operations ("send out on the van")
name that service, not a place: "send my contract out on the van to Fairfield Farm" asks for
it. "bring my contract to the van" says no service's name and is declined as ever.

Where the speaker says they did it ("I put my book in my car") it is their own doing, read by
the other rules; a place of the office ("on my desk", "in the fridge") is a delivery, read as
before."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import DETERMINERS
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english, language

_OUTSIDE = english.words("outside_containers") | english.words("home_nouns")
_INTO = english.words("to_facility_prepositions")  # "in", "into", "to" ...
_OFFICE = frozenset({"place", "facility", "group"})
# the speaker (or a colleague) as the subject before the verb: told, not asked
_SUBJECTS = frozenset({"i", "we", "ive", "id", "he", "she", "they", "someone", "somebody"})
_PARTICLES = frozenset({"back", "down", "over", "up", "away", "out", "it", "them"})
# "(we)'re out of ties on the van", "(it)'s in my car", "have some in the van": a verb of being
# or having (its subject dropped with the contraction) tells where things are, asks nothing
_STATES = frozenset({"be", "have"})


def _service_named(terms: Terms, said: list[str]) -> bool:
    """Whether ``said`` ("on the van") is said inside the name of one of the office's
    operations ("send out on the van"): the service is named, not a place outside asked for;
    its own destination ("to Fairfield Farm") is read by the send-out rules."""
    size = len(said)
    for op in terms.office.operations:
        name = [w.casefold() for w in op.name.split()]
        if any(name[n : n + size] == said for n in range(len(name) - size + 1)):
            return True
    return False


def outside_vehicle(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    del msg, requester
    if piece.asks and not piece.acts.request:
        return None  # "did you put it in my car?": asked about, not asked for
    words = piece.words
    verb = piece.verb_at(terms.en.lead_in)
    if verb >= len(words) or not language.verb_lemmas(words[verb]):
        return None
    if language.verb_lemmas(words[verb]) & _STATES:
        return None  # "we're out of zip ties on the van": where a lack is, no placement
    if _SUBJECTS.intersection(words[:verb]) or any(
        m.kind == "person" and not m.possessive for m in piece.lexed.mentions
    ):
        return None  # "I put my book in my car", "Wang left it in his van": told
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    told = [t.word for t in tokens]
    thing = next((m for m in mentions if m.kind in ("item", "pronoun")), None)
    if thing is None:
        return None
    n = thing.end
    while n < len(told) and told[n] in _PARTICLES:
        n += 1  # "leave it back in the van"
    if n >= len(told) or told[n] not in _INTO:
        return None
    k = n + 1
    while k < len(told) and (told[k] in DETERMINERS or tokens[k].possessive):
        k += 1  # "in my car", "in Wang's van"
    if k >= len(told) or told[k] not in _OUTSIDE:
        return None
    if any(m.kind in _OFFICE and m.start <= k < m.end for m in mentions):
        return None  # a place of the office that shares the word
    if _service_named(terms, told[n : k + 1]):
        return None  # "send it out on the van": the words of a service's own name
    owner = next(
        (m for m in mentions if m.kind == "person" and m.possessive and m.end <= thing.start),
        None,
    )
    theirs = ""
    if owner is not None and len(owner.ids) == 1:
        name = terms.office.person(owner.id).name
        theirs = f" It is {name}'s, too, so it would need their yes anyway."
    where = " ".join(t.text for t in tokens[n + 1 : k + 1])  # "my car"
    return Finding(
        "unsupported",
        piece,
        f"a place outside the office: {where}",
        message=(
            f"Sorry, I can't take things outside the office ({where} is not a place here): "
            f"I only go to people and places here.{theirs} If someone here should have it, "
            "tell me who. I did nothing."
        ),
    )
