"""A send-out's "to" phrase that is a bare common noun ("courier my sample to the factory",
"post my letter to the council", "to head office", "to the lab") where the service needs an
address: which factory, at what address? The words give the kind of place only, so the
service asks its own question ("Where should I courier it to? Please give me the name and
address of the place.") before anything moves, never sending the thing "to the factory".

The office's data says what its send-out needs (``destination_asked``): a service that asks
for an address is owed one. The phrase is bare when, past courtesy and an article or
possessive, it is one or two lower-case words the dictionary knows as nouns or adjectives (or
a doer noun made from a verb it knows, "the distributor"; or a participle that describes the
noun after it, "the pressing plant"), with no proper name, no digit and no preposition ("the
factory", "head office", "the main lab"); a name ("Acme Ltd"), an address ("4 Mill Road"), or
anything more ("the factory in Leeds") is where it goes, as said."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.doer_nouns import is_made_doer_noun
from assistantx.core import english, language

_OPENERS = frozenset({"the", "a", "an", "our", "my", "your", "their", "his", "her"})
_COURTESY = frozenset({"please", "pls", "plz", "thanks", "thx", "cheers", "asap", "ta"})
# The clipped words of English ("lab" of laboratory): a clip is the word it clips
_CLIPPED = {c: word for word, clips in english.phrase_table("clipped_words").items() for c in clips}
# The most words of a kind of place said with nothing else ("the main lab", "head office")
_BARE_WORDS = 2


def needs_address(asked: str) -> bool:
    """Whether a service's question for where it sends (``destination_asked``) asks for an
    address ("the name and address of the place", "the postal address")."""
    return "address" in language.words(asked)


def bare_common_noun(phrase: str) -> bool:
    """Whether ``phrase`` names only a kind of place in common words (see the module)."""
    said = [w for w in phrase.split() if w.lower().strip(".,!?") not in _COURTESY]
    if said and said[0].lower() in _OPENERS:
        said = said[1:]
    if not said or len(said) > _BARE_WORDS:
        return False
    for at, word in enumerate(said):
        if not word.isalpha() or not word.islower():
            return False  # "Acme", "4", "client's": a name, a number, an owner
        kinds = language.lemmas(_CLIPPED.get(word, word))
        if "NOUN" in kinds or "ADJ" in kinds or is_made_doer_noun(word):
            continue  # "the main lab", "the distributor"
        if at < len(said) - 1 and language.is_present_participle(word):
            continue  # "the *pressing* plant", "the *sorting* office": a kind described
        return False  # "the celestia": a word no dictionary has, a name in lower case
    last = said[-1]
    return language.is_noun(_CLIPPED.get(last, last)) or is_made_doer_noun(last)
