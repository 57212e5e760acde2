"""The words of an office that are only parts of a longer name of a thing ("heat" of "heat
pack", "book" of "pocket book" where nothing is called just "book").

A word of the office's vocabulary is kept from being read as a service the office lacks
("could you print ..." where printing is offered). A word said only inside an item's longer
name is no thing of the office on its own: "heat up my lunch" asks for heating whatever the
office calls "heat pack", and "book us the lounge" asks for a booking whatever it calls a
"pocket book". Where such a word heads an imperative it is the verb, and a verb nothing here
offers is declined ("Sorry, I can't heat: ..."), never reduced to fetching its object. The
whole name said there ("heat pack for me please") is still the thing.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.core import language
from assistantx.core.office import Office


def name_inner_words(office: Office, lex: Lexicon) -> frozenset[str]:
    """The words that occur in the office's names of things of several words and in no
    name of one word: not an item's, a person's, a facility's or a place's, nor a service's
    verb or name, nor a task word."""
    inner = {w for phrase in lex.items if len(phrase.split()) > 1 for w in phrase.split()}
    alone = {
        phrase
        for names in (lex.items, lex.people, lex.name_words, lex.facilities, lex.places)
        for phrase in names
        if len(phrase.split()) == 1
    }
    own_verbs = {
        w
        for op in office.operations
        for phrase in (*op.verbs, op.name)
        for w in language.words(phrase)
    }
    return frozenset(inner - alone - own_verbs - lex.cue_words)


def inside_a_name(lex: Lexicon, words: Sequence[str], at: int) -> bool:
    """Whether the word at ``at`` opens one of the office's names of things said whole
    there ("*heat pack* for me please"): then it is that thing, no verb."""
    return any(
        tuple(words[at : at + len(phrase.split())]) == tuple(phrase.split())
        for phrase in lex.items
        if len(phrase.split()) > 1
    )
