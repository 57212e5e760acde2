"""Hope: "really hope Otto gets his phone back from lost property", "hoping Bea finds her
keys": a hope about what happens to someone else, asking nobody for anything. Answered in
words; nobody is asked, nothing moves. A hope that names the assistant or the speaker ("I
hope you can bring me a battery", "hope Joss lends me his") is left to be read as a request."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english, language

# the verb, by its lemma ("hope", "hoping"), and the adverb; never listed with the English
# data, where no colleague's name may stand
_HOPE = "hope"
_HOPEFULLY = "hopefully"
# "I wish Otto would get his phone back": a wish read as a hope where what is wished for is
# someone's own ("his", "her", "their"); other wishes that name a colleague are requests of
# them ("I wish Hal would sign the form")
_WISH = "wish"
_THEIR_OWN = frozenset({"his", "her", "hers", "their", "theirs"})
# what may stand before the hope itself ("I really do hope ...", "just hoping ...")
_BEFORE_HOPE = english.words("hope_leads")
# the assistant or the speaker: a hope with these in it may be a request in disguise
_ASKED_OR_FOR_ME = english.words("hope_asks")


def hope(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if _hoped(terms, piece):
        return Finding(
            "wish",
            piece,
            "a hope about someone else, not a request",
            message="I hope so too; there is nothing there for me to do.",
        )
    if _about_them(piece) and any(_hoped(terms, p) for p in msg.pieces if p.start < piece.start):
        # "..., she needs it today", "..., he's lost without it": why it is hoped for, said
        # of the colleague hoped about; nobody is asked for it
        return Finding("wish", piece, "the reason for the hope")
    return None


def _told(piece: Piece) -> bool:
    acts = piece.acts
    return not (acts.imperative or acts.question is not None or piece.asks)


def _hoped(terms: Terms, piece: Piece) -> bool:
    """A hope with nothing in it for the assistant or the speaker; not "I'm hoping to borrow
    a ruler" (the speaker's own need), nor a colleague called Hope ("Hope needs a ruler")."""
    if not _told(piece):
        return False
    words = content(piece.words)
    n = 0
    while n < len(words) and words[n] in _BEFORE_HOPE:
        n += 1
    if n >= len(words) or not (_hoping(words[n]) or words[n] == _WISH):
        return False
    if _colleagues_possessive(piece, words[n]):
        return False  # "need a ruler. Hope's please": the colleague's, no verb
    if n == 0 and words[n] in terms.lex.name_words and _read_as_name(piece, words[n]):
        return False  # the word opens the piece and the lexicon read it as someone's name
    hoped = words[n + 1 :]
    if words[n] == _WISH and not set(hoped) & _THEIR_OWN:
        return False  # "I wish Hal would sign the form": who is to do the work, asked
    return hoped[:1] not in ([], ["to"]) and not set(hoped) & _ASKED_OR_FOR_ME


def _colleagues_possessive(piece: Piece, word: str) -> bool:
    """Whether ``word`` (folded: "hopes") was written as a colleague's name with "'s",
    capitalised ("Hope's please", "Hope's would do"): a verb is never spelled with an
    apostrophe, and the capital makes it the name, as the lexicon read it. Lower-case
    ("hope's not lost") is the ordinary word and stays a hope."""
    tokens = piece.lexed.tokens
    return any(
        m.kind == "person"
        and m.possessive
        and m.end - m.start == 1
        and tokens[m.start].text[:1].isupper()
        and tokens[m.start].word + "s" == word
        for m in piece.lexed.mentions
    )


def _read_as_name(piece: Piece, word: str) -> bool:
    """Whether the lexicon read ``word`` in ``piece`` as a colleague's name ("Hope needs a
    ruler"), not as the word of a fixed phrase ("Hope so, thanks": ``name_reading``)."""
    tokens = piece.lexed.tokens
    return any(
        m.kind == "person" and any(t.word == word for t in tokens[m.start : m.end])
        for m in piece.lexed.mentions
    )


def _hoping(word: str) -> bool:
    return word == _HOPEFULLY or _HOPE in language.verb_lemmas(word)


def _about_them(piece: Piece) -> bool:
    """Told of "he"/"she"/"they", with nothing in it for the assistant or the speaker."""
    words = piece.words
    return (
        _told(piece)
        and words[:1] in (["he"], ["hes"], ["she"], ["shes"], ["they"], ["theyre"])
        and not set(words) & _ASKED_OR_FOR_ME
    )
