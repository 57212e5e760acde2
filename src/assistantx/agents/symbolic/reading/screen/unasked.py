"""Unasked: a message none of whose pieces asks for anything is restated and asked before
anything moves ("Shall I pass Drew's file to you?"). Only a request moves the robot; a
sentence that tells ("Drew up tomorrow's interview list. It's miles longer than last week's")
must not become one because a word of it names a colleague or a thing. The rules for
statements read the kinds of telling they know; this is the net under them, for the kinds no
rule knows yet, on any office.

A piece asks when it has request wording (an imperative or a plain verb first, a polite
question, one's own need, a third person's need, someone's work on the speaker's thing), a
question mark, or a word that asks however short it is ("pls", "asap", "thanks"). A bare
fragment that opens with the thing wanted, after its determiners, owner and describing
words ("stapler", "my lunch from the fridge", "Wang's stapler on my desk", "two coffees",
"something to cut this with"), is a request said short and is read as before, and so is the
speaker's own lack of a thing ("I've run out of wipes", ``statement.told_lack``): said to
the assistant, a want."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.destructive import commanded
from assistantx.agents.symbolic.reading.screen.english import DETERMINERS
from assistantx.agents.symbolic.reading.screen.pieces import Piece
from assistantx.agents.symbolic.reading.screen.statement import told_lack
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english, language

_ASKING = english.words("asking_words")
_QUANTITIES = english.words("object_quantifiers") | frozenset(
    {"some", "any", "another", "more", "one", "few", "couple", "of", "extra", "spare", "new"}
)
_WANTING = english.words("need_verbs") | frozenset({"needed", "wanted", "wanna"})
_OWN = frozenset({"my", "our", "your", "his", "her", "their"})
_ANY_THING = frozenset({"something", "anything", "smth", "sth", "summat"})


def unasked(terms: Terms, kept: list[Piece]) -> bool:
    """Whether no piece of ``kept`` asks for anything, and none is a request said short."""
    return bool(kept) and not any(
        _asks(p) or commanded(terms, p) or _bare_request(p) or told_lack(terms, p) for p in kept
    )


def _asks(piece: Piece) -> bool:
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return True
    if acts.need or acts.owner_work or acts.note_asks:
        return True
    if any(m.kind == "cue" for m in piece.lexed.mentions):
        return True  # a task word anywhere ("cld u get me ...", "needs stamping", "hoping to
        # borrow"): the rules for requests read it; the net is for messages with none
    return bool(set(piece.words) & (_ASKING | _WANTING))


def _bare_request(piece: Piece) -> bool:
    """ "stapler", "my lunch from the fridge", "Wang's stapler", "two coffees": the thing
    wanted first, after its determiners, owner, amount and describing words."""
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    said = content([t.word for t in tokens])
    if not said:
        return False
    skip = len(tokens) - len(said) if [t.word for t in tokens][-len(said) :] == said else 0
    if said[0] in _ANY_THING:
        return True  # "something to cut this with": the thing wanted, by its use
    starts = {m.start: m for m in mentions}
    k = skip
    while k < len(tokens):
        m = starts.get(k)
        if m is not None and m.kind in ("item", "cue"):
            # the thing wanted, or a task word first ("printe my file": a typo the lexicon
            # reads as "print", an imperative the speech acts did not see)
            return m.kind == "item" or k == skip
        if m is not None and m.kind in ("person", "pronoun") and m.possessive:
            k = m.end  # "Wang's stapler", "her mug"
            continue
        word = tokens[k].word
        if word in DETERMINERS or word in _OWN or word in _QUANTITIES or word.isdigit():
            k += 1
            continue
        if "ADJ" in language.lemmas(word) and not language.verb_lemmas(word):
            k += 1  # "a big stapler", "cold water"
            continue
        return False
    return False
