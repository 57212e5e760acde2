"""A send-out's "to" phrase that names only someone by their role or a firm by what it does
("courier my contract to my agent", "courier my form to the supplier", "DX it to the other
side's solicitors", "post it to our lawyers"): whom, said in common words, with no proper
name, no place and no address. A courier or a fax needs where to; a role says whom, never
where (which importer? at what address?), so the service asks its own question ("Where should
I courier it to? Please give me the address.") rather than send the thing "to the supplier".

The phrase is a role when, past courtesy ("pls"), it is a determiner or a possessive ("the",
"my", "our") and then only lower-case words the dictionary knows as nouns or adjectives, the
last a noun that names no place ("the importer", "our new accountant", "the other side's
solicitors"; "the distributor", a doer noun the dictionary lacks made from a verb it knows).
A capital (a proper name: "Bodegas Ruiz", "Westgate branch", "the Celestia"), a
digit (an address: "12 High Street"), a word the dictionary lacks (a name said in lower case),
any other word ("the supplier *in* Madrid", "the lawyer *at* 4 Quay Street") or a place head
("the client's *office*", "the central *library*", "the *bank*") makes it where, sent as
said; but a place head owned only by "his"/"her"/"their" ("back to his school", "to her
office") says whose place, not which one nor where, and is asked too."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.doer_nouns import is_made_doer_noun
from assistantx.core import english, language

# The head nouns that name a place, an establishment or a building, never a person: where a
# thing can be sent even said in common words ("the client's office", "the warehouse").
_PLACE_HEADS = (
    english.words("place_heads")
    | english.words("outside_workplaces")
    | english.words("outside_shops")
    | english.words("home_nouns")
    | english.words("street_words")
    | english.words("place_words")
    | english.words("establishment_heads")
)
# What starts a phrase that only describes: an article, a demonstrative or a possessive
# ("the importer", "my agent", "those suppliers"); not a quantity ("all", "some", "any").
_OPENERS = frozenset({"the", "a", "an", "this", "that", "these", "those"}) | frozenset(
    {"my", "our", "your", "his", "her", "their"}
)
# a possessive of someone else that says whose a place is but not which or where ("courier my
# report back to his school", "to her office"): asked, like a role
_SOMEONES = frozenset({"his", "her", "their", "its"})
# words that place or join ("up", "near", "back" are nouns or adjectives too): a phrase with
# one says more than whom ("the supplier up north", "the agent near the port")
_JOINS = english.words("prepositions_and_joins") | english.words("party_prepositions")
# courtesy said after the phrase, no part of where ("to my agent pls")
_COURTESY = frozenset({"please", "pls", "plz", "thanks", "thx", "cheers", "asap", "ta"})
# a word as said, with a possessive ending kept apart ("side's" → "side", "clients'" → "clients")
_WORD = re.compile(r"[^\W\d_]+(?:['’]s\b|['’](?=\s|$))?|\S")
_POSSESSIVE_END = re.compile(r"['’]s?$")


def _said_words(phrase: str) -> list[str]:
    """The words of ``phrase`` as said (case kept), each without its possessive ending."""
    return [_POSSESSIVE_END.sub("", w) for w in _WORD.findall(phrase)]


def _common(word: str) -> bool:
    """Whether ``word`` is a common word of a noun phrase: lower case (no proper name), no
    preposition, and known to the dictionary as a noun, an adjective or a participle that
    describes ("the *shipping* agent", "the *forwarding* firm"), or a doer noun it lacks made
    from a verb it knows ("the *distributor*")."""
    if not word.islower() or word in _JOINS:
        return False
    parts = language.lemmas(word)
    if "NOUN" in parts or "ADJ" in parts or language.is_present_participle(word):
        return True
    return is_made_doer_noun(word)


def names_only_a_role(phrase: str) -> bool:
    """Whether ``phrase`` (a send-out's destination as said) names only a person or a firm by
    their role: a determiner or possessive, then common nouns and adjectives only, the last a
    noun that is no place (no proper name, no digit, no preposition, no place head)."""
    said = [w for w in _said_words(phrase) if w.lower() not in _COURTESY]
    if len(said) < 2 or said[0].lower() not in _OPENERS:
        return False  # "Westgate branch", "Agent Smith": a name is where it goes
    rest = said[1:]
    if not all(_common(w) for w in rest):
        return False  # a name, a digit, a preposition: "the supplier in Madrid"
    head = rest[-1]
    if not (language.is_noun(head) or is_made_doer_noun(head)):
        return False
    lemmas = set(language.lemmas(head).get("NOUN", ())) | {head}
    if said[0].lower() in _SOMEONES:
        return True  # "his school", "her office": someone's place, never said which or where
    return not lemmas & _PLACE_HEADS  # "the client's office", "the bank": a place
