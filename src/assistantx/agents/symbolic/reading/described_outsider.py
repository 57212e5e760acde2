"""An outsider described in the message, and what points back to them or says where they come
from: "I need a coffee for a visitor from Shenzhen", "we've got a client visiting from Dublin,
could you get me a coffee for him?", "an instructor coming over from Verbier", "Mrs Hughes
is coming in at 3. I need a printout for her meeting".

A person described by what they are (a determiner, at most a few describing words, and a noun
that names a person by what they are or by their work: "a visitor", "the client", "our
auditor"), or as travelling ("an instructor visiting", "a visiting instructor", "someone
coming over"), or named by a title and a name nobody of the office has ("Mrs Hughes"), is
nobody of the office. Two things follow, both rules about English:

- a capitalised word after "from" right after such a person ("a visitor from Shenzhen", "a
  client visiting from Dublin") says where they come from: a place, no colleague to look up;
- "for him"/"for her"/"for them" with no colleague named before it points back to that
  outsider: the thing is for them, and since only people of the office are handed anything,
  the requester receives it to pass on (as "I need a coffee for a visitor" already reads).
"""

from __future__ import annotations

from collections.abc import Collection, Sequence

from assistantx.agents.symbolic.reading.lexicon import Lexed, Mention
from assistantx.agents.symbolic.reading.named_once import the_ones_named
from assistantx.agents.symbolic.reading.outsider_need import is_outsider_noun
from assistantx.agents.symbolic.reading.titled_stranger import titled_stranger
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

_ROLES = english.words("role_nouns")
# the words that open a described person's phrase
_DETERMINERS = frozenset(
    {"a", "an", "the", "our", "my", "their", "your", "this", "that", "some", "another"}
)
# who is described by no noun at all, only as travelling ("someone coming over")
_ANYONE = frozenset({"someone", "somebody"})
# a person said to be on their way here: "visiting", "coming", "flying"
_TRAVELLING = english.words("travelling_participles")
# between the journey's participle and its "from": "coming over from", "is visiting from"
_ON_THE_WAY = english.words("travelling_particles") | {"is", "are", "was", "were", "s"}
_MOST_MODIFIERS = 2  # "a visiting young instructor"
_TO_FROM = 4
_OFFICE_KINDS = frozenset(
    {"person", "item", "facility"}
)  # "a supplier is coming over from Leeds": words between the person and "from"


def named_things(mentions: Sequence[Mention]) -> frozenset[int]:
    """The tokens that name something of the office (a colleague, an item, a facility)."""
    return frozenset(i for m in mentions if m.kind in _OFFICE_KINDS for i in range(m.start, m.end))


def _person_noun(word: str) -> bool:
    return is_outsider_noun(word) or word in _ROLES


def _described_at(tokens: Sequence[Token], k: int, taken: Collection[int]) -> int | None:
    """The index of the head of a described outsider's phrase opened at ``k``, if one is;
    ``taken``: the tokens that name something of the office (never a described person)."""
    word = tokens[k].word
    if word in _ANYONE:
        return k if k + 1 < len(tokens) and tokens[k + 1].word in _TRAVELLING else None
    if word not in _DETERMINERS:
        return None
    travelling = False  # "a visiting instructor"
    for h in range(k + 1, min(len(tokens), k + 2 + _MOST_MODIFIERS)):
        t = tokens[h]
        if h in taken or t.after_pause or t.opens or not t.text[:1].islower():
            return None
        if t.word in _TRAVELLING:
            travelling = True
            continue
        nxt = tokens[h + 1] if h + 1 < len(tokens) else None
        # "an instructor visiting": the person on their way, said after the noun
        on_the_way = nxt is not None and nxt.word in _TRAVELLING and not nxt.after_pause
        if _person_noun(t.word) or ((travelling or on_the_way) and language.is_noun(t.word)):
            return h
    return None


def described_outsiders(tokens: Sequence[Token], taken: Collection[int]) -> list[int]:
    """The heads of the described outsiders of the message, in order: a person described by
    what they are, or named by a title and a name nobody of the office has ("Mrs Hughes is
    coming in at 3": ``titled_stranger``; the name is the head)."""
    found = (
        k if titled_stranger(tokens, k, taken) else _described_at(tokens, k, taken)
        for k in range(len(tokens))
    )
    return [h for h in found if h is not None]


def outsider_origin(tokens: Sequence[Token], at: int, taken: Collection[int]) -> bool:
    """Whether the word at ``at`` (capitalised, no colleague) is where a described outsider
    comes from: "a visitor from *Shenzhen*", "a client visiting from *Dublin*"."""
    if at < 2 or tokens[at - 1].word != "from" or not tokens[at].text[:1].isupper():
        return False
    before = at - 1  # the "from"
    for head in described_outsiders(tokens, taken):
        between = tokens[head + 1 : before]
        if head < before and len(between) <= _TO_FROM:
            words = _TRAVELLING | _ON_THE_WAY
            if all(t.word in words and not t.after_pause for t in between):
                return True
    return False


def points_to_outsider(tokens: Sequence[Token], at: int) -> bool:
    """Whether the pronoun at ``at`` points back to an outsider described before it in the
    same words ("a client visiting from Dublin, get me a coffee for *him*"); the caller has
    found no colleague named before it."""
    return any(head < at for head in described_outsiders(tokens, ()))


def outsider_only(whole: Lexed, requester: str) -> bool:
    """Whether the whole message describes an outsider and names no colleague besides the
    requester ("We've got an instructor visiting tomorrow. Could you get me a ticket for
    him?"): a "him" of the request, which the screen reads apart from the statement, can
    only be that outsider. With a colleague named too, whom it means is left as before."""
    if the_ones_named(whole, requester):
        return False
    return bool(described_outsiders(whole.tokens, named_things(whole.mentions)))
