"""Narrative: "Blaze flew brilliantly today, 2 mins to the lure and straight back to the fist",
"the demo went great today, 5 mins on the projector and straight back to the laptop": news told,
a subject and its past verb, with verbless fragments after it that say how it went. Nothing is
asked: the things the fragments name (the lure, the glove) are where the story went, never
things to fetch for the speaker. It had carried them.

Two rules, each on a piece that asks nothing itself (no request wording, no imperative, no
question, no need or wish, no "please", no modal):

- ``told_subject``: a capitalised word that is nobody and nothing of the office, then a past
  verb ("Blaze flew ..."): the subject of a statement, never a name to ask about (it had been
  read as a request nobody could make sense of: "What should I do?").
- ``narrative_fragment``: a piece with no verb after such a statement, in a message that asks
  nothing anywhere, whose every thing of the office comes after a preposition ("to the lure",
  "back to the fist"): where the story went. A fragment that names its thing first ("Wang flew
  in today, a coffee for her") still asks for it, as does any message with a request in it
  ("Wang flew in today, bring her a coffee")."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import COMMON
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english, language

# Words that ask, however the piece is shaped ("please", "pls"), the helping verbs of an ask
# ("could", "would", "can"), and the words of a want or need.
_ASKING = (english.words("asking_words") - english.words("thanks_words") - {"now"}) | english.words(
    "modal_auxiliaries"
)
_WANTS = english.words("narrative_wants")
# What may come between a preposition and its thing ("to *the* lure", "on *my* laptop").
_DETERMINERS = english.words("determiners")
_PREPOSITIONS = english.words("narrative_prepositions")
# Words that are no name however they are spelt ("We", "Ours", "Someone"): the speaker, their
# own, anyone.
_NO_NAME = COMMON | english.words("unnamed_subjects")
# The subjects a clause of its own opens with: no fragment of the news.
_SUBJECTS = english.words("narrative_subjects")
# The kinds of mention a fragment may name only after a preposition.
_THINGS = frozenset({"item", "cue", "facility"})


def told_subject(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if _asks(piece) or not _capitalised_subject(terms, piece):
        return None
    return Finding("statement", piece, "news of someone or something outside the office, told")


def narrative_fragment(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if any(_asks(p) for p in msg.pieces):
        return None
    if not any(p.end <= piece.start and _told_past(terms, p) for p in msg.pieces):
        return None
    words = content(piece.words)
    if not words or any(_verb(w) for w in words) or set(words) & _SUBJECTS:
        return None  # "I'm sending everything out": a clause of its own, read as before
    tokens = piece.lexed.tokens
    for m in piece.lexed.mentions:
        if m.kind not in _THINGS:
            continue
        k = m.start - 1
        while k >= 0 and tokens[k].word in _DETERMINERS:
            k -= 1
        if k < 0 or tokens[k].word not in _PREPOSITIONS:
            return None  # "a coffee for her": the thing said first is asked for
    return Finding("statement", piece, "how the news told went, asking nothing")


def _asks(piece: Piece) -> bool:
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return True
    if acts.need or acts.wish or acts.note is not None or acts.condition or acts.owner_work:
        return True
    return bool(set(piece.words) & (_ASKING | _WANTS))


def _past(word: str) -> bool:
    """A simple past verb ("flew", "went"), never a present one ("needs")."""
    return (
        language.is_finite_verb(word)
        and language.is_past_verb(word)
        and not language.is_third_person_verb(word)
    )


def _verb(word: str) -> bool:
    """A finite verb that is no noun too ("flew", "went"; never "mins" or "books")."""
    return language.is_finite_verb(word) and not language.is_noun(word)


def _capitalised_subject(terms: Terms, piece: Piece) -> bool:
    """ "Blaze flew ...": a capitalised first word that no mention of the office covers and no
    word of the office is, then a simple past verb."""
    tokens = piece.lexed.tokens
    if len(tokens) < 2 or not tokens[0].text[:1].isupper() or tokens[0].possessive:
        return False
    first = tokens[0].word
    if first in _NO_NAME or not tokens[0].text.isalpha():
        return False  # "We've got ...", "Ours went ...": no name told of (a contraction neither)
    if first in terms.office_words or first in terms.lex.cue_words or tokens[0].corrected:
        return False
    if any(m.start == 0 and m.kind != "word" for m in piece.lexed.mentions):
        return False
    return _past(tokens[1].word)


def _told_past(terms: Terms, piece: Piece) -> bool:
    """A statement told in the past ("the demo went great", "Blaze flew brilliantly")."""
    if _asks(piece) or piece.acts.world_wish:
        return False  # "I wish we had a GC-MS": a wish, no news
    if _capitalised_subject(terms, piece):
        return True
    return piece.acts.statement and any(_past(w) for w in content(piece.words)[1:])
