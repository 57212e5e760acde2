"""The recipient of a giving verb left unsaid after "and": "bring Wang a coffee and Sun a
water" is "bring Wang a coffee and [bring] Sun a water" (English gapping).

Read one name at a time, "Sun" after "and" had no verb before it and got no role, so the water
went to the recipient said before all objects (Wang): a wrong hand-over. A person (or "me",
"him"/"her") right after "and", with a noun phrase opening right after it, in a clause whose
giving verb already had an indirect object ("bring *Wang* a coffee"), or whose need had its
subject ("*Wang* needs my stapler and Sun a coffee"), is that verb's indirect object again,
for the object that follows it (``Roles.for_next_at``; the object's recipient is read by
``_parties.recipient_of``).

A name joined to the one before it ("bring Wang and Sun a coffee") is a group of recipients
(``joined_recipients``), not a gap.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.indirect_object import gives_from_verb, opens_noun_phrase
from assistantx.agents.symbolic.reading.joined_recipients import one_party
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token, prev_word
from assistantx.core import english

_DATIVE_VERBS = english.words("dative_verbs")
_NEEDS = english.words("need_verbs")


def _indirect_object(tokens: Sequence[Token], ms: Sequence[Mention], k: int) -> bool:
    """Whether mention ``k`` is a giving verb's indirect object: right after the verb, the
    thing's noun phrase opening right after it ("bring *Wang* a coffee"), or the one in need
    of it ("*Wang* needs my stapler and Sun a coffee": "needs" left unsaid the second time)."""
    if not one_party(ms[k], tokens):
        return False
    m = ms[k]
    if m.end < len(tokens) and tokens[m.end].word in _NEEDS:
        return opens_noun_phrase(tokens, m.end + 1)
    prev = prev_word(tokens, m.start)
    verb = prev in _DATIVE_VERBS or gives_from_verb(tokens, ms, k, prev)
    return verb and opens_noun_phrase(tokens, m.end)


def gapped_recipient(tokens: Sequence[Token], ms: Sequence[Mention], n: int) -> bool:
    """Whether mention ``n`` is the indirect object of a giving verb left unsaid after "and"
    ("... and *Sun* a water"), the clause's verb having had one before it."""
    m = ms[n]
    if not one_party(m, tokens) or prev_word(tokens, m.start) != "and":
        return False
    if not opens_noun_phrase(tokens, m.end):
        return False
    if n > 0 and one_party(ms[n - 1], tokens) and ms[n - 1].end == m.start - 1:
        return False  # "Wang and Sun a coffee": one group (``joined_recipients``)
    if not _object_follows(ms, n):
        return False  # "... and Rose a <thing the office has not>": no object of the gap
    return any(_indirect_object(tokens, ms, k) for k in range(n))


def _object_follows(ms: Sequence[Mention], n: int) -> bool:
    """Whether an item of the office is named after mention ``n``, before anyone else: the
    object the unsaid verb gives (without one, the name would take the object before it)."""
    for x in ms[n + 1 :]:
        if x.kind == "item":
            return True
        if x.kind in ("person", "self", "pronoun") and not x.possessive:
            return False
    return False
