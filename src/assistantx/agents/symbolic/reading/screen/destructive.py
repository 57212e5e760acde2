"""Destructive: "throw away Wang's stapler", "hide ...", "get rid of ...": declined, unless
the office offers it as a service ("shred" where a shredder is). So is a request that puts a
thing into a waste container ("chuck Reed's clipboard in the skip"), whatever its verb: a
verb the reader does not know must not turn disposal into an errand, and the container, no
place of the office, is no destination to deliver to."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import DETERMINERS, starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece, sub_pieces
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english, language

# "in the skip", "into a bin", "to the rubbish": where a put-request sends its thing.
_INTO = english.words("to_facility_prepositions") | {"down"}


def destructive(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    for sub in sub_pieces(piece):
        at = sub.verb_at(terms.en.lead_in)
        for verb in terms.en.destructive:
            if verb[0] in terms.lex.operation_words:
                continue  # "shred my drafts" where a shredder is offered: a service
            if starts_with(sub.words, at, verb):
                return _declined(terms, piece, " ".join(verb))
    if commanded(terms, piece) and (container := _waste_container(terms, piece)) is not None:
        return _declined(terms, piece, f"put things in the {container}", what="")
    return None


def commanded(terms: Terms, piece: Piece) -> bool:
    """Whether the piece tells the robot to do something: request wording, or a verb in its
    plain form first, after any lead-in or not ("chuck ...", "ditch ...", "go to Zhang's desk
    and take ..."), a verb the office's words need not know."""
    if piece.acts.request:
        return True
    words = piece.words
    at = piece.verb_at(terms.en.lead_in)
    return any(k < len(words) and words[k] in language.verb_lemmas(words[k]) for k in {0, at})


def _waste_container(terms: Terms, piece: Piece) -> str | None:
    """The waste container a request puts its thing into ("in the skip"), unless the words
    are the office's own facility ("the confidential recycling bin", a service there)."""
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    words = [t.word for t in tokens]
    for n, word in enumerate(words):
        if word not in _INTO or n == 0:
            continue
        k = n + 1
        while k < len(words) and words[k] in DETERMINERS:
            k += 1
        for phrase in terms.en.waste_containers:
            end = k + len(phrase)
            if not starts_with(words, k, phrase):
                continue
            office_name = any(
                m.kind in ("facility", "item", "place") and m.start < end and k < m.end
                for m in mentions
            )
            if not office_name:
                return " ".join(phrase)
    return None


def _declined(terms: Terms, piece: Piece, said: str, what: str = " anything") -> Finding:
    return Finding(
        "destructive",
        piece,
        f"destructive: {said}",
        message=(
            f"Sorry, I won't {said}{what}: I don't dispose of, damage or take "
            f"people's things. {terms.capabilities()}"
        ),
    )
