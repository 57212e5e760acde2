"""Unplaced: "chuck Reed's clipboard in the van", "stick my torch on the shelf": a thing told
to go somewhere by a verb that is no errand the reader knows, into a place that names nothing
of the office (no person, room or facility). Asked, never read as a fetch for the requester:
what is done with the thing, and where it ends up, are both unknown.

A known errand verb keeps its place phrase as where the thing is ("bring me the clipboard on
the shelf"), and a place the office names is read by the later stages ("put my lunch in the
fridge" where a fridge is a facility); a waste container was declined before this rule
(``destructive``). Whom the favour is for ("chuck my tunic on the pump *for me*") places
nothing: the pump is still no place of the office, and where the tunic should go is asked."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.english import DETERMINERS
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# "in the van", "onto the shelf": where a put-request sends its thing.
_INTO = english.words("to_facility_prepositions") - {"to"}
# What a place phrase that names something of the office is.
_OFFICE_PLACES = frozenset({"person", "self", "place", "facility"})
# The verbs of placing that also give ("leave the embosser on the shelf for me": for the
# speaker to have).
_GIVING = english.words("placing_giving_verbs")
# Words between a thing and where it is told to go ("stick it *back* in the drawer").
_PARTICLES = frozenset({"back", "down", "over", "up", "away", "out"})


def unplaced(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    words = piece.words
    at = piece.verb_at(terms.en.lead_in)
    if at >= len(words) or not _unknown_verb(terms, words[at]):
        return None
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    told = [t.word for t in tokens]
    items = [m for m in mentions if m.kind == "item"]
    if not items:
        return None
    thing = items[0]
    placing = _without_favour(tokens, mentions, thing, giving=words[at] in _GIVING)
    if any(m.kind in _OFFICE_PLACES and not m.possessive for m in placing):
        return None  # "run it down to Dot", "put my lunch in the fridge"
    n = thing.end
    while n < len(told) and told[n] in _PARTICLES:
        n += 1  # "chuck it back in the van"
    if n >= len(told) or told[n] not in _INTO:
        return None  # the place, if any, is not where the thing is told to go
    k = n + 1
    while k < len(told) and told[k] in DETERMINERS:
        k += 1
    if k >= len(told) or told[k] in terms.en.modifier_prepositions:
        return None  # "put the kettle on", "stick it on for me": no place named
    if _service_word(terms, told[k + 1 if told[k] == "to" else k]):
        return None  # "stick my jump pack on charge": the office's service, read later
    if any(m.kind in _OFFICE_PLACES and m.start > n for m in placing):
        return None  # "leave my form on Hal's desk": a person's place, a delivery
    verb = next((j for j, w in enumerate(told) if w == words[at]), 0)
    said = " ".join(t.text for t in tokens[verb + 1 : thing.end])
    stop = next((j for j in range(k, len(told)) if told[j] == "for"), len(told))
    where = " ".join(t.text for t in tokens[n:stop])  # "on the pump", its "for me" left out
    return Finding(
        "unplaced",
        piece,
        f"unplaced: {words[at]} ... {where}",
        message=(
            f"Sorry, I'm not sure what to do with {said} ({where}). "
            f"{terms.capabilities()} Who should I bring it to?"
        ),
    )


def _without_favour(
    tokens: Sequence[Token], mentions: Sequence[Mention], thing: Mention, *, giving: bool
) -> list[Mention]:
    """The mentions less whom the favour is for: "chuck *my* tunic on the pump for me" (the
    speaker's own thing, onto words that name nothing of the office) says the pump is where
    it goes, and "for me" only whom it pleases; so does a colleague's thing ("stick Omar's
    cable ties in the snowcat for me", "for Zhang"), and any thing put by a verb of placing
    alone ("pop", "stick", "stash", "load"): read as a fetch for whom it pleases, the thing
    was handed over and never put where it was told to go. Only a verb that also gives
    (``giving``: "leave the embosser on the shelf for me") with a thing nobody is named as
    owning leaves it for the speaker to have, and a thing of the office named in the place
    ("turn my plan into a PDF for Bill") is read later: both as before."""
    owned = any(
        m.kind in ("self", "person") and m.possessive and m.end == thing.start for m in mentions
    )
    favour = [m for m in mentions if m.start > thing.end and tokens[m.start - 1].word == "for"]
    if (giving and not owned) or not favour:
        return list(mentions)
    named = [m for m in mentions if thing.end <= m.start < favour[0].start and m.kind != "word"]
    if named:
        return list(mentions)
    return [m for m in mentions if m not in favour]


def _service_word(terms: Terms, word: str) -> bool:
    """ "on *charge*", "in for a *wash*": a word that asks for a service of the office, so
    where the thing goes is that service."""
    return word in terms.lex.operation_words or word in terms.service_verbs


def _unknown_verb(terms: Terms, word: str) -> bool:
    """A verb in its plain form that names no errand of the reader nor service of the
    office ("chuck", "stick", "put")."""
    if word not in language.verb_lemmas(word):
        return False
    return not (
        word in terms.lex.cue_words
        or word in terms.service_verbs
        or word in terms.en.service_verbs
        or word in terms.lex.operation_words
    )
