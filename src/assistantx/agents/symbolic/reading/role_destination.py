"""A send-out's "to" phrase that names only someone's role ("courier my contract to my agent",
"post it to my lawyer", "fax it to our accountant"): a person said by what they do, with no
place and no address. A courier or a fax needs where to; the role says whom, never where, so
the service asks its own question ("Where should I courier it to? Please give me the
branch.") rather than send the thing "to my agent".

The phrase is a role when, past a possessive ("my", "our", "her") and courtesy ("pls"), it is
one role or person noun in the singular (``role_nouns``, ``outsider_nouns``), with at most two
modifiers before it ("my literary agent"): someone of the speaker's, never a place. "The
supplier", "the insurers", "our lawyers" (a firm said by its role) stay as said; "the lawyer
at 12 High Street" (an address), "the client's office" (a place) and "Westgate branch" (a
name) are places and stay as said."""

from __future__ import annotations

from assistantx.core import english, language

_ROLES = english.words("role_nouns") | english.words("outsider_nouns")
# whose person it is: the speaker's or another's ("my agent", "her accountant"); "the
# supplier", "the insurers", "a client" are an outside firm said by its role, which the project
# reads as where (tests of send-outs to "the customer", "the insurers"), and stay as said
_POSSESSIVES = frozenset({"my", "our", "your", "his", "her", "their"})
# courtesy said after the phrase, no part of where ("to my agent pls")
_COURTESY = frozenset({"please", "pls", "plz", "thanks", "thx", "cheers", "asap", "ta"})
# a role may carry a word or two before it ("my literary agent", "the new client")
_MODIFIERS = 2


def names_only_a_role(phrase: str) -> bool:
    """Whether ``phrase`` (a send-out's destination as said) names only a person by their role:
    a possessive, at most two modifiers, then one role noun, and nothing else
    (no digit, no possessive "'s", no place after it)."""
    if any(c.isdigit() for c in phrase) or "'" in phrase or "’" in phrase:
        return False  # an address or a number; "the client's office" names a place
    said = [w for w in language.words(phrase) if w not in _COURTESY]
    if not said or said[0] not in _POSSESSIVES:
        return False  # "Westgate branch", "Agent Smith", "the supplier": left as said
    rest = said[1:]
    if not rest or rest[-1] not in _ROLES or language.is_plural_noun(rest[-1]):
        return False  # "our lawyers": a firm, said by its people, is where it goes
    return len(rest) - 1 <= _MODIFIERS
