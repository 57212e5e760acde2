"""A colleague named in apposition to their role: "get the duty manager, Frank, to sign my
report", "could the night porter, Li, bring me a coffee". The name between the commas is who
is meant; the role before it ("the duty manager": a determiner and a few words ending in a
noun) only describes them, so it is read away and the name stands in its place ("get Frank to
sign my report"). Left as said, a role word the office knows otherwise ("manager" of "Manager
Mao") would name someone else, and one it does not ("duty") would be asked about.

Only where the name closes with a comma (a name at the text's end, "take it to our intern,
Bo", is the recipient's apposition, ``core.appositive``), the name is one colleague's, and the
role names nothing of the office but people (no thing, machine or place: "the stapler, Wang,
..." is a thing and a vocative)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.aligned import aligned_reading
from assistantx.agents.symbolic.reading.lexicon import Lexicon, Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# "the", "our", "my", "your", "their", "his", "her": a role's noun phrase opens with one
_OPENERS = english.words("determiners") - {"me", "a", "an", "some", "any", "this", "that"}
# The most words of a role said before a name ("the new night porter")
_ROLE_WORDS = 4
# What a role may name besides plain words: a person's title or alias word ("manager" of
# "Manager Mao"), never a thing, a machine or a place
_ROLE_KINDS = frozenset({"word", "person", "cue"})


def without_role_appositives(lex: Lexicon, text: str) -> str:
    """``text`` with the first "<determiner> <role>, <Name>," read as the name alone;
    unchanged where no name stands in apposition to a role."""
    spans, tokens, mentions = aligned_reading(lex, text)
    if spans is None:
        return text
    for name in mentions:
        if name.kind != "person" or len(name.ids) != 1 or name.possessive:
            continue
        first = tokens[name.start]
        if first.opens or not first.after_pause:
            continue  # "..., Frank": the name follows a comma
        after = name.end
        if after >= len(tokens) or not tokens[after].after_pause or tokens[after].opens:
            continue  # "Frank, to sign ...": the name closes with a comma
        opener = _role_opener(tokens, mentions, name.start)
        if opener is None:
            continue
        start, stop = spans[opener][0], spans[name.start][0]
        rest = text[spans[name.end - 1][1] :].lstrip()
        rest = rest[1:].lstrip() if rest.startswith(",") else rest
        return text[:start] + text[stop : spans[name.end - 1][1]] + " " + rest
    return text


def _role_opener(tokens: list[Token], mentions: list[Mention], name_at: int) -> int | None:
    """The token of the determiner that opens the role just before the name at ``name_at``
    ("the" of "the duty manager, Frank"), or None where no role stands there."""
    end = name_at  # the role's words are [opener + 1, end)
    k = end - 1
    while k >= 0 and tokens[k].word not in _OPENERS:
        if tokens[k].opens or tokens[k].after_pause or end - k > _ROLE_WORDS:
            return None
        k -= 1
    if k < 0 or k == end - 1:
        return None  # no determiner, or no word between it and the name
    if any(tokens[j].after_pause for j in range(k + 1, end)):
        return None
    head = tokens[end - 1].word
    if not language.is_noun(head) or tokens[end - 1].possessive:
        return None  # the role ends with a noun ("manager", "porter")
    for m in mentions:
        if m.start < end and m.end > k + 1 and m.kind not in _ROLE_KINDS:
            return None  # "the stapler, Wang, ...": a thing of the office, no role
    return k
