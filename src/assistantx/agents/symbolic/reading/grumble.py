"""A grumble told: "ugh still miles to go with these invoices", "gonna be a long day", "won't
be done till 6". Venting about the speaker's own work asks nobody for anything: answered in
words, nothing moves. Read as a request, the words were taken for one: a colleague whose name
is a word of the grumble ("Miles" of "miles to go") was the party, the things grumbled about
("these invoices") the thing whose owner was asked.

An interjection of annoyance said alone ("ugh", "argh Frank") is one too. Two longer shapes,
both read from the words as said, never from names: a way still to go said by an
amount or a plural noun right before "to go" ("miles", "loads", "three more"), with nothing
after it but what it is on or when ("with these invoices", "till friday"); and a set phrase of
a long day's work (``grumble_phrases``). "a coffee to go" asks (the thing is the office's, and
a request's own words are read before this), and so does "any chance of ...". Where the
office names a thing before "to go", it is no grumble."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.agents.symbolic.reading.phrase_index import by_first_word, phrase_at
from assistantx.core import english, language
from assistantx.core.name_reading import numeral

_AMOUNTS = english.words("grumble_amounts")
_AFTER_GO = english.words("grumble_after_go")
_INTERJECTIONS = english.words("grumble_interjections")
_PHRASES = by_first_word([tuple(p.split()) for p in english.entries("grumble_phrases")])
_WISH_OPENERS = by_first_word([tuple(p.split()) for p in english.entries("grumble_wish_openers")])
_WISH_HAVING = by_first_word([tuple(p.split()) for p in english.entries("grumble_wish_having")])
_WISH_OWNERS = english.words("grumble_wish_owners")
_WISH_STATES = english.words("grumble_wish_states")
_WISH_RELATIVES = english.words("grumble_wish_relatives")
_WISH_USERS = english.words("grumble_wish_users")
_SPEAKERS = frozenset({"i", "we"})


def grumble(w: Sequence[str], names_thing: Callable[[str], bool]) -> bool:
    """Whether the content words ``w`` of a piece are a grumble; ``names_thing``: whether a
    word names a thing of the office ("coffee" of "a coffee to go")."""
    words = list(w)
    if any(phrase_at(words, k, _PHRASES) is not None for k in range(len(words))):
        return True
    for k in range(1, len(words) - 1):
        if words[k : k + 2] != ["to", "go"]:
            continue
        amount = words[k - 1]
        if names_thing(amount):
            return False  # "a coffee to go": the office's thing, asked
        if not (amount in _AMOUNTS or numeral(amount) or language.is_plural_noun(amount)):
            continue
        after = words[k + 2 : k + 3]
        if not after or after[0] in _AFTER_GO:
            return True
    return False


def wished_better(w: Sequence[str], names_person: Callable[[list[str]], bool]) -> bool:
    """A wish for a better thing, said of the speaker's own lot: "wish i had a stapler that
    actually worked", "if only I had a pen that didn't leak", "i wish my stapler actually
    worked", "if only my pen didn't leak". The thing is described by what it would do or not
    do (a relative clause after it, or a state or past verb after "my" thing): a grumble,
    nothing asked. Unchanged: "wish i had a pen" (no clause: read as before), "I wish I had a
    pen that I could borrow" (a use of the thing, not its quality), a person the wish is about
    (``names_person`` of the words after the opener: "if only my boss signed it")."""
    words = list(w)
    opener = phrase_at(words, 0, _WISH_OPENERS) if words else None
    if opener is None:
        return False
    rest = words[len(opener) :]
    if names_person(rest):
        return False
    if rest[:1] and rest[0] in _SPEAKERS:
        having = phrase_at(rest, 1, _WISH_HAVING)
        if having is None:
            return False
        thing = rest[1 + len(having) :]
        # the relative pronoun after at least the thing's noun: "a stapler that ...", never
        # "that stapler" (a determiner) or a clause with the speaker as its subject
        return any(
            thing[k] in _WISH_RELATIVES
            and k + 1 < len(thing)
            and not language.is_function_word(thing[k - 1])
            and thing[k + 1] not in _WISH_USERS
            for k in range(1, len(thing))
        )
    if rest[:1] and rest[0] in _WISH_OWNERS:
        # "my pen didn't leak", "my stapler actually worked": the thing's own state
        return any(
            x in _WISH_STATES or (language.is_past_verb(x) and not language.is_noun(x))
            for x in rest[2:]
        )
    return False


def grumbled(words: Sequence[str], named: Callable[[str], bool]) -> bool:
    """Whether ``words`` are only interjections of annoyance ("ugh", "argh"), and the name of
    the colleague they are said to ("ugh Miles"): venting, nothing to act on."""
    return any(x in _INTERJECTIONS for x in words) and all(
        x in _INTERJECTIONS or named(x) for x in words
    )
